"""The checks that make points depend on the task, on hand-made traces:
closed_loop (a twin run's commands), log_period, log_pose, log_counter's
pattern, turtles_caught's targets, time_moving without turning, distance
without teleports, and no_crash's lines of the student's file."""

from __future__ import annotations

import numpy as np
from test_checks import judge, log, poses, trace

from turtletui.grading.trace import ServiceCall, Trace
from turtletui.interfaces.turtlesim import Kill, Spawn
from turtletui.runtime.report import CrashReport


def commands(rows):
    """A cmd_vel stream: (t, linear.x, angular.z) rows."""
    return {"turtle1": np.array([(t, v, 0.0, w) for t, v, w in rows], dtype=float).reshape(-1, 4)}


def twin_of(rows, start=(3.0, 7.0, 1.0), **fields) -> Trace:
    return Trace(scenario="s", seed=0, duration=10.0, start=start, sim_time=10.0, commands=commands(rows), **fields)


# -- closed_loop ------------------------------------------------------------------------

STEADY = [(0.016 * i, 2.0, 1.0) for i in range(1, 600)]


def test_the_same_commands_from_another_start_are_an_open_loop():
    verdict = judge("closed_loop", trace(commands=commands(STEADY), twin=twin_of(STEADY)))
    assert not verdict.passed and verdict.judged
    assert "same 599 commands on /turtle1/cmd_vel at the same times" in verdict.measured
    assert "x=3.00, y=7.00" in verdict.measured and "an open loop" in verdict.measured


def test_commands_that_differ_from_another_start_follow_the_pose():
    # a 20 Hz timer publishing from the latest pose: it turns at another moment
    mine = [(0.05 * i, 5.0, 0.0 if i < 40 else 1.5) for i in range(1, 200)]
    other = [(0.05 * i, 5.0, 0.0 if i < 13 else 1.5) for i in range(1, 200)]
    verdict = judge("closed_loop", trace(commands=commands(mine), twin=twin_of(other)))
    assert verdict.passed and "differed from t=0.650 s" in verdict.measured


def test_fewer_commands_from_another_start_are_a_difference_too():
    verdict = judge("closed_loop", trace(commands=commands(STEADY), twin=twin_of(STEADY[:100])))
    assert verdict.passed and "differed from t=1.616 s" in verdict.measured


def test_no_commands_at_all_is_no_loop():
    verdict = judge("closed_loop", trace(twin=twin_of([])))
    assert not verdict.passed and "no velocity commands on /turtle1/cmd_vel" in verdict.measured


def test_a_twin_that_crashed_is_compared_until_the_crash():
    crash = CrashReport("node.py", 2.0, "exception", "ValueError: boom")
    verdict = judge("closed_loop", trace(commands=commands(STEADY), twin=twin_of(STEADY, crashes=[crash])))
    assert not verdict.passed and "until it crashed at t=2.000 s" in verdict.measured


def test_without_a_twin_run_the_loop_is_not_judged():
    verdict = judge("closed_loop", trace(commands=commands(STEADY)))
    assert not verdict.passed and not verdict.judged


def test_closed_loop_asks_for_a_twin_of_its_window():
    from turtletui.grading.checks import BUILTIN_CHECKS

    check = BUILTIN_CHECKS["closed_loop"]
    assert check.twin and check.twin_window({}) == 10.0 and check.twin_window({"window": 4}) == 4.0
    assert BUILTIN_CHECKS["wall_hits"].twin_window({}) is None


# -- log_period and log_counter -----------------------------------------------------------

COUNTER = r"(-?\d+)\W*$"


def test_lines_one_per_period_pass_and_a_burst_does_not():
    steady = [log(f"Hello {i}", t=1.0 + i) for i in range(6)]
    verdict = judge("log_period", trace(logs=steady), pattern=COUNTER, min=4, max_period=2.0)
    assert verdict.passed and "6 log lines" in verdict.measured and "one every 1 s" in verdict.measured
    burst = [log(f"Hello {i}", t=0.0) for i in range(10)]
    verdict = judge("log_period", trace(logs=burst), pattern=COUNTER, min=4)
    assert not verdict.passed and "in bursts" in verdict.measured


