"""The built-in checks on hand-made traces: what passes, what fails, what they say."""

from __future__ import annotations

import math

import numpy as np
import pytest

from turtletui.grading.checks import BUILTIN_CHECKS, fit_circle
from turtletui.grading.checks.base import bounds
from turtletui.grading.trace import POSE_COLUMNS, ServiceCall, Trace
from turtletui.graph.logs import INFO, LogRecord
from turtletui.runtime.report import CrashReport


def poses(points, dt=0.016, colour=(179, 184, 255), speed=1.0):
    rows = []
    for i, (x, y, *rest) in enumerate(points):
        theta = rest[0] if rest else 0.0
        rgb = rest[1] if len(rest) > 1 else colour
        rows.append((i * dt, x, y, theta, speed, *rgb, 0.0))
    return np.array(rows, dtype=float).reshape(-1, len(POSE_COLUMNS))


def trace(points=((5.5, 5.5),), **fields):
    data = {"poses": {"turtle1": poses(points)}}
    data.update(fields)
    return Trace(scenario="s", seed=0, duration=10.0, start=(5.5, 5.5, 0.0), sim_time=10.0, **data)


def judge(name, t, **thresholds):
    return BUILTIN_CHECKS[name].judge(t, thresholds)


def test_wall_hits_default_to_none_allowed():
    assert judge("wall_hits", trace(wall_hits={"turtle1": 0})).passed
    verdict = judge("wall_hits", trace(wall_hits={"turtle1": 2}))
    assert not verdict.passed and "2" in verdict.measured
    assert judge("wall_hits", trace(wall_hits={"turtle1": 2}), max=3).passed


def test_min_clearance_measures_the_closest_wall():
    t = trace([(5.0, 5.0), (0.4, 5.0), (5.0, 10.5)])
    verdict = judge("min_clearance", t, min=0.5)
    assert not verdict.passed and "0.40 m" in verdict.measured
    assert judge("min_clearance", t, min=0.3).passed


def test_a_turtle_held_at_a_surface_is_0_m_from_it_not_float_noise():
    t = trace([(5.0, 5.0), (0.1 + 0.2 - 0.3, 5.0)])  # 5.55e-17 m from the left wall
    verdict = judge("min_clearance", t, min=0.2)
    assert verdict.measured.startswith("closest to a wall or obstacle: 0 m (needs")
    assert "0.005 m" in judge("min_clearance", trace([(5.0, 5.0), (0.005, 5.0)]), min=0.2).measured


def test_coverage_counts_cells_visited():
    line = [(0.5 + i, 0.5) for i in range(11)]  # 11 of the 121 one-metre cells
    verdict = judge("coverage", trace(line), min=0.1)
    assert not verdict.passed and "0.09" in verdict.measured


def test_mean_speed_and_distance():
    t = trace([(1.0 + 0.016 * i, 5.0) for i in range(101)])  # 1 m/s for 1.6 s
    assert judge("mean_speed", t, min=0.9, max=1.1).passed
    assert not judge("mean_speed", t, min=1.5).passed
    assert judge("distance", t, min=1.59, max=1.61).passed


def test_commands_per_pose_tells_closed_from_open_loop():
    t = trace([(5.0, 5.0)] * 100, commands={"turtle1": np.zeros((98, 4))})
    assert judge("commands_per_pose", t, min=0.9).passed
    t = trace([(5.0, 5.0)] * 100, commands={"turtle1": np.zeros((2, 4))})
    assert not judge("commands_per_pose", t, min=0.9).passed


def test_fit_circle_recovers_centre_and_radius():
    angles = np.linspace(0, 2 * math.pi, 200)
    cx, cy, r, rms = fit_circle(3 + 2 * np.cos(angles), 4 + 2 * np.sin(angles))
    assert (round(cx, 6), round(cy, 6), round(r, 6)) == (3.0, 4.0, 2.0)
    assert rms < 1e-9


def test_circle_check_wants_round_laps_of_the_right_size():
    angles = np.linspace(0, 2.2 * math.pi, 400)
    circle = [(5 + 2 * math.cos(a), 5 + 2 * math.sin(a)) for a in angles]
    assert judge("circle", trace(circle), min_radius=1.5, max_radius=2.5).passed
    verdict = judge("circle", trace(circle), min_radius=3.0, max_radius=4.0)
    assert not verdict.passed and "radius 2.00 m" in verdict.measured
    straight = [(1 + 0.02 * i, 5.0) for i in range(300)]
    assert not judge("circle", trace(straight)).passed


