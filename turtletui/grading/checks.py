"""The built-in checks: each turns a :class:`~turtletui.grading.trace.Trace`
into a :class:`Verdict` (passed or not, and what was measured).

A check judges behaviour, not one student's numbers: ``min_clearance`` asks
for room to spare from the walls, not for particular turn rates. A lesson
names checks in its ``[[checks]]`` tables with their ``thresholds``; every
threshold a built-in check takes is listed in its :class:`Check` ``params``,
so a misspelt one is an error when the lesson is prepared for grading.

Plugins add checks through ``turtletui_register_checks``: ``register(name,
function, description)`` where ``function(trace, thresholds) -> Verdict``
(or a ``(passed, message)`` pair, or a bool).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from turtletui.grading.trace import Trace
from turtletui.graph.logs import LEVEL_NAMES

CheckFunction = Callable[[Trace, Mapping[str, Any]], "Verdict"]


@dataclass(frozen=True)
class Verdict:
    """A check's judgement of one run."""

    passed: bool
    measured: str
    """What was measured and what was asked, e.g. ``closest to a wall 0.31 m (needs >= 0.5 m)``."""


@dataclass(frozen=True)
class Check:
    """A check the lessons can name."""

    name: str
    function: Callable[..., Any]
    description: str = ""
    params: Mapping[str, str] | None = None
    """Threshold name -> kind ("number", "integer", "text", "point", "colour",
    "pattern"); None when unknown (a plugin's check: thresholds are passed as given)."""
    required: tuple[str, ...] = ()

    def judge(self, trace: Trace, thresholds: Mapping[str, Any]) -> Verdict:
        """Run the check; a plugin's answer is normalised to a Verdict."""
        answer = self.function(trace, thresholds)
        if isinstance(answer, Verdict):
            return answer
        if isinstance(answer, bool):
            return Verdict(answer, "")
        if isinstance(answer, tuple) and len(answer) == 2:
            return Verdict(bool(answer[0]), str(answer[1]))
        raise TypeError(f"check {self.name!r} returned {type(answer).__name__}, not a Verdict")

    def problem(self, thresholds: Mapping[str, Any]) -> str | None:
        """Why these thresholds cannot be used, or None."""
        if self.params is None:
            return None
        for key in thresholds:
            if key not in self.params:
                known = ", ".join(self.params) or "none"
                return f"check {self.name!r} takes no threshold {key!r} (it takes: {known})"
        for key in self.required:
            if key not in thresholds:
                return f"check {self.name!r} needs the threshold {key!r}"
        for key, value in thresholds.items():
            reason = _kind_problem(self.params[key], value)
            if reason:
                return f"check {self.name!r}: threshold {key!r} {reason}, got {value!r}"
        return None


def _kind_problem(kind: str, value: Any) -> str | None:
    number = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    if kind == "number":
        return None if number else "must be a number"
    if kind == "integer":
        return None if isinstance(value, int) and not isinstance(value, bool) else "must be an integer"
    if kind == "text":
        return None if isinstance(value, str) and value else "must be a non-empty string"
    if kind == "pattern":
        if not isinstance(value, str):
            return "must be a regular expression string"
        try:
            re.compile(value)
        except re.error as err:
            return f"is not a valid regular expression ({err})"
        return None
    if kind == "numbers":
        ok = isinstance(value, list) and value and all(_kind_problem("number", v) is None for v in value)
        return None if ok else "must be a non-empty list of numbers"
    if kind == "point":
        ok = isinstance(value, list) and len(value) == 2 and all(_kind_problem("number", v) is None for v in value)
        return None if ok else "must be [x, y] in metres"
    if kind == "colour":
        ok = (
            isinstance(value, list)
            and len(value) == 3
            and all(isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= 255 for v in value)
        )
        return None if ok else "must be [r, g, b] with integers 0..255"
    raise ValueError(f"unknown threshold kind {kind!r}")


BUILTIN_CHECKS: dict[str, Check] = {}


def check(name: str, description: str, params: Mapping[str, str], required: tuple[str, ...] = ()):
    """Register a function as a built-in check."""

    def decorate(function: Callable[[Trace, Mapping[str, Any]], Verdict]) -> Callable[..., Verdict]:
        BUILTIN_CHECKS[name] = Check(name, function, description, dict(params), required)
        return function

    return decorate


# -- helpers ----------------------------------------------------------------------