def test_three_lines_every_three_seconds_are_not_one_per_period():
    lines = [log(f"Hello {3 * k + j}", t=3.0 * k) for k in range(1, 4) for j in range(3)]
    verdict = judge("log_period", trace(logs=lines), pattern=COUNTER, min=4)
    assert not verdict.passed and "in bursts" in verdict.measured
    uneven = [log(f"Hello {i}", t=t) for i, t in enumerate([1.0, 2.0, 3.0, 4.6, 5.6])]
    verdict = judge("log_period", trace(logs=uneven), pattern=COUNTER, min=4)
    assert not verdict.passed and "1.6 s between t=3.000 s and t=4.600 s" in verdict.measured


def test_a_period_outside_the_lessons_range_fails():
    slow = [log(f"Hello {i}", t=3.0 * i) for i in range(5)]
    verdict = judge("log_period", trace(logs=slow), pattern=COUNTER, max_period=2.0)
    assert not verdict.passed and "one every 3 s (needs <= 2 s)" in verdict.measured


def test_the_counter_is_read_by_the_pattern_not_the_first_number_of_a_line():
    lines = [log("Part 3 node has started")] + [log(f"[node1] counter = {i}", t=i) for i in range(1, 6)]
    assert judge("log_counter", trace(logs=lines), pattern=COUNTER, min=4).passed
    # without the pattern's group, the first integer wins: node1's 1, every line
    verdict = judge("log_counter", trace(logs=lines), pattern="counter", min=4)
    assert verdict.passed  # from where "counter" matches on: the counter itself
    verdict = judge("log_counter", trace(logs=lines), min=4)
    assert not verdict.passed and "went from 1 to 1" in verdict.measured


def test_another_kind_of_line_ending_with_a_number_does_not_break_the_counter():
    # a right node that also logs its uptime every tick ("uptime ms: 1000")
    lines = [
        record
        for i in range(6)
        for record in (log(f"Hello {i}", t=1.0 + i), log(f"uptime ms: {1000 * (i + 1)}", t=1.0 + i))
    ]
    assert judge("log_counter", trace(logs=lines), pattern=COUNTER, min=4).passed
    verdict = judge("log_period", trace(logs=lines), pattern=COUNTER, min=4, max_period=2.0)
    assert verdict.passed and "6 log lines" in verdict.measured


def test_both_checks_judge_the_same_kind_so_two_halves_make_no_counter():
    # a burst that counts from __init__, beside a timer whose numbers do not count
    burst = [log(f"Hello {i}", t=0.0) for i in range(10)]
    ticks = [log(f"tick {1000 * i}", t=1.0 + i) for i in range(8)]
    logs = burst + ticks
    assert judge("log_counter", trace(logs=logs), pattern=COUNTER, min=4).passed
    verdict = judge("log_period", trace(logs=logs), pattern=COUNTER, min=4)
    assert not verdict.passed and "in bursts" in verdict.measured
    one = judge("log_period", trace(logs=[log("Hello 0", t=1.0)]), pattern=COUNTER, min=4)
    assert "1 log line matching" in one.measured


# -- log_pose ----------------------------------------------------------------------------

def moving():
    """The turtle drives east at 1 m/s from (5, 5): a pose every 16 ms for 2 s."""
    return [(5.0 + 0.016 * i, 5.0) for i in range(126)]


def test_lines_with_the_pose_of_the_moment_pass_to_the_digits_they_print():
    points = moving()
    lines = [log("Pose subscriber has started")]
    lines += [log(f"({x}, {y})", t=0.016 * i) for i, (x, y) in enumerate(points)]
    lines += [log(f"x={x:.2f} y={y:.1f} theta=0.00", t=0.016 * i) for i, (x, y) in enumerate(points)]
    verdict = judge("log_pose", trace(points, logs=lines))
    assert verdict.passed and f"{2 * len(points)} of {2 * len(points)} log lines" in verdict.measured


def test_a_constant_or_a_stale_pose_fails_and_shows_a_line_that_is_wrong():
    points = moving()
    constant = [log("(5.544, 5.544)", t=0.016 * i) for i in range(len(points))]
    verdict = judge("log_pose", trace(points, logs=constant))
    assert not verdict.passed and "the line said '(5.544, 5.544)' but the turtle was at x=" in verdict.measured
    stale = [log(f"({points[0][0]}, {points[0][1]})", t=0.016 * i) for i in range(len(points))]
    assert not judge("log_pose", trace(points, logs=stale)).passed
    # y before x is not the pose either
    swapped = [log(f"({y}, {x})", t=0.016 * i) for i, (x, y) in enumerate(points)]
    assert not judge("log_pose", trace(points, logs=swapped)).passed


