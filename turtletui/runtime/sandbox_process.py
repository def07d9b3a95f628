"""The process of a sandboxed controller: start, pipes, output, end.

:class:`ChildProcess` starts turtletui.runtime.child in a fresh interpreter
(or forks it from a fork server) with CPU, memory and file-size limits, in its
own session so that every process it starts can be killed; sends and
receives frames with deadlines; shows what the controller prints within its
budget; and says why the process died. Every failure is a
:class:`ChildFailed` with the crash kind and a one-line reason. What the
frames mean is turtletui.runtime.sandbox's business.
"""

from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from time import monotonic as _monotonic  # bound at import: an in-process run simulates time's
from typing import TYPE_CHECKING, Any

from turtletui.graph.logs import ERROR_SUFFIX, INFO, OUTPUT_SUFFIX, WARN
from turtletui.runtime import forkserver, stuck, wire
from turtletui.runtime.budget import OutputBudget, size_text
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.processes import (
    TOKEN_VAR,
    cpu_seconds,
    has_exited,
    kill_tree,
    run_queue_seconds,
)

if TYPE_CHECKING:
    from turtletui.runtime.sandbox import Limits

_PACKAGE_ROOT = str(Path(__file__).resolve().parents[2])
_BOOTSTRAP = (
    "import sys; sys.path.insert(0, {root!r}); "
    "from turtletui.runtime.child import main; main()"
)
_OUTPUT_READ_LIMIT = 1 << 20
"""Bytes of print() output read in one go, so a flood cannot keep the parent reading."""
_LIVENESS_SECONDS = 0.1
"""How often a parent waiting for an answer checks that the child is still alive."""


class ChildFailed(Exception):
    """The child must be stopped: ``kind`` as in CrashReport, ``message`` one
    line; ``where()`` finds the frames of the controller's file it is at (as
    CrashReport's), asked only when the failure is reported (:attr:`frames`)."""

    def __init__(self, kind: str, message: str, where: Callable[[], list[str]] | None = None) -> None:
        super().__init__(message)
        self.kind = kind
        self.message = message
        self._where = where
        self._frames: list[str] | None = None

    @property
    def frames(self) -> list[str]:
        if self._frames is None:
            self._frames = self._where() if self._where is not None else []
        return self._frames


Log = Callable[[str, int, str], object]
"""Graph.log: (node, level, text)."""


