"""Find and kill every process a sandboxed controller started (Linux /proc).

A sandbox's processes are its descendants and anything whose environment
holds its token (TOKEN_VAR=token), which whatever it starts inherits: found
even if they left its session and lost their parent.
"""

from __future__ import annotations

import os
import signal
from collections.abc import Iterator

TOKEN_VAR = "TURTLETUI_SANDBOX"


def _processes() -> Iterator[tuple[int, bytes, int]]:
    """(pid, state, parent pid) of every process in /proc (none elsewhere)."""
    try:
        entries = os.listdir("/proc")
    except OSError:
        return
    for entry in entries:
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as f:
                fields = f.read().rpartition(b")")[2].split()
            state, ppid = fields[0], int(fields[1])
        except (OSError, ValueError, IndexError):
            continue
        yield int(entry), state, ppid


_HALTED = frozenset({b"T", b"t", b"Z", b"X"})
"""Process states in which a process cannot start another: stopped, traced, dead."""


def _sandboxed(root: int, token: bytes) -> tuple[set[int], bool]:
    """Processes the child ``root`` started (Linux /proc; empty elsewhere): its
    descendants, and any process whose environment holds ``token``; and
    whether ``root`` is halted (stopped or dead) or gone."""
    children: dict[int, list[int]] = {}
    marked: set[int] = set()
    me = os.getpid()
    halted = True
    for pid, state, ppid in _processes():
        if pid == root:
            halted = state in _HALTED
        children.setdefault(ppid, []).append(pid)
        try:
            with open(f"/proc/{pid}/environ", "rb") as f:
                if token in f.read().split(b"\0"):
                    marked.add(pid)
        except OSError:
            pass
    stack = [root, *marked]  # and what the marked ones started (a clean exec's environment)
    seen = set(stack)
    while stack:
        for pid in children.get(stack.pop(), ()):
            if pid not in seen:
                seen.add(pid)
                marked.add(pid)
                stack.append(pid)
    marked.discard(me)
    marked.discard(1)
    return marked, halted


def _signal(pid: int, sig: int, group: bool = False) -> None:
    try:
        if group:
            os.killpg(pid, sig)
        else:
            os.kill(pid, sig)
    except (ProcessLookupError, PermissionError):
        pass


def kill_tree(pid: int, token: str, *, reaped: bool = False, spare: int | None = None) -> None:
    """Kill the child ``pid``, its process group, and every process it started,
    also those that left its group or session (frozen first, so that none can
    fork away while they are looked for). Once reaped, ``pid`` may be another
    process's: it is spared then, but not its group or what holds the token.
    ``spare`` is a process holding the token that must live on (a fork server)."""
    marker = f"{TOKEN_VAR}={token}".encode()
    stopped: set[int] = set()
    try:
        _signal(pid, signal.SIGSTOP, group=True)
        if not reaped:
            _signal(pid, signal.SIGSTOP)
        for _ in range(8):
            found, halted = _sandboxed(-1 if reaped else pid, marker)
            fresh = found - stopped
            fresh.discard(spare)
            if not fresh or (not reaped and halted and fresh == {pid}):
                break  # the child alone and stopped (killed below): nothing can have started since
            for child in fresh:
                _signal(child, signal.SIGSTOP)
            stopped |= fresh
    finally:
        # Even when interrupted (the grader stopping this worker): a process
        # left stopped would never end, not even on its pipes closing.
        _signal(pid, signal.SIGKILL, group=True)
        if not reaped:
            _signal(pid, signal.SIGKILL)
        for child in stopped:
            _signal(child, signal.SIGKILL)


def kill_children(keep: set[int]) -> None:
    """Kill this process's children but ``keep``, and theirs that it inherits
    meanwhile (a child subreaper inherits the orphans of what it started),
    each frozen first so that none can fork away."""
    me = os.getpid()
    for _ in range(8):
        found = {pid for pid, state, ppid in _processes() if ppid == me and pid not in keep and state not in (b"Z", b"X")}
        if not found:
            break
        for pid in found:
            _signal(pid, signal.SIGSTOP)
        for pid in found:
            _signal(pid, signal.SIGKILL)
    reap_zombie_children()


def reap_zombie_children() -> None:
    """Reap this process's children that have died and that nobody waits for:
    a child subreaper inherits the orphans of what it started and kills them."""
    me = os.getpid()
    for pid, state, ppid in _processes():
        if state == b"Z" and ppid == me:
            try:
                os.waitpid(pid, os.WNOHANG)
            except ChildProcessError:
                pass


def has_exited(pid: int) -> bool:
    """Whether this process's child ``pid`` has ended, without reaping it (its
    CPU time can still be read then); True if it is gone already."""
    try:
        return os.waitid(os.P_PID, pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None
    except ChildProcessError:
        return True
    except (AttributeError, OSError):  # no waitid (not POSIX)
        return False


def cpu_seconds(pid: int) -> float | None:
    """CPU time (user and system) process ``pid`` has used, also once it has
    ended and until it is reaped (Linux /proc); None if it cannot be read."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rpartition(b")")[2].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


def run_queue_seconds(pid: int | str) -> float | None:
    """Seconds the threads of process ``pid`` ("self" for this one) have spent
    ready to run, waiting for a CPU that other processes held (Linux
    schedstat); None if it cannot be read. Threads that ended are not counted."""
    folder = f"/proc/{pid}/task"
    try:
        threads = os.listdir(folder)
    except OSError:
        return None
    total = 0
    for thread in threads:
        try:
            with open(f"{folder}/{thread}/schedstat", "rb") as f:
                total += int(f.read().split()[1])
        except (OSError, ValueError, IndexError):
            continue
    return total / 1e9
