"""Running turtletui on a real ROS 2 graph: the bridge joined to a simulation,
and controller files as ordinary ROS 2 processes (``turtletui run --ros``).
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import threading
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from turtletui.api import RunResult, TurtleSummary
from turtletui.bridge.host import RosBridge
from turtletui.bridge.process import RUN_FILE_SCRIPT, TwinProcess, start_twin
from turtletui.compat.distro import distro_of_ros
from turtletui.graph.core import NS_PER_S
from turtletui.graph.logs import INFO, LogRecord
from turtletui.runtime.loader import ControllerError, ControllerSpec, check_source
from turtletui.runtime.report import CrashReport
from turtletui.runtime.simulation import Simulation

if TYPE_CHECKING:
    from turtletui.sim import World

STOP_GRACE = 3.0
"""Wall seconds a controller has to end after Ctrl-C before it is terminated."""

_SLICE_NS = 100_000_000
"""How often (simulated ns) a run looks at its controllers between steps."""


@dataclass
class RosConnection:
    """A twin started and ready (a front end starts it first, to fail in one line)."""

    twin: TwinProcess
    info: dict[str, Any]


def connect(ros_python: str | None = None) -> RosConnection:
    """Start the twin in a ROS 2 python; RosUnavailable (one line) if there is none."""
    return RosConnection(*start_twin(ros_python))


def distro_of(ros: RosConnection) -> str:
    """The distro a simulation joined to ``ros`` runs as: the real graph's, so
    that both name turtlesim's types alike (turtlesim_msgs/... from Kilted on)."""
    return distro_of_ros(str(ros.info.get("distro", "")), str(ros.info.get("turtlesim_package", "")))


def attach(
    sim: Simulation,
    ros: RosConnection | str | None = None,
    earlier_logs: Iterable[LogRecord] = (),
    log_filter: Callable[[Callable[[LogRecord], None]], Callable[[LogRecord], None]] | None = None,
) -> RosBridge:
    """Put ``sim`` (real time) on the ROS 2 graph, through ``ros`` (a started
    twin, or the python to start one in); RosUnavailable if there is none.

    ``earlier_logs``: lines logged before (turtlesim's start lines), sent on
    to /rosout once the twin is there; ``log_filter``: what of turtletui's
    log goes to /rosout (turtlesim's ``--log-level``).
    """
    if not isinstance(ros, RosConnection):
        ros = connect(ros)
    bridge = RosBridge(sim, ros.twin, ros.info, log_filter)
    for record in earlier_logs:
        bridge.log_sink(record)
    sim.remotes.append(bridge)
    return bridge


class RosController:
    """One controller file running as a ROS 2 process of the bridge's python.

    The app holds it as it holds a sandboxed controller: ``finished``,
    ``crash`` and ``close()``.
    """

    def __init__(
        self,
        python: str,
        spec: ControllerSpec,
        ros_args: Sequence[str] = (),
        output: Callable[[str, str], None] | None = None,
        clock: Callable[[], float] = lambda: 0.0,
    ) -> None:
        self.spec = spec
        self._clock = clock
        self._ended_at: float | None = None
        capture = subprocess.PIPE if output is not None else None
        self._proc = subprocess.Popen(
            [python, str(RUN_FILE_SCRIPT), str(spec.path), *ros_args],
            stdin=subprocess.DEVNULL,
            stdout=capture,
            stderr=subprocess.STDOUT if output is not None else None,
            start_new_session=True,  # Ctrl-C reaches turtletui, which stops it as ros2 launch does
        )
        if output is not None:
            threading.Thread(target=self._pass_on, args=(output,), daemon=True).start()

    def _pass_on(self, output: Callable[[str, str], None]) -> None:
        for line in self._proc.stdout:
            output(self.spec.label, line.decode(errors="replace").rstrip("\n"))

    def poll(self) -> int | None:
        """Its exit status once it ended, else None."""
        status = self._proc.poll()
        if status is not None and self._ended_at is None:
            self._ended_at = self._clock()
        return status

    @property
    def finished(self) -> bool:
        return self.poll() is not None

    @property
    def crash(self) -> CrashReport | None:
        """Why it ended, if it failed (a non-zero exit status)."""
        status = self.poll()
        if not status:
            return None
        return CrashReport(self.spec.label, self._ended_at or 0.0, "exit", f"exit status {status}")

    def close(self) -> None:
        self.stop()

    def stop(self) -> None:
        """Ctrl-C its process group, then terminate what is left."""
        if self._proc.poll() is not None:
            return
        for sig, grace in ((signal.SIGINT, STOP_GRACE), (signal.SIGTERM, 1.0), (signal.SIGKILL, None)):
            try:
                os.killpg(self._proc.pid, sig)
            except ProcessLookupError:
                return
            try:
                self._proc.wait(grace)
                return
            except subprocess.TimeoutExpired:
                continue


