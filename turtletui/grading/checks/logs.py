"""Checks of the controller's log lines."""

from __future__ import annotations

import math
import re
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
from turtletui.graph.logs import LEVEL_NAMES, PRINTED_SUFFIXES
from turtletui.messages import plural

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
    {**MINMAX, **_LOG, "min_rate": "number", "max_rate": "number"},
)
def log_lines(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    level = th.get("level", "").upper()
    if level and level not in LEVEL_NAMES.values():
        return Verdict(False, f"unknown log level {level!r}")
    lines = _matching_logs(trace, th)
    what = f"log lines matching {th['pattern']!r}" if "pattern" in th else "log lines"
    verdict = bounds(len(lines), th)
    if "min_rate" in th or "max_rate" in th:
        rate = len(lines) / trace.sim_time if trace.sim_time > 0 else 0.0
        by_rate = bounds(rate, {"min": th.get("min_rate"), "max": th.get("max_rate")}, " per s")
        return Verdict(verdict.passed and by_rate.passed, f"{what}: {len(lines)}, {by_rate.measured}")
    return measured(f"{what}:", verdict)


def _counter(pattern: re.Pattern[str], text: str) -> int | None:
    """The counter a log line carries: the pattern's first group if it has
    one, else the first integer from where the pattern matched on."""
    match = pattern.search(text)
    if match is None:
        return None
    found = re.search(r"-?\d+", match.group(1) if pattern.groups else text[match.start() :])
    return int(found.group()) if found else None


def _kind(text: str) -> str:
    """A log line's words with its numbers left out: "Hello 3" and "Hello 4"
    are lines of one kind, "uptime ms: 3000" of another."""
    return _NUMBER.sub("#", text)


def _counter_lines(trace: Trace, th: Mapping[str, Any]) -> list[Any]:
    """The matching lines log_counter and log_period judge: the lines of one
    kind, so that a node logging another line that ends with a number beside
    its counter ("uptime ms: 3000") is judged on its counter. Of the kinds, the
    one that counts up and comes one per period; else one that counts up (a
    burst of "Hello 0..9" beside a timer's "tick 1000" is judged as a burst);
    else one per period; else the one with the most lines."""
    kinds: dict[str, list[Any]] = {}
    for record in _matching_logs(trace, th):
        kinds.setdefault(_kind(record.msg), []).append(record)
    if not kinds:
        return []
    return max(
        kinds.values(),
        key=lambda lines: (_counts_up(lines, th).passed, _one_per_period(lines, th).passed, len(lines)),
    )


def _matching(th: Mapping[str, Any]) -> str:
    return f" matching {th['pattern']!r}" if "pattern" in th else ""


@check(
    "log_counter",
    "The matching log lines carry a counter that goes up by one each line (at least `min` lines); "
    "the counter is the first group of `pattern` (e.g. '(\\d+)\\W*$': the number that ends the "
    "line), or else the first integer from where the pattern matches. Lines of one kind are judged "
    "(the same words around the numbers): other lines with a number do not break the counter.",
    {**_LOG, "min": "number"},
)
def log_counter(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    return _counts_up(_counter_lines(trace, th), th)


def _counts_up(records: list[Any], th: Mapping[str, Any]) -> Verdict:
    pattern = re.compile(th.get("pattern", ""))
    numbers = []
    for record in records:
        number = _counter(pattern, record.msg)
        if number is not None:
            numbers.append(number)
    need = th.get("min", 3)
    if len(numbers) < need:
        return Verdict(False, f"{plural(len(numbers), 'log line')} with a number (needs >= {number_text(need)})")
    steps = [b - a for a, b in zip(numbers, numbers[1:], strict=False)]
    if any(step != 1 for step in steps):
        bad = next(i for i, step in enumerate(steps) if step != 1)
        return Verdict(False, f"the counter went from {numbers[bad]} to {numbers[bad + 1]}: it should go up by one")
    return Verdict(True, f"counter logged {len(numbers)} times, {numbers[0]} to {numbers[-1]}")


@check(
    "log_period",
    "The matching log lines come one per period, as a timer's do: at least `min` of them "
    "(default 3), every gap within `tolerance` (a fraction, default 0.1) of the median gap, "
    "which must lie between `min_period` and `max_period` seconds when given. Lines of one kind "
    "are judged, as by log_counter. With `in_callback = true` they must also come from "
    "callbacks the executor ran (a timer's), not from a loop outside spin (time.sleep in main()), "
    "each from a call of its own (not a loop inside one callback), "
    "and only the logger's lines count (a printed line cannot say where it was printed).",
    {**_LOG, "min": "number", "tolerance": "number", "min_period": "number", "max_period": "number",
     "in_callback": "boolean"},
)
def log_period(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    if th.get("in_callback"):
        # A printed line cannot say where it was printed (the sandbox reads it
        # from a pipe), so only the node's logger's lines are judged here.
        printed = [r for r in _matching_logs(trace, th) if r.node.endswith(PRINTED_SUFFIXES)]
        trace = replace(trace, logs=[r for r in trace.logs if not r.node.endswith(PRINTED_SUFFIXES)])
        verdict = _log_period(trace, th)
        if printed and not verdict.passed:
            return Verdict(
                False,
                f"{verdict.measured}; {plural(len(printed), 'printed line')} do not count: print() cannot "
                "say which callback printed it, log with self.get_logger().info(...)",
            )
        return _unmatched_callback_lines(trace, th, verdict)
    return _log_period(trace, th)


def _unmatched_callback_lines(trace: Trace, th: Mapping[str, Any], verdict: Verdict) -> Verdict:
    """``verdict``, and when too few lines matched, the line a callback logged
    most often that the pattern missed: a counter in mid-line ("Hello 3 from
    node"), or an f-string without its f ("Hello {self.counter_}")."""
    if verdict.passed or len(_counter_lines(trace, th)) >= max(th.get("min", 3), 2) or "pattern" not in th:
        return verdict
    pattern = re.compile(th["pattern"])
    missed: dict[str, int] = {}
    for record in trace.logs:
        if (
            record.in_callback
            and record.node not in ("turtlesim", "turtletui")
            and not record.node.endswith(PRINTED_SUFFIXES)
            and not pattern.search(record.msg)
        ):
            missed[record.msg] = missed.get(record.msg, 0) + 1
    kinds: dict[str, list[str]] = {}
    for msg, count in missed.items():
        kinds.setdefault(_kind(msg), []).extend([msg] * count)
    if not kinds:
        return verdict
    lines = max(kinds.values(), key=len)
    return Verdict(
        False,
        f"{verdict.measured}; {plural(len(lines), 'line')} logged from callbacks did not match it, "
        f"such as {lines[-1]!r}",
    )


def _log_period(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    lines = _counter_lines(trace, th)
    outside = [record for record in lines if not record.in_callback] if th.get("in_callback") else []
    if outside and len(lines) >= max(th.get("min", 3), 2):  # too few lines: that is said first
        return Verdict(
            False,
            f"{len(outside)} of the {plural(len(lines), 'log line')}{_matching(th)} were logged outside any "
            f"callback (the first at t={outside[0].t:.3f} s): from code the executor did not call, such as a "
            "loop that sleeps or calls spin_once between lines, not from a timer callback that rclpy.spin runs",
        )
    verdict = _one_per_period(lines, th)
    looped = _one_call(lines) if th.get("in_callback") else None
    if looped is not None and verdict.passed:
        return looped
    if outside and not verdict.passed:
        when = ", ".join(f"t={record.t:.3f} s" for record in outside[:3])
        return Verdict(
            False,
            f"{verdict.measured}, logged outside any callback ({when}): by code that runs once, such as "
            "__init__ or main(), not by a timer's callback",
        )
    return verdict


def _one_call(records: list[Any]) -> Verdict | None:
    """A failing verdict when one call of a callback logged several of the
    lines (a timer callback that loops and sleeps instead of returning: the
    timer fired once, and the executor is stuck in it); else None."""
    calls: dict[tuple[str, int], list[Any]] = {}
    for record in records:
        if record.call:  # numbered by each controller's host: with its logger, one call
            calls.setdefault((record.node, record.call), []).append(record)
    lines = max(calls.values(), key=len, default=[])
    if len(lines) < 2:
        return None
    return Verdict(
        False,
        f"{len(lines)} of the {plural(len(records), 'log line')} were logged by one call of a callback, from "
        f"t={lines[0].t:.3f} s to t={lines[-1].t:.3f} s: it loops (and sleeps) instead of returning, so the "
        "executor is stuck in it; a timer callback logs one line and returns, and the timer calls it again",
    )


def _one_per_period(records: list[Any], th: Mapping[str, Any]) -> Verdict:
    times = np.array([record.t for record in records], dtype=float)
    need = th.get("min", 3)
    if len(times) < max(need, 2):
        return Verdict(False, f"{plural(len(times), 'log line')}{_matching(th)} (needs >= {number_text(max(need, 2))})")
    what = f"log lines{_matching(th)}"
    gaps = np.diff(times)
    period = float(np.median(gaps))
    if period <= 0.0:
        return Verdict(False, f"{what} come in bursts: most of them at the same moment, not one per period")
    off = np.abs(gaps - period) > th.get("tolerance", 0.1) * period
    if off.any():
        first = int(np.nonzero(off)[0][0])
        return Verdict(
            False,
            f"{what} are not one per period: mostly {period:.3g} s apart, but {gaps[first]:.3g} s"
            f" between t={times[first]:.3f} s and t={times[first + 1]:.3f} s",
        )
    verdict = bounds(period, {"min": th.get("min_period"), "max": th.get("max_period")}, " s")
    return Verdict(verdict.passed, f"{len(times)} {what}, one every {verdict.measured}")


_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
POSE_TOLERANCE = 0.001
"""Metres: the least a logged coordinate may differ from the pose (float32
messages, and numbers printed with many digits)."""


def _logged_numbers(text: str) -> list[tuple[float, float]]:
    """(value, tolerance) of every number in a log line: a number matches what
    it printed to the digits it shows (5.5 stands for 5.45 to 5.55)."""
    numbers = []
    for match in _NUMBER.finditer(text):
        token = match.group()
        mantissa, _, exponent = token.lower().partition("e")
        decimals = len(mantissa.partition(".")[2])
        try:
            step = 10.0 ** (int(exponent or 0) - decimals)
        except OverflowError:
            continue  # 1e400: no coordinate, and no step a float can hold
        numbers.append((float(token), max(step / 2, POSE_TOLERANCE)))
    return numbers


def _shows(numbers: list[tuple[float, float]], x: float, y: float) -> bool:
    """Whether the numbers hold x and, after it, y."""
    for i, (value, tolerance) in enumerate(numbers):
        if abs(value - x) <= tolerance:
            return any(abs(v - y) <= tol for v, tol in numbers[i + 1 :])
    return False


_LABELLED = tuple(
    re.compile(rf"(?<![A-Za-z0-9_]){axis}\s*[:=]\s*({_NUMBER.pattern})", re.IGNORECASE) for axis in "xy"
)
"""A coordinate named in the line: "x=5.54", "y: 3.2", "pose.x = 5.54"."""


def _read_pose(text: str) -> list[tuple[float, float]]:
    """The numbers of a log line as log_pose reads them: when the line names
    both coordinates ("y=3.20 x=5.54"), x's number then y's, in whichever
    order the line has them; else every number, in order (x must come first)."""
    found = [pattern.search(text) for pattern in _LABELLED]
    if all(found):
        return [_logged_numbers(match.group(1))[0] for match in found if match]
    return _logged_numbers(text)


@check(
    "log_pose",
    "The matching log lines (default: lines with two numbers or more) carry the turtle's x and "
    "then y (or, named x= and y=, in either order) as they were when the line was logged (the pose of the last `max_age` seconds, "
    "default 0.1), to the digits they print: share of such lines, threshold `min` (default 0.9).",
    {**_LOG, **TURTLE, "min": "number", "max_age": "number"},
)
def log_pose(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    poses = trace.pose_array(turtle_of(th))
    max_age = th.get("max_age", 0.1)
    lines = [(r, _read_pose(r.msg)) for r in _matching_logs(trace, th)]
    if "pattern" not in th:
        lines = [(r, numbers) for r, numbers in lines if len(numbers) >= 2]
    if not lines:
        return Verdict(False, "no log lines with the pose's numbers")
    times = poses[:, 0]
    right = 0
    wrong = None
    for record, numbers in lines:
        recent = poses[(times <= record.t + 1e-9) & (times >= record.t - max_age - 1e-9)]
        if any(_shows(numbers, x, y) for x, y in recent[:, 1:3].tolist()):
            right += 1
        elif wrong is None:
            wrong = (record, recent[-1] if len(recent) else None)
    share = right / len(lines)
    verdict = bounds(share, {"min": th.get("min", 0.9)})
    text = f"{right} of {len(lines)} log lines carry the pose of the moment ({share:.0%}, needs >= {th.get('min', 0.9):.0%})"
    if wrong is not None:
        record, pose = wrong
        where = f"the turtle was at x={pose[1]:.3f}, y={pose[2]:.3f}" if pose is not None else "no pose yet"
        text += f"; at t={record.t:.3f} s the line said {record.msg[:80]!r} but {where}"
        lag = _lag(poses, record.t, max_age, _read_pose(record.msg))
        if lag is not None:
            text += (
                f" (it was there {lag:.2f} s before: the lines lag behind the poses, as when the callback "
                "sleeps or blocks and the poses wait in its queue)"
            )
    return Verdict(verdict.passed, text)


_LAG_LOOKBACK_S = 10.0


def _lag(poses: Any, t: float, max_age: float, numbers: list[tuple[float, float]]) -> float | None:
    """How long before ``t`` (seconds) the turtle was where ``numbers`` say,
    more than ``max_age`` and at most _LAG_LOOKBACK_S before; None if it was not."""
    times = poses[:, 0]
    earlier = poses[(times < t - max_age - 1e-9) & (times >= t - _LAG_LOOKBACK_S)]
    for when, x, y in reversed(earlier[:, 0:3].tolist()):
        if _shows(numbers, x, y):
            return t - when
    return None


@check(
    "log_feedback",
    "Log lines of the controller's nodes (optionally matching `pattern`, from `node`, at "
    "`level`) that carry the feedback of a RotateAbsolute goal sent to `action` (default "
    "/turtle1/rotate_absolute) while it was in progress: a number equal, to the digits it "
    "prints, to the angle the turtle still had to turn (the feedback's remaining, in radians or "
    "degrees, either sign) in the last `max_age` seconds (default 0.1). Lines logged the "
    "instant a goal was sent (\"Sending goal: 1.57\") do not count: thresholds min and max.",
    {**MINMAX, **_LOG, "action": "text", "max_age": "number"},
)
def log_feedback(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    """Whatever words the lines use ("Remaining: 0.42 rad", "0.42 rad to go",
    "feedback 24.1 deg"): the numbers are what the feedback said."""
    action = th.get("action", "/turtle1/rotate_absolute")
    max_age = th.get("max_age", 0.1)
    goals = [goal for goal in trace.goals if goal.action == action]
    poses = trace.pose_array(action.strip("/").split("/")[0])
    if not goals or len(poses) == 0:
        return measured("log lines with the feedback:", bounds(0, th))
    sent = np.array([goal.t for goal in goals])
    times = poses[:, 0]
    count = 0
    for record in _matching_logs(trace, th):
        latest = int(np.searchsorted(sent, record.t + 1e-9, side="right")) - 1
        if latest < 0 or record.t - sent[latest] <= 1e-9:
            continue  # before any goal, or the line that announces one
        numbers = [(abs(value), tolerance) for value, tolerance in _logged_numbers(record.msg)]
        if not numbers:
            continue
        target = float(goals[latest].goal.theta)
        recent = poses[(times <= record.t + 1e-9) & (times >= record.t - max_age - 1e-9)]
        remaining = np.abs(np.remainder(target - recent[:, 3] + math.pi, math.tau) - math.pi)
        said = [*remaining.tolist(), *np.degrees(remaining).tolist()]
        if any(abs(value - r) <= tolerance for value, tolerance in numbers for r in said):
            count += 1
    return measured("log lines with the feedback:", bounds(count, th))
