"""Library API: run controllers against the simulated turtlesim from Python.

    from turtletui.api import run

    result = run(["my_node.py"], duration=10.0, keep_poses=True)
    result.wall_hits, result.turtles["turtle1"].x, result.poses["turtle1"][-1]
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.compat.distro import choose_distro
from turtletui.compat.ros_args import RosArgsError, parse_ros_args
from turtletui.errors import TurtletuiError, UsageError
from turtletui.graph.core import NS_PER_S
from turtletui.graph.logs import INFO, LogRecord
from turtletui.runtime import replica
from turtletui.runtime.loader import ControllerError, ControllerSpec, check_source
from turtletui.runtime.outputs import run_outputs
from turtletui.runtime.report import CrashReport
from turtletui.runtime.runner import run_controllers
from turtletui.runtime.simulation import Simulation

if TYPE_CHECKING:
    from turtletui.runtime.sandbox import Limits
    from turtletui.sim import World



@dataclass
class TurtleSummary:
    """Where a turtle ended and what it did."""

    x: float
    y: float
    theta: float
    distance: float
    wall_hits: int
    obstacle_hits: int = 0


@dataclass
class RunResult:
    """Outcome of ``run``: times in seconds, distances in metres."""

    sim_time: float
    wall_time: float
    turtles: dict[str, TurtleSummary]
    logs: list[LogRecord]
    crashes: list[CrashReport] = field(default_factory=list)
    service_calls: list[tuple[float, str, Any, Any]] = field(default_factory=list)
    poses: dict[str, list[tuple[float, float, float, float]]] = field(default_factory=dict)
    """(t, x, y, theta) per turtle at every pose, if ``keep_poses`` was asked."""
    interrupted: bool = False
    """Ctrl-C ended the run before its duration."""

    @property
    def distance(self) -> float:
        return sum(t.distance for t in self.turtles.values())

    @property
    def wall_hits(self) -> int:
        return sum(t.wall_hits for t in self.turtles.values())

    @property
    def obstacle_hits(self) -> int:
        return sum(t.obstacle_hits for t in self.turtles.values())

    @property
    def ok(self) -> bool:
        return not self.crashes

    def summary(self) -> str:
        """The one line ``turtletui run --headless`` ends with."""
        status = "ok" if self.ok else f"{len(self.crashes)} controller(s) failed"
        if self.interrupted:
            status = f"interrupted, {status}"
        hits = f"wall hits {self.wall_hits}"
        if self.obstacle_hits:  # only a world with obstacles has any
            hits += f", obstacle hits {self.obstacle_hits}"
        return (
            f"sim time {self.sim_time:.3f} s, wall time {self.wall_time:.3f} s, "
            f"distance {self.distance:.2f} m, {hits}: {status}"
        )


def as_spec(controller: str | Path | ControllerSpec) -> ControllerSpec:
    """A ControllerSpec for a path (sandboxed), or an existing spec as it is."""
    if isinstance(controller, ControllerSpec):
        return controller
    path = Path(controller)
    return ControllerSpec(name=path.stem, path=path)


def run(
    controllers: Sequence[str | Path | ControllerSpec],
    *,
    duration: float = 60.0,
    seed: int = 0,
    realtime: bool = False,
    sandbox: bool | None = None,
    ros_args: Sequence[str] = (),
    record: str | Path | None = None,
    on_log: Callable[[LogRecord], None] | None = None,
    keep_poses: bool = False,
    keep_calls: bool = True,
    setup: Callable[[Simulation], None] | None = None,
    limits: Limits | None = None,
    world: World | None = None,
    foxglove: str | None = None,
    distro: str | None = None,
) -> RunResult:
    """Run controllers for ``duration`` simulated seconds and summarise the run.

    Files are sandboxed in a child process unless ``sandbox=False``; specs
    marked trusted run in this process. ``ros_args`` is a ``--ros-args``
    section (``["-p", "goal_x:=3.0"]``) given to every controller. Bad input
    raises a TurtletuiError with a one-line message (ControllerError,
    RosArgsError, RecordingError for ``record``, UsageError for ``duration``).
    ``limits`` (turtletui.runtime.sandbox.Limits) bounds what sandboxed
    controllers may use; the defaults when None. One sandboxed controller
    out of real time may take the fast path (turtletui.runtime.fastpath):
    where it pays, or as ``limits.lockstep`` says; ``setup`` (called with the simulation before the
    controllers start) keeps it there only as a
    turtletui.runtime.replica.ReplicableSetup, whose steps the sandboxed
    child can redo on its own copy. ``world`` is a fresh World
    to run in (turtlesim's empty arena when None). ``record`` names a
    recording (``run.jsonl``, ``run.mcap`` or a rosbag2 folder ``run/``);
    ``foxglove`` (``HOST:PORT``) serves the run live to Foxglove, in real time.
    ``distro`` is the ROS 2 distribution controllers run as (``"jazzy"``:
    ``turtlesim.msg``; ``"kilted"``, ``"lyrical"``: ``turtlesim_msgs.msg``);
    None: ``$TURTLETUI_DISTRO``, else Jazzy for files that import
    ``turtlesim`` (logged as turtletui says why), else the newest LTS.
    """
    if not (duration > 0 and duration < 1e7):
        raise UsageError(f"duration must be a positive number of seconds, got {duration}")
    args = list(ros_args)
    if args and args[0] != "--ros-args":
        args = ["--ros-args", *args]
    parse_ros_args(args)  # fail early with a one-line RosArgsError
    specs = [as_spec(c) for c in controllers]
    if sandbox is not None:
        specs = [replace(s, trusted=not sandbox) for s in specs]
    for spec in specs:
        if spec.path is not None:
            check_source(spec.path)
    if foxglove is not None:
        from turtletui.recording.foxglove import parse_address

        parse_address(foxglove)  # a bad address is a ValueError before anything starts
        realtime = True  # a live view of a run that ends in a blink shows nothing
    distro, distro_note = choose_distro(distro, None, (spec.path for spec in specs if spec.path is not None))
    logs: list[LogRecord] = []
    sinks = [logs.append] if on_log is None else [logs.append, on_log]
    may_replicate = len(specs) == 1 and not specs[0].trusted and not realtime
    world_before = replica.snapshot_world(world) if may_replicate else ""
    sim = Simulation(world=world, realtime=realtime, log_sinks=sinks, distro=distro)
    built_version = sim.graph.version
    if distro_note is not None:
        sim.graph.log("turtletui", INFO, distro_note)
    if setup is not None:
        setup(sim)
    calls: list[tuple[float, str, Any, Any]] = []
    poses: dict[str, list[tuple[float, float, float, float]]] = {}

    def tap(kind: str, payload: Any) -> None:
        if kind == "service":
            calls.append((sim.t, *payload))
        elif kind == "topic" and keep_poses and payload[0].name.endswith("/pose"):
            topic, msg = payload
            name = topic.name[1:-5]
            if sim.turtlesim.published(name, msg):
                poses.setdefault(name, []).append((sim.t, msg.x, msg.y, msg.theta))

    if keep_poses or keep_calls:
        sim.graph.taps.append(tap)
    # turtlesim's start lines were logged before the recorder existed
    with run_outputs(sim, record, foxglove, earlier_logs=list(logs)):
        end_ns = int(round(duration * NS_PER_S))
        recipe = replica.recipe_for(
            sim,
            specs,
            world=world_before,
            setup=setup,
            graph_version=built_version,
            end_ns=end_ns,
            lockstep=None if limits is None else limits.lockstep,
        )
        started = time.perf_counter()
        outcome = run_controllers(sim, specs, end_ns, ros_args=args, seed=seed, limits=limits, recipe=recipe)
    wall = time.perf_counter() - started
    turtles = {
        name: TurtleSummary(t.x, t.y, t.theta, t.distance, t.wall_hits, t.obstacle_hits)
        for name, t in sim.world.turtles.items()
    }
    return RunResult(sim.t, wall, turtles, logs, outcome.crashes, calls, poses, outcome.interrupted)


__all__ = [
    "ControllerError",
    "ControllerSpec",
    "RosArgsError",
    "RunResult",
    "Simulation",
    "TurtletuiError",
    "UsageError",
    "run",
]
