"""Checks of what a controller asks of turtlesim: service calls, pen colours,
action goals, spawned, killed and caught turtles."""

from __future__ import annotations

import math
from collections.abc import Mapping
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
from turtletui.grading.checks.motion import pauses
from turtletui.grading.trace import Trace
from turtletui.messages import plural


@check(
    "service_calls",
    "Number of calls of `service` (e.g. /turtle1/set_pen), thresholds min and max.",
    {**MINMAX, "service": "text"},
    required=("service",),
)
def service_calls(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    count = sum(1 for call in trace.service_calls if call.service == th["service"])
    return measured(f"calls of {th['service']}:", bounds(count, th))


def _side_changes(x: np.ndarray, split: float) -> int:
    sides = x > split
    return int(np.count_nonzero(sides[1:] != sides[:-1]))


@check(
    "calls_per_side_change",
    "Calls of `service` per crossing of the line x = `split_x`: a node that calls only when "
    "the side changes makes about one (threshold max, default 1).",
    {**MINMAX, **TURTLE, "service": "text", "split_x": "number"},
)
def calls_per_side_change(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    service = th.get("service", "/turtle1/set_pen")
    poses = trace.pose_array(turtle_of(th))
    changes = _side_changes(poses[:, 1], th.get("split_x", 5.5)) if len(poses) else 0
    calls = sum(1 for call in trace.service_calls if call.service == service)
    # the first side is set once at the start, so one call more than crossings is fine
    ratio = calls / (changes + 1)
    verdict = bounds(ratio, th, default_max=1.0)
    return Verdict(
        verdict.passed and calls > 0,
        f"{calls} calls of {service} for {changes} crossings of x = {th.get('split_x', 5.5)}:"
        f" {verdict.measured} per side change",
    )


@check(
    "pen_colour_by_side",
    "The pen draws one colour right of x = `split_x` and another left of it (`right` and "
    "`left` optionally name them); `min` is the fraction of the poses where the turtle moved "
    "(drew) that must agree (default 0.95), and the share of crossings of the line where the "
    "colour did not change `margin` m or more before it.",
    {**TURTLE, "split_x": "number", "margin": "number", "right": "colour", "left": "colour", "min": "number"},
)
def pen_colour_by_side(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    split = th.get("split_x", 5.5)
    margin = th.get("margin", 0.3)  # a service answer takes a moment near the line
    need = th.get("min", 0.95)
    # Only where it moved: a turtle standing still draws nothing, and one
    # waits at its start until the node has discovered turtlesim and set a pen.
    moved = np.zeros(len(poses), dtype=bool)
    moved[1:] = (np.diff(poses[:, 1:3], axis=0) != 0).any(axis=1)
    # nor with its pen off (set_pen's off = 1): turtlesim then keeps the old colour, undrawn
    pen_off = moved & (poses[:, 8] != 0)
    poses_off = poses[pen_off]
    poses = poses[moved & ~pen_off]
    colours = poses[:, 5:8].astype(int)
    found: dict[str, tuple[int, int, int]] = {}
    shares: dict[str, float] = {}
    for side, mask in (("right", poses[:, 1] > split + margin), ("left", poses[:, 1] < split - margin)):
        side_colours = [tuple(c) for c in colours[mask].tolist()]
        if not side_colours:
            off_there = poses_off[:, 1] > split + margin if side == "right" else poses_off[:, 1] < split - margin
            if off_there.any():
                return Verdict(
                    False, f"the pen was off wherever the turtle drove on the {side} side of x = {split}: "
                    "it drew nothing there (set_pen's off must be 0 to draw)"
                )
            stood = pauses(trace, turtle_of(th))
            return Verdict(False, f"the turtle never drove on the {side} side of x = {split}{stood}")
        wanted = tuple(th[side]) if side in th else max(set(side_colours), key=side_colours.count)
        found[side] = wanted
        shares[side] = side_colours.count(wanted) / len(side_colours)
    early, crossings = _early_crossings(poses[:, 1], colours, split, margin, found)
    passed = (
        all(share >= need for share in shares.values())
        and found["right"] != found["left"]
        and crossings - early >= need * crossings
    )
    detail = ", ".join(f"{side} {found[side]} on {shares[side]:.0%} of poses" for side in ("right", "left"))
    if found["right"] == found["left"]:
        detail += ": the same colour on both sides"
    else:
        detail += f"; changed colour {margin} m or more before reaching x = {split} at {early} of {crossings} crossings"
    text = f"pen colour {detail} (needs {need:.0%})"
    if not passed and found["right"] != found["left"]:
        text += _changed_at(poses[:, 1], colours, split)
    return Verdict(passed, text)


def _changed_at(x: np.ndarray, colours: np.ndarray, split: float) -> str:
    """Where the pen changed colour, for a student whose node changes it elsewhere
    than at the line (another number, pose.y for pose.x, a timer)."""
    changes = np.flatnonzero((colours[1:] != colours[:-1]).any(axis=1)) + 1
    if not len(changes):
        return ""
    shown = ", ".join(f"{value:.1f}" for value in x[changes[:5]].tolist())
    more = ", ..." if len(changes) > 5 else ""
    return f"; the pen changed colour at x = {shown}{more} (the line is x = {split})"


def _early_crossings(
    x: np.ndarray, colours: np.ndarray, split: float, margin: float, found: Mapping[str, tuple[int, int, int]]
) -> tuple[int, int]:
    """(early, all) crossings of x = ``split``: an early one already drew the new side's colour
    ``margin`` before the line. Whole-run shares hide a pen that changes at the wrong place
    (x = 5.0 for 5.5: on one way across it is late, which shares see only a little, and on
    the other it is early, which this sees at every crossing). A late colour is left to the
    shares: a service's answer takes a moment."""
    outside = np.flatnonzero(np.abs(x - split) > margin)
    early = crossings = 0
    for before, after in zip(outside[:-1].tolist(), outside[1:].tolist(), strict=True):
        if (x[before] > split) != (x[after] > split):
            crossings += 1
            early += tuple(colours[before]) == found["right" if x[after] > split else "left"]
    return early, crossings


@check(
    "goals_sent",
    "Number of goals sent to `action` (default /turtle1/rotate_absolute), thresholds min and max.",
    {**MINMAX, "action": "text"},
)
def goals_sent(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    action = th.get("action", "/turtle1/rotate_absolute")
    count = sum(1 for goal in trace.goals if goal.action == action)
    return measured(f"goals sent to {action}:", bounds(count, th))


@check("turtles_spawned", "Turtles spawned during the run, thresholds min and max.", MINMAX)
def turtles_spawned(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    return measured("turtles spawned:", bounds(len(trace.spawned), th))


@check("turtles_killed", "Turtles killed through /kill during the run, thresholds min and max.", MINMAX)
def turtles_killed(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    return measured("turtles killed:", bounds(len(trace.killed), th))


def _angle_error(theta: np.ndarray | float, target: float) -> np.ndarray:
    """Absolute angle between headings and ``target``, in [0, pi] (wrapped)."""
    return np.abs(np.remainder(np.asarray(theta) - target + math.pi, math.tau) - math.pi)


@check(
    "goals_reached",
    "Share of the goals sent to `action` (default /turtle1/rotate_absolute) whose heading the "
    "turtle reached, within `tolerance` radians (default 0.05), before the next goal replaced "
    "it (threshold min, default 1).",
    {**MINMAX, "action": "text", "tolerance": "number"},
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
    in_progress: list[tuple[float, float]] = []  # (from, until) each goal was reached or replaced
    for i, goal in enumerate(goals):
        start = goal.t
        end = goals[i + 1].t if i + 1 < len(goals) else math.inf
        if end <= start:  # replaced at once: turtlesim aborts it before it starts
            continue
        window = poses[(poses[:, 0] >= start) & (poses[:, 0] <= end)] if len(poses) else poses
        if len(window):
            near = _angle_error(window[:, 3], float(goal.goal.theta)) <= tolerance
            if near.any():
                reached += 1
                end = float(window[near.argmax(), 0])
        in_progress.append((start, end))
    share = reached / len(goals)
    verdict = bounds(share, {"min": th.get("min", 1.0), "max": th.get("max")})
    text = f"{reached} of {len(goals)} goals reached: {verdict.measured}"
    commands = trace.command_array(turtle)
    times = commands[:, 0] if len(commands) else commands
    during = sum(int(((times >= start) & (times < end)).sum()) for start, end in in_progress)
    if not verdict.passed and during:
        # turtlesim aborts a rotation on any cmd_vel message, a zero Twist too
        text += (
            f"; the node published {plural(during, 'velocity command')} on /{turtle}/cmd_vel while a goal "
            "was in progress, and any cmd_vel message aborts the goal in progress"
        )
    return Verdict(verdict.passed, text)


@check(
    "headings_faced",
    "The turtle stopped facing each of `headings` (radians, in this order) within `tolerance` "
    "radians (default 0.05); stopped means it did not turn or move between two poses.",
    {**TURTLE, "headings": "numbers", "tolerance": "number"},
    required=("headings",),
)
def headings_faced(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    headings = th["headings"]
    tolerance = th.get("tolerance", 0.05)
    poses = trace.pose_array(turtle_of(th))
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


TARGET_TOLERANCE = 0.05
"""Metres between a Spawn request's x, y and the target it stands for."""


@check(
    "turtles_caught",
    "Turtles killed through /kill while the chasing `turtle` (default turtle1) was within "
    "`radius` metres of them (default 1.0); a kill of a turtle that does not exist or is far "
    "away does not count. With `targets` ([x, y] points the scenario gives the node), only a "
    "turtle spawned on one of them counts, each target once, and the chaser must be within "
    "`radius` of that point: the scenario, not the node, decides where the prey are "
    "(thresholds min and max).",
    {**MINMAX, **TURTLE, "radius": "number", "targets": "points"},
)
def turtles_caught(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    chaser = turtle_of(th)
    radius = th.get("radius", 1.0)
    targets = [tuple(point) for point in th.get("targets", [])]
    left = list(targets)
    hunter = trace.pose_array(chaser)
    caught = missing = far = elsewhere = 0
    notes = []
    killed_at: dict[str, float] = {}
    spawned_at: dict[str, tuple[float, float]] = {}
    for call in trace.service_calls:
        if call.service == "/spawn" and call.response.name:
            spawned_at[call.response.name] = (call.request.x, call.request.y)
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
        prey = (before[-1, 1], before[-1, 2])
        if targets:
            spawn = spawned_at.get(name, (math.inf, math.inf))
            place = next((p for p in left if math.dist(p, spawn) <= TARGET_TOLERANCE), None)
            if place is None:
                elsewhere += 1
                continue
            prey = place
        near = hunter[hunter[:, 0] <= call.t] if len(hunter) else hunter
        if len(near) and math.hypot(near[-1, 1] - prey[0], near[-1, 2] - prey[1]) <= radius:
            caught += 1
            if targets:
                left.remove(prey)
        else:
            far += 1
    if missing:
        notes.append(f"{missing} kills of turtles that did not exist")
    if elsewhere:
        notes.append(f"{elsewhere} kills of turtles not spawned on a target the scenario gave (or caught already)")
    if far:
        notes.append(f"{far} turtles killed from more than {number_text(radius)} m away")
    verdict = measured("turtles caught:", bounds(caught, th))
    return Verdict(verdict.passed, verdict.measured + ("; " + "; ".join(notes) if notes else ""))
