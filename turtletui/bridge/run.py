"""Running turtletui on a real ROS 2 graph: the bridge joined to a simulation,
and controller files as ordinary ROS 2 processes (``turtletui run --ros``).
"""

from __future__ import annotations

import os
import signal
import subprocess
import threading
import time
from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING

from turtletui.api import RunResult, TurtleSummary
from turtletui.bridge.host import RosBridge
from turtletui.bridge.process import RUN_FILE_SCRIPT, start_twin
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


def attach(sim: Simulation, ros_python: str | None = None, earlier_logs: Iterable[LogRecord] = ()) -> RosBridge:
    """Put ``sim`` (real time) on the ROS 2 graph; RosUnavailable if there is none.

    ``earlier_logs``: lines logged before (turtlesim's start lines), sent on
    to /rosout once the twin is there.
    """
    twin, info = start_twin(ros_python)
    bridge = RosBridge(sim, twin, info)
    for record in earlier_logs:
        bridge.forward_log(record)
    sim.remotes.append(bridge)
    return bridge


class RosController:
    """One controller file running as a ROS 2 process of the bridge's python."""

    def __init__(
        self,
        python: str,
        spec: ControllerSpec,
        ros_args: Sequence[str] = (),
        output: Callable[[str, str], None] | None = None,
    ) -> None:
        self.spec = spec
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
        return self._proc.poll()

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
    sim = Simulation(world=world, realtime=True, log_sinks=[logs.append])
    bridge = attach(sim, ros_python, earlier_logs=logs)
    if on_log is not None:
        for record in logs:
            on_log(record)
        sim.graph.log_sinks.append(bridge.local_only(on_log))
    started = time.perf_counter()
    running = [RosController(bridge.twin.python, spec, args, output) for spec in specs]
    crashes: list[CrashReport] = []
    interrupted = False
    limit = round(duration * NS_PER_S) if duration is not None else None
    try:
        while running and (limit is None or sim.graph.now_ns < limit):
            step = sim.graph.now_ns + _SLICE_NS
            sim.run_until(step if limit is None else min(step, limit))
            for controller in [c for c in running if c.poll() is not None]:
                running.remove(controller)
                status = controller.poll()
                if status != 0:
                    crash = CrashReport(controller.spec.label, sim.t, "exit", f"exit status {status}")
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
        name: TurtleSummary(t.x, t.y, t.theta, t.distance, t.wall_hits) for name, t in sim.world.turtles.items()
    }
    return RunResult(sim.t, wall, turtles, logs, crashes, interrupted=interrupted)

