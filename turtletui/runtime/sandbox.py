"""Run an untrusted controller in a child process, in lockstep with the simulation.

The child (turtletui.runtime.child) runs the student's code with CPU, memory
and file-size limits, in its own session so every process it starts can be
killed. Each exchange the parent sends the simulated time and the messages
for the child's subscriptions; the child answers in JSON with what its nodes
declared, published, called and logged. The parent validates every message
against its type before it enters the simulation.
"""

from __future__ import annotations

import itertools
import json
import os
import select
import signal
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from time import monotonic as _monotonic  # bound at import: an in-process run simulates time's
from time import perf_counter as _perf_counter
from typing import Any

from turtletui.graph.core import GoalHandle, GraphError, NodeRecord
from turtletui.graph.logs import ERROR, INFO, OUTPUT_SUFFIX, WARN
from turtletui.interfaces import InterfaceError, from_values, get_interface, to_values
from turtletui.runtime import forkserver, graph_mirror, wire
from turtletui.runtime.budget import CALLS, WAKE, OutputBudget, Pace, size_text
from turtletui.runtime.loader import ControllerSpec, check_source, factory_reference, import_root
from turtletui.runtime.processes import (
    TOKEN_VAR,
    cpu_seconds,
    has_exited,
    kill_tree,
    run_queue_seconds,
)
from turtletui.runtime.report import CrashReport, log_crash, stop_turtles
from turtletui.runtime.simulation import MAX_ROUNDS_PER_INSTANT, Simulation

_PACKAGE_ROOT = str(Path(__file__).resolve().parents[2])
_BOOTSTRAP = (
    "import sys; sys.path.insert(0, {root!r}); "
    "from turtletui.runtime.child import main; main()"
)


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
    log_lines: int = 20_000
    """Log records (get_logger()) kept per run; the rest is dropped with a notice."""
    log_bytes: int = 4_000_000
    """Bytes of log messages kept per run; the rest is dropped with a notice."""
    spin_seconds: float | None = None
    """Wall seconds the simulator and the controller poll for each other's
    answer before sleeping in the kernel; None: the machine's default
    (turtletui.runtime.wire.default_spin_seconds). 0 when runs share the CPUs."""
    run_as: tuple[int, int] | None = None
    """(uid, gid) the child runs as, with no supplementary groups: a grader
    running as root drops the student's code to an unprivileged user."""


_CRASH_KINDS = frozenset({"exception", "exit", "memory", "load", "cpu", "timeout", "killed"})
"""Kinds a child may report about itself (anything else is reported as an exception)."""
_OUTPUT_READ_LIMIT = 1 << 20
"""Bytes of print() output read in one go, so a flood cannot keep the parent reading."""