def test_time_to_goal_and_final_error():
    path = [(1 + 0.1 * i, 1.0) for i in range(51)]  # reaches x = 6 after 50 poses
    t = trace(path)
    verdict = judge("time_to_goal", t, goal=[5.0, 1.0], tolerance=0.05, max=1.0)
    assert verdict.passed and "0.64 s" in verdict.measured
    assert not judge("time_to_goal", t, goal=[5.0, 3.0]).passed
    assert judge("final_error", t, goal=[6.0, 1.0], max=0.01).passed
    assert not judge("final_error", t, goal=[5.0, 1.0], max=0.5).passed


def test_heading_error_wraps_around_pi():
    t = trace([(5.0, 5.0, math.pi - 0.01)])
    assert judge("heading_error", t, theta=-math.pi + 0.01, max=0.05).passed
    assert not judge("heading_error", t, theta=0.0, max=0.05).passed


def test_longest_turn_adds_up_one_way_across_pi_and_starts_again_on_a_turn_back_or_a_teleport():
    # left from 0 to 3 rad, across +-pi and on to -2.5 (0.78 rad past pi): 3.78 rad one way
    left = [(5.0, 5.0, math.remainder(a, math.tau)) for a in np.linspace(0.0, 3.78, 80)]
    verdict = judge("longest_turn", trace(left), max=4.71)
    assert verdict.passed and "longest turn one way: 3.78 rad" in verdict.measured
    # on round to a full turn and a half: the long way
    longer = [(5.0, 5.0, math.remainder(a, math.tau)) for a in np.linspace(0.0, 3 * math.pi, 150)]
    verdict = judge("longest_turn", trace(longer), max=4.71)
    assert not verdict.passed and "9.42 rad (needs <= 4.71 rad)" in verdict.measured
    assert "1.50 of a full turn" in verdict.measured
    # the same angles left then right: two turns of half that each
    back = [(5.0, 5.0, math.remainder(a, math.tau)) for a in np.linspace(0.0, 1.4 * math.pi, 75)]
    back += list(reversed(back))
    assert judge("longest_turn", trace(back), max=4.71).passed
    # a teleport between two left turns ends the first
    jumps = np.zeros(len(longer), dtype=bool)
    jumps[75] = True
    assert judge("longest_turn", trace(longer, jumps={"turtle1": jumps}), max=4.71).passed
    # with a goal, only the turning on the way there counts: circling it once there is final_error's
    arrive = [(5.0 + 0.02 * i, 5.0, 0.0) for i in range(50)]
    circling = arrive + [(6.0, 5.0, math.remainder(a, math.tau)) for a in np.linspace(0.0, 3 * math.pi, 150)]
    verdict = judge("longest_turn", trace(circling), goal=[6.0, 5.0], max=4.71)
    assert verdict.passed and "longest turn one way on its way to the goal: 0 rad" in verdict.measured
    assert not judge("longest_turn", trace(circling), max=4.71).passed
    assert not judge("longest_turn", trace(circling), goal=[9.0, 5.0], max=4.71).passed  # never got there


def test_longest_turn_with_a_service_starts_a_new_turn_at_each_call():
    # a turn and a half left (9.42 rad) in 150 poses 0.016 s apart: /kill answered at
    # poses 75 and 149 splits it into two turns of 4.74 and 4.68 rad
    longer = [(5.0, 5.0, math.remainder(a, math.tau)) for a in np.linspace(0.0, 3 * math.pi, 150)]
    kills = [ServiceCall(75 * 0.016, "/kill", None, None), ServiceCall(149 * 0.016, "/kill", None, None)]
    verdict = judge("longest_turn", trace(longer, service_calls=kills), service="/kill", max=4.75)
    assert verdict.passed and "longest turn one way up to each call of /kill: 4.74 rad" in verdict.measured
    assert not judge("longest_turn", trace(longer, service_calls=kills), max=4.75).passed  # no service: one turn
    # only turns that end with a call count: after the last one the turtle chases nothing
    first = kills[:1]
    assert judge("longest_turn", trace(longer, service_calls=first), service="/kill", max=4.75).passed
    late = [ServiceCall(140 * 0.016, "/kill", None, None)]
    verdict = judge("longest_turn", trace(longer, service_calls=late), service="/kill", max=4.75)
    assert not verdict.passed and "8.86 rad" in verdict.measured
    other = [ServiceCall(149 * 0.016, "/spawn", None, None)]
    verdict = judge("longest_turn", trace(longer, service_calls=other), service="/kill", max=4.75)
    assert verdict.passed and "no call of /kill ended a turn" in verdict.measured

