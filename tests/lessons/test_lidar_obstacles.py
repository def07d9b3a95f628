"""LiDAR obstacle avoidance: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest
from support.lessons import SOLUTIONS, failed, failed_checks, feedback_of, not_judged

from turtletui.grading.engine import grade_controllers
from turtletui.grading.engine import random_start as random_start_pose
from turtletui.runtime.resolve import resolve_controllers

LESSON = "lidar-obstacles"
HERE = SOLUTIONS / "lidar_obstacles"
STARTER = Path(__file__).parents[2] / "lessons" / "lidar_obstacles_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "lidar_obstacle_avoider")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_a_narrower_sector_and_other_numbers_pass_too(grade):
    result = grade(LESSON, HERE / "narrow_sector_slow.py")
    assert failed_checks(result) == set()
    assert result.score == result.max_score


def test_every_start_is_clear_of_the_obstacles(grade):
    # random starts are drawn 2 m from the walls, not from the obstacles: the
    # lesson's seeds were chosen so the turtle starts in the open
    from turtletui.sim.obstacles import nearest_distance

    plan = grade.plan(LESSON)
    obstacles = plan.worlds["lidar-course"](0).obstacles
    for run in plan.runs:
        if run.scenario.start == "random":
            assert run.start == random_start_pose(run.seed)
        assert nearest_distance(obstacles, run.start[0], run.start[1]) >= 0.6, run.label


def test_the_part6_wall_avoider_drives_into_the_box_east_of_the_centre(grade):
    # It answers every pose, 62.5 times a second, which makes its sandboxed
    # runs slow: two visible scenarios show the mistake.
    plan = grade.plan(LESSON)
    runs = tuple(r for r in plan.runs if r.label in {"centre", "facing a box"})
    specs = resolve_controllers([HERE / "part6_unchanged.py"])
    result = grade_controllers(dataclasses.replace(plan, runs=runs), specs)
    assert failed(result)["obstacle_hits"] == {"centre", "facing a box"}
    assert "steers by the pose alone" in feedback_of(result, "obstacle_hits")[0]
    assert "wall_hits" not in failed_checks(result)  # inside Part 6's safe box, it is the box it hits


def test_the_middle_of_ranges_is_behind_the_turtle(grade):
    result = grade(LESSON, HERE / "front_is_the_middle.py")
    failures = failed(result)
    assert {"centre", "facing a box", "under the pillar"} <= failures["obstacle_hits"]
    assert "no_crash" not in failures
    text = feedback_of(result, "obstacle_hits")[0]
    assert "ranges[0] is straight ahead" in text and "middle of the list looks behind" in text


def test_stopping_in_front_of_an_obstacle_without_turning_fails_distance_only(grade):
    result = grade(LESSON, HERE / "stops_when_blocked.py")
    assert failed_checks(result) == {"distance"}
    assert len(failed(result)["distance"]) == len(grade.plan(LESSON).runs)  # in every run
    assert "turn toward the more open side" in feedback_of(result, "distance")[0]
    # a turtle that stopped cannot hit anything: the safety checks earn nothing
    # then, and its loop is not judged (it stopped because of the scan, but
    # a node that does not drive earns nothing for its loop)
    gated = not_judged(result)
    assert {"obstacle_hits", "wall_hits", "min_clearance", "no_crash", "closed_loop"} <= set(gated)
    assert result.score == 0.0


def test_reading_inf_as_zero_spins_in_place(grade):
    result = grade(LESSON, HERE / "inf_as_zero.py")
    assert "distance" in failed_checks(result)
    text = feedback_of(result, "distance")[0]
    assert "distance driven: 0 m" in text
    assert "inf means nothing within range_max" in text
    # every reading looks like an obstacle and it turns on the spot: its turns
    # follow the scan (a closed loop), but a turtle that never drives earns
    # nothing for missing the obstacles
    assert {"obstacle_hits", "wall_hits", "min_clearance", "no_crash"} <= set(not_judged(result))
    assert result.score < 1.5


def test_one_beam_misses_no_obstacle_but_scrapes_past_them(grade):
    result = grade(LESSON, HERE / "one_beam.py")
    assert failed_checks(result) == {"min_clearance"}
    assert "watch a sector of beams" in feedback_of(result, "min_clearance")[0]
    assert 0 < result.score < result.max_score


def test_the_starter_runs_and_logs_but_drives_blind(grade):
    result = grade(LESSON, STARTER)
    failures = failed(result)
    assert "no_crash" not in failures
    # it creeps ahead whatever the scan says, too slowly to count as driving:
    # nothing else earns points
    assert "distance" in failures
    assert {"closed_loop", "no_crash"} <= set(not_judged(result))
    assert result.score == 0.0


@pytest.mark.parametrize("solution", ["left_half_of_the_front.py", "stops_at_twenty_centimetres.py"])
def test_shaving_past_obstacles_costs_as_much_as_a_crash_would(grade, solution):
    # half a front sector, or a 0.2 m stop distance: the point turtle never
    # hits anything, but comes within 0.1 m, where a real robot would have
    result = grade(LESSON, HERE / solution)
    assert failed_checks(result) == {"min_clearance"}
    assert result.score < 7.0


def test_scan_without_the_turtles_namespace_is_named_with_the_one_meant(grade):
    result = grade(LESSON, HERE / "scan_without_namespace.py")
    assert result.score == 0.0
    text = feedback_of(result, "distance")[0]
    assert "/obstacle_avoider subscribes to /scan, but nothing publishes it (did you mean /turtle1/scan?)" in text


def test_a_reliable_scan_subscription_hears_nothing_and_is_told_why(grade):
    # The LiDAR publishes best effort, as drivers and Gazebo do: the right
    # avoider with the default QoS never gets a scan, here as on a robot.
    result = grade(LESSON, HERE / "reliable_scan_qos.py")
    assert result.score == 0.0
    text = feedback_of(result, "distance")[0]
    assert (
        "/obstacle_avoider subscribes to /turtle1/scan asking for RELIABLE delivery, but /turtlesim publishes it "
        "BEST_EFFORT: their QoS never match" in text
    )
    assert "subscribe with qos_profile_sensor_data" in text
    hidden = [t.output for t in result.tests if t.hidden and t.check == "distance"]
    assert hidden and all("QoS never matches your node's" in output for output in hidden)


def test_a_sector_minimum_that_keeps_lost_readings_drives_on_blind(grade):
    # numpy.min of a sector with one nan in it is nan, and nan < 0.9 is False:
    # with one reading in ten lost, the turtle misses obstacles it saw coming
    result = grade(LESSON, HERE / "numpy_min_keeps_nan.py")
    assert {"obstacle_hits", "min_clearance"} <= failed_checks(result)
    assert result.score < 5.0
    assert "one nan in the sector makes numpy.min" in feedback_of(result, "obstacle_hits")[0]