class SandboxHost:
    """Parent-side proxy of a controller running in a child process."""

    def __init__(self, sim: Simulation, spec: ControllerSpec, limits: Limits) -> None:
        self.sim = sim
        self.graph = sim.graph
        self.spec = spec
        self.limits = limits
        self._spin = wire.default_spin_seconds() if limits.spin_seconds is None else limits.spin_seconds
        self.owner = f"sandbox:{spec.name}:{id(self):x}"
        self.wake_ns: int | None = None
        self.crash: CrashReport | None = None
        self.finished = False
        self._request_ids = itertools.count(1)
        self._awaiting: float | None = None
        """Real time only: when the unanswered message went out (monotonic s)."""
        self._inbox: list = []
        self._responses: list = []
        self._goal_events: list = []
        self._served_out: list = []
        """Goals and cancel requests for the child's own action servers, to send."""
        self._requests: list = []
        self._params: list = []
        self._poll = False
        self._instant = -1
        self._rounds = 0
        self._nodes: dict[int, NodeRecord] = {}
        self._endpoints: dict[int, Any] = {}
        self._goals: dict[int, Any] = {}
        self._served: dict[int, GoalHandle] = {}
        """Goals of the child's action servers not finished yet, by goal id."""
        self._cancel_decisions: dict[int, Any] = {}
        self._service_calls: dict[int, Any] = {}
        self._mirror: graph_mirror.GraphMirror | None = None
        """The graph as the child last heard of it."""
        self._mirrored_version = -1
        """The graph's version when the child was last sent the mirror (or
        when only the child's own doings changed it)."""
        self._read_buffer = b""
        self._output = OutputBudget(
            self._show_output,
            max_bytes=limits.output_bytes,
            max_lines=limits.output_lines,
            line_chars=limits.output_line_chars,
        )
        self._log_lines = 0
        self._log_bytes = 0
        self._log_dropped = 0
        self._child_dropped = 0
        """Log records the child did not send (over the budget), as it counts them."""
        self._pace = Pace(start_ns=0)
        """The wall time the child takes to answer (lockstep, after start-up)."""
        self._metering = False
        self._wall_start = 0.0
        self._queued_at_start = 0.0
        self._recheck = 0.0
        self._stdout_open = True
        self._started = False
        self._token = ""
        self._spare: int | None = None
        """A process holding the token that is not this child's (its fork server)."""
        self.proc: Any = None
        """The child: a subprocess.Popen, or a forkserver.ForkedChild."""

    # -- life cycle -----------------------------------------------------------
    @classmethod
    def start(
        cls, sim: Simulation, spec: ControllerSpec, *, ros_args: list[str], seed: int, limits: Limits | None = None
    ) -> SandboxHost:
        """Check the file, start the child and let it load the controller."""
        if spec.path is not None:
            check_source(spec.path)
        host = cls(sim, spec, limits or Limits())
        host._spawn(ros_args, seed)
        sim.remotes.append(host)
        try:
            host._receive(host.limits.start_timeout, first=True)
        except _Stop:
            return host  # it failed to start; host.crash says why
        host._started = True
        host.exchange(timeout=host.limits.start_timeout, wait=True)
        if not sim.realtime and not host.finished:
            host._pace.start_ns = host.graph.now_ns
            host._queued_at_start = host._queued()
            host._wall_start = _perf_counter()
            host._metering = True
        return host

    def _spawn(self, ros_args: list[str], seed: int) -> None:
        to_child_r, to_child_w = os.pipe()
        from_child_r, from_child_w = os.pipe()
        config = {
            "fd_in": to_child_r,
            "fd_out": from_child_w,
            "name": self.spec.name,
            "path": str(self.spec.path.resolve()) if self.spec.path else None,
            "module": self.spec.module,
            "function": self.spec.function,
            "factory": factory_reference(self.spec.factory) if self.spec.factory else None,
            "sys_path": [import_root(self.spec.factory)] if self.spec.factory else [],
            "ros_args": ros_args,
            "seed": seed,
            "distro": self.sim.distro,
            "epoch_ns": self.graph.epoch_ns,
            "discovery_ns": self.graph.discovery_ns,
            "realtime": self.sim.realtime,
            "spin_seconds": self._spin,
            "limits": {
                "cpu_seconds": self.limits.cpu_seconds,
                "memory_bytes": self.limits.memory_bytes,
                "file_bytes": self.limits.file_bytes,
                "log_lines": self.limits.log_lines,
            },
        }
        cwd = str(self.spec.path.resolve().parent) if self.spec.path else None
        fds = (to_child_r, from_child_w)
        self.proc = self._fork(config, cwd, fds) or self._exec(config, cwd, fds)
        os.close(to_child_r)
        os.close(from_child_w)
        self._to_child = to_child_w
        # A child that stopped reading (it forged an answer, then hung) must not
        # block the parent on a full pipe: writes wait up to the step timeout.
        os.set_blocking(to_child_w, False)
        self._from_child = from_child_r
        os.set_blocking(from_child_r, False)  # polled briefly, then select (wire.spin_read)
        self._stdout = self.proc.stdout.fileno()
        os.set_blocking(self._stdout, False)
        # asked every exchange whether there is output: cheaper than a read that fails
        self._stdout_poll = select.poll()
        self._stdout_poll.register(self._stdout, select.POLLIN)

    def _exec(self, config: dict[str, Any], cwd: str | None, fds: tuple[int, int]) -> subprocess.Popen:
        """Start a fresh interpreter for the child."""
        # Inherited by whatever the controller starts: found and killed at the end
        # even if it left the child's session and lost its parent.
        self._token = _new_token()
        return subprocess.Popen(
            [sys.executable, "-s", "-c", _BOOTSTRAP.format(root=_PACKAGE_ROOT), json.dumps(config)],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            pass_fds=fds,
            start_new_session=True,
            cwd=cwd,
            env=_child_environment(self._token),
            **self._credentials(),
        )

    def _fork(self, config: dict[str, Any], cwd: str | None, fds: tuple[int, int]) -> Any:
        """Fork the child from this submission's fork server, if this process
        uses them (grading workers); None to start it the usual way."""
        servers = forkserver.servers()
        if servers is None or self.spec.path is None:
            return None

        def start() -> forkserver.ForkServer:
            token = _new_token()
            return forkserver.ForkServer(_PACKAGE_ROOT, _child_environment(token), token, self._credentials())

        key = (str(self.spec.path.resolve()), self.limits.run_as)
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

    def close(self) -> CrashReport | None:
        """End the child (asking it first), kill what it left behind, report."""
        if self.proc is not None and not self.finished:
            if self._awaiting is not None:
                self._collect(self.limits.step_timeout)
        if self.proc is not None and not self.finished:
            try:
                wire.send_to_child(self._to_child, {"end": True}, _monotonic() + 1.0)
                self._receive(1.0, final=True)
            except (OSError, wire.WireError, _Stop):
                pass
        self._terminate()
        return self.crash

    def _terminate(self) -> None:
        self.finished = True
        if self in self.sim.remotes:
            self.sim.remotes.remove(self)
        self.wake_ns = None
        proc = self.proc
        if proc is None:
            return
        kill_tree(proc.pid, self._token, reaped=proc.returncode is not None, spare=self._spare)
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            pass
        self._drain_output(final=True)
        self._report_dropped()
        for fd in (self._to_child, self._from_child):
            try:
                os.close(fd)
            except OSError:
                pass
        if proc.stdout:
            proc.stdout.close()
        if self.crash is not None:
            # A controller that ends normally leaves its last command to
            # turtlesim's 1 s timeout, as in ROS; a failed one stops its turtle.
            stop_turtles(self.sim, self.owner)
        self.graph.remove_owner(self.owner)
        self.proc = None

    def _fail(self, kind: str, message: str, frames: list[str] | None = None) -> None:
        if self.crash is None:
            message = " ".join(message.splitlines())  # the summary stays one line
            self.crash = CrashReport(self.spec.label, self.sim.t, kind, message, frames or [])
            log_crash(self.graph, self.crash)
        self._terminate()

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
        if self._inbox or self._responses or self._goal_events or self._served_out or self._requests or self._params:
            return True
        if self._poll or self.graph.version != self._mirrored_version:
            return True  # a change on the graph: a waiting node may be waiting for it
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
        message: dict[str, Any] = {"now": self.graph.now_ns}
        cause: Any = WAKE
        if self._responses:
            message["responses"], self._responses = self._responses, []
            cause = CALLS
        if self._goal_events:
            message["goals"], self._goal_events = self._goal_events, []
            cause = CALLS
        if self._requests:
            message["requests"], self._requests = self._requests, []
            cause = CALLS
        if self._served_out:
            message["served"], self._served_out = self._served_out, []
            cause = CALLS
        if self._params:
            message["params"], self._params = self._params, []
            cause = CALLS
        inbox = self._inbox
        if inbox:
            message["msgs"], self._inbox = inbox, []
            cause = inbox[0][0] if len(inbox) == 1 else _subscriptions(inbox)
        if self.graph.version != self._mirrored_version:
            self._mirrored_version = self.graph.version
            mirror = graph_mirror.snapshot(self.graph, self.owner, self._own_ids())
            if mirror != self._mirror:
                self._mirror = mirror
                message["graph"] = mirror.to_wire()
        timeout = timeout or self.limits.step_timeout
        sent = _perf_counter()
        try:
            wire.send_to_child(self._to_child, message, _monotonic() + timeout)
        except wire.WireTimeout:
            self._fail(
                "timeout",
                f"did not take the next step within {self.limits.step_timeout:g} s of wall time "
                "(it stopped reading what turtletui sends)",
            )
            return True
        except OSError:
            self._child_died()
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

    def _own_ids(self) -> dict[int, int]:
        """``id(record)`` to wire id, for the child's nodes and topic endpoints here."""
        ids = {id(node): wire_id for wire_id, node in self._nodes.items()}
        ids.update((id(endpoint), wire_id) for wire_id, endpoint in self._endpoints.items())
        return ids

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
        """Seconds the child's threads and this process's have waited for a CPU."""
        child = run_queue_seconds(self.proc.pid) if self.proc is not None else None
        own = run_queue_seconds("self")
        return (child or 0.0) + (own or 0.0)

    def _collect(self, budget: float) -> bool:
        """Real time: apply the pending answer if it arrives within ``budget``
        seconds; stop the child once it is later than the step deadline."""
        deadline = _monotonic() + budget
        fd = self._from_child
        try:
            while True:
                if self._frame_ready():
                    self._awaiting = None
                    self._receive(0.0)
                    return True
                remaining = deadline - _monotonic()
                if remaining <= 0:
                    break
                select.select([fd], [], [], remaining)
        except _Stop:
            return True
        assert self._awaiting is not None
        if _monotonic() - self._awaiting > self.limits.step_timeout:
            self._fail(
                "timeout",
                f"did not answer within {self.limits.step_timeout:g} s of wall time "
                "(an endless loop, a sleep or a blocking call in a callback?)",
            )
            return True
        return False

    def _frame_ready(self) -> bool:
        """Read what the child has sent without waiting; is a whole frame in?"""
        buffer = self._read_buffer
        while True:
            try:
                chunk = os.read(self._from_child, 1 << 16)
            except BlockingIOError:
                break
            if not chunk:
                self._child_died()
                raise _Stop
            buffer += chunk
            if len(buffer) > wire.MAX_REPLY_BYTES + 4:
                break
        self._read_buffer = buffer
        self._drain_output()
        if len(buffer) < 4:
            return False
        try:
            size = wire.read_header(buffer[:4])
        except wire.WireError as err:
            self._fail("flood", str(err))
            raise _Stop from None
        return len(buffer) >= 4 + size

    # -- receiving ---------------------------------------------------------------
    def _receive(self, timeout: float, *, first: bool = False, final: bool = False) -> None:
        deadline = _monotonic() + timeout
        buffer = self._read_buffer
        if len(buffer) < 4:
            buffer = self._read_more(buffer, 4, deadline)
        try:
            size = wire.read_header(buffer[:4])
        except wire.WireError as err:
            self._fail("flood", str(err))
            raise _Stop from None
        end = 4 + size
        if len(buffer) < end:
            buffer = self._read_more(buffer, end, deadline)
        payload = buffer[4:end]
        self._read_buffer = buffer[end:]
        try:
            reply = wire.parse_reply(payload)
        except wire.WireError as err:
            self._fail("exception", str(err))
            raise _Stop from None
        if first:
            return
        try:
            self._apply(reply)
        except _Stop:
            raise
        except (InterfaceError, GraphError) as err:
            self._fail("exception", f"sent something turtlesim cannot accept: {err}")
            raise _Stop from None
        except Exception as err:  # noqa: BLE001 - a forged reply may break anything in _apply
            self._fail("exception", f"sent something turtlesim cannot accept ({type(err).__name__}: {err})")
            raise _Stop from None

    def _read_more(self, buffer: bytes, total: int, deadline: float) -> bytes:
        """``buffer`` extended with what the child sends until it holds ``total``
        bytes: one select and one read per chunk the pipe has, not per field."""
        chunks = [buffer]
        have = len(buffer)
        fd = self._from_child
        stdout = self._stdout
        watch = [fd, stdout] if self._stdout_open else [fd]
        while have < total:
            remaining = deadline - _monotonic()
            if remaining <= 0:
                self._read_buffer = b"".join(chunks)
                self._fail(
                    "timeout",
                    f"did not answer within {self.limits.step_timeout:g} s of wall time "
                    "(an endless loop, a sleep or a blocking call in a callback?)",
                )
                raise _Stop
            size = max(min(total - have, 1 << 20), 1 << 16)
            chunk = wire.spin_read(fd, size, self._spin)
            if chunk is None:
                # Wake up now and then to notice a child that died while something
                # it started still holds the pipe open (no end of file then).
                readable, _, _ = select.select(watch, [], [], min(remaining, _LIVENESS_SECONDS))
                if stdout in readable:
                    self._drain_output()
                    if not self._stdout_open and stdout in watch:
                        watch.remove(stdout)
                if fd not in readable:
                    if not readable and self.proc is not None and has_exited(self.proc.pid):
                        self._child_died()
                        raise _Stop
                    continue
                try:
                    chunk = os.read(fd, size)
                except BlockingIOError:
                    continue
            else:
                # What the child printed before answering is logged before the
                # answer, as when select reports both pipes ready.
                self._drain_output()
            if not chunk:
                self._child_died()
                raise _Stop
            chunks.append(chunk)
            have += len(chunk)
        return b"".join(chunks)

    def _child_died(self) -> None:
        proc = self.proc
        # read before it is reaped: a child the CPU limit killed has used it all
        cpu = cpu_seconds(proc.pid) if proc is not None and proc.returncode is None else None
        try:
            code = proc.wait(timeout=1) if proc is not None else None
        except subprocess.TimeoutExpired:
            # Still running, but it closed its end of the pipe.
            self._fail("exception", "closed its connection to turtletui and was stopped")
            return
        if code is not None and code < 0:
            sig = -code
            over_cpu = ("cpu", f"used more than its CPU limit of {self.limits.cpu_seconds} s")
            limit = self.limits.cpu_seconds
            if sig == signal.SIGKILL and cpu is not None and limit is not None and cpu >= limit:
                sig = signal.SIGXCPU  # it ignored SIGXCPU: the hard limit's SIGKILL came
            kind, why = {
                signal.SIGXCPU: over_cpu,
                signal.SIGKILL: ("killed", "was killed (SIGKILL): by someone, or the system ran out of memory"),
                signal.SIGSEGV: ("killed", "crashed the interpreter (SIGSEGV)"),
            }.get(sig, ("killed", f"was killed by signal {_signal_name(sig)}"))
            self._fail(kind, why)
        elif not self._started:
            self._fail("exit", f"exited with status {code} while starting, before loading the controller (see its output)")
        else:
            self._fail("exit", f"exited with status {code} without finishing its run")

    def _drain_output(self, final: bool = False) -> None:
        if self.proc is None or self.proc.stdout is None or not self._stdout_open:
            return
        if not final and not self._stdout_poll.poll(0):
            return  # nothing printed (POLLHUP when closed counts as something)
        chunks = []
        read = 0
        try:
            while read < _OUTPUT_READ_LIMIT:
                data = os.read(self._stdout, 65536)
                if not data:
                    self._stdout_open = False
                    break
                read += len(data)
                chunks.append(data)
        except (BlockingIOError, OSError, ValueError):
            pass
        # past the budget the output is still read (so the child never blocks), then dropped
        if self._output.feed(b"".join(chunks), final=final or not self._stdout_open):
            self.graph.log(
                "turtletui",
                WARN,
                f"{self.spec.label}: output over its budget of {size_text(self.limits.output_bytes)} or "
                f"{self.limits.output_lines:,} lines per run: the rest is dropped",
            )

    def _show_output(self, line: str) -> None:
        self.graph.log(f"{self.spec.name}{OUTPUT_SUFFIX}", INFO, line)

    def _report_dropped(self) -> None:
        """One line at the end of the run saying how much was not shown."""
        dropped = self._output.dropped()
        if dropped:
            self.graph.log("turtletui", WARN, f"{self.spec.label}: {dropped}")
        dropped = self._log_dropped + self._child_dropped
        if dropped:
            self.graph.log("turtletui", WARN, f"{self.spec.label}: {dropped:,} log messages over its budget dropped")

    # -- applying what the child did ------------------------------------------------
    def _apply(self, reply: dict) -> None:
        graph = self.graph
        unchanged = graph.version == self._mirrored_version
        for decl in reply.get("decl", ()):
            self._declare(decl)
        for removed in reply.get("removed", ()):
            self._remove(graph_mirror.Removed.parse(removed))
        if unchanged:
            # The child knows what it did itself: no exchange just to tell it.
            self._mirrored_version = graph.version
        for level, node, msg in reply.get("log", ()):
            text = str(msg)[:10_000]
            self._log_lines += 1
            self._log_bytes += len(text) + 1
            if self._log_lines <= self.limits.log_lines and self._log_bytes <= self.limits.log_bytes:
                graph.log(str(node)[:200], int(level), text)
                continue
            self._log_dropped += 1
            if self._log_dropped == 1:
                graph.log(
                    "turtletui",
                    ERROR,
                    f"{self.spec.label}: log over its budget of {self.limits.log_lines:,} messages or "
                    f"{size_text(self.limits.log_bytes)} per run: the rest is dropped",
                )
        dropped = reply.get("logs_dropped")
        if isinstance(dropped, int) and dropped > self._child_dropped:
            self._child_dropped = dropped  # the child's own count: only ever shown
        for name, fields in reply.get("pub", ()):
            topic = graph.topics.get(name)
            if topic is None:
                raise GraphError(f"published on undeclared topic {name}")
            msg = from_values(topic.msg_type, fields)
            graph.publish(topic, msg, source=self.owner)
        for call_id, name, fields in reply.get("call", ()):
            service = graph.services.get(name)
            if service is None:
                continue
            request = from_values(service.srv_type.Request, fields)
            response_type = f"{service.type_name}_Response"
            graph.call(
                name,
                request,
                lambda response, cid=call_id, rt=response_type: self._responses.append([cid, rt, to_values(response)]),
                self.owner,
            )
        for goal_id, name, fields in reply.get("goal", ()):
            server = graph.action_servers.get(name)
            if server is None:
                continue
            goal = from_values(server.action_type.Goal, fields)
            graph.send_goal(
                name,
                goal,
                self.owner,
                lambda handle, gid=goal_id: self._goal_accepted(gid, handle),
                lambda feedback, gid=goal_id: self._goal_events.append([gid, "feedback", to_values(feedback)]),
                lambda status, result, gid=goal_id: self._goal_events.append(
                    [gid, "result", [status, to_values(result)]]
                ),
                lambda status, gid=goal_id: self._goal_events.append([gid, "status", status]),
            )
        for goal_id in reply.get("cancel", ()):
            handle = self._goals.get(goal_id)
            if handle is not None:
                graph.cancel_goal(
                    handle,
                    self.owner,
                    lambda code, canceling, gid=goal_id: self._goal_events.append([gid, "cancel", [code, canceling]]),
                )
        for goal_id, kind, payload in reply.get("served", ()):
            self._served_event(goal_id, kind, payload)
        for req_id, fields in reply.get("resp", ()):
            respond = self._service_calls.pop(req_id, None)
            if respond is not None:
                respond(fields)
        wake = reply.get("wake")
        now = graph.now_ns
        if wake is not None and int(wake) <= now:
            self.wake_ns, self._poll = None, True
        else:
            self.wake_ns, self._poll = (None if wake is None else int(wake)), False
        if reply.get("done"):
            crash = reply.get("crash")
            if crash:
                if not isinstance(crash, dict):
                    raise TypeError("crash report is not an object")
                frames = [str(f)[:1000] for f in crash.get("frames", [])][:50]
                kind = str(crash.get("kind", "exception"))
                self._fail(
                    kind if kind in _CRASH_KINDS else "exception", str(crash.get("message", ""))[:2000], frames
                )
            else:
                self._terminate()
            raise _Stop

    def _set_parameter(self, node: NodeRecord, wire_id: int, name: str, value: Any) -> str | None:
        """``ros2 param set`` on a sandboxed node: refused here if ROS would refuse
        the type, else sent with the next exchange (the node's own on-set
        callbacks may still refuse it, and its log then says why)."""
        if self.finished:
            return f"{node.fqn} is not running"
        from turtletui.compat.node import InvalidParameterTypeException
        from turtletui.compat.parameter import Parameter, type_matches

        if name in node.parameters:
            expected = Parameter.Type.from_parameter_value(node.parameters[name])
            if expected is not Parameter.Type.NOT_SET and not type_matches(expected, value):
                # what the node would answer (unless it declared dynamic typing)
                return str(InvalidParameterTypeException(Parameter(name, value=value), expected))
        self._params.append([wire_id, name, value])
        return None

    def _remove(self, removed: graph_mirror.Removed) -> None:
        """The child destroyed a service, client or action client."""
        graph = self.graph
        node = self._nodes.get(removed.node)
        if removed.kind == "service":
            service = graph.services.get(removed.name)
            if service is not None and service.node is node:
                graph.remove_service(service)
            return
        if removed.kind == "action_server":
            server = graph.action_servers.get(removed.name)
            if server is not None and server.node is node:
                graph.remove_action_server(server)
            return
        records = graph.clients if removed.kind == "client" else graph.action_clients
        record = next((r for r in records if r.node is node and r.name == removed.name), None)
        if record is None:
            return
        if removed.kind == "client":
            graph.remove_client(record)
        else:
            graph.remove_action_client(record)

    def _goal_accepted(self, goal_id: int, handle: Any) -> None:
        if handle is None:
            self._goal_events.append([goal_id, "rejected", None])
            return
        self._goals[goal_id] = handle
        self._goal_events.append([goal_id, "accepted", [handle.goal_id, handle.status]])

    def _serve(self, handle: GoalHandle) -> None:
        """A goal for one of the child's action servers: sent with the next exchange."""
        goal_id = handle.goal_id
        self._served[goal_id] = handle

        def decide_cancel(decided: Any) -> None:
            self._cancel_decisions[goal_id] = decided
            self._served_out.append([goal_id, "cancel", None])

        handle.decide_cancel = decide_cancel
        self._served_out.append([goal_id, "goal", [handle.action.name, to_values(handle.goal)]])

    def _served_event(self, goal_id: Any, kind: Any, payload: Any) -> None:
        """What the child's action server did with one of its goals (checked: the child is untrusted)."""
        handle = self._served.get(goal_id) if type(goal_id) is int else None
        if handle is None:
            return  # finished already, or never sent
        action_type = handle.action.action_type
        if kind == "accept" and payload in ("accepted", "executing"):
            handle.accept(payload)
        elif kind == "reject":
            handle.reject()
            del self._served[goal_id]
        elif kind == "status" and payload in ("executing", "canceling"):
            handle.set_status(payload)
        elif kind == "feedback":
            handle.publish_feedback(from_values(action_type.Feedback, payload))
        elif kind == "result" and payload[0] in ("succeeded", "aborted", "canceled"):
            handle.finish(payload[0], from_values(action_type.Result, payload[1]))
            del self._served[goal_id]
        elif kind == "cancel" and goal_id in self._cancel_decisions:
            code, canceling = payload
            if type(code) is not int or not 0 <= code <= 3:
                raise ValueError(f"cancel answer with return code {str(code)[:20]}")
            decided = self._cancel_decisions.pop(goal_id)
            decided(True) if canceling is True else decided(False, code)
        else:
            raise ValueError(f"goal event {str(kind)[:20]} with {str(payload)[:100]}")

    def _declare(self, decl: list) -> None:
        graph = self.graph
        kind = decl[0]
        if kind == "node":
            _, wire_id, name, namespace = decl
            node = graph.add_node(str(name), str(namespace), self.owner)
            node.parameter_setter = lambda key, value, node=node, wire_id=wire_id: self._set_parameter(
                node, wire_id, key, value
            )
            self._nodes[wire_id] = node
        elif kind == "rmnode":
            node = self._nodes.pop(decl[1], None)
            if node is not None:
                graph.remove_node(node)
        elif kind == "pub":
            _, wire_id, node_id, topic, type_name, depth, *rest = decl
            self._endpoints[wire_id] = graph.add_publisher(
                self._nodes[node_id], str(topic), get_interface(type_name), int(depth), qos=_qos(rest)
            )
        elif kind == "sub":
            _, wire_id, node_id, topic, type_name, depth, *rest = decl
            self._pace.subscriptions[wire_id] = (_label(rest), str(topic)[:200])

            def forward(msg: Any, wire_id: int = wire_id) -> None:
                self._inbox.append((wire_id, to_values(msg)))

            self._endpoints[wire_id] = graph.add_subscription(
                self._nodes[node_id], str(topic), get_interface(type_name), int(depth), forward, qos=_qos(rest)
            )
        elif kind == "timer":
            if len(self._pace.timers) < 100:
                self._pace.timers.append((int(decl[2]), _label(decl[3:])))
        elif kind == "rm":
            endpoint = self._endpoints.pop(decl[1], None)
            if endpoint is not None:
                graph.remove_endpoint(endpoint)
        elif kind == "client":
            graph.add_client(self._nodes[decl[1]], str(decl[2]), get_interface(decl[3]))
        elif kind == "aclient":
            graph.add_action_client(self._nodes[decl[1]], str(decl[2]), get_interface(decl[3]))
        elif kind == "asrv":
            _, node_id, name, type_name = decl
            graph.add_action_server(self._nodes[node_id], str(name), get_interface(type_name), self._serve, answers=True)
        elif kind == "srv":
            _, node_id, name, type_name = decl
            srv_type = get_interface(type_name)

            def handler(request: Any, respond: Any, name: str = str(name), srv_type: Any = srv_type) -> None:
                req_id = next(self._request_ids)
                self._service_calls[req_id] = lambda fields: respond(from_values(srv_type.Response, fields))
                self._requests.append([req_id, name, to_values(request)])

            graph.add_service(self._nodes[node_id], str(name), srv_type, handler)
        elif kind == "param":
            _, node_id, name, value, remove = decl
            if isinstance(value, dict) or (isinstance(value, list) and not all(map(_is_scalar, value))):
                raise TypeError(f"parameter {str(name)[:100]} has a value no ROS parameter can hold")
            graph.set_parameter(self._nodes[node_id], str(name), value, remove=bool(remove))


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