def test_pen_colour_by_side_and_calls_per_side_change():
    red, green = (255, 0, 0), (0, 255, 0)
    path = [(x, 5.0, 0.0, red if x > 5.5 else green) for x in np.linspace(2, 9, 100)]
    path += list(reversed(path))
    calls = [ServiceCall(0.0, "/turtle1/set_pen", None, None)] * 3
    t = trace(path, service_calls=calls)
    assert judge("pen_colour_by_side", t).passed
    assert judge("pen_colour_by_side", t, right=[255, 0, 0], left=[0, 255, 0]).passed
    assert not judge("pen_colour_by_side", t, right=[0, 0, 255]).passed
    verdict = judge("calls_per_side_change", t)
    assert verdict.passed and "3 calls" in verdict.measured and "2 crossings" in verdict.measured
    flood = trace(path, service_calls=[ServiceCall(0.0, "/turtle1/set_pen", None, None)] * 200)
    assert not judge("calls_per_side_change", flood).passed
    same = trace([(x, 5.0, 0.0, red) for x in np.linspace(2, 9, 100)])
    verdict = judge("pen_colour_by_side", same)
    assert not verdict.passed and "same colour" in verdict.measured


def test_pen_colour_by_side_fails_a_colour_that_changes_before_the_line():
    # split at x = 5.0, not 5.5, back and forth across the arena 6 times: the
    # miscoloured poses are too few for the shares, but every crossing to the
    # right is red 0.3 m before the line already
    red, green = (255, 0, 0), (0, 255, 0)
    there = [(x, 5.0, 0.0, red if x > 5.0 else green) for x in np.linspace(1, 10, 400)]
    verdict = judge("pen_colour_by_side", trace((there + list(reversed(there))) * 3))
    assert "right (255, 0, 0) on 100% of poses" in verdict.measured
    assert not verdict.passed and "before reaching x = 5.5 at 3 of 6 crossings" in verdict.measured
    # a colour that changes just after the line (the service's answer) passes
    late = [(x, 5.0, 0.0, red if x > 5.6 else green) for x in np.linspace(1, 10, 400)]
    verdict = judge("pen_colour_by_side", trace((late + [(x, y, t, red if x > 5.4 else green) for x, y, t, _ in reversed(late)]) * 3))
    assert verdict.passed and "at 0 of 6 crossings" in verdict.measured


def test_pen_colour_by_side_says_when_the_pen_was_off():
    # set_pen with off = 1 (width and off swapped: off = 3) lifts the pen and
    # turtlesim keeps its old colour: not "the same colour on both sides"
    default, green = (179, 184, 255), (0, 255, 0)
    t = trace([(x, 5.0, 0.0, default if x > 5.5 else green) for x in np.linspace(9, 2, 100)])
    t.poses["turtle1"][:, POSE_COLUMNS.index("pen_off")] = [1.0 if x > 5.5 else 0.0 for x in np.linspace(9, 2, 100)]
    verdict = judge("pen_colour_by_side", t)
    assert not verdict.passed
    assert verdict.measured == (
        "the pen was off wherever the turtle drove on the right side of x = 5.5: "
        "it drew nothing there (set_pen's off must be 0 to draw)"
    )


def test_pen_colour_by_side_counts_only_where_the_turtle_drew():
    # It waits at its start with turtlesim's pen (its node has not yet
    # discovered turtlesim) for 10 of the 60 poses on the right: nothing drawn.
    red, green, default = (255, 0, 0), (0, 255, 0), (179, 184, 255)
    path = [(9.0, 5.0, 0.0, default)] * 10 + [(x, 5.0, 0.0, red if x > 5.5 else green) for x in np.linspace(9, 2, 100)]
    verdict = judge("pen_colour_by_side", trace(path))
    assert verdict.passed and "right (255, 0, 0) on 100% of poses" in verdict.measured
    # but while it drives, the pen it draws with counts
    late = [(x, 5.0, 0.0, default if x > 8.0 else red if x > 5.5 else green) for x in np.linspace(9, 2, 100)]
    verdict = judge("pen_colour_by_side", trace(late))
    assert not verdict.passed and "right (255, 0, 0) on 69% of poses" in verdict.measured
    standing = judge("pen_colour_by_side", trace([(9.0, 5.0, 0.0, red)] * 10 + [(4.0, 5.0, 0.0, green)] * 2))
    assert not standing.passed and "never drove on the right side" in standing.measured


def log(msg, node="my_node", t=0.0):
    return LogRecord(0, t, INFO, node, msg)


def test_log_lines_count_and_rate_ignore_the_simulators_own_lines():
    logs = [log(f"x: {i}") for i in range(20)] + [log("Oh no! I hit the wall!", node="turtlesim")]
    t = trace(logs=logs)
    assert judge("log_lines", t, pattern="x", min=20, max=20).passed
    assert not judge("log_lines", t, pattern="wall", min=1).passed
    assert judge("log_lines", t, min_rate=1.9).passed  # 20 lines in 10 s
    assert not judge("log_lines", t, min_rate=5).passed


