"""The time_moving check: the share of the run the turtle was driving or turning."""

from __future__ import annotations

import numpy as np

from turtletui.grading.checks import BUILTIN_CHECKS
from turtletui.grading.trace import POSE_COLUMNS, Trace

CHECK = BUILTIN_CHECKS["time_moving"]


def trace_of(speed, theta) -> Trace:
    """A trace of poses every 16 ms with these speeds and headings (x and y still)."""
    n = len(speed)
    poses = np.zeros((n, len(POSE_COLUMNS)))
    poses[:, 0] = np.arange(n) * 0.016
    poses[:, 1:3] = 5.5
    poses[:, 3] = theta
    poses[:, 4] = speed
    return Trace(scenario="s", seed=0, duration=n * 0.016, start=(5.5, 5.5, 0.0), poses={"turtle1": poses})


def test_a_turtle_that_stops_after_one_second_of_ten_fails():
    speed = np.where(np.arange(625) < 62, 2.0, 0.0)
    verdict = CHECK.judge(trace_of(speed, np.zeros(625)), {"min": 0.8})
    assert not verdict.passed
    assert verdict.measured == "moving 10% of the run (needs >= 80%)"


def test_a_turtle_driving_all_the_time_passes():
    verdict = CHECK.judge(trace_of(np.full(100, 2.0), np.zeros(100)), {"min": 0.8})
    assert verdict.passed
    assert verdict.measured == "moving 100% of the run (needs >= 80%)"


def test_turning_in_place_counts_as_moving_even_across_the_pi_wrap():
    theta = np.arctan2(np.sin(np.arange(100) * 0.1 + 3.0), np.cos(np.arange(100) * 0.1 + 3.0))
    verdict = CHECK.judge(trace_of(np.zeros(100), theta), {"min": 0.9})
    assert verdict.passed


def test_a_max_threshold_and_no_poses():
    assert not CHECK.judge(trace_of(np.full(10, 1.0), np.zeros(10)), {"max": 0.5}).passed
    empty = Trace(scenario="s", seed=0, duration=1.0, start=(0.0, 0.0, 0.0))
    assert CHECK.judge(empty, {"min": 0.5}).measured == "the turtle never published a pose"


def test_thresholds_are_validated():
    assert CHECK.problem({"min": 0.8}) is None
    assert "takes no threshold 'minimum'" in CHECK.problem({"minimum": 0.8})
