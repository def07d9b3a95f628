"""Run an untrusted controller in a child process, in lockstep with the simulation.

The child (turtletui.runtime.child) runs the student's code with CPU, memory
and file-size limits, in its own session so every process it starts can be
killed (turtletui.runtime.sandbox_process). Each exchange the parent sends a
Tick, the simulated time and what arrived for the child's nodes; the child
answers with a Report of what its nodes declared, published, called and
logged (turtletui.runtime.protocol). The parent checks every field before it
enters the simulation (turtletui.runtime.sandbox_proxy). :class:`SandboxHost`
drives the exchanges: when, how long they may take, and what ends the child.
"""

from __future__ import annotations

from dataclasses import dataclass
from time import monotonic as _monotonic  # bound at import: an in-process run simulates time's
from time import perf_counter as _perf_counter
from typing import Any

from turtletui.graph.core import GraphError
from turtletui.graph.logs import WARN
from turtletui.interfaces import InterfaceError
from turtletui.runtime import protocol, wire
from turtletui.runtime.budget import Pace
from turtletui.runtime.loader import ControllerSpec, check_source, factory_reference, import_root
from turtletui.runtime.report import (
    CrashReport,
    log_crash,
    log_ended_early,
    log_exited,
    stop_turtles,
)
from turtletui.runtime.sandbox_process import ChildFailed, ChildProcess
from turtletui.runtime.sandbox_proxy import GraphProxy
from turtletui.runtime.simulation import MAX_ROUNDS_PER_INSTANT, Simulation


@dataclass(frozen=True)
class Limits:
    """What a sandboxed controller may use (and how its pipes are read)."""

    step_timeout: float = 2.0
    """Wall seconds the child may take to answer one exchange (a hung callback)."""
    start_timeout: float = 10.0
    """Wall seconds for start-up and loading the controller's module."""
    cpu_seconds: int | None = 120
    """CPU seconds the child may use (RLIMIT_CPU: SIGXCPU, then SIGKILL a few
    seconds later if it is ignored); None: no cap (the app's controllers live
    as long as the app)."""
    memory_bytes: int = 2 * 1024**3
    file_bytes: int = 64 * 1024**2
    realtime_lag: float | None = 3.0
    """Lockstep: wall seconds the controller may fall behind real time (its
    answers take more wall time than the simulated time they cover) before it
    is stopped as too slow for a robot; None: never."""
    run_seconds: float | None = None
    """Lockstep: wall seconds the run may take after start-up; None: no limit."""
    run_seconds_reason: str = ""
    """Why the run has ``run_seconds`` (said when the limit stops it)."""
    output_bytes: int = 1_000_000
    """Bytes of print() output shown per run; the rest is counted and dropped."""
    output_lines: int = 10_000
    """Lines of print() output shown per run; the rest is counted and dropped."""
    output_line_chars: int = 1000
    """Characters of one line of print() output shown; the rest is cut."""
    output_lines_per_second: int | None = None
    """Lines of print() output shown per wall second, the rest counted and
    dropped with a note each second; None: no such cap (the app has one: its
    screen and simulation share a process with the reading of the output)."""
    log_lines: int = 20_000
    """Log records (get_logger()) kept per run; the rest is dropped with a notice."""
    log_bytes: int = 4_000_000
    """Bytes of log messages kept per run; the rest is dropped with a notice."""
    log_lines_per_second: int | None = None
    """Log records the child sends per wall second, the rest counted and
    dropped with a note each second; None: no such cap (the app has one, as
    for print(): decoding a flood would starve its simulation and screen)."""
    spin_seconds: float | None = None
    """Wall seconds the simulator and the controller poll for each other's
    answer before sleeping in the kernel; None: the machine's default
    (turtletui.runtime.wire.default_spin_seconds). 0 when runs share the CPUs."""
    lockstep: bool | None = None
    """Which path a run that may take the fast one (turtletui.runtime.fastpath)
    takes: None, the fast path where it pays (see replica.FAST_PATH_MIN_NS);
    True, lockstep; False, the fast path. The run is the same on both: tests
    and benchmarks choose to compare them."""
    file_folder: bool = False
    """Start the child in its controller file's folder (grading: a
    submission's relative paths are its own) instead of the folder turtletui
    runs in, as ``python3 FILE`` and in-process runs keep it."""
    run_as: tuple[int, int] | None = None
    """(uid, gid) the child runs as, with no supplementary groups: a grader
    running as root drops the student's code to an unprivileged user."""


