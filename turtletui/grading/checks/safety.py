"""Checks of safety: crashes, wall and obstacle hits, clearance."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import numpy as np

from turtletui.grading.checks.base import (
    MINMAX,
    TURTLE,
    Verdict,
    bounds,
    check,
    measured,
    number_text,
    turtle_of,
)
from turtletui.grading.trace import Trace
from turtletui.runtime.report import CrashReport

SHOWN_FRAMES = 3
"""Lines of the student's own file a crash shows (the innermost calls)."""


def crash_text(crash: CrashReport) -> str:
    """What happened, then the lines of the student's file it happened in."""
    return "\n".join([replace(crash, frames=[]).summary(), *crash.frames[-SHOWN_FRAMES:]])


@check("no_crash", "The controller ran the whole scenario without crashing or being stopped.", {})
def no_crash(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    if not trace.crashes:
        return Verdict(True, "ran to the end without crashing")
    return Verdict(False, "\n".join(crash_text(c) for c in trace.crashes))


@check("wall_hits", "Times a turtle ran into a wall (default: at most 0).", {**MINMAX, **TURTLE})
def wall_hits(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    hits = trace.wall_hits.get(turtle_of(th), 0)
    return measured("wall hits:", bounds(hits, th, default_max=0))


@check("obstacle_hits", "Times a turtle ran into an obstacle (default: at most 0).", {**MINMAX, **TURTLE})
def obstacle_hits(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    hits = trace.obstacle_hits.get(turtle_of(th), 0)
    return measured("obstacle hits:", bounds(hits, th, default_max=0))


def clearances(trace: Trace, turtle: str = "turtle1") -> np.ndarray:
    """Distance from the turtle to the nearest wall or obstacle at every pose."""
    poses = trace.pose_array(turtle)
    x, y = poses[:, 1], poses[:, 2]
    size = trace.arena_size
    gap = np.minimum(np.minimum(x, size - x), np.minimum(y, size - y))
    if trace.obstacles:
        from turtletui.sim.obstacles import nearest_distance

        to_obstacles = [nearest_distance(trace.obstacles, px, py) for px, py in zip(x.tolist(), y.tolist(), strict=True)]
        gap = np.minimum(gap, np.array(to_obstacles))
    return gap


@check(
    "min_clearance",
    "Closest the turtle came to a wall or an obstacle, in metres (threshold min).",
    {**MINMAX, **TURTLE},
    required=("min",),
)
def min_clearance(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    gaps = clearances(trace, turtle_of(th))
    if gaps.size == 0:
        return Verdict(False, "the turtle never published a pose")
    return measured("closest to a wall or obstacle:", bounds(float(gaps.min()), th, " m"))


@check(
    "coordinate_range",
    "Lowest and highest x or y the turtle reached, in metres: threshold min bounds the lowest, "
    "max the highest (a box it must keep within, give or take its turns).",
    {**MINMAX, **TURTLE},
)
def coordinate_range(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    if len(poses) == 0:
        return Verdict(False, "the turtle never published a pose")
    xy = poses[:, 1:3]
    lowest, highest = float(xy.min()), float(xy.max())
    verdicts = []
    if "min" in th:
        verdicts.append(measured("lowest x or y:", bounds(lowest, {"min": th["min"]}, " m")))
    if "max" in th:
        verdicts.append(measured("highest x or y:", bounds(highest, {"max": th["max"]}, " m")))
    if not verdicts:
        return Verdict(True, f"x and y between {number_text(lowest)} m and {number_text(highest)} m")
    return Verdict(all(v.passed for v in verdicts), "; ".join(v.measured for v in verdicts))
