"""The sandboxed side: runs one controller in a child process.

The child has its own Graph holding the controller's nodes, and records
standing for everyone else's, rebuilt from the mirror of the parent's graph
the parent sends when it changed (turtletui.runtime.graph_mirror). Whenever the
controller waits (spin, spin_once, sleeps, waiting for a future) and has
nothing ready, the child sends the parent a Report of what its nodes did
(declarations, messages, calls, logs: queued by the graph's outbox,
turtletui.runtime.outbox) and blocks until the parent answers with a Tick,
the new time and what arrived for it (turtletui.runtime.protocol). The
parent's simulation never trusts anything else. On the fast path
(turtletui.runtime.fastpath) the child's own copy of the simulation answers
instead, and the parent replays what the controller did.
This module must not import numpy or Textual: start-up time counts (the fast
path's copy of the simulation imports numpy when it is taken).
"""

from __future__ import annotations

import errno
import itertools
import json
import os
import random
import sys
import threading
import traceback
from collections.abc import Callable
from pathlib import Path
from select import select as _select
from time import monotonic as _monotonic
from typing import Any

from turtletui.graph.core import Graph
from turtletui.graph.logs import WARN
from turtletui.runtime import protocol, wire
from turtletui.runtime.budget import RateCap
from turtletui.runtime.host import CallbackTracking, RunEnded
from turtletui.runtime.outbox import OWNER, ParentOutbox
from turtletui.runtime.scheduler import Scheduler


class ChildHost(CallbackTracking):
    """The compat Host inside the sandbox: waiting means asking the parent.

    The controller's threads take turns (turtletui.runtime.scheduler): a
    thread that waits lets the others run, and when none can, the exchange
    with the parent moves simulated time on.
    """

    owner = OWNER

    def __init__(self, graph: Graph, outbox: ParentOutbox, fd_in: int, fd_out: int, *, spin_seconds: float = 0.0) -> None:
        self.graph = graph
        self.outbox = outbox
        self.fd_in = fd_in
        self.fd_out = fd_out
        self.reader = wire.FrameReader(fd_in, spin=spin_seconds, blocking=spin_seconds <= 0)
        """Reads the parent's messages; polls ``spin_seconds`` for each before it
        sleeps (a blocking read when 0)."""
        self.running = True
        self.scheduler = Scheduler(graph, self.exchange, lambda: self.running)
        self.controller_thread = threading.get_ident()
        self.call_numbers = itertools.count(1)

    def spin(self, stop: Callable[[], bool]) -> None:
        """Run every callback as it becomes ready until ``stop()`` or the end."""
        graph = self.graph
        ready = graph.ready
        scheduler = self.scheduler

        def work() -> bool:
            return bool(ready) or stop()

        while self.running:
            if ready:
                while ready:
                    ready.popleft()[1]()
                    if stop():
                        return
            elif stop():  # (after a callback it was just asked)
                return
            if scheduler.alone():
                self.exchange(graph.next_due())  # what wait() does then, on the hottest path
            else:
                scheduler.wait(work, None, spinning=True)

    def exchange(self, wake_ns: int | None) -> None:
        """Report to the parent and wait for the next instant it gives us."""
        tick = self.ask(self.outbox.report(wake_ns))
        if type(tick) is protocol.End:
            self.running = False
            return
        graph = self.graph
        now = tick.now_ns
        # Timers due now first, as in-process: there they become ready before
        # anything the parent's callbacks of this instant publish.
        while graph.advance(now):
            pass
        graph.now_ns = now
        self.outbox.apply(tick)

    def ask(self, report: protocol.Report) -> protocol.Tick | protocol.End:
        """Send ``report`` and wait for the parent's answer (on the fast path,
        turtletui.runtime.fastpath.Loopback answers instead)."""
        wire.write_frame(self.fd_out, protocol.encode_report(report))
        return protocol.decode_from_parent(self.reader.read_frame())

    def spin_once(self, timeout_ns: int | None, wake: Callable[[], bool] | None = None) -> bool:
        ready = self.graph.ready
        if not ready and self.running:
            if timeout_ns == 0:
                self.scheduler.poll()
            else:
                deadline = None if timeout_ns is None else self.graph.now_ns + max(timeout_ns, 0)
                woken = (lambda: bool(ready)) if wake is None else (lambda: bool(ready) or wake())
                self.scheduler.wait(woken, deadline, spinning=True)
        if ready and self.running:
            ready.popleft()[1]()
            return True
        return False if self.running else self.waited_after_end()

    def spin_until(self, done: Callable[[], bool], timeout_ns: int | None, *, callbacks: bool = True) -> bool:
        graph = self.graph
        ready = graph.ready
        deadline = None if timeout_ns is None else graph.now_ns + max(timeout_ns, 0)

        def go_on() -> bool:
            return done() or (callbacks and bool(ready))

        while not done():
            if not self.running or (deadline is not None and graph.now_ns >= deadline):
                return False
            if callbacks and ready:
                ready.popleft()[1]()
                continue
            self.scheduler.wait(go_on, deadline, spinning=callbacks)
        return True

    def sleep_until(self, t_ns: int) -> bool:
        if self.graph.now_ns < t_ns:
            self.scheduler.wait(None, t_ns)  # after the run: passes at once
        elif self.running:
            self.scheduler.pause()  # time.sleep(0): let the other threads run
        return self.running or self.waited_after_end()

    def clock_read(self) -> None:
        """A reading of a simulated clock (Scheduler.clock_read); a loop that
        polls the clock after the run is over waits like a sleep."""
        if self.scheduler.clock_read() and not self.running:
            self.waited_after_end()