def test_log_counter_wants_steps_of_one():
    assert judge("log_counter", trace(logs=[log(f"Hello {i}") for i in range(5)])).passed
    verdict = judge("log_counter", trace(logs=[log(f"Hello {i}") for i in (0, 1, 1, 2)]))
    assert not verdict.passed and "from 1 to 1" in verdict.measured
    assert not judge("log_counter", trace(logs=[log("Hello")] * 5)).passed


def test_no_crash_quotes_the_crash():
    crash = CrashReport("me", 1.5, "exception", "ZeroDivisionError: division by zero")
    verdict = judge("no_crash", trace(crashes=[crash]))
    assert not verdict.passed and "ZeroDivisionError" in verdict.measured
    assert judge("no_crash", trace()).passed


@pytest.mark.parametrize(
    ("name", "thresholds", "problem"),
    [
        ("wall_hits", {"maxx": 0}, "takes no threshold 'maxx'"),
        ("min_clearance", {}, "needs the threshold 'min'"),
        ("log_lines", {"pattern": "("}, "not a valid regular expression"),
        ("pen_colour_by_side", {"right": [300, 0, 0]}, "integers 0..255"),
        ("final_error", {"goal": [1, "a"], "max": 1}, "[x, y]"),
        ("wall_hits", {"max": True}, "must be a number"),
    ],
)
def test_bad_thresholds_are_named(name, thresholds, problem):
    assert problem in BUILTIN_CHECKS[name].problem(thresholds)


def test_every_builtin_check_is_described():
    for check in BUILTIN_CHECKS.values():
        assert check.description and check.params is not None


def test_the_lessons_readme_documents_every_builtin_check():
    from pathlib import Path

    text = (Path(__file__).parents[2] / "lessons" / "README.md").read_text(encoding="utf-8")
    assert [name for name in BUILTIN_CHECKS if f"`{name}`" not in text] == []


def test_min_clearance_counts_obstacles_too():
    from turtletui.sim.obstacles import Box, Circle

    t = trace([(5.0, 5.0), (6.0, 5.0)], obstacles=(Circle(8.0, 5.0, 1.5), Box(5.0, 6.0, 6.0, 7.0)))
    verdict = judge("min_clearance", t, min=0.6)
    assert not verdict.passed and "0.50 m" in verdict.measured  # circle at 6.5, 0.5 m from x = 6


def test_a_turtle_no_command_reached_is_told_to_look_at_the_topic():
    still = [(5.5, 5.5)] * 20
    silent = trace(still)
    silent.poses["turtle1"][:, 4] = 0.0  # standing: no forward speed
    zero_twists = trace(still, commands={"turtle1": np.zeros((20, 4))})
    zero_twists.poses["turtle1"][:, 4] = 0.0
    note = "nothing was published on /turtle1/cmd_vel (is that the topic your node publishes on?)"
    for name, thresholds in (("distance", {"min": 1.0}), ("time_moving", {"min": 0.5}), ("circle", {})):
        verdict = judge(name, silent, **thresholds)
        assert not verdict.passed and verdict.measured.endswith(note), (name, verdict.measured)
        # zero Twists did reach it: the topic is right, the numbers are not
        assert "nothing was published" not in judge(name, zero_twists, **thresholds).measured
    # a turtle that moved was moved by something (a teleop driver, a teleport)
    assert "nothing was published" not in judge("distance", trace([(5.0, 5.0), (5.5, 5.0)]), min=9.0).measured


def test_coordinate_range_names_the_side_that_went_too_far():
    t = trace([(5.0, 5.0), (2.5, 6.0), (6.0, 8.4)])
    high = judge("coordinate_range", t, max=7.5)
    assert not high.passed and high.measured == "highest x or y: 8.40 m (needs <= 7.50 m)"
    low = judge("coordinate_range", t, min=3.0)
    assert not low.passed and low.measured == "lowest x or y: 2.50 m (needs >= 3 m)"
    both = judge("coordinate_range", t, min=2.0, max=9.0)
    assert both.passed and both.measured == "lowest x or y: 2.50 m (needs >= 2 m); highest x or y: 8.40 m (needs <= 9 m)"
    assert judge("coordinate_range", t).measured == "x and y between 2.50 m and 8.40 m"
    assert not judge("coordinate_range", trace([]), max=7.0).passed


@pytest.mark.parametrize(
    ("value", "thresholds", "shown"),
    [
        (1.49962, {"min": 1.5}, "1.4996 (needs >= 1.50)"),  # not "1.50 (needs >= 1.50)", a fail that reads as a pass
        (2.0004, {"max": 2}, "2.0004 (needs <= 2)"),
        (1.2, {"min": 1.5}, "1.20 (needs >= 1.50)"),
        (1.5, {"min": 1.5}, "1.50 (needs >= 1.50)"),
    ],
)
def test_a_number_that_missed_its_bound_is_shown_with_the_digits_that_tell_them_apart(value, thresholds, shown):
    assert bounds(value, thresholds).measured == shown
