"""What the grader keeps of a run: the trusted simulation's own record of it.

A :class:`TraceCollector` taps the graph of the grader's simulation while a
scenario runs; :meth:`TraceCollector.finish` returns a :class:`Trace`, the
input of every check. Nothing in it comes from the controller's process
except what the controller published and called, as on a real robot.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from turtletui.graph.logs import LogRecord
from turtletui.runtime.report import CrashReport
from turtletui.runtime.simulation import Simulation
from turtletui.sim.constants import ARENA_SIZE

POSE_COLUMNS = ("t", "x", "y", "theta", "speed", "r", "g", "b", "pen_off")
"""Columns of :attr:`Trace.poses` arrays, one row per pose turtlesim published."""
JUMPING_SERVICES = ("teleport_absolute", "teleport_relative")
"""A turtle's own services that move it without driving (and /reset moves them all)."""


@dataclass(frozen=True)
class ServiceCall:
    """A call some node made and the answer it got."""

    t: float
    service: str
    request: Any
    response: Any


@dataclass(frozen=True)
class GoalSent:
    """An action goal a node sent."""

    t: float
    action: str
    goal: Any


@dataclass
class Trace:
    """Everything the checks judge, from one scenario run."""

    scenario: str
    seed: int
    duration: float
    """Simulated seconds the run was asked to last."""
    start: tuple[float, float, float]
    """turtle1's start pose (x, y, theta)."""
    poses: dict[str, np.ndarray] = field(default_factory=dict)
    """Per turtle, an (n, 9) float array of :data:`POSE_COLUMNS`."""
    jumps: dict[str, np.ndarray] = field(default_factory=dict)
    """Per turtle, a bool per pose row: a teleport or /reset moved it there
    since the pose before (it did not drive that step)."""
    commands: dict[str, np.ndarray] = field(default_factory=dict)
    """Per turtle, an (n, 4) array of (t, linear.x, linear.y, angular.z) of every
    Twist a controller published on its cmd_vel."""
    service_calls: list[ServiceCall] = field(default_factory=list)
    goals: list[GoalSent] = field(default_factory=list)
    logs: list[LogRecord] = field(default_factory=list)
    crashes: list[CrashReport] = field(default_factory=list)
    wall_hits: dict[str, int] = field(default_factory=dict)
    obstacle_hits: dict[str, int] = field(default_factory=dict)
    spawned: list[str] = field(default_factory=list)
    """Turtles a /spawn call created, in order."""
    killed: list[str] = field(default_factory=list)
    """Turtles a /kill call removed, in order (failed calls are not kills)."""
    obstacles: tuple[Any, ...] = ()
    """The world's obstacles (turtletui.sim.obstacles shapes)."""
    arena_size: float = ARENA_SIZE
    sim_time: float = 0.0
    """Simulated seconds the run actually lasted."""
    publishers_made: dict[str, int] = field(default_factory=dict)
    """Twist topic -> publishers the controller's nodes created on it during
    the run, whether or not they published (a silent turtle's node may have
    the right publisher and never use it); more than one is a node that makes
    a publisher per message."""
    twin: Trace | None = None
    """The twin run, for checks that compare with one
    (:attr:`turtletui.grading.checks.Check.twin`): the same scenario and seed
    from another start, usually shorter; None when no check asked for it."""

    def pose_array(self, turtle: str = "turtle1") -> np.ndarray:
        """The turtle's pose rows; an empty (0, 9) array when it never moved."""
        return self.poses.get(turtle, np.empty((0, len(POSE_COLUMNS))))

    def jumped(self, turtle: str = "turtle1") -> np.ndarray:
        """Which of the turtle's poses a teleport or /reset put it at (see :attr:`jumps`)."""
        jumps = self.jumps.get(turtle)
        return jumps if jumps is not None else np.zeros(len(self.pose_array(turtle)), dtype=bool)

    def command_array(self, turtle: str = "turtle1") -> np.ndarray:
        return self.commands.get(turtle, np.empty((0, 4)))


_TWIST = "geometry_msgs/msg/Twist"
"""What turtlesim's cmd_vel carries: the commands a trace keeps."""
_NOT_CONTROLLERS = frozenset({"sim", "scenario"})
"""Owners of the graph's endpoints that are not the controller's: the
simulator's own nodes and a scenario's scripted teleop."""


def controller_twist_publishers(sim: Simulation) -> dict[str, int]:
    """Twist topic -> publishers a controller's nodes created on it during the run."""
    made = {}
    for topic in sim.graph.channels():
        if topic.type_name == _TWIST:
            count = sum(n for owner, n in topic.publishers_made.items() if owner not in _NOT_CONTROLLERS)
            if count:
                made[topic.name] = count
    return made


