"""A lesson as data: frozen dataclasses built by :mod:`turtletui.lessons.loader`."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

DEFAULT_START: dict[str, float] = {"x": 5.544445, "y": 5.544445, "theta": 0.0}
"""Where turtlesim spawns turtle1 (the centre of the 11.09 m arena), facing east."""


@dataclass(frozen=True)
class Scenario:
    """One run a lesson is tried in: where the turtle starts, for how long, with which seed."""

    name: str
    start: dict[str, float] | str = field(default_factory=lambda: dict(DEFAULT_START))
    """``x``, ``y`` (metres) and ``theta`` (radians) of turtle1 at the start, or
    ``"random"``: a start pose drawn from each run's seed by the scenario runner."""
    duration: float = 60.0
    """Simulated seconds."""
    seeds: tuple[int, ...] = (0,)
    """The scenario is run once per seed."""
    hidden: bool = False
    """Hidden scenarios are graded but not shown to the student beforehand."""
    world: str | None = None
    """A registered world's name; None means the lesson's world."""
    ros_args: tuple[str, ...] = ()
    """Arguments after ``--ros-args`` given to the controller (``-p speed:=2.0``)."""
    drive: tuple[float, float] | None = None
    """(linear.x m/s, angular.z rad/s) the scenario itself drives turtle1 with,
    as a person at turtle_teleop_key would, for lessons whose node only watches;
    None: only the controller moves the turtle."""
    teleport: tuple[float, float, float, float] | None = None
    """(at s, x m, y m, theta rad): at ``at`` simulated seconds someone teleports
    turtle1 there, as ``ros2 service call /turtle1/teleport_absolute`` from a
    terminal would, so that a node that planned its way once, from the start
    pose, loses it; None: nobody does."""

    @property
    def seed(self) -> int:
        """The first (usually the only) seed."""
        return self.seeds[0]


@dataclass(frozen=True)
class CheckSpec:
    """A check a lesson asks for, stored as data (the checks engine interprets it)."""

    name: str
    weight: float = 1.0
    feedback: str = ""
    label: str = ""
    """How results name it; the check's name when empty. Unique within a lesson."""
    thresholds: dict[str, Any] = field(default_factory=dict)
    scenarios: tuple[str, ...] = ()
    """Names of the scenarios it judges; empty means every scenario."""
    requires: tuple[str, ...] = ()
    """Checks (by label or name) that must pass in a run for this one to earn
    its points there: a gate, so that, say, ``wall_hits`` earns nothing while
    the turtle stands still."""
    line: int = 0
    """Line of its ``[[checks]]`` table in the lesson file (for error messages)."""

    def is_named(self, name: str) -> bool:
        """Whether ``name`` (in a ``requires`` list) means this check: its label or its name."""
        return name in (self.label, self.name)

    @property
    def title(self) -> str:
        """The label, or the check's name."""
        return self.label or self.name


@dataclass(frozen=True)
class ArenaOverlay:
    """A rectangle the app draws on the arena while the lesson is open (a dotted
    outline, e.g. Part 6's safe box), in metres."""

    x0: float
    y0: float
    x1: float
    y1: float
    color: tuple[int, int, int] | None = None
    """RGB of the outline; None: the app's overlay colour (orange)."""


@dataclass(frozen=True)
class Lesson:
    """A lesson file, parsed and validated."""

    id: str
    title: str
    path: Path
    """The lesson's Markdown file."""
    body: str
    """The Markdown after the front matter block."""
    part: int | None = None
    """Course part number; None for lessons beyond the series."""
    objectives: tuple[str, ...] = ()
    starter: str | None = None
    """File name of the starter code, relative to the lesson file."""
    executable: str | None = None
    """The console_scripts executable graded in a ROS package submission when
    it has several (``turtle_controller``), as ``ros2 run PKG NAME`` names it."""
    reference: str | None = None
    """Name of a registered controller that solves the lesson."""
    world: str = "empty"
    time_limit: float | None = None
    """Wall-clock seconds all the runs of one submission may take together
    when graded; None: turtletui's default (turtletui.grading.batch)."""
    distro: str | None = None
    """The ROS 2 distro the lesson's code is written for (``jazzy``: ``turtlesim.msg``);
    None: the run's default (turtletui.compat.distro)."""
    scenarios: tuple[Scenario, ...] = ()
    checks: tuple[CheckSpec, ...] = ()
    overlays: tuple[ArenaOverlay, ...] = ()
    """Rectangles drawn on the arena while the lesson is open."""
    forbidden_services: tuple[str, ...] = ()
    """Services (shell-style patterns such as ``/*/teleport_absolute``) the
    controller must not call: a run in which it does fails every check."""

    @property
    def starter_path(self) -> Path | None:
        """The starter file next to the lesson, or None when the lesson has none."""
        return None if self.starter is None else self.path.parent / self.starter