_CRASH_KINDS = frozenset({"exception", "exit", "memory", "load", "cpu", "timeout", "deadlock", "killed"})
"""Kinds a child may report about itself (anything else is reported as an exception)."""
_DECODED_KEPT = 64
_DECODED_BYTES = 2048
"""Reports up to this size are kept decoded, this many at most (then forgotten all at once)."""


class SandboxHost:
    """Parent-side host of a controller running in a child process: a
    RemoteHost of the simulation (turtletui.runtime.simulation)."""

    def __init__(self, sim: Simulation, spec: ControllerSpec, limits: Limits) -> None:
        self.sim = sim
        self.graph = sim.graph
        self.spec = spec
        self.limits = limits
        self.owner = f"sandbox:{spec.name}:{id(self):x}"
        self.wake_ns: int | None = None
        self.crash: CrashReport | None = None
        self.finished = False
        self._ending = False
        """The run is over: the child's last report answers its end (not an end of its own)."""
        spin = wire.default_spin_seconds() if limits.spin_seconds is None else limits.spin_seconds
        self.process = ChildProcess(spec, limits, self.graph.log, spin=spin)
        self._pace = Pace(start_ns=0)
        """The wall time the child takes to answer (lockstep, after start-up)."""
        self.proxy = GraphProxy(
            self.graph, self.owner, spec.label, self._pace, log_lines=limits.log_lines, log_bytes=limits.log_bytes
        )
        self._awaiting: float | None = None
        """Real time only: when the unanswered message went out (monotonic s)."""
        self._poll = False
        self._instant = -1
        self._rounds = 0
        self._metering = False
        self._wall_start = 0.0
        self._queued_at_start = 0.0
        self._recheck = 0.0
        self._decoded: dict[bytes, protocol.Report] = {}
        """Reports decoded, by their bytes: a controller often says the same
        thing tick after tick (the same command, the same log line)."""

    # -- life cycle -----------------------------------------------------------
    @classmethod
    def start(
        cls,
        sim: Simulation,
        spec: ControllerSpec,
        *,
        ros_args: list[str],
        seed: int,
        limits: Limits | None = None,
        **extra: Any,
    ) -> SandboxHost:
        """Check the file, start the child and let it load the controller.
        ``extra`` goes to the constructor (a subclass's own arguments)."""
        if spec.path is not None:
            check_source(spec.path)
        host = cls(sim, spec, limits or Limits(), **extra)
        host.process.spawn(host._config(ros_args, seed))
        sim.remotes.append(host)
        try:
            host._receive(host.limits.start_timeout, first=True)
        except _Stop:
            return host  # it failed to start; host.crash says why
        host.process.started = True
        host.exchange(timeout=host.limits.start_timeout, wait=True)
        if not sim.realtime and not host.finished:
            host._pace.start_ns = host.graph.now_ns
            host._queued_at_start = host._queued()
            host._wall_start = _perf_counter()
            host._metering = True
        return host

    def _config(self, ros_args: list[str], seed: int) -> dict[str, Any]:
        """What the child needs to load and run the controller (turtletui.runtime.child.main)."""
        spec = self.spec
        return {
            "name": spec.name,
            "path": str(spec.path.resolve()) if spec.path else None,
            "module": spec.module,
            "function": spec.function,
            "factory": factory_reference(spec.factory) if spec.factory else None,
            "sys_path": [import_root(spec.factory)] if spec.factory else [],
            "ros_args": ros_args,
            "seed": seed,
            "distro": self.sim.distro,
            "epoch_ns": self.graph.epoch_ns,
            "discovery_ns": self.graph.discovery_ns,
            "realtime": self.sim.realtime,
            "limits": {
                "cpu_seconds": self.limits.cpu_seconds,
                "memory_bytes": self.limits.memory_bytes,
                "file_bytes": self.limits.file_bytes,
                "log_lines": self.limits.log_lines,
                "log_lines_per_second": self.limits.log_lines_per_second,
            },
        }

    def close(self) -> CrashReport | None:
        """End the child (asking it first), kill what it left behind, report."""
        self._ending = True
        if not self.finished and self._awaiting is not None:
            self._collect(self.limits.step_timeout)
        if not self.finished:
            try:
                self.process.send(protocol.encode_end(), 1.0)
                payload = self.process.receive(1.0)
            except ChildFailed as failed:
                self._no_last_report(failed)
            else:
                try:
                    self._apply(self._decode(payload))
                except _Stop:
                    pass
        self._terminate()
        return self.crash

    def _no_last_report(self, failed: ChildFailed) -> None:
        """The child did not answer the run's end with its last report. What a
        controller does once the run is over counts for nothing (after Ctrl-C
        in ROS, a thread that never returns keeps a node's process alive):
        not a fault of the run. One still busy is told so; the caller ends it."""
        if failed.kind == "timeout":
            self.graph.log(
                "turtletui",
                WARN,
                f"{self.spec.label}: still busy 1 s after the run ended (a loop in a thread that never "
                "returns?): stopped",
            )

    def _terminate(self) -> None:
        self.finished = True
        self.proxy.running = False
        if self in self.sim.remotes:
            self.sim.remotes.remove(self)
        self.wake_ns = None
        if self.process.proc is None:
            return
        self.process.kill()
        self._report_dropped()
        if self.crash is not None:
            # A controller that ends normally leaves its last command to
            # turtlesim's 1 s timeout, as in ROS; a failed one stops its turtle.
            stop_turtles(self.sim, self.owner)
        self.graph.remove_owner(self.owner)

    def _fail(self, kind: str, message: str, frames: list[str] | None = None) -> None:
        if self.crash is None:
            message = " ".join(message.splitlines())  # the summary stays one line
            self.crash = CrashReport(self.spec.label, self.sim.t, kind, message, frames or [])
            log_crash(self.graph, self.crash)
        self._terminate()

    def _failed(self, failed: ChildFailed) -> None:
        """:meth:`_fail` as the child's process said it failed."""
        self._fail(failed.kind, failed.message, failed.frames)

    def _report_dropped(self) -> None:
        """One line at the end of the run saying how much was not shown."""
        dropped = self.process.output_dropped()
        if dropped:
            self.graph.log("turtletui", WARN, f"{self.spec.label}: {dropped}")
        logs = self.proxy.dropped_logs
        if logs:
            self.graph.log("turtletui", WARN, f"{self.spec.label}: {logs:,} log messages over its budget dropped")

    # -- RemoteHost -------------------------------------------------------------
    def wants_exchange(self, now_ns: int) -> bool:
        if self.finished:
            return False
        if now_ns != self._instant:
            self._instant = now_ns
            self._rounds = 0
        elif self._rounds >= MAX_ROUNDS_PER_INSTANT:
            return False
        if self._awaiting is not None:
            return True  # real time: see whether the answer has come
        if self._poll or self.proxy.has_news():
            return True  # news, or a change on the graph a waiting node may be waiting for
        return self.wake_ns is not None and self.wake_ns <= now_ns

    def exchange(self, timeout: float | None = None, *, wait: bool = False) -> bool:
        """Send the time and inbox and apply the child's answer. Returns whether
        anything happened.

        In lockstep the answer is awaited (up to the step deadline). In real
        time it is awaited only until the simulation's next step is due; a
        slower answer is picked up by a later call and its commands are late,
        as they would be in ROS.
        """
        if self.finished:
            return False
        if self._awaiting is not None:
            return self._collect(0.0)
        self._rounds += 1
        tick, cause = self.proxy.tick()
        timeout = timeout or self.limits.step_timeout
        sent = _perf_counter()
        try:
            self.process.send(protocol.encode_tick(tick), timeout)
        except ChildFailed as failed:
            self._failed(failed)
            return True
        if self.sim.realtime and not wait:
            self._awaiting = _monotonic()
            self._collect(min(self.sim.wall_budget(), timeout))
            return True
        try:
            self._receive(timeout)
        except _Stop:
            return True
        if self._metering:
            answered = _perf_counter()
            self._meter(cause, answered - sent, answered)
        return True

    def _meter(self, cause: Any, seconds: float, answered: float) -> None:
        """Charge one answer's wall time (it came at ``answered``, perf_counter);
        stop a child that fell too far behind real time, or a run over its
        wall-clock limit."""
        pace = self._pace
        now = self.graph.now_ns
        behind = pace.charge(cause, seconds, now)
        limits = self.limits
        if limits.realtime_lag is not None and behind > limits.realtime_lag and pace.busy >= self._recheck:
            # Before stopping it, take off the time a busy machine kept it (or
            # this process) from a CPU: only its own slowness counts.
            behind = pace.excuse(self._queued() - self._queued_at_start, now)
            self._recheck = pace.busy + _RECHECK_SECONDS
        if limits.realtime_lag is not None and behind > limits.realtime_lag:
            self._fail("slow", pace.report(now))
        elif limits.run_seconds is not None and answered - self._wall_start > limits.run_seconds:
            why = limits.run_seconds_reason or f"the run's limit is {limits.run_seconds:g} s"
            message = f"ran out of time after {answered - self._wall_start:.1f} s of wall time: {why}"
            # On a busy machine the run's limit can come before the pace's
            # verdict: if the controller is well behind real time, still say why.
            if pace.excuse(self._queued() - self._queued_at_start, now) > _BEHIND_WORTH_SAYING:
                message += f"; it {pace.report(now)}"
            self._fail("time", message)

    def _queued(self) -> float:
        """Seconds the processes an answer's wall time waited on spent waiting
        for a CPU: in lockstep the child's and this process's (the answer is
        timed here, from the Tick sent to the Report read)."""
        return self.process.queued_seconds()

    def _collect(self, budget: float) -> bool:
        """Real time: apply the pending answer if it arrives within ``budget``
        seconds; stop the child once it is later than the step deadline."""
        deadline = _monotonic() + budget
        process = self.process
        try:
            while True:
                if process.answer_ready():
                    self._awaiting = None
                    self._receive(0.0)
                    return True
                remaining = deadline - _monotonic()
                if remaining <= 0:
                    break
                process.wait_for_answer(remaining)
        except ChildFailed as failed:
            self._failed(failed)
            return True
        except _Stop:
            return True
        assert self._awaiting is not None
        if _monotonic() - self._awaiting > self.limits.step_timeout:
            failed = process.no_answer()
            self._failed(failed)
            return True
        return False

    # -- receiving ---------------------------------------------------------------
    def _receive(self, timeout: float, *, first: bool = False) -> None:
        """Read the child's next Report and apply it; raises _Stop when the child
        finished or failed (``self.crash`` then says why)."""
        try:
            payload = self.process.receive(timeout)
        except ChildFailed as failed:
            self._failed(failed)
            raise _Stop from None
        report = self._decode(payload)
        if not first:
            self._apply(report)

    def _decode(self, payload: bytes) -> protocol.Report:
        """The Report in ``payload``; raises _Stop (having said why) if it is none."""
        report = self._decoded.get(payload)
        if report is not None:
            return report  # applying a Report builds new messages from it: it is never changed
        try:
            report = protocol.decode_report(payload)
            if len(payload) <= _DECODED_BYTES:
                if len(self._decoded) >= _DECODED_KEPT:
                    self._decoded.clear()
                self._decoded[payload] = report
            return report
        except protocol.ProtocolError as err:
            self._fail("exception", f"{_REFUSED}: {err}")
            raise _Stop from None
        except wire.WireError as err:
            self._fail("exception", str(err))
            raise _Stop from None

    def _apply(self, report: protocol.Report) -> None:
        """Apply one Report of the child; raises _Stop as :meth:`_receive`."""
        try:
            self.proxy.apply(report)
        except (InterfaceError, GraphError, protocol.ProtocolError) as err:
            self._fail("exception", f"{_REFUSED}: {err}")
            raise _Stop from None
        except Exception as err:  # noqa: BLE001 - a forged reply may break anything in apply
            self._fail("exception", f"{_REFUSED} ({type(err).__name__}: {err})")
            raise _Stop from None
        wake = report.wake_ns
        if wake is not None and wake <= self.graph.now_ns:
            self.wake_ns, self._poll = None, True
        else:
            self.wake_ns, self._poll = wake, False
        if report.done:
            crash = report.crash
            if crash is None or crash.kind == protocol.EXITED:
                if self._ending:
                    pass  # it ended as the run did
                elif crash is None:
                    log_ended_early(self.graph, self.spec.label, self.sim.t)
                else:
                    log_exited(self.graph, self.spec.label, self.sim.t, [frame[:1000] for frame in crash.frames[:50]])
                self._terminate()
            else:
                kind = crash.kind if crash.kind in _CRASH_KINDS else "exception"
                self._fail(kind, crash.message[:2000], [frame[:1000] for frame in crash.frames[:50]])
            raise _Stop


_REFUSED = "sent something turtlesim cannot accept"


class _Stop(Exception):
    """The child finished or failed during an exchange."""


_BEHIND_WORTH_SAYING = 0.5
"""Wall seconds behind real time from which a run stopped by its time limit
is also told that it could not keep up."""
_RECHECK_SECONDS = 0.5
"""Wall seconds of a controller's answers between two looks at how long the
machine kept it waiting for a CPU (a look reads /proc: not at every answer)."""