_CONSOLE_LOG = re.compile(r"\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[\d+\.\d+\] \[[^\]]*\]: ")


def is_console_log(line: str) -> bool:
    """Whether a line of a ROS 2 process's output is one of its log lines
    (``[INFO] [1700000000.000000000] [node]: ...``), which /rosout also carries."""
    return _CONSOLE_LOG.match(line) is not None


def ros_specs(specs: Sequence[ControllerSpec]) -> list[ControllerSpec]:
    """The specs that can run as ROS 2 processes (files); ControllerError names the others."""
    for spec in specs:
        if spec.path is None:
            raise ControllerError(
                f"{spec.label}: a plugin's node factory, not a file: --ros runs controller files"
            )
        check_source(spec.path)
    return list(specs)


def run_ros(
    controllers: Sequence[ControllerSpec],
    *,
    duration: float | None = 60.0,
    ros_python: str | None = None,
    ros_args: Sequence[str] = (),
    on_log: Callable[[LogRecord], None] | None = None,
    world: World | None = None,
    output: Callable[[str, str], None] | None = None,
) -> RunResult:
    """Run controller files as ROS 2 processes against the bridged turtlesim,
    in real time, for ``duration`` wall seconds (None: until they all end or
    Ctrl-C). ``on_log`` gets turtletui's own log lines (the controllers print
    theirs, or hand every line of output to ``output(controller, line)``).
    RosUnavailable when there is no ROS 2; ControllerError for a bad file.
    """
    specs = ros_specs(controllers)
    args = list(ros_args)
    if args and args[0] != "--ros-args":
        args = ["--ros-args", *args]
    logs: list[LogRecord] = []
    ros = connect(ros_python)
    sim = Simulation(world=world, realtime=True, log_sinks=[logs.append], distro=distro_of(ros))
    bridge = attach(sim, ros, earlier_logs=logs)
    if on_log is not None:
        for record in logs:
            on_log(record)
        sim.graph.log_sinks.append(bridge.local_only(on_log))
    started = time.perf_counter()
    running = [RosController(bridge.twin.python, spec, args, output, lambda: sim.t) for spec in specs]
    crashes: list[CrashReport] = []
    interrupted = False
    limit = round(duration * NS_PER_S) if duration is not None else None
    try:
        while running and (limit is None or sim.graph.now_ns < limit):
            step = sim.graph.now_ns + _SLICE_NS
            sim.run_until(step if limit is None else min(step, limit))
            if bridge.gone:  # the files can no longer reach turtlesim: say so and stop
                crashes.append(CrashReport("ROS 2", sim.t, "killed", "the ROS 2 side (the bridge's twin) ended"))
                break
            for controller in [c for c in running if c.finished]:
                running.remove(controller)
                crash = controller.crash
                if crash is not None:
                    crashes.append(crash)
                    sim.graph.log("turtletui", INFO, crash.summary())
    except KeyboardInterrupt:
        interrupted = True
    finally:
        for controller in running:
            controller.stop()
        bridge.close()
    wall = time.perf_counter() - started
    turtles = {
        name: TurtleSummary(t.x, t.y, t.theta, t.distance, t.wall_hits, t.obstacle_hits)
        for name, t in sim.world.turtles.items()
    }
    return RunResult(sim.t, wall, turtles, logs, crashes, interrupted=interrupted)