class _Stop(Exception):
    """The child finished or failed during an exchange."""


_BEHIND_WORTH_SAYING = 0.5
"""Wall seconds behind real time from which a run stopped by its time limit
is also told that it could not keep up."""
_RECHECK_SECONDS = 0.5
"""Wall seconds of a controller's answers between two looks at how long the
machine kept it waiting for a CPU (a look reads /proc: not at every answer)."""
_LIVENESS_SECONDS = 0.1
"""How often a parent waiting for an answer checks that the child is still alive."""


def _subscriptions(inbox: list) -> Any:
    """What an exchange delivered messages for: one subscription's wire id, or
    a tuple of several."""
    ids = sorted({wire_id for wire_id, _ in inbox})
    return ids[0] if len(ids) == 1 else tuple(ids)


def _label(rest: list) -> str:
    """A callback's name as the child declared it (only ever shown, so only a
    short identifier is kept)."""
    label = rest[0] if rest else ""
    return label if isinstance(label, str) and label.isidentifier() and len(label) <= 60 else ""


def _qos(rest: list) -> graph_mirror.QosPolicies | None:
    """An endpoint's QoS policies as the child declared them (after its label)."""
    return graph_mirror.QosPolicies.parse(rest[1]) if len(rest) > 1 and rest[1] is not None else None


def _is_scalar(value: Any) -> bool:
    return value is None or isinstance(value, (bool, int, float, str))


def _signal_name(sig: int) -> str:
    try:
        return signal.Signals(sig).name
    except ValueError:
        return f"{sig}"
