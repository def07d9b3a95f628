"""The log_feedback check: log lines that carry a rotate_absolute goal's remaining angle."""

from __future__ import annotations

import math

import numpy as np

from turtletui.grading.checks import BUILTIN_CHECKS
from turtletui.grading.trace import POSE_COLUMNS, GoalSent, Trace
from turtletui.graph.logs import INFO, LogRecord
from turtletui.interfaces.turtlesim import RotateAbsolute

CHECK = BUILTIN_CHECKS["log_feedback"]
ACTION = "/turtle1/rotate_absolute"


def trace_of(lines: list[tuple[float, str]]) -> Trace:
    """Turning from 0 to pi/2 at 1 rad/s (poses every 16 ms), one goal at t=0; log lines as (t, text)."""
    t = np.arange(0, 1.6, 0.016)
    poses = np.zeros((len(t), len(POSE_COLUMNS)))
    poses[:, 0] = t
    poses[:, 1:3] = 5.5
    poses[:, 3] = t
    logs = [LogRecord(round(when * 1e9), when, INFO, "rotate_client", text) for when, text in lines]
    goals = [GoalSent(0.0, ACTION, RotateAbsolute.Goal(theta=math.pi / 2))]
    return Trace(scenario="s", seed=0, duration=1.6, start=(5.5, 5.5, 0.0), poses={"turtle1": poses}, goals=goals, logs=logs)


def remaining(when: float) -> float:
    return math.pi / 2 - when


def test_lines_carrying_the_remaining_angle_count_whatever_their_words():
    lines = [
        (0.32, f"Remaining: {remaining(0.32):.2f} rad"),
        (0.64, f"{remaining(0.64):.3f} rad to go"),
        (0.96, f"feedback {math.degrees(remaining(0.96)):.1f} deg"),
        (1.28, f"left: -{remaining(1.28):.2f}"),
    ]
    verdict = CHECK.judge(trace_of(lines), {"min": 3})
    assert verdict.passed
    assert verdict.measured == "log lines with the feedback: 4 (needs >= 3)"


def test_other_numbers_and_the_line_that_sends_the_goal_do_not_count():
    lines = [(0.0, "Sending goal: theta = 1.57 rad"), (0.5, "step 12"), (0.8, "Remaining: 3.00 rad"), (1.0, "no numbers")]
    verdict = CHECK.judge(trace_of(lines), {"min": 1})
    assert not verdict.passed
    assert verdict.measured == "log lines with the feedback: 0 (needs >= 1)"


def test_no_goals_no_feedback():
    trace = trace_of([(0.5, f"Remaining: {remaining(0.5):.2f}")])
    trace.goals.clear()
    assert not CHECK.judge(trace, {"min": 1}).passed


def test_a_number_too_large_for_a_float_is_no_feedback_and_no_failure_of_the_check():
    lines = [(0.32, "Remaining: 1e400 rad"), (0.64, f"Remaining: {remaining(0.64):.2f} rad, 9e999999 to go")]
    verdict = CHECK.judge(trace_of(lines), {"min": 1})
    assert verdict.judged and verdict.passed
    assert verdict.measured == "log lines with the feedback: 1 (needs >= 1)"