def _out_of_memory(exc: BaseException) -> bool:
    """An error that is the memory limit showing through: mmap refused (ENOMEM),
    e.g. importing an extension module with too little address space left."""
    if isinstance(exc, OSError) and exc.errno == errno.ENOMEM:
        return True
    return isinstance(exc, ImportError) and "failed to map segment" in str(exc)


def _address_space() -> int:
    """Bytes of address space this process uses (Linux; 0 elsewhere)."""
    try:
        with open("/proc/self/statm", "rb") as f:
            return int(f.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


CPU_GRACE_SECONDS = 5
"""The hard CPU limit is this much above the soft one: SIGXCPU at the soft
limit ends the child (and says why), SIGKILL at the hard one if it is ignored."""


def _apply_limits(limits: dict[str, int]) -> None:
    import resource

    cpu = limits.get("cpu_seconds")
    for name, value, grace in (
        ("RLIMIT_CPU", cpu, CPU_GRACE_SECONDS),
        ("RLIMIT_AS", limits.get("memory_bytes"), 0),
        ("RLIMIT_FSIZE", limits.get("file_bytes"), 0),
        ("RLIMIT_CORE", 0, 0),
    ):
        if value is None or not hasattr(resource, name):
            continue
        kind = getattr(resource, name)
        soft, hard = resource.getrlimit(kind)
        new_hard = value + grace if hard == resource.RLIM_INFINITY else min(value + grace, hard)
        try:
            resource.setrlimit(kind, (min(value, new_hard), new_hard))
        except (ValueError, OSError):
            pass  # the limit is lower already


def _become_subreaper() -> None:
    """Processes the controller starts stay in this process's tree even when
    their own parent dies (Linux), so that the parent finds and kills them all."""
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
    except (OSError, AttributeError):
        pass


def _wait_to_be_ended(fd_in: int, seconds: float = 10.0) -> None:
    """After the last report: stay alive until the parent has killed everything
    this process started (it ends us with them), or it went away."""
    deadline = _monotonic() + seconds
    while (remaining := deadline - _monotonic()) > 0:
        try:
            readable, _, _ = _select([fd_in], [], [], remaining)
            if readable and not os.read(fd_in, 65536):
                return
        except BlockingIOError:
            continue
        except OSError:
            return


def _finish(outbox: ParentOutbox, loopback: Any, fd_in: int, fd_out: int, crash: protocol.Crash | None) -> None:
    """Send the last report (saying ``crash``), wait to be ended and exit."""
    try:
        sys.stdout.flush()
        sys.stderr.flush()
        last = outbox.report(None, done=True, crash=crash)
        if loopback is not None:
            loopback.finish(last)
        else:
            wire.write_frame(fd_out, protocol.encode_report(last))
    except (OSError, wire.WireError):
        pass
    except Exception:  # noqa: BLE001 - the report itself failed; say so on stderr
        traceback.print_exc()
    _wait_to_be_ended(fd_in)
    os._exit(0)


def _rate_note(graph: Graph, per_second: int) -> Callable[[int], None]:
    """What the child logs of the log records it did not send for the app's cap."""

    def note(count: int) -> None:
        graph.log(
            "turtletui", WARN, f"{count:,} log messages not shown: the app shows at most {per_second:,} a second of each controller"
        )

    return note


def _deadlock_crash(idents: list[int], path: Any) -> protocol.Crash:
    """The Crash of a deadlock among the threads ``idents`` (the one that found
    it last): where each waits, its innermost line of the student's files."""
    from turtletui.runtime.loader import frame_text, own_files

    mine = own_files(path) if path is not None else None
    stacks = sys._current_frames()
    stacks[threading.get_ident()] = sys._getframe()
    frames = []
    for ident in idents:
        stack = traceback.extract_stack(stacks[ident]) if ident in stacks else []
        own = [f for f in stack if mine is not None and mine(f.filename)]
        if own:
            f = own[-1]
            frames.append(frame_text(f.filename, f.lineno, f.name, f.line or ""))
    if len(idents) == 1:
        why = "it waits for a lock that only it could release (a threading.Lock taken twice?)"
    else:
        why = f"each of its {len(idents)} threads waits for a lock (or a join, an event) that only another could release"
    return protocol.Crash("deadlock", f"deadlock: {why}; under ROS the program would hang here", tuple(frames))


def main(config: dict[str, Any] | None = None) -> None:
    """Run the controller ``config`` describes (by default: the JSON in argv[1]),
    report to the parent and exit."""
    if config is None:
        config = json.loads(sys.argv[1])
    fd_in, fd_out = config["fd_in"], config["fd_out"]
    os.set_inheritable(fd_in, False)
    os.set_inheritable(fd_out, False)
    _become_subreaper()
    _apply_limits(config.get("limits", {}))
    if config.get("fd_stack") is not None:
        from turtletui.runtime import stuck

        stuck.install(config["fd_stack"])  # where a callback is stuck, when the simulator asks
    from turtletui import compat
    from turtletui.compat import context as compat_context
    from turtletui.compat.distro import resolve_distro, type_description_names, type_namer
    from turtletui.runtime import scheduler, virtual_time
    from turtletui.runtime.loader import (
        ControllerError,
        ControllerSpec,
        resolve_factory,
        run_controller,
        seed_numpy,
        spin_nodes,
        user_frames,
    )
    from turtletui.runtime.report import exception_message, exit_message, exited_in_callback

    distro = resolve_distro(config.get("distro"))
    compat.install(distro)
    graph = Graph(
        epoch_ns=config["epoch_ns"], type_name=type_namer(distro), type_description_names=type_description_names(distro)
    )
    graph.discovery_ns = config.get("discovery_ns", 0)
    limits = config.get("limits", {})
    log_lines, per_second = limits.get("log_lines"), limits.get("log_lines_per_second")
    outbox = ParentOutbox(
        graph,
        log_budget=1 << 62 if log_lines is None else int(log_lines) + 1,
        log_rate=None if per_second is None else RateCap(int(per_second), _monotonic, _rate_note(graph, per_second)),
    )
    outbox.install()
    host = ChildHost(graph, outbox, fd_in, fd_out, spin_seconds=config.get("spin_seconds", 0.0))
    loopback = None
    if config.get("fast") is not None:
        from turtletui.runtime.fastpath import start_loopback

        loopback = start_loopback(host, config)
    compat_context.reset_default_context()
    compat_context.bind_host(host)
    scheduler.install(host.scheduler)
    spec = ControllerSpec(
        name=config["name"],
        path=None if config.get("path") is None else Path(config["path"]),
        module=config.get("module"),
        function=config.get("function"),
    )
    host.scheduler.deadlocked = lambda idents: _finish(
        outbox, loopback, fd_in, fd_out, _deadlock_crash(idents, spec.path)
    )
    virtual_time.install_simulated_sleep(host)
    virtual_time.install_simulated_select(host)
    if not config.get("realtime"):
        virtual_time.patch_clocks(graph, host.clock_read)
    sys.argv = [spec.label, *config.get("ros_args", [])]
    random.seed(config.get("seed", 0))
    crash = None
    try:
        host.exchange(None)  # start together with the parent's clock
        memory_limit = config.get("limits", {}).get("memory_bytes")
        if memory_limit and _address_space() > memory_limit:
            raise MemoryError  # forked warm: a fresh interpreter would not have started
        try:
            if config.get("factory"):
                sys.path[1:1] = [p for p in config.get("sys_path", []) if p]
                factory = resolve_factory(config["factory"])
                seed_numpy(config.get("seed", 0))
                spin_nodes(list(factory()))
            else:
                seed_numpy(config.get("seed", 0))
                run_controller(spec)
        except RunEnded:
            pass  # still waiting when the run ended: stopped, as with Ctrl-C
        host.scheduler.join_threads()  # as Python does before it exits
    except ControllerError as err:
        crash = protocol.Crash("load", str(err), ())
    except SystemExit as exc:
        if exc.code not in (None, 0):
            crash = protocol.Crash("exit", exit_message(exc.code), tuple(user_frames(exc.__traceback__, spec.path)))
        elif exited_in_callback(exc):  # said in the log, as the program's clean end (no crash)
            crash = protocol.Crash(protocol.EXITED, "exited with status 0", tuple(user_frames(exc.__traceback__, spec.path)))
    except MemoryError as exc:
        # Free what the failed frames hold before building the report.
        traceback.clear_frames(exc.__traceback__)
        try:
            frames = user_frames(exc.__traceback__, spec.path)
        except MemoryError:
            frames = []
        limit = config.get("limits", {}).get("memory_bytes")
        within = f" of {limit / 1024**2:g} MiB" if limit else ""
        crash = protocol.Crash("memory", f"MemoryError: ran out of its memory limit{within}", tuple(frames))
    except BaseException as exc:  # noqa: BLE001 - controller code may raise anything
        kind = "memory" if _out_of_memory(exc) else "exception"
        crash = protocol.Crash(kind, exception_message(exc), tuple(user_frames(exc.__traceback__, spec.path)))
    _finish(outbox, loopback, fd_in, fd_out, crash)


if __name__ == "__main__":
    main()