class TraceCollector:
    """Taps a simulation's graph and builds the :class:`Trace` of the run."""

    def __init__(
        self, sim: Simulation, *, scenario: str, seed: int, duration: float, scripted: Any = None
    ) -> None:
        """``scripted``: a Twist object the scenario itself publishes (it is not the controller's)."""
        self.sim = sim
        self._scripted = scripted
        self._jumped: set[str] = set()
        self._jumps: dict[str, list[int]] = {}
        self._poses: dict[str, list[tuple[float, ...]]] = {}
        self._commands: dict[str, list[tuple[float, float, float, float]]] = {}
        self._calls: list[ServiceCall] = []
        self._goals: list[GoalSent] = []
        self._alive = set(sim.world.turtles)
        self._spawned: list[str] = []
        self._killed: list[str] = []
        start = sim.world.turtles.get("turtle1")
        self._start = (start.x, start.y, start.theta) if start else (0.0, 0.0, 0.0)
        self._meta = (scenario, seed, duration)
        sim.graph.taps.append(self._tap)

    def _tap(self, kind: str, payload: Any) -> None:
        if kind == "topic":
            topic, msg = payload
            name = topic.name
            if name.endswith("/pose"):
                self._pose(name[1:-5], msg)
            elif name.endswith("/cmd_vel") and topic.type_name == _TWIST and msg is not self._scripted:
                # (a TwistStamped on cmd_vel reaches no turtle: endpoints of other types never match)
                turtle = name[1:-8]
                self._commands.setdefault(turtle, []).append(
                    (self.sim.t, msg.linear.x, msg.linear.y, msg.angular.z)
                )
        elif kind == "service":
            name, request, response = payload
            self._calls.append(ServiceCall(self.sim.t, name, request, response))
            if name == "/reset":
                self._jumped.update(self.sim.world.turtles)
            elif name.rsplit("/", 1)[-1] in JUMPING_SERVICES:
                self._jumped.add(name.strip("/").split("/")[0])
            # answered after the request took effect: a kill that worked leaves
            # no turtle of that name, a spawn that worked answers its name
            if name == "/kill" and request.name in self._alive and request.name not in self.sim.world.turtles:
                self._alive.discard(request.name)
                self._killed.append(request.name)
            elif name == "/spawn" and response.name:
                self._alive.add(response.name)
                self._spawned.append(response.name)
        elif kind == "goal":
            name, goal = payload
            self._goals.append(GoalSent(self.sim.t, name, goal))

    def teleported(self, turtle: str) -> None:
        """``turtle`` jumped without a service call (a scenario's teleport): its
        next pose is marked as a teleport's."""
        self._jumped.add(turtle)

    def _pose(self, name: str, msg: Any) -> None:
        if not self.sim.turtlesim.published(name, msg):
            return
        turtle = self.sim.world.turtles[name]
        r, g, b = turtle.pen_color
        self._poses.setdefault(name, []).append(
            (self.sim.t, turtle.x, turtle.y, turtle.theta, msg.linear_velocity, r, g, b, 0.0 if turtle.pen_on else 1.0)
        )
        if name in self._jumped:
            self._jumped.discard(name)
            self._jumps.setdefault(name, []).append(len(self._poses[name]) - 1)

    def finish(self, *, logs: list[LogRecord], crashes: list[CrashReport]) -> Trace:
        """Stop tapping and return the trace."""
        sim = self.sim
        if self._tap in sim.graph.taps:
            sim.graph.taps.remove(self._tap)
        scenario, seed, duration = self._meta
        width = len(POSE_COLUMNS)
        turtles = sim.world.turtles
        return Trace(
            scenario=scenario,
            seed=seed,
            duration=duration,
            start=self._start,
            poses={k: np.array(v, dtype=float).reshape(-1, width) for k, v in self._poses.items()},
            jumps={k: np.isin(np.arange(len(self._poses[k])), v) for k, v in self._jumps.items()},
            commands={k: np.array(v, dtype=float).reshape(-1, 4) for k, v in self._commands.items()},
            service_calls=self._calls,
            goals=self._goals,
            logs=list(logs),
            crashes=list(crashes),
            wall_hits={name: t.wall_hits for name, t in turtles.items()},
            obstacle_hits={name: getattr(t, "obstacle_hits", 0) for name, t in turtles.items()},
            spawned=self._spawned,
            killed=self._killed,
            obstacles=tuple(getattr(sim.world, "obstacles", ()) or ()),
            sim_time=sim.t,
            publishers_made=controller_twist_publishers(sim),
        )
