"""The degenerate corpus: controllers that must not score on any lesson, and
each lesson's cheats and right alternatives (tests/lessons/corpus/).

- ``generic/`` holds degenerate controllers that work for every lesson (they
  drive /turtle1/cmd_vel and nothing else a lesson names). Their ROS
  parameters' defaults are their settings: :func:`generic_controllers`
  writes one file per entry of :data:`GENERIC`, defaults replaced, so the
  same file is a spin, a circle or a straight line.
- ``<lesson id>/cheat_*.py`` are that lesson's own shortcuts (teleport onto
  the goal, spawn prey next to turtle1, log constants...); ``right_*.py``
  are correct solutions written differently from the reference (other
  thresholds and gains, a timer using the latest pose, extra log lines,
  other names). A lesson without a folder of at least two right ones fails
  the corpus test: a new lesson is covered as soon as it is added.
"""

from __future__ import annotations

import re
from pathlib import Path

CORPUS = Path(__file__).parents[1] / "lessons" / "corpus"
GENERIC_FOLDER = CORPUS / "generic"

GENERIC: dict[str, tuple[str, dict[str, float]]] = {
    "idle": ("idle.py", {}),
    "spin from the pose callback": ("spin_pose.py", {"turn": 2.0}),
    "spin from a timer": ("timer_twist.py", {"linear": 0.0, "angular": 2.0}),
    "fixed circle": ("timer_twist.py", {"linear": 2.0, "angular": 1.0}),
    "straight ahead": ("timer_twist.py", {"linear": 2.0, "angular": 0.0}),
    "random velocities": ("random_velocities.py", {}),
    "teleport to the goal or centre": ("teleport.py", {}),
}
"""Name -> (file in generic/, parameter defaults to give it)."""

SOLVES: dict[str, set[str]] = {"part4-open-loop-circle": {"fixed circle"}}
"""Lesson id -> generic controllers that are that lesson's task (Part 4 asks
for a fixed circle): they must pass, not fail."""

SANDBOXED_MARK = "# corpus: sandboxed"
"""In a cheat: grade it sandboxed only (it chains service calls within one
simulated instant, which the sandbox bounds and the in-process host does not)."""

LEAST_RIGHT = 2
"""Right alternatives each lesson's corpus folder must hold."""


def with_defaults(source: str, params: dict[str, float]) -> str:
    """``source`` with each ``declare_parameter(name, default)`` of ``params`` given that default."""
    for name, value in params.items():
        source, found = re.subn(
            rf'declare_parameter\("{name}", [^)]+\)', f'declare_parameter("{name}", {value!r})', source
        )
        if found != 1:
            raise ValueError(f"no declare_parameter({name!r}, ...) to set")
    return source


def generic_controllers(folder: Path) -> dict[str, Path]:
    """Name -> a file in ``folder`` for every entry of :data:`GENERIC`."""
    paths = {}
    for name, (file, params) in GENERIC.items():
        stem = re.sub(r"\W+", "_", name)
        path = folder / f"{stem}.py"
        path.write_text(with_defaults((GENERIC_FOLDER / file).read_text(encoding="utf-8"), params), encoding="utf-8")
        paths[name] = path
    return paths


def lesson_files(lesson_id: str, kind: str) -> list[Path]:
    """The lesson's ``cheat`` or ``right`` files, in name order."""
    return sorted((CORPUS / lesson_id).glob(f"{kind}_*.py"))
