"""The headings_faced check: the turtle stopped facing each heading, in order."""

from __future__ import annotations

import math

import numpy as np

from turtletui.grading.checks import BUILTIN_CHECKS
from turtletui.grading.trace import POSE_COLUMNS, Trace

CHECK = BUILTIN_CHECKS["headings_faced"]
COMPASS = {"headings": [math.pi / 2, math.pi, -math.pi / 2, 0.0]}


def trace_of(theta) -> Trace:
    n = len(theta)
    poses = np.zeros((n, len(POSE_COLUMNS)))
    poses[:, 0] = np.arange(n) * 0.016
    poses[:, 1:3] = 5.5
    poses[:, 3] = np.arctan2(np.sin(theta), np.cos(theta))
    return Trace(scenario="s", seed=0, duration=n * 0.016, start=(5.5, 5.5, 0.0), poses={"turtle1": poses})


def turns(*stops: float) -> np.ndarray:
    """Turn at 1 rad/s from stop to stop, resting 3 poses at each."""
    parts = []
    for a, b in zip(stops, stops[1:], strict=False):
        parts += [np.full(3, a), np.linspace(a, b, max(2, int(abs(b - a) / 0.016)))]
    parts.append(np.full(3, stops[-1]))
    return np.concatenate(parts)


def test_stopping_at_each_compass_heading_in_order_passes():
    verdict = CHECK.judge(trace_of(turns(0.0, math.pi / 2, math.pi, 3 * math.pi / 2, 2 * math.pi)), COMPASS)
    assert verdict.passed, verdict.measured


def test_passing_through_a_heading_without_stopping_does_not_count():
    # degrees as radians: 90 rad is 2.04 rad, so the turtle only turns through pi/2
    theta = turns(0.0, 90.0 % math.tau, 180.0 % math.tau, -90.0 % math.tau, 0.0)
    verdict = CHECK.judge(trace_of(theta), COMPASS)
    assert not verdict.passed
    assert verdict.measured.startswith("never stopped facing 1.57 rad")
    assert "stopped at 0.00, 2.04" in verdict.measured


def test_the_order_matters():
    theta = turns(0.0, math.pi, math.pi / 2, -math.pi / 2, 0.0)
    verdict = CHECK.judge(trace_of(theta), COMPASS)
    assert not verdict.passed
    assert verdict.measured.startswith("never stopped facing 3.14 rad")


def test_bad_headings_and_no_poses_fail_with_a_reason():
    assert CHECK.problem({}) == "check 'headings_faced' needs the threshold 'headings'"
    assert "must be a non-empty list of numbers" in CHECK.problem({"headings": "north"})
    empty = Trace(scenario="s", seed=0, duration=1.0, start=(0.0, 0.0, 0.0))
    assert CHECK.judge(empty, COMPASS).measured == "the turtle never published a pose"
