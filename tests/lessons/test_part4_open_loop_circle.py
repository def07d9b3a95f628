"""Part 4: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.lessons import SOLUTIONS, failed_checks, feedback_of

LESSON = "part4-open-loop-circle"
HERE = SOLUTIONS / "part4"
STARTER = Path(__file__).parents[2] / "lessons" / "part4_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "part4_draw_circle")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_a_smaller_clockwise_circle_published_faster_passes_too(grade):
    result = grade(LESSON, HERE / "small_clockwise_circle.py")
    assert result.score == result.max_score


@pytest.mark.parametrize(
    ("solution", "driving"),
    [
        # from __init__, before turtlesim discovered the publisher: lost
        ("publish_once.py", 0),
        # once turtlesim subscribes: 1 s of a 15 s run
        ("publish_once_when_matched.py", 7),
    ],
)
def test_publishing_once_fails_the_keep_moving_check(grade, solution, driving):
    result = grade(LESSON, HERE / solution)
    assert {"time_moving", "circle"} <= failed_checks(result)
    text = feedback_of(result, "time_moving")[0]
    assert "1 s after the last velocity command" in text
    assert f"driving {driving}% of the run (needs >= 80%; turning in place does not count)" in text


def test_a_timer_slower_than_the_command_timeout_fails_only_the_keep_moving_check(grade):
    result = grade(LESSON, HERE / "slow_timer.py")
    assert failed_checks(result) == {"time_moving"}
    assert "period is well under 1 s" in feedback_of(result, "time_moving")[0]


def test_linear_only_drives_straight_into_the_wall(grade):
    result = grade(LESSON, HERE / "linear_only.py")
    assert failed_checks(result) == {"circle", "wall_hits"}
    assert "radius is linear.x / angular.z" in feedback_of(result, "circle")[0]


def test_a_circle_too_big_for_the_arena_hits_the_wall(grade):
    result = grade(LESSON, HERE / "too_big.py")
    assert "wall_hits" in failed_checks(result)
    assert "keep linear.x / angular.z under about 2.5 m" in feedback_of(result, "wall_hits")[0]


def test_the_hidden_start_is_graded_but_not_named(grade):
    result = grade(LESSON, "part4_draw_circle")
    hidden = [t for t in result.tests if t.hidden]
    assert hidden and all(t.scenario == "hidden 1" for t in hidden)
    assert not any("west" in t.name for t in hidden)


def test_the_starter_runs_without_crashing(grade):
    result = grade(LESSON, STARTER)
    assert "no_crash" not in failed_checks(result)
    assert "time_moving" in failed_checks(result)


def test_a_misspelt_topic_is_named_as_the_likely_cause(grade):
    result = grade(LESSON, HERE / "misspelt_topic.py")
    assert failed_checks(result) == {"circle", "time_moving"}
    text = feedback_of(result, "circle")[0]
    assert "barely moved" in text and "nothing was published on /turtle1/cmd_vel" in text
    assert result.score == 0.0


def test_a_loop_on_create_rate_beside_a_spinning_thread_passes_too(grade):
    # sandboxed only: the in-process host runs no threads of a controller
    result = grade(LESSON, HERE / "right_rate_in_a_thread.py")
    assert result.score == result.max_score


@pytest.mark.parametrize("in_process", [False, True], ids=["sandboxed", "in-process"])
def test_a_twist_stamped_on_cmd_vel_moves_nothing_and_feedback_says_why(grade, in_process):
    # As in ROS: endpoints of different types never match; nothing crashes the grader
    result = grade(LESSON, HERE / "twist_stamped.py", in_process=in_process)
    assert "no_crash" not in failed_checks(result)
    assert {"circle", "time_moving"} <= failed_checks(result)
    assert result.score == 0.0
    text = " ".join(feedback_of(result, "circle"))
    assert "with type geometry_msgs/msg/TwistStamped" in text and "never match" in text
    assert "cannot accept" not in " ".join(t.output for t in result.tests)


def test_a_node_stopped_without_a_traceback_is_not_told_to_read_one(grade):
    result = grade(LESSON, HERE / "blocks_in_a_callback.py")
    assert "no_crash" in failed_checks(result)
    text = "\n".join(feedback_of(result, "no_crash"))
    assert "did not answer within" in text
    assert "traceback" not in text.lower()
    assert "the lines above say why" in text


def test_an_error_in_an_executor_thread_is_the_crash_it_is_in_ros(grade):
    # The pose callback fails once in the MultiThreadedExecutor's other thread: in ROS 2
    # spin() raises it in main() and the node dies; it must not drive on to full marks.
    result = grade(LESSON, HERE / "raises_in_an_executor_thread.py")
    assert "no_crash" in failed_checks(result)
    assert result.score == 0.0
    text = "\n".join(feedback_of(result, "no_crash"))
    assert "IndexError: list index out of range" in text
    assert "executor.spin()" in text and "self.speeds[-1]" in text  # the traceback, through main()


def test_a_publisher_that_never_publishes_is_told_so_not_to_check_its_topic(grade):
    result = grade(LESSON, HERE / "timer_after_spin.py")
    assert result.score == 0.0
    text = feedback_of(result, "circle")[0]
    assert "your node has a publisher on it but never published" in text
    assert "is that the topic" not in text


def test_cmd_vel_without_the_turtles_namespace_is_named_with_the_one_meant(grade):
    result = grade(LESSON, HERE / "cmd_vel_without_namespace.py")
    assert result.score == 0.0
    text = feedback_of(result, "circle")[0]
    assert "/draw_circle publishes on /cmd_vel, but nothing subscribes to it (did you mean /turtle1/cmd_vel?)" in text


@pytest.mark.parametrize(
    ("solution", "why"),
    [
        ("sleeps_in_the_timer.py", "the commands came up to 2.0 s apart, and turtlesim stops a turtle 1 s after"),
        ("slow_timer.py", "s apart, and turtlesim stops a turtle 1 s after the last one"),
        ("stops_after_a_lap.py", "the last velocity command that moves the turtle came at t=7.0 s of 15 s"),
    ],
)
def test_a_circle_in_fits_and_starts_earns_the_circle_only_and_is_told_why(grade, solution, why):
    # keeping off the walls and not crashing count only for a turtle that keeps driving
    result = grade(LESSON, HERE / solution)
    assert failed_checks(result) == {"time_moving"}
    assert result.score == 4.0
    assert why in feedback_of(result, "time_moving")[0]
