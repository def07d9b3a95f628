"""Checks of how the turtle moves: coverage, speed, distance, time moving,
commands per pose, circles, goals and headings."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
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
    turtle_of,
)
from turtletui.grading.trace import Trace
from turtletui.messages import plural


@check(
    "coverage",
    "Fraction of the arena's cells (1 m squares by default) the turtle drove through.",
    {**MINMAX, **TURTLE, "cell": "number"},
)
def coverage(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    cell = float(th.get("cell", 1.0))
    cells = max(1, int(trace.arena_size // cell))  # the last sliver joins the last cell
    if poses.size == 0:
        return Verdict(False, "the turtle never published a pose")
    ix = np.clip((poses[:, 1] / cell).astype(int), 0, cells - 1)
    iy = np.clip((poses[:, 2] / cell).astype(int), 0, cells - 1)
    visited = len(set(zip(ix.tolist(), iy.tolist(), strict=True)))
    verdict = _held(trace, measured("arena covered:", bounds(visited / (cells * cells), th)), turtle_of(th))
    return _circling(trace, verdict, turtle_of(th))


HELD_SHARE = 0.25
"""The share of a run a turtle may spend held back by a wall or an obstacle
before a failed distance or coverage says so."""


def held_back(trace: Trace, turtle: str) -> tuple[float, float | None, str]:
    """The share of the run the turtle spent driving into something that held
    it back (its speed says it drives, it moved less than half of that), since
    when it was held to the end (None if it got free), and what held it ("a
    wall" if it was at the arena's edge then, else "an obstacle")."""
    poses = trace.pose_array(turtle)
    if len(poses) < 2:
        return 0.0, None, "a wall"
    dt = np.diff(poses[:, 0])
    speed = np.abs(poses[1:, 4])
    moved = np.hypot(np.diff(poses[:, 1]), np.diff(poses[:, 2]))
    held = (speed > 1e-6) & (moved < 0.5 * speed * dt) & ~trace.jumped(turtle)[1:]
    share = float(held.mean())
    x, y = poses[1:, 1][held], poses[1:, 2][held]
    edge = 1e-6
    at_wall = (x <= edge) | (x >= trace.arena_size - edge) | (y <= edge) | (y >= trace.arena_size - edge)
    what = "a wall" if at_wall.any() or not len(x) else "an obstacle"
    if not held[-1]:
        return share, None, what
    free = np.flatnonzero(~held)
    since = float(poses[free[-1] + 1, 0]) if len(free) else float(poses[0, 0])
    return share, since, what


def _held(trace: Trace, verdict: Verdict, turtle: str) -> Verdict:
    """A failed verdict of a turtle that spent much of its run pushing against
    a wall or an obstacle, told so: the node drove on (it did not "hardly
    drive"), and the command that should have turned it away never came."""
    if verdict.passed:
        return verdict
    share, since, what = held_back(trace, turtle)
    if share < HELD_SHARE:
        return verdict
    when = f"from t={since:.1f} s to the end" if since is not None else f"for {share:.0%} of the run"
    note = (
        f"; {when} the turtle was pushing against {what}: it drove into it and its "
        "commands kept driving it forward (did the condition that should turn it away ever hold?)"
    )
    return replace(verdict, measured=verdict.measured + note)


CIRCLE_SPAN = 2.5
"""Metres across (x and y) within which a turtle that keeps turning one way is going round in circles."""
CIRCLE_DRIFT = 0.25
"""Metres a circle may drift (turtlesim's steps do not close it exactly) and still be the same circle."""
CIRCLE_TURNS = 2.0
"""Full turns one way, at least, that make a stretch of a run going round in circles."""


def circling(trace: Trace, turtle: str) -> tuple[float, float, float, float] | None:
    """When the turtle ended its run going round in circles (turning one way
    round a circle :data:`CIRCLE_DRIFT` to :data:`CIRCLE_SPAN` metres across,
    :data:`CIRCLE_TURNS` turns or more, for :data:`HELD_SHARE` of the run or
    more): since when, the centre (x, y) and how many metres across; else None."""
    poses = trace.pose_array(turtle)
    if len(poses) < 3 or trace.jumped(turtle).any():
        return None
    x, y = poses[:, 1], poses[:, 2]
    span = np.maximum(
        np.maximum.accumulate(x[::-1])[::-1] - np.minimum.accumulate(x[::-1])[::-1],
        np.maximum.accumulate(y[::-1])[::-1] - np.minimum.accumulate(y[::-1])[::-1],
    )
    # the last full turn gives the circle's size; it began where the path first stayed that close
    heading = np.unwrap(poses[:, 3])
    whole = np.flatnonzero(np.abs(heading - heading[-1]) >= math.tau)
    across = float(span[whole[-1]]) if len(whole) else 0.0
    if not CIRCLE_DRIFT <= across <= CIRCLE_SPAN:  # (a turn on the spot is no circle)
        return None
    first = int(np.argmax(span <= across + CIRCLE_DRIFT))  # the spans shrink towards the end
    times = poses[:, 0]
    if times[-1] - times[first] < HELD_SHARE * (times[-1] - times[0]):
        return None
    tail = poses[first:]
    steps = np.diff(heading[first:])
    turned = float(steps.sum())
    one_way = (steps * math.copysign(1.0, turned) >= -TURN_NOISE).all()
    if abs(turned) < CIRCLE_TURNS * math.tau or not one_way:
        return None
    return float(times[first]), float(tail[:, 1].mean()), float(tail[:, 2].mean()), across


def _circling(trace: Trace, verdict: Verdict, turtle: str) -> Verdict:
    """A failed verdict of a turtle that ended its run going round in
    circles, told so: the turn that should have ended (back on course, away
    from a wall) never did, and "it stayed in a small part" alone does not
    say that it drove off well and was caught later."""
    if verdict.passed:
        return verdict
    found = circling(trace, turtle)
    if found is None:
        return verdict
    since, cx, cy, across = found
    note = (
        f"; from t={since:.1f} s to the end the turtle went round and round in circles {across:.1f} m across "
        f"at ({cx:.1f}, {cy:.1f}), turning one way all the time: the turn it began there never ended "
        "(did the condition that ends it ever hold again?)"
    )
    return replace(verdict, measured=verdict.measured + note)


def _distance(trace: Trace, turtle: str) -> float:
    """Metres driven: teleports and resets move the turtle without driving it."""
    poses = trace.pose_array(turtle)
    if len(poses) < 2:
        return 0.0
    steps = np.hypot(np.diff(poses[:, 1]), np.diff(poses[:, 2]))
    return float(steps[~trace.jumped(turtle)[1:]].sum())


@check("mean_speed", "Mean forward speed over the run, in m/s.", {**MINMAX, **TURTLE})
def mean_speed(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    if len(poses) < 2:
        return Verdict(False, "the turtle never moved")
    speed = _distance(trace, turtle_of(th)) / (poses[-1, 0] - poses[0, 0])
    return measured("mean speed:", bounds(speed, th, " m/s"))


def _unheard(trace: Trace, verdict: Verdict, turtle: str, moved: bool) -> Verdict:
    """A failed verdict of a turtle that did not move and that no command
    reached, told so: a node publishing on a misspelt topic (/turtle/cmd_vel)
    raises no error, and "it barely moved" alone sends the student looking at
    their numbers."""
    if verdict.passed or moved or len(trace.command_array(turtle)):
        return verdict
    topic = f"/{turtle}/cmd_vel"
    made = trace.publishers_made.get(topic, 0)
    if made > 1:
        # a publisher per message: each is discovered too late for its one message
        note = (
            f"; nothing reached turtlesim on {topic}: your node created {made} publishers on it, a new one "
            "for each message, and a publisher made just before it publishes is not yet matched with "
            "turtlesim's subscription (DDS discovery takes a moment), so its message is lost: create the "
            "publisher once, in __init__, and publish through that one"
        )
    elif made:
        # the right publisher, never used: the code that publishes never ran
        note = (
            f"; nothing was published on {topic}: your node has a publisher on it but never published "
            "(does the timer or callback that publishes ever run?)"
        )
    else:
        note = f"; nothing was published on {topic} (is that the topic your node publishes on?)"
    return replace(verdict, measured=verdict.measured + note)


@check("distance", "Metres the turtle drove.", {**MINMAX, **TURTLE})
def distance(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    turtle = turtle_of(th)
    driven = _distance(trace, turtle)
    verdict = _held(trace, measured("distance driven:", bounds(driven, th, " m")), turtle)
    return _unheard(trace, verdict, turtle, driven > 0.0)


@check(
    "time_moving",
    "Fraction of the run the turtle was moving, thresholds min and max (0..1): turtlesim stops "
    "a turtle 1 s after its last velocity command. Turning in place counts as moving unless "
    "`turning` is false.",
    {**MINMAX, **TURTLE, "turning": "boolean"},
)
def time_moving(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    if len(poses) < 2:
        return Verdict(False, "the turtle never published a pose")
    # the pose's linear_velocity stays up while a wall holds the turtle back:
    # that is still a driving turtle; a turn in place shows in theta
    moving = poses[1:, 4] > 1e-6
    if th.get("turning", True):
        moving |= np.abs(np.diff(np.unwrap(poses[:, 3]))) > 1e-6
    share = float(moving.mean())
    verdict = bounds(share, th)
    wanted = []
    if "min" in th:
        wanted.append(f">= {th['min']:.0%}")
    if "max" in th:
        wanted.append(f"<= {th['max']:.0%}")
    notes = [f"needs {' and '.join(wanted)}"] if wanted else []
    if not th.get("turning", True):
        notes.append("turning in place does not count")
    need = f" ({'; '.join(notes)})" if notes else ""
    what = "moving" if th.get("turning", True) else "driving"
    moved = bool((poses[:, 4] > 1e-6).any() or (np.diff(poses[:, 1:4], axis=0) != 0).any())  # or turned
    text = f"{what} {share:.0%} of the run{need}"
    if not verdict.passed:
        text += pauses(trace, turtle_of(th), turning=th.get("turning", True))
    return _unheard(trace, Verdict(verdict.passed, text), turtle_of(th), moved)


COMMAND_TIMEOUT = 1.0
"""Seconds after its last velocity command that turtlesim stops a turtle."""


def pauses(trace: Trace, turtle: str, *, turning: bool = True) -> str:
    """Why a turtle that was sent commands stood still, from when they came:
    the commands that move it stopped (a stop sent, or nothing more), or came
    further apart than turtlesim's 1 s timeout (a slow timer, a callback that
    sleeps). "" when neither."""
    commands = trace.command_array(turtle)
    if not len(commands):
        return ""
    moves = (commands[:, 1] != 0) | (commands[:, 2] != 0)
    if turning:
        moves |= commands[:, 3] != 0
    times = commands[moves, 0]
    if not len(times):
        return "; every velocity command the node sent was a stop (all zeros)"
    end = max(trace.sim_time, float(times[-1]))
    if end - times[-1] > COMMAND_TIMEOUT and end - times[-1] >= 0.2 * end:
        later = int((commands[:, 0] > times[-1]).sum())
        after = f" (the {plural(later, 'command')} after it stopped the turtle)" if later else ""
        return f"; the last velocity command that moves the turtle came at t={times[-1]:.1f} s of {end:.0f} s{after}"
    gaps = np.diff(times)
    if len(gaps) and gaps.max() > COMMAND_TIMEOUT:
        return (
            f"; the commands came up to {gaps.max():.1f} s apart, and turtlesim stops a turtle "
            f"{COMMAND_TIMEOUT:g} s after the last one (a timer that slow, or a callback that sleeps, "
            "leaves it standing in between)"
        )
    return ""


@check(
    "commands_per_pose",
    "Velocity commands published per pose received: about 1 for a closed loop driven by the pose callback.",
    {**MINMAX, **TURTLE},
)
def commands_per_pose(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    turtle = turtle_of(th)
    poses = len(trace.pose_array(turtle))
    if poses == 0:
        return Verdict(False, "the turtle never published a pose")
    ratio = len(trace.command_array(turtle)) / poses
    return measured("commands per pose:", bounds(ratio, th))


@check(
    "closed_loop",
    "The velocity commands depend on where the turtle is, as a closed loop's do: from another "
    "start (a twin run of the same scenario and seed, the first `window` seconds, default 10) "
    "the node sends other commands. An open loop (a timer, or a pose callback that ignores "
    "the pose) sends the very same ones at the same times.",
    {**TURTLE, "window": "number"},
    twin=True,
)
def closed_loop(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    """A counterfactual test: would the commands have been different had the
    turtle been somewhere else? Runs are deterministic (same seed, same
    simulated times), so a controller whose commands do not depend on what it
    senses sends exactly the same stream from any start, and one that
    computes each command from the latest pose (in the pose callback, or in
    a timer that reads the pose the callback stored) does not. No threshold
    on gains, rates or shapes: any loop that follows the pose passes, any
    stream that does not fails, and the feedback says which it saw."""
    twin = trace.twin
    if twin is None:
        return Verdict(False, "not judged: no twin run to compare with", judged=False)
    turtle = turtle_of(th)
    end = twin.sim_time
    note = ""
    if twin.crashes:
        end = min(end, twin.crashes[0].t)
        note = f", until it crashed at t={end:.3f} s"
    mine = trace.command_array(turtle)
    other = twin.command_array(turtle)
    mine, other = mine[mine[:, 0] <= end], other[other[:, 0] <= end]
    topic = f"/{turtle}/cmd_vel"
    if len(mine) == 0 and len(other) == 0:
        return Verdict(False, f"no velocity commands on {topic} in the first {end:.0f} s")
    same = min(len(mine), len(other))
    differs = np.nonzero(np.any(mine[:same] != other[:same], axis=1))[0]
    if differs.size:
        t = float(mine[differs[0], 0])
    elif len(mine) != len(other):
        t = float((mine if len(mine) > same else other)[same, 0])
    else:
        x, y, _ = twin.start
        return Verdict(
            False,
            f"from another start (x={x:.2f}, y={y:.2f}) the node sent the same {len(mine)} commands on "
            f"{topic} at the same times{note}: they do not depend on where the turtle is or what it"
            f" senses (an open loop){_all_alike(mine)}",
        )
    return Verdict(True, f"the commands depend on where the turtle is: from another start they differed from t={t:.3f} s")


def _all_alike(commands: np.ndarray) -> str:
    """A note for an open loop whose commands were one Twist over and over: a
    node that reads the pose and always takes the same branch of its if."""
    if len(commands) < 2 or (commands[1:, 1:] != commands[0, 1:]).any():
        return ""
    linear, _, angular = commands[0, 1:].tolist()
    return (
        f"; every one was the same Twist (linear.x={linear:g}, angular.z={angular:g}): if the node "
        "compares the pose, that comparison came out the same on every pose"
    )


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
        **TURTLE,
        "min_radius": "number",
        "max_radius": "number",
        "max_error": "number",
        "min_laps": "number",
        "centre": "point",
        "centre_tolerance": "number",
    },
)
def circle(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    moving = poses[poses[:, 4] > 1e-6] if len(poses) else poses
    if len(moving) < 10:
        return _unheard(trace, Verdict(False, "the turtle barely moved: no circle to fit"), turtle_of(th), False)
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


_GOAL = {**TURTLE, "goal": "point", "tolerance": "number"}


def _goal_distances(trace: Trace, th: Mapping[str, Any]) -> tuple[np.ndarray, np.ndarray]:
    poses = trace.pose_array(turtle_of(th))
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
        text = f"never came within {tolerance} m of the goal (closest {closest})"
        return Verdict(False, text + _how_it_missed(trace, th, dists, tolerance))
    return measured("reached the goal after", bounds(float(times[inside[0]]), th, " s"))


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
    verdict = measured("distance from the goal at the end:", bounds(float(dists[-1]), th, " m"))
    if verdict.passed:
        return verdict
    return Verdict(False, verdict.measured + _how_it_missed(trace, th, dists, th["max"]))


BACKWARDS = 0.1
"""Share of the commands with a negative linear.x from which a missed goal says the turtle backed."""
STOPPED_SHORT = 1.0
"""Metres from the goal within which a node that stopped the turtle is told its tolerance is too wide
(further out, it was steering somewhere else)."""
SLOW_COMMANDS = 0.15
"""Seconds between commands (the median) from which a missed goal names the node's rate."""


def _how_it_missed(trace: Trace, th: Mapping[str, Any], dists: np.ndarray, tolerance: float) -> str:
    """What the commands say about a goal missed: the node drove the turtle
    backwards (linear.x from dx, or from a signed error), steered from stale
    poses (a callback that sleeps), or stopped it short on purpose (a stop
    tolerance wider than the check's). "" when none of these."""
    commands = trace.command_array(turtle_of(th))
    if not len(commands) or not dists.size:
        return ""
    notes = []
    backwards = float((commands[:, 1] < -1e-3).mean())
    if backwards >= BACKWARDS:
        notes.append(f"linear.x was negative in {backwards:.0%} of the commands: the turtle drove backwards")
    gaps = np.diff(commands[:, 0])
    if len(gaps) and float(np.median(gaps)) >= SLOW_COMMANDS:
        notes.append(
            f"your node sent a command only every {float(np.median(gaps)):.2f} s, while turtlesim sends "
            "62.5 poses a second: a slow timer, or a pose callback that sleeps and then steers from the "
            "old poses that queued up meanwhile, reacts late"
        )
    poses = trace.pose_array(turtle_of(th))
    end = poses[-1, 0]
    recent = poses[poses[:, 0] >= end - COMMAND_TIMEOUT]
    still = len(recent) > 1 and not (np.diff(recent[:, 1:3], axis=0) != 0).any()
    last = commands[commands[:, 0] >= end - COMMAND_TIMEOUT]
    stopping = len(last) > 0 and not last[:, 1:].any()
    driven = float(np.hypot(*np.diff(poses[:, 1:3], axis=0).T).sum())
    if still and stopping and driven > 2 * tolerance and dists[-1] > tolerance:
        if dists[-1] <= STOPPED_SHORT:
            notes.append(
                f"the turtle drove, then your node stopped it {dists[-1]:.2f} m from the goal with zero "
                f"Twists: it stops further out than {tolerance:g} m"
            )
        else:
            x, y = poses[-1, 1:3].tolist()
            notes.append(
                f"the turtle drove, then your node stopped it with zero Twists at ({x:.2f}, {y:.2f}), "
                f"{dists[-1]:.2f} m from the goal: does it steer to another goal?"
            )
    return "".join(f"; {note}" for note in notes)


@check(
    "heading_error",
    "Angle between the turtle's final heading and `theta` (radians), threshold max.",
    {**TURTLE, "theta": "number", "max": "number"},
    required=("theta", "max"),
)
def heading_error(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    if poses.size == 0:
        return Verdict(False, "the turtle never published a pose")
    error = abs(math.remainder(poses[-1, 3] - th["theta"], math.tau))
    return measured("final heading error:", bounds(error, th, " rad"))


TURN_NOISE = 1e-4
"""Radians per pose below which a change of heading is noise: it neither ends a turn nor adds to it."""


def longest_turn_of(trace: Trace, turtle: str, until: int | None = None, ends: Sequence[float] = ()) -> float:
    """The largest angle (radians) the turtle turned one way without turning
    back, over its poses up to the index ``until`` (all of them by default);
    a teleport or /reset ends a turn, as a turn the other way does, and so
    does each time in ``ends`` (the pose after it turns anew)."""
    poses = trace.pose_array(turtle)[:until]
    if len(poses) < 2:
        return 0.0
    steps = np.diff(np.unwrap(poses[:, 3]))
    restart = trace.jumped(turtle)[: len(poses)].copy()
    if len(ends):
        after = np.searchsorted(poses[:, 0], ends, side="right")
        restart[after[after < len(poses)]] = True
    longest = turn = 0.0
    for step, jump in zip(steps.tolist(), restart[1:].tolist(), strict=True):
        if jump:
            turn = 0.0
        elif abs(step) >= TURN_NOISE:
            turn = turn + step if turn * step >= 0 else step
            longest = max(longest, abs(turn))
    return longest


@check(
    "longest_turn",
    "The largest angle in radians the turtle turned one way without turning back (a teleport "
    "or /reset starts a new turn), threshold max; with `goal`, only until the turtle first came "
    "within `tolerance` (0.1 m) of it: a heading error wrapped into [-pi, pi] never turns it "
    "more than half a turn towards a goal, while circling a goal once there is final_error's to judge. "
    "With `service` (e.g. /kill), each call of it ends a turn, and the turning after the last "
    "call is not judged: one chase per target.",
    {**MINMAX, **_GOAL, "service": "text"},
)
def longest_turn(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    turtle = turtle_of(th)
    if len(trace.pose_array(turtle)) < 2:
        return Verdict(False, "the turtle never published a pose")
    until = None
    where = ""
    service = th.get("service")
    called = [call.t for call in trace.service_calls if call.service == service] if service else []
    if "goal" in th:
        _, dists = _goal_distances(trace, th)
        inside = np.nonzero(dists <= th.get("tolerance", 0.1))[0]
        if inside.size:
            until = int(inside[0]) + 1
            where = " on its way to the goal"
    elif service:
        if not called:
            return Verdict(True, f"no call of {service} ended a turn: nothing to judge")
        # the turning after the last call chases nothing the check knows of
        until = int(np.searchsorted(trace.pose_array(turtle)[:, 0], called[-1], side="right"))
        where = f" up to each call of {service}"
    turned = longest_turn_of(trace, turtle, until, called)
    verdict = bounds(turned, th, " rad")
    return Verdict(
        verdict.passed, f"longest turn one way{where}: {verdict.measured} ({turned / math.tau:.2f} of a full turn)"
    )