def test_a_pose_a_timer_kept_from_its_last_callback_is_the_pose_of_the_moment():
    points = moving()
    every_tenth = [log(f"({x:.3f}, {y:.3f})", t=0.016 * (i + 1)) for i, (x, y) in enumerate(points) if i % 10 == 0]
    assert judge("log_pose", trace(points, logs=every_tenth)).passed


def test_no_lines_with_numbers_is_no_pose():
    verdict = judge("log_pose", trace(moving(), logs=[log("I got a pose")]))
    assert not verdict.passed and "no log lines with the pose's numbers" in verdict.measured


# -- turtles_caught with targets ------------------------------------------------------------

TARGETS = [[8.0, 8.0], [2.0, 2.0]]


def chase(spawn_at, hunter_at, kill_t=1.0):
    """A trace where turtle2 is spawned at ``spawn_at`` and killed at ``kill_t``
    while turtle1 is at ``hunter_at``."""
    spawn = ServiceCall(0.1, "/spawn", Spawn.Request(x=spawn_at[0], y=spawn_at[1]), Spawn.Response(name="turtle2"))
    kill = ServiceCall(kill_t, "/kill", Kill.Request(name="turtle2"), Kill.Response())
    prey = poses([spawn_at] * 70)
    prey[:, 0] += 0.1
    hunter = poses([hunter_at] * 70)
    return trace(poses={"turtle1": hunter, "turtle2": prey}, service_calls=[spawn, kill])


def test_prey_spawned_on_a_scenario_target_and_reached_is_caught():
    verdict = judge("turtles_caught", chase((8.0, 8.0), (7.6, 8.0)), targets=TARGETS, min=1)
    assert verdict.passed and "turtles caught: 1" in verdict.measured


def test_prey_spawned_next_to_the_chaser_earns_nothing():
    verdict = judge("turtles_caught", chase((5.5, 5.0), (5.0, 5.0)), targets=TARGETS, min=1)
    assert not verdict.passed
    assert "1 kills of turtles not spawned on a target the scenario gave" in verdict.measured
    # without targets, the same kill is a catch: the lesson decides
    assert judge("turtles_caught", chase((5.5, 5.0), (5.0, 5.0)), min=1).passed


def test_the_chaser_must_be_at_the_targets_place():
    verdict = judge("turtles_caught", chase((8.0, 8.0), (5.0, 5.0)), targets=TARGETS, min=1)
    assert not verdict.passed and "killed from more than 1 m away" in verdict.measured


# -- time_moving, distance, no_crash ----------------------------------------------------------

def test_turning_on_the_spot_counts_as_moving_only_when_asked():
    spin = trace([(5.0, 5.0, 0.1 * i) for i in range(100)])
    spin.poses["turtle1"][:, 4] = 0.0  # no forward speed
    assert judge("time_moving", spin, min=0.8).passed
    verdict = judge("time_moving", spin, min=0.8, turning=False)
    assert not verdict.passed
    assert verdict.measured == "driving 0% of the run (needs >= 80%; turning in place does not count)"


def test_a_teleport_is_no_distance_driven():
    points = [(2.0 + 0.016 * i, 5.0) for i in range(50)] + [(9.0, 9.0)]
    jumps = np.zeros(len(points), dtype=bool)
    jumps[-1] = True
    t = trace(points, jumps={"turtle1": jumps})
    assert judge("distance", t, min=0.78, max=0.79).passed  # 49 steps of 16 mm, not the jump


def test_a_crash_shows_the_lines_of_the_students_file():
    frames = [
        '  File "node.py", line 9, in main\n    rclpy.spin(Node())',
        '  File "node.py", line 20, in on_pose\n    speed = spede * 2',
    ]
    crash = CrashReport("node.py", 1.5, "exception", "NameError: name 'spede' is not defined", frames)
    verdict = judge("no_crash", trace(crashes=[crash]))
    lines = verdict.measured.splitlines()
    assert lines[0] == "controller node.py crashed at t=1.500 s: NameError: name 'spede' is not defined"
    assert lines[1:] == [*frames[0].splitlines(), *frames[1].splitlines()]
