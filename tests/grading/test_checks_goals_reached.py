"""The goals_reached check: rotate_absolute goals the turtle got to before the next one."""

from __future__ import annotations

import math

import numpy as np

from turtletui.grading.checks import BUILTIN_CHECKS
from turtletui.grading.trace import POSE_COLUMNS, GoalSent, Trace
from turtletui.interfaces.turtlesim import RotateAbsolute

CHECK = BUILTIN_CHECKS["goals_reached"]
ACTION = "/turtle1/rotate_absolute"


def trace_of(theta, goals) -> Trace:
    """Poses every 16 ms with these headings; goals as (t, theta)."""
    n = len(theta)
    poses = np.zeros((n, len(POSE_COLUMNS)))
    poses[:, 0] = np.arange(n) * 0.016
    poses[:, 1:3] = 5.5
    poses[:, 3] = theta
    sent = [GoalSent(t, ACTION, RotateAbsolute.Goal(theta=g)) for t, g in goals]
    return Trace(scenario="s", seed=0, duration=n * 0.016, start=(5.5, 5.5, 0.0), poses={"turtle1": poses}, goals=sent)


def turn(start: float, end: float, n: int) -> np.ndarray:
    return np.linspace(start, end, n)


def test_goals_reached_one_after_the_other_pass():
    theta = np.concatenate([turn(0.0, math.pi / 2, 100), turn(math.pi / 2, 0.0, 100)])
    verdict = CHECK.judge(trace_of(theta, [(0.0, math.pi / 2), (1.6, 0.0)]), {})
    assert verdict.passed
    assert verdict.measured == "2 of 2 goals reached: 1 (needs >= 1)"


def test_goals_sent_at_once_replace_each_other():
    theta = np.zeros(100)
    goals = [(0.0, math.pi / 2), (0.0, math.pi), (0.0, 0.0)]
    verdict = CHECK.judge(trace_of(theta, goals), {})
    assert not verdict.passed
    assert verdict.measured.startswith("1 of 3 goals reached")


def test_a_goal_replaced_halfway_is_not_reached_and_min_is_a_share():
    theta = turn(0.0, 1.0, 100)  # 1.6 s turning towards pi/2, then replaced by 1.0
    goals = [(0.0, math.pi / 2), (0.5, 1.0)]
    assert not CHECK.judge(trace_of(theta, goals), {}).passed
    assert CHECK.judge(trace_of(theta, goals), {"min": 0.5}).passed


def test_headings_wrap_at_pi():
    theta = np.full(10, -math.pi + 0.01)
    assert CHECK.judge(trace_of(theta, [(0.0, math.pi)]), {}).passed


def test_no_goals_fails_and_thresholds_are_validated():
    verdict = CHECK.judge(trace_of(np.zeros(10), []), {})
    assert not verdict.passed and verdict.measured == f"no goals sent to {ACTION}"
    assert CHECK.problem({"min": 1.0, "tolerance": 0.05, "action": ACTION}) is None
    assert CHECK.problem({"tolerence": 0.05}) is not None


def test_only_velocity_commands_sent_while_a_goal_was_in_progress_are_blamed():
    # the first goal is reached at 1.6 s; the second, sent at 2 s, never is
    theta = np.concatenate([turn(0.0, math.pi / 2, 100), np.full(200, math.pi / 2)])
    trace = trace_of(theta, [(0.0, math.pi / 2), (2.0, 0.0)])
    times = [0.5, 1.0, 1.8, 1.9, 2.5]  # two while turning, two between the goals, one after the second
    trace.commands["turtle1"] = np.array([[t, 0.0, 0.0, 0.0] for t in times])
    verdict = CHECK.judge(trace, {})
    assert not verdict.passed
    assert verdict.measured.startswith("1 of 2 goals reached")
    assert "published 3 velocity commands on /turtle1/cmd_vel while a goal was in progress" in verdict.measured