def _bounds(value: float, th: Mapping[str, Any], unit: str = "", *, default_max: float | None = None) -> Verdict:
    """Judge ``value`` against the thresholds ``min`` and ``max``."""
    low = th.get("min")
    high = th.get("max", default_max)
    passed = (low is None or value >= low) and (high is None or value <= high)
    wanted = []
    if low is not None:
        wanted.append(f">= {_num(low)}{unit}")
    if high is not None:
        wanted.append(f"<= {_num(high)}{unit}")
    need = f" (needs {' and '.join(wanted)})" if wanted else ""
    return Verdict(passed, f"{_num(value)}{unit}{need}")


def _num(value: float) -> str:
    if isinstance(value, int) or float(value).is_integer():
        return str(int(value))
    return f"{value:.3g}" if abs(value) < 0.01 else f"{value:.2f}"


def _turtle(th: Mapping[str, Any]) -> str:
    return th.get("turtle", "turtle1")


def _measured(label: str, verdict: Verdict) -> Verdict:
    return Verdict(verdict.passed, f"{label} {verdict.measured}")


_MINMAX = {"min": "number", "max": "number"}
_TURTLE = {"turtle": "text"}


# -- safety -----------------------------------------------------------------------


@check("no_crash", "The controller ran the whole scenario without crashing or being stopped.", {})
def no_crash(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    if not trace.crashes:
        return Verdict(True, "ran to the end without crashing")
    return Verdict(False, "; ".join(c.summary() for c in trace.crashes))


@check("wall_hits", "Times a turtle ran into a wall (default: at most 0).", {**_MINMAX, **_TURTLE})
def wall_hits(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    hits = trace.wall_hits.get(_turtle(th), 0)
    return _measured("wall hits:", _bounds(hits, th, default_max=0))


@check("obstacle_hits", "Times a turtle ran into an obstacle (default: at most 0).", {**_MINMAX, **_TURTLE})
def obstacle_hits(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    hits = trace.obstacle_hits.get(_turtle(th), 0)
    return _measured("obstacle hits:", _bounds(hits, th, default_max=0))


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
    {**_MINMAX, **_TURTLE},
    required=("min",),
)
def min_clearance(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    gaps = clearances(trace, _turtle(th))
    if gaps.size == 0:
        return Verdict(False, "the turtle never published a pose")
    return _measured("closest to a wall or obstacle:", _bounds(float(gaps.min()), th, " m"))


# -- motion -----------------------------------------------------------------------


@check(
    "coverage",
    "Fraction of the arena's cells (1 m squares by default) the turtle drove through.",
    {**_MINMAX, **_TURTLE, "cell": "number"},
)
def coverage(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(_turtle(th))
    cell = float(th.get("cell", 1.0))
    cells = max(1, int(trace.arena_size // cell))  # the last sliver joins the last cell
    if poses.size == 0:
        return Verdict(False, "the turtle never published a pose")
    ix = np.clip((poses[:, 1] / cell).astype(int), 0, cells - 1)
    iy = np.clip((poses[:, 2] / cell).astype(int), 0, cells - 1)
    visited = len(set(zip(ix.tolist(), iy.tolist(), strict=True)))
    return _measured("arena covered:", _bounds(visited / (cells * cells), th))


def _distance(poses: np.ndarray) -> float:
    if len(poses) < 2:
        return 0.0
    return float(np.hypot(np.diff(poses[:, 1]), np.diff(poses[:, 2])).sum())


@check("mean_speed", "Mean forward speed over the run, in m/s.", {**_MINMAX, **_TURTLE})
def mean_speed(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(_turtle(th))
    if len(poses) < 2:
        return Verdict(False, "the turtle never moved")
    speed = _distance(poses) / (poses[-1, 0] - poses[0, 0])
    return _measured("mean speed:", _bounds(speed, th, " m/s"))


@check("distance", "Metres the turtle drove.", {**_MINMAX, **_TURTLE})
def distance(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    return _measured("distance driven:", _bounds(_distance(trace.pose_array(_turtle(th))), th, " m"))


@check(
    "time_moving",
    "Fraction of the run the turtle was moving (driving or turning), thresholds min and max "
    "(0..1): turtlesim stops a turtle 1 s after its last velocity command.",
    {**_MINMAX, **_TURTLE},
)
def time_moving(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(_turtle(th))
    if len(poses) < 2:
        return Verdict(False, "the turtle never published a pose")
    # the pose's linear_velocity stays up while a wall holds the turtle back:
    # that is still a driving turtle; a turn in place shows in theta
    turning = np.abs(np.diff(np.unwrap(poses[:, 3]))) > 1e-6
    moving = (poses[1:, 4] > 1e-6) | turning
    share = float(moving.mean())
    verdict = _bounds(share, th)
    wanted = []
    if "min" in th:
        wanted.append(f">= {th['min']:.0%}")
    if "max" in th:
        wanted.append(f"<= {th['max']:.0%}")
    need = f" (needs {' and '.join(wanted)})" if wanted else ""
    return Verdict(verdict.passed, f"moving {share:.0%} of the run{need}")


@check(
    "commands_per_pose",
    "Velocity commands published per pose received: about 1 for a closed loop driven by the pose callback.",
    {**_MINMAX, **_TURTLE},
)
def commands_per_pose(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    turtle = _turtle(th)
    poses = len(trace.pose_array(turtle))
    if poses == 0:
        return Verdict(False, "the turtle never published a pose")
    ratio = len(trace.command_array(turtle)) / poses
    return _measured("commands per pose:", _bounds(ratio, th))


def fit_circle(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float, float]:
    """Least-squares circle through the points (Kasa's method): cx, cy, radius
    and the RMS distance of the points from that circle."""
    a = np.column_stack([x, y, np.ones_like(x)])
    b = x * x + y * y
    (p, q, c), *_ = np.linalg.lstsq(a, b, rcond=None)
    cx, cy = p / 2.0, q / 2.0
    radius = math.sqrt(max(c + cx * cx + cy * cy, 0.0))
    rms = float(np.sqrt(np.mean((np.hypot(x - cx, y - cy) - radius) ** 2)))
    return float(cx), float(cy), radius, rms


@check(
    "circle",
    "The trajectory is a circle: radius between min_radius and max_radius, RMS error at most "
    "max_error metres, at least min_laps laps; optionally its centre near `centre`.",
    {
        **_TURTLE,
        "min_radius": "number",
        "max_radius": "number",
        "max_error": "number",
        "min_laps": "number",
        "centre": "point",
        "centre_tolerance": "number",
    },
)
def circle(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(_turtle(th))
    moving = poses[poses[:, 4] > 1e-6] if len(poses) else poses
    if len(moving) < 10:
        return Verdict(False, "the turtle barely moved: no circle to fit")
    x, y = moving[:, 1], moving[:, 2]
    cx, cy, radius, rms = fit_circle(x, y)
    angles = np.unwrap(np.arctan2(y - cy, x - cx))
    laps = abs(angles[-1] - angles[0]) / (2 * math.pi)
    problems = []
    if radius < th.get("min_radius", 0.0) or radius > th.get("max_radius", math.inf):
        problems.append(f"radius {radius:.2f} m outside {th.get('min_radius', 0)}..{th.get('max_radius', 'any')} m")
    if rms > th.get("max_error", 0.05):
        problems.append(f"not round: points stray {rms:.2f} m from the best circle (max {th.get('max_error', 0.05)} m)")
    if laps < th.get("min_laps", 1.0):
        problems.append(f"only {laps:.2f} laps (needs {th.get('min_laps', 1.0)})")
    if "centre" in th:
        want_x, want_y = th["centre"]
        off = math.hypot(cx - want_x, cy - want_y)
        if off > th.get("centre_tolerance", 0.2):
            problems.append(f"centre ({cx:.2f}, {cy:.2f}) is {off:.2f} m from ({want_x}, {want_y})")
    if radius > 2 * trace.arena_size:
        return Verdict(False, "the path is (nearly) straight: no circle")
    measured = f"circle of radius {radius:.2f} m around ({cx:.2f}, {cy:.2f}), {laps:.1f} laps, RMS error {rms:.3f} m"
    return Verdict(not problems, measured + (": " + "; ".join(problems) if problems else ""))


# -- goals ------------------------------------------------------------------------

_GOAL = {**_TURTLE, "goal": "point", "tolerance": "number"}


def _goal_distances(trace: Trace, th: Mapping[str, Any]) -> tuple[np.ndarray, np.ndarray]:
    poses = trace.pose_array(_turtle(th))
    gx, gy = th["goal"]
    return poses[:, 0], np.hypot(poses[:, 1] - gx, poses[:, 2] - gy)


@check(
    "time_to_goal",
    "Simulated seconds until the turtle is within `tolerance` metres of `goal` (threshold max).",
    {**_GOAL, "max": "number"},
    required=("goal",),
)
def time_to_goal(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    times, dists = _goal_distances(trace, th)
    tolerance = th.get("tolerance", 0.1)
    inside = np.nonzero(dists <= tolerance)[0]
    if inside.size == 0:
        closest = f"{dists.min():.2f} m" if dists.size else "never moved"
        return Verdict(False, f"never came within {tolerance} m of the goal (closest {closest})")
    return _measured("reached the goal after", _bounds(float(times[inside[0]]), th, " s"))


@check(
    "final_error",
    "Distance from `goal` at the end of the run, in metres (threshold max).",
    {**_GOAL, "max": "number"},
    required=("goal", "max"),
)
def final_error(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    _, dists = _goal_distances(trace, th)
    if dists.size == 0:
        return Verdict(False, "the turtle never published a pose")
    return _measured("distance from the goal at the end:", _bounds(float(dists[-1]), th, " m"))


@check(
    "heading_error",
    "Angle between the turtle's final heading and `theta` (radians), threshold max.",
    {**_TURTLE, "theta": "number", "max": "number"},
    required=("theta", "max"),
)
def heading_error(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(_turtle(th))
    if poses.size == 0:
        return Verdict(False, "the turtle never published a pose")
    error = abs(math.remainder(poses[-1, 3] - th["theta"], math.tau))
    return _measured("final heading error:", _bounds(error, th, " rad"))


# -- services, actions, turtles ------------------------------------------------------


@check(
    "service_calls",
    "Number of calls of `service` (e.g. /turtle1/set_pen), thresholds min and max.",
    {**_MINMAX, "service": "text"},
    required=("service",),
)
def service_calls(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    count = sum(1 for call in trace.service_calls if call.service == th["service"])
    return _measured(f"calls of {th['service']}:", _bounds(count, th))


def _side_changes(x: np.ndarray, split: float) -> int:
    sides = x > split
    return int(np.count_nonzero(sides[1:] != sides[:-1]))


@check(
    "calls_per_side_change",
    "Calls of `service` per crossing of the line x = `split_x`: a node that calls only when "
    "the side changes makes about one (threshold max, default 1).",
    {**_MINMAX, **_TURTLE, "service": "text", "split_x": "number"},
)
def calls_per_side_change(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    service = th.get("service", "/turtle1/set_pen")
    poses = trace.pose_array(_turtle(th))
    changes = _side_changes(poses[:, 1], th.get("split_x", 5.5)) if len(poses) else 0
    calls = sum(1 for call in trace.service_calls if call.service == service)
    # the first side is set once at the start, so one call more than crossings is fine
    ratio = calls / (changes + 1)
    verdict = _bounds(ratio, th, default_max=1.0)
    return Verdict(
        verdict.passed and calls > 0,
        f"{calls} calls of {service} for {changes} crossings of x = {th.get('split_x', 5.5)}:"
        f" {verdict.measured} per side change",
    )


@check(
    "pen_colour_by_side",
    "The pen draws one colour right of x = `split_x` and another left of it (`right` and "
    "`left` optionally name them); `min` is the fraction of poses that must agree (default 0.95).",
    {**_TURTLE, "split_x": "number", "margin": "number", "right": "colour", "left": "colour", "min": "number"},
)
def pen_colour_by_side(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(_turtle(th))
    split = th.get("split_x", 5.5)
    margin = th.get("margin", 0.3)  # a service answer takes a moment near the line
    need = th.get("min", 0.95)
    colours = poses[:, 5:8].astype(int) if len(poses) else np.empty((0, 3), int)
    found: dict[str, tuple[int, int, int]] = {}
    shares: dict[str, float] = {}
    for side, mask in (("right", poses[:, 1] > split + margin), ("left", poses[:, 1] < split - margin)):
        side_colours = [tuple(c) for c in colours[mask].tolist()] if len(poses) else []
        if not side_colours:
            return Verdict(False, f"the turtle never drove on the {side} side of x = {split}")
        wanted = tuple(th[side]) if side in th else max(set(side_colours), key=side_colours.count)
        found[side] = wanted
        shares[side] = side_colours.count(wanted) / len(side_colours)
    passed = all(share >= need for share in shares.values()) and found["right"] != found["left"]
    detail = ", ".join(f"{side} {found[side]} on {shares[side]:.0%} of poses" for side in ("right", "left"))
    if found["right"] == found["left"]:
        detail += ": the same colour on both sides"
    return Verdict(passed, f"pen colour {detail} (needs {need:.0%})")


@check(
    "goals_sent",
    "Number of goals sent to `action` (default /turtle1/rotate_absolute), thresholds min and max.",
    {**_MINMAX, "action": "text"},
)
def goals_sent(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    action = th.get("action", "/turtle1/rotate_absolute")
    count = sum(1 for goal in trace.goals if goal.action == action)
    return _measured(f"goals sent to {action}:", _bounds(count, th))


@check("turtles_spawned", "Turtles spawned during the run, thresholds min and max.", _MINMAX)
def turtles_spawned(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    return _measured("turtles spawned:", _bounds(len(trace.spawned), th))


@check("turtles_killed", "Turtles killed through /kill during the run, thresholds min and max.", _MINMAX)
def turtles_killed(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    return _measured("turtles killed:", _bounds(len(trace.killed), th))


# -- logs ---------------------------------------------------------------------------

_LOG = {"pattern": "pattern", "node": "text", "level": "text"}


def _matching_logs(trace: Trace, th: Mapping[str, Any]) -> list[Any]:
    pattern = re.compile(th.get("pattern", ""))
    node = th.get("node")
    level = th.get("level", "").upper()
    return [
        r
        for r in trace.logs
        if r.node != "turtlesim"
        and r.node != "turtletui"
        and (node is None or r.node == node.lstrip("/"))
        and (not level or r.level_name == level)
        and pattern.search(r.msg)
    ]


@check(
    "log_lines",
    "Log lines of the controller's nodes matching `pattern` (optionally from `node`, at `level`): "
    "thresholds min and max, or min_rate and max_rate in lines per simulated second.",
    {**_MINMAX, **_LOG, "min_rate": "number", "max_rate": "number"},
)
def log_lines(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    level = th.get("level", "").upper()
    if level and level not in LEVEL_NAMES.values():
        return Verdict(False, f"unknown log level {level!r}")
    lines = _matching_logs(trace, th)
    what = f"log lines matching {th['pattern']!r}" if "pattern" in th else "log lines"
    verdict = _bounds(len(lines), th)
    if "min_rate" in th or "max_rate" in th:
        rate = len(lines) / trace.sim_time if trace.sim_time > 0 else 0.0
        by_rate = _bounds(rate, {"min": th.get("min_rate"), "max": th.get("max_rate")}, " per s")
        return Verdict(verdict.passed and by_rate.passed, f"{what}: {len(lines)}, {by_rate.measured}")
    return _measured(f"{what}:", verdict)


@check(
    "log_counter",
    "The matching log lines carry a counter that goes up by one each line (at least `min` lines).",
    {**_LOG, "min": "number"},
)
def log_counter(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    numbers = []
    for record in _matching_logs(trace, th):
        found = re.search(r"-?\d+", record.msg)
        if found:
            numbers.append(int(found.group()))
    need = th.get("min", 3)
    if len(numbers) < need:
        return Verdict(False, f"{len(numbers)} log lines with a number (needs >= {_num(need)})")
    steps = [b - a for a, b in zip(numbers, numbers[1:], strict=False)]
    if any(step != 1 for step in steps):
        bad = next(i for i, step in enumerate(steps) if step != 1)
        return Verdict(False, f"the counter went from {numbers[bad]} to {numbers[bad + 1]}: it should go up by one")
    return Verdict(True, f"counter logged {len(numbers)} times, {numbers[0]} to {numbers[-1]}")


# -- rotate_absolute goals and chases (lessons beyond the series) ---------------------


def _angle_error(theta: np.ndarray | float, target: float) -> np.ndarray:
    """Absolute angle between headings and ``target``, in [0, pi] (wrapped)."""
    return np.abs(np.remainder(np.asarray(theta) - target + math.pi, math.tau) - math.pi)


@check(
    "goals_reached",
    "Share of the goals sent to `action` (default /turtle1/rotate_absolute) whose heading the "
    "turtle reached, within `tolerance` radians (default 0.05), before the next goal replaced "
    "it (threshold min, default 1).",
    {**_MINMAX, "action": "text", "tolerance": "number"},
)
def goals_reached(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    action = th.get("action", "/turtle1/rotate_absolute")
    turtle = action.strip("/").split("/")[0]
    tolerance = th.get("tolerance", 0.05)
    goals = [goal for goal in trace.goals if goal.action == action]
    if not goals:
        return Verdict(False, f"no goals sent to {action}")
    poses = trace.pose_array(turtle)
    reached = 0
    for i, goal in enumerate(goals):
        start = goal.t
        end = goals[i + 1].t if i + 1 < len(goals) else math.inf
        if end <= start:  # replaced at once: turtlesim aborts it before it starts
            continue
        window = poses[(poses[:, 0] >= start) & (poses[:, 0] <= end)] if len(poses) else poses
        if len(window) and _angle_error(window[:, 3], float(goal.goal.theta)).min() <= tolerance:
            reached += 1
    share = reached / len(goals)
    verdict = _bounds(share, {"min": th.get("min", 1.0), "max": th.get("max")})
    return Verdict(verdict.passed, f"{reached} of {len(goals)} goals reached: {verdict.measured}")


@check(
    "headings_faced",
    "The turtle stopped facing each of `headings` (radians, in this order) within `tolerance` "
    "radians (default 0.05); stopped means it did not turn or move between two poses.",
    {**_TURTLE, "headings": "numbers", "tolerance": "number"},
    required=("headings",),
)
def headings_faced(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    headings = th["headings"]
    tolerance = th.get("tolerance", 0.05)
    poses = trace.pose_array(_turtle(th))
    if len(poses) < 2:
        return Verdict(False, "the turtle never published a pose")
    still = (np.abs(np.diff(poses[:, 3])) < 1e-6) & (poses[1:, 4] < 1e-6)
    stops = poses[1:][still][:, 3]
    # the headings it stopped at, once per stop (a long stop is many poses)
    stopped: list[float] = []
    for theta in stops.tolist():
        if not stopped or _angle_error(theta, stopped[-1]) > tolerance:
            stopped.append(theta)
    shown = ", ".join(f"{h:.2f}" for h in stopped[:8]) + (", ..." if len(stopped) > 8 else "")
    position = 0
    for heading in headings:
        while position < len(stopped) and _angle_error(stopped[position], heading) > tolerance:
            position += 1
        if position == len(stopped):
            where = f"stopped at {shown} rad" if stopped else "never stopped"
            return Verdict(False, f"never stopped facing {heading:.2f} rad after the headings before it ({where})")
        position += 1
    wanted = ", ".join(f"{h:.2f}" for h in headings)
    return Verdict(True, f"stopped facing {wanted} rad in this order (stopped at {shown} rad)")


@check(
    "turtles_caught",
    "Turtles killed through /kill while the chasing `turtle` (default turtle1) was within "
    "`radius` metres of them (default 1.0); a kill of a turtle that does not exist or is far "
    "away does not count (thresholds min and max).",
    {**_MINMAX, **_TURTLE, "radius": "number"},
)
def turtles_caught(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    chaser = _turtle(th)
    radius = th.get("radius", 1.0)
    hunter = trace.pose_array(chaser)
    caught = missing = far = 0
    notes = []
    killed_at: dict[str, float] = {}
    for call in trace.service_calls:
        if call.service != "/kill":
            continue
        name = call.request.name
        if name == chaser:
            notes.append(f"killed the chaser {chaser} itself")
            continue
        target = trace.pose_array(name)
        before = target[target[:, 0] <= call.t] if len(target) else target
        # alive: it published a pose in the last few ticks and was not killed since
        if (
            len(before) == 0
            or call.t - before[-1, 0] > 0.05
            or killed_at.get(name, -math.inf) >= before[-1, 0]
        ):
            missing += 1
            continue
        killed_at[name] = call.t
        near = hunter[hunter[:, 0] <= call.t] if len(hunter) else hunter
        if len(near) and math.hypot(near[-1, 1] - before[-1, 1], near[-1, 2] - before[-1, 2]) <= radius:
            caught += 1
        else:
            far += 1
    if missing:
        notes.append(f"{missing} kills of turtles that did not exist")
    if far:
        notes.append(f"{far} turtles killed from more than {_num(radius)} m away")
    verdict = _measured("turtles caught:", _bounds(caught, th))
    return Verdict(verdict.passed, verdict.measured + ("; " + "; ".join(notes) if notes else ""))