class ChildProcess:
    """One sandboxed controller's process and its four pipes (its input, its
    answers, its stdout and its stderr)."""

    def __init__(self, spec: ControllerSpec, limits: Limits, log: Log, *, spin: float) -> None:
        self.spec = spec
        self.limits = limits
        self._log = log
        self._spin = spin
        self.started = False
        """Whether it has loaded: it sent its first answer."""
        self.running = False
        """Whether the controller has run up to its first wait (rclpy.spin,
        a sleep): an answer came after the first."""
        self.proc: Any = None
        """A subprocess.Popen, or a forkserver.ForkedChild; None once ended."""
        self._token = ""
        self._spare: int | None = None
        """A process holding the token that is not this child's (its fork server)."""
        self._to_child = -1
        self._answers: wire.FrameReader | None = None
        self._outputs = [-1, -1]
        """The pipes of the child's stdout and stderr (read ends)."""
        self._open = [True, True]
        self._output_poll = select.poll()
        self._errors = bytearray()
        """Lockstep: stderr read while the child runs its step, shown with its
        answer after the step's stdout, as the fast path shows them."""
        self._held: list[bytearray] | None = None
        """Fast path: stdout and stderr read but not yet shown (:meth:`hold_output`)."""
        self._fed = [0, 0]
        """Fast path: bytes of stdout and stderr shown or dropped so far."""
        self.max_frame = wire.MAX_REPLY_BYTES
        """The largest frame the child may send."""
        self.journal_fd: int | None = None
        """Fast path: the shared memory the child also writes its answers to
        (turtletui.runtime.fastpath), given to the child at its start."""
        self.stack_fd: int | None = None
        """The memory file the child dumps its stack into when asked where it is stuck
        (turtletui.runtime.stuck)."""
        self._output = OutputBudget(
            self._show_output,
            max_bytes=limits.output_bytes,
            max_lines=limits.output_lines,
            line_chars=limits.output_line_chars,
            show_stderr=self._show_errors,
            lines_per_second=limits.output_lines_per_second,
            note=self._note_rate_dropped,
        )

    @property
    def pid(self) -> int | None:
        return None if self.proc is None else self.proc.pid

    # -- start ----------------------------------------------------------------------------------
    def spawn(self, config: dict[str, Any]) -> None:
        """Start the child with ``config`` (what turtletui.runtime.child.main
        reads; the pipes' descriptors are added here)."""
        to_child_r, to_child_w = os.pipe()
        from_child_r, from_child_w = os.pipe()
        config = {**config, "fd_in": to_child_r, "fd_out": from_child_w, "spin_seconds": self._spin}
        cwd = _start_folder(self.spec, self.limits)
        fds: tuple[int, ...] = (to_child_r, from_child_w)
        # in forkserver._EXTRA_FDS's order
        self.stack_fd = stuck.stack_file() if self.spec.path is not None else None
        for name, fd in (("fd_stack", self.stack_fd), ("fd_journal", self.journal_fd)):
            if fd is not None:
                fds += (fd,)
                config[name] = fd
        self.proc = self._fork(config, cwd, fds)
        if self.proc is None:
            # A server that did not answer in time (then stopped with all it
            # started) may have forked the child late: what it wrote is not ours.
            _forget_writes(from_child_r, self.journal_fd)
            self.proc = self._exec(config, cwd, fds)
        os.close(to_child_r)
        os.close(from_child_w)
        if self.journal_fd is not None:
            _widen(from_child_r)  # the fast path streams: the child need not wait for each read
        self._to_child = to_child_w
        # A child that stopped reading (it forged an answer, then hung) must not
        # block the parent on a full pipe: writes wait up to the step timeout.
        os.set_blocking(to_child_w, False)
        self._answers = wire.FrameReader(
            from_child_r,
            spin=self._spin,  # polled briefly, then select (wire.spin_read)
            max_size=self.max_frame,
            wait=self._wait_for_answer,
            # What the child printed before answering is logged before the answer.
            on_data=self.drain_output,
        )
        self._outputs = [self.proc.stdout.fileno(), self.proc.stderr.fileno()]
        for fd in self._outputs:
            os.set_blocking(fd, False)
            # asked every exchange whether there is output (one poll for both):
            # cheaper than a read that fails
            self._output_poll.register(fd, select.POLLIN)

    def _exec(self, config: dict[str, Any], cwd: str | None, fds: tuple[int, ...]) -> subprocess.Popen:
        """Start a fresh interpreter for the child."""
        # Inherited by whatever the controller starts: found and killed at the end
        # even if it left the child's session and lost its parent.
        self._token = _new_token()
        return subprocess.Popen(
            [sys.executable, "-s", "-c", _BOOTSTRAP.format(root=_PACKAGE_ROOT), json.dumps(config)],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            pass_fds=fds,
            start_new_session=True,
            cwd=cwd,
            env=_child_environment(self._token),
            **self._credentials(),
        )

    def _fork(self, config: dict[str, Any], cwd: str | None, fds: tuple[int, ...]) -> Any:
        """Fork the child from this submission's fork server, if this process
        uses them (grading workers); None to start it the usual way."""
        servers = forkserver.servers()
        if servers is None or self.spec.path is None:
            return None

        def start(template: bool = False) -> forkserver.ForkServer:
            token = _new_token()
            return forkserver.ForkServer(
                _PACKAGE_ROOT, _child_environment(token), token, self._credentials(), config.get("distro"),
                template=template,
            )

        key = (str(self.spec.path.resolve()), self.limits.run_as, config.get("distro"))
        forked = servers.spawn(key, start, config, cwd, fds, self.limits.start_timeout)
        if forked is None:
            return None
        child, server = forked
        # the server's token marks what the child starts; the server lives on
        self._token, self._spare = server.token, server.proc.pid
        return child

    def _credentials(self) -> dict[str, Any]:
        if self.limits.run_as is None:
            return {}
        uid, gid = self.limits.run_as
        return {"user": uid, "group": gid, "extra_groups": []}

    # -- frames ---------------------------------------------------------------------------------
    def send(self, payload: bytes, timeout: float) -> None:
        """Send one frame; the child must take it within ``timeout`` seconds."""
        try:
            wire.write_frame(self._to_child, payload, _monotonic() + timeout)
        except wire.WireTimeout:
            raise ChildFailed(
                "timeout",
                f"did not take the next step within {self.limits.step_timeout:g} s of wall time "
                "(it stopped reading what turtletui sends)",
                self.where_stuck,
            ) from None
        except OSError:
            raise self._death() from None

    def receive(self, timeout: float) -> bytes:
        """The child's next frame, which must come within ``timeout`` seconds."""
        assert self._answers is not None
        try:
            frame = self._answers.read_frame(_monotonic() + timeout)
            self.running = self.started
            if self._errors:
                # stderr read while the step ran (a wait that woke for it), its answer
                # read straight after: shown now, with the step, not with the next one
                self.drain_output()
            return frame
        except wire.WireTimeout:
            raise self.no_answer(timeout) from None
        except wire.FrameTooLarge as err:
            raise ChildFailed("flood", str(err)) from None
        except wire.WireClosed:
            raise self._death() from None

    def answer_ready(self) -> bool:
        """Without waiting: has a whole frame come?"""
        assert self._answers is not None
        try:
            return self._answers.frame_ready()
        except wire.FrameTooLarge as err:
            raise ChildFailed("flood", str(err)) from None
        except wire.WireClosed:
            raise self._death() from None

    def wait_for_answer(self, timeout: float) -> None:
        """Return when the child's answer may have come, or after ``timeout`` seconds."""
        assert self._answers is not None
        select.select([self._answers.fd], [], [], timeout)

    def no_answer(self, waited: float | None = None) -> ChildFailed:
        """The child gave no answer within ``waited`` seconds (the step timeout
        unless said): stopped, with the line it is stuck on."""
        seconds = self.limits.step_timeout if waited is None else waited
        # until it answers the first step it is still starting: its file's
        # code, a node's __init__, main() before it spins; no callback has run
        guess = (
            "(an endless loop, a sleep or a blocking call in a callback?)"
            if self.running
            else "while starting (an endless loop or a blocking call before it spins?)"
        )
        # where it is stuck is asked when the failure is reported: a fast-path child that
        # is slow, not stuck (its journal has new answers), is never signalled
        return ChildFailed("timeout", f"did not answer within {seconds:g} s of wall time {guess}", self.where_stuck)

    def where_stuck(self) -> list[str]:
        """The line of the controller's file the child is stuck on (asked now), or []."""
        proc, path = self.proc, self.spec.path
        if proc is None or path is None or self.stack_fd is None or proc.returncode is not None:
            return []
        return stuck.where_stuck(proc.pid, self.stack_fd, path)

    def _wait_for_answer(self, fd: int, remaining: float | None) -> None:
        """How the reader waits: showing output as it comes, and waking up now and
        then to notice a child that died while something it started still holds
        the pipe open (no end of file then)."""
        timeout = _LIVENESS_SECONDS if remaining is None else min(remaining, _LIVENESS_SECONDS)
        outputs = [out for out, is_open in zip(self._outputs, self._open, strict=True) if is_open]
        readable, _, _ = select.select([fd, *outputs], [], [], timeout)
        if fd in readable:
            if len(readable) > 1 or self._errors:
                self.drain_output()  # its answer is coming: everything of its step was written before
        elif readable:
            self.drain_output(answered=False)
        if not readable and self.proc is not None and has_exited(self.proc.pid):
            raise self._death()

    def _death(self) -> ChildFailed:
        """Why the child is gone (or, still running, closed its pipe)."""
        proc = self.proc
        # read before it is reaped: a child the CPU limit killed has used it all
        cpu = cpu_seconds(proc.pid) if proc is not None and proc.returncode is None else None
        try:
            code = proc.wait(timeout=1) if proc is not None else None
        except subprocess.TimeoutExpired:
            return ChildFailed("exception", "closed its connection to turtletui and was stopped")
        if code is not None and code < 0:
            sig = -code
            limit = self.limits.cpu_seconds
            if sig == signal.SIGKILL and cpu is not None and limit is not None and cpu >= limit:
                sig = signal.SIGXCPU  # it ignored SIGXCPU: the hard limit's SIGKILL came
            kind, why = {
                signal.SIGXCPU: ("cpu", f"used more than its CPU limit of {limit} s"),
                signal.SIGKILL: ("killed", "was killed (SIGKILL): by someone, or the system ran out of memory"),
                signal.SIGSEGV: ("killed", "crashed the interpreter (SIGSEGV)"),
            }.get(sig, ("killed", f"was killed by signal {_signal_name(sig)}"))
            return ChildFailed(kind, why)
        if not self.started:
            return ChildFailed(
                "exit", f"exited with status {code} while starting, before loading the controller (see its output)"
            )
        return ChildFailed("exit", f"exited with status {code} without finishing its run")

    # -- output ---------------------------------------------------------------------------------
    def drain_output(self, final: bool = False, *, answered: bool = True) -> None:
        """Show what the child printed (within its budget), without waiting:
        its stdout, then (once it ``answered`` its step, or at the ``final``
        end) its stderr; lines written to each are shown in the order written."""
        out, err = self._read_output(final)
        if not (out or err or final or self._errors):
            return  # the common case, every exchange: nothing written
        held = self._held
        if held is not None:
            held[0] += out
            held[1] += err
            if not final and not self._output.over and len(held[0]) + len(held[1]) <= self.limits.output_bytes:
                return  # shown when the step it was printed in is replayed
            # the end, or over its budget anyway: when it is shown no longer matters
            for stream, data in enumerate(held):
                self._fed[stream] += len(data)
                self._feed(bytes(data), final or not self._open[stream], stream)
                data.clear()
            return
        if out or final:
            self._feed(out, final or not self._open[0], 0)
        errors = self._errors
        errors += err
        # a flood of stderr within one step is shown at once: its place no longer matters
        if final or (errors and (answered or len(errors) > self.limits.output_bytes)):
            data = bytes(errors)
            errors.clear()
            self._feed(data, final or not self._open[1], 1)

    def _read_output(self, final: bool) -> tuple[bytes, bytes]:
        """What the child wrote to stdout and stderr since the last read."""
        if self.proc is None:
            return b"", b""
        if final:
            streams = [stream for stream in (0, 1) if self._open[stream]]
        else:
            # one look at both pipes; nothing written: no read (POLLHUP when closed counts as something)
            events = self._output_poll.poll(0)
            if not events:
                return b"", b""
            ready = {fd for fd, _ in events}
            streams = [stream for stream in (0, 1) if self._open[stream] and self._outputs[stream] in ready]
        found = [b"", b""]
        for stream in streams:
            chunks = []
            read = 0
            try:
                while read < _OUTPUT_READ_LIMIT:
                    data = os.read(self._outputs[stream], 65536)
                    if not data:
                        self._open[stream] = False
                        self._output_poll.unregister(self._outputs[stream])
                        break
                    read += len(data)
                    chunks.append(data)
            except (BlockingIOError, OSError, ValueError):
                pass
            found[stream] = b"".join(chunks)
        return found[0], found[1]

    def hold_output(self) -> None:
        """Fast path: keep what the child prints until :meth:`show_output_until`
        says in which step it printed it."""
        self._held = [bytearray(), bytearray()]

    def show_output_until(self, out_total: int, err_total: int) -> None:
        """Show what the child had written to stdout and stderr, counted from
        its start, by the step that counted ``out_total`` and ``err_total``
        bytes (stdout first); the rest waits for its own step."""
        held = self._held
        assert held is not None
        fed = self._fed
        if out_total <= fed[0] and err_total <= fed[1]:
            return  # nothing printed since: not even a look at the pipes
        if len(held[0]) < out_total - fed[0] or len(held[1]) < err_total - fed[1]:
            self.drain_output()
        for stream, total in enumerate((out_total, err_total)):
            data = held[stream]
            take = min(total - fed[stream], len(data))
            if take > 0:
                chunk = bytes(data[:take])
                del data[:take]
                fed[stream] += take
                self._feed(chunk, False, stream)

    def _feed(self, data: bytes, final: bool, stream: int = 0) -> None:
        # past the budget the output is still read (so the child never blocks), then dropped
        if self._output.feed(data, final=final, stderr=stream == 1):
            self._log(
                "turtletui",
                WARN,
                f"{self.spec.label}: output over its budget of {size_text(self.limits.output_bytes)} or "
                f"{self.limits.output_lines:,} lines per run: the rest is dropped",
            )

    def _note_rate_dropped(self, lines: int) -> None:
        self._log(
            "turtletui",
            WARN,
            f"{self.spec.label}: {lines:,} lines of output not shown: the app shows at most "
            f"{self.limits.output_lines_per_second:,} a second of each controller",
        )

    def _show_output(self, line: str) -> None:
        self._log(f"{self.spec.name}{OUTPUT_SUFFIX}", INFO, line)

    def _show_errors(self, line: str) -> None:
        self._log(f"{self.spec.name}{ERROR_SUFFIX}", INFO, line)

    def output_dropped(self) -> str:
        """How much output was not shown ("" if none)."""
        return self._output.dropped()

    # -- end --------------------------------------------------------------------------------------
    def queued_seconds(self, *, own: bool = True) -> float:
        """Seconds the child's threads and (``own``) this process's have waited for a CPU."""
        child = run_queue_seconds(self.proc.pid) if self.proc is not None else None
        mine = run_queue_seconds("self") if own else None
        return (child or 0.0) + (mine or 0.0)

    def kill(self) -> None:
        """Kill the child and everything it started, show its last output and
        close the pipes."""
        proc = self.proc
        if proc is None:
            return
        kill_tree(proc.pid, self._token, reaped=proc.returncode is not None, spare=self._spare)
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            pass
        self.drain_output(final=True)
        for fd in (self._to_child, None if self._answers is None else self._answers.fd, self.stack_fd):
            if fd is None or fd < 0:
                continue
            try:
                os.close(fd)
            except OSError:
                pass
        self.stack_fd = None
        for pipe in (proc.stdout, proc.stderr):
            if pipe:
                pipe.close()
        self.proc = None


