"""The turtles_caught check: kills of existing turtles while the chaser was close."""

from __future__ import annotations

import numpy as np

from turtletui.grading.checks import BUILTIN_CHECKS
from turtletui.grading.trace import POSE_COLUMNS, ServiceCall, Trace
from turtletui.interfaces.turtlesim import Kill

CHECK = BUILTIN_CHECKS["turtles_caught"]


def still(x: float, y: float, t0: float, t1: float) -> np.ndarray:
    """Poses every 16 ms from t0 to t1 (inclusive) of a turtle standing at (x, y)."""
    times = np.arange(round(t0 / 0.016), round(t1 / 0.016) + 1) * 0.016
    poses = np.zeros((len(times), len(POSE_COLUMNS)))
    poses[:, 0], poses[:, 1], poses[:, 2] = times, x, y
    return poses


def kill(t: float, name: str) -> ServiceCall:
    return ServiceCall(t, "/kill", Kill.Request(name=name), Kill.Response())


def test_kills_next_to_the_chaser_count_far_and_missing_ones_do_not():
    t2 = 0.016 * 62  # a tick
    t3 = 0.016 * 125
    trace = Trace(
        scenario="s",
        seed=0,
        duration=3.0,
        start=(5.5, 5.5, 0.0),
        poses={
            "turtle1": still(5.5, 5.5, 0.0, 3.0),
            "turtle2": still(5.8, 5.5, 0.0, t2),  # caught: 0.3 m away
            "turtle3": still(9.0, 9.0, 0.0, t3),  # killed from 4.9 m away
        },
        service_calls=[kill(t2, "turtle2"), kill(t2, "turtle2"), kill(t3, "turtle3"), kill(2.5, "turtle9")],
    )
    verdict = CHECK.judge(trace, {"min": 1})
    assert verdict.passed
    assert verdict.measured == (
        "turtles caught: 1 (needs >= 1); 2 kills of turtles that did not exist;"
        " 1 turtles killed from more than 1 m away"
    )
    assert not CHECK.judge(trace, {"min": 2}).passed


def test_killing_the_chaser_is_reported():
    trace = Trace(
        scenario="s",
        seed=0,
        duration=1.0,
        start=(5.5, 5.5, 0.0),
        poses={"turtle1": still(5.5, 5.5, 0.0, 0.496)},
        service_calls=[kill(0.496, "turtle1")],
    )
    verdict = CHECK.judge(trace, {"min": 1})
    assert not verdict.passed
    assert verdict.measured == "turtles caught: 0 (needs >= 1); killed the chaser turtle1 itself"


def test_a_name_reused_after_a_kill_can_be_caught_again():
    trace = Trace(
        scenario="s",
        seed=0,
        duration=3.0,
        start=(5.5, 5.5, 0.0),
        poses={
            "turtle1": still(5.5, 5.5, 0.0, 3.0),
            "prey": np.concatenate([still(5.6, 5.5, 0.0, 0.992), still(5.4, 5.5, 1.504, 2.0)]),
        },
        service_calls=[kill(0.992, "prey"), kill(2.0, "prey")],
    )
    assert CHECK.judge(trace, {"min": 2, "radius": 0.5}).measured == "turtles caught: 2 (needs >= 2)"
    assert CHECK.problem({"min": 5, "radius": 1.0, "turtle": "turtle1"}) is None