def _forget_writes(answers: int, journal: int | None) -> None:
    """Empty the answers pipe (read end ``answers``) and the journal (a memfd)
    of whatever a process that had them wrote."""
    blocking = os.get_blocking(answers)
    os.set_blocking(answers, False)
    try:
        while os.read(answers, 1 << 16):
            pass
    except BlockingIOError:
        pass
    finally:
        os.set_blocking(answers, blocking)
    if journal is not None:
        size = os.fstat(journal).st_size
        os.ftruncate(journal, 0)  # all zeros again, as new
        os.ftruncate(journal, size)


def _widen(fd: int, size: int = 1 << 20) -> None:
    """Let the pipe ``fd`` hold ``size`` bytes (Linux; as much as allowed)."""
    try:
        import fcntl

        fcntl.fcntl(fd, getattr(fcntl, "F_SETPIPE_SZ", 1031), size)
    except (OSError, ImportError):
        pass


def _new_token() -> str:
    return f"{os.getpid()}.{os.urandom(8).hex()}"


def _child_environment(token: str) -> dict[str, str]:
    """The environment of a sandbox child (and of a fork server)."""
    # Only what a program needs to run is passed on: the grader's own
    # environment may hold secrets (the results key, CI tokens, cloud
    # credentials) that student code must never read, let alone log.
    # No -I/-E: they would also drop PYTHONHASHSEED, and a fixed hash seed
    # keeps the iteration order of the student's sets and dicts of strings
    # the same in every run. Python's own variables are set below instead.
    env = {k: v for k, v in os.environ.items() if _passed_to_children(k)}
    env.update(
        OPENBLAS_NUM_THREADS="1",
        OMP_NUM_THREADS="1",
        PYTHONUNBUFFERED="1",
        PYTHONHASHSEED="0",
        PYTHONNOUSERSITE="1",
        PYTHONDONTWRITEBYTECODE="1",  # no __pycache__ left in students' folders
    )
    env[TOKEN_VAR] = token
    return env


_PASSED_NAMES = frozenset(
    {"PATH", "HOME", "USER", "LOGNAME", "LANG", "LANGUAGE", "TZ", "TERM", "TMPDIR", "LD_LIBRARY_PATH"}
)
_PASSED_PREFIXES = ("LC_", "ROS_", "RCUTILS_", "RMW_")
"""Locale, and the variables ROS 2 itself reads (ROS_DOMAIN_ID, RCUTILS_CONSOLE_OUTPUT_FORMAT...)."""


def _passed_to_children(name: str) -> bool:
    return name in _PASSED_NAMES or name.startswith(_PASSED_PREFIXES)


def _signal_name(sig: int) -> str:
    try:
        return signal.Signals(sig).name
    except ValueError:
        return f"{sig}"


def _start_folder(spec: ControllerSpec, limits: Limits) -> str | None:
    """The folder the child starts in (named even when it is this process's:
    a fork server started elsewhere must not choose it)."""
    if limits.file_folder and spec.path is not None:
        return str(spec.path.resolve().parent)
    try:
        return os.getcwd()
    except OSError:  # this process's folder was removed: the child starts where the server is
        return None
