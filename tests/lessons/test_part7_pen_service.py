"""Part 7: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

from support.lessons import SOLUTIONS, failed, failed_checks, feedback, feedback_of

LESSON = "part7-pen-service"
HERE = SOLUTIONS / "part7"
STARTER = Path(__file__).parents[2] / "lessons" / "part7_starter.py"

ONLY_ON_CHANGE = "only when the turtle changes side"
TWO_COLOURS = "one colour right of x = 5.5 and another colour left of it"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "part7_pen_color")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_other_colours_and_another_way_to_remember_the_side_pass_too(grade):
    result = grade(LESSON, HERE / "side_attribute_blue_yellow.py")
    assert result.score == result.max_score


def test_calling_from_every_pose_fails_the_calls_check_only(grade):
    result = grade(LESSON, HERE / "calls_every_pose.py")
    assert failed_checks(result) == {"calls_per_side_change"}
    text = feedback_of(result, "calls_per_side_change")[0]
    assert ONLY_ON_CHANGE in text and "62.5 calls a second" in text


def test_forgetting_to_store_the_side_floods_the_service_and_keeps_one_colour(grade):
    result = grade(LESSON, HERE / "forgets_previous_x.py")
    assert failed_checks(result) == {"calls_per_side_change", "pen_colour_by_side"}
    # (each flooded call makes a new client that waits for discovery, 50 ms:
    # from the centre the slowed node never reaches the left side)
    assert any("the same colour on both sides" in text for text in feedback_of(result, "pen_colour_by_side"))


def test_the_same_colour_on_both_sides_fails_the_colour_check_only(grade):
    result = grade(LESSON, HERE / "same_colour_both_sides.py")
    assert failed_checks(result) == {"pen_colour_by_side"}
    text = feedback_of(result, "pen_colour_by_side")[0]
    assert TWO_COLOURS in text and "use two different colours" in text


def test_a_request_never_sent_fails_both_and_is_told_about_call_async(grade):
    result = grade(LESSON, HERE / "never_sends_the_request.py")
    assert failed_checks(result) == {"calls_per_side_change", "pen_colour_by_side"}
    text = feedback_of(result, "calls_per_side_change")[0]
    assert "0 calls of /turtle1/set_pen" in text and "client.call_async(request)" in text


def test_hidden_starts_are_graded_but_not_described(grade):
    result = grade(LESSON, "part7_pen_color")
    hidden = [t for t in result.tests if t.hidden]
    assert {t.scenario for t in hidden} == {"hidden 1", "hidden 2"}
    assert not any("west" in t.name for t in hidden)


def test_the_starter_runs_without_crashing(grade):
    result = grade(LESSON, STARTER)
    assert "no_crash" not in failed_checks(result)
    assert {"calls_per_side_change", "pen_colour_by_side"} <= failed_checks(result)


def test_a_synchronous_call_in_the_pose_callback_is_the_deadlock_it_is_in_ros(grade):
    result = grade(LESSON, HERE / "sync_call_in_the_callback.py")
    assert failed_checks(result) == {"no_crash"}
    assert result.score == 0.0
    text = "\n".join(feedback_of(result, "no_crash"))
    assert "Client.call() inside a callback would deadlock in ROS 2" in text and "call_async()" in text


def test_skipping_wait_for_service_loses_every_request_and_is_told_so(grade):
    # a new client per call, as in the course's code, without its wait: each
    # request goes out before discovery and is lost, as in ROS 2
    result = grade(LESSON, HERE / "skips_wait_for_service.py")
    assert failed_checks(result) == {"calls_per_side_change", "pen_colour_by_side"}
    assert result.score == 0.0
    for check in ("calls_per_side_change", "pen_colour_by_side"):
        text = feedback_of(result, check)[0]
        assert "before it had discovered the service's server, so the request was lost" in text
        assert text.count("Wait with client.wait_for_service() before the first call.") == 1  # said once


def test_width_and_off_swapped_lifts_the_pen_and_is_told_so(grade):
    result = grade(LESSON, HERE / "width_and_off_swapped.py")
    assert failed_checks(result) == {"pen_colour_by_side"}
    assert result.score == 0.0
    text = feedback_of(result, "pen_colour_by_side")[0]
    assert "the pen was off wherever the turtle drove" in text and "off must be 0" in text
    assert "same colour" not in text


def test_colours_as_fractions_are_refused_as_in_ros(grade):
    result = grade(LESSON, HERE / "colours_as_fractions.py")
    assert failed_checks(result) == {"no_crash"}
    assert result.score == 0.0
    assert "The 'r' field must be of type 'int' (got float 1.0" in feedback_of(result, "no_crash")[0]


STOOD_STILL = "the last velocity command that moves the turtle came at t=0.1 s of 12 s"


def test_driving_only_when_the_side_changes_is_not_part_6s_turtle(grade):
    # it publishes a Twist only at a crossing: the turtle moves 1 s and stops;
    # where it still crossed the line by luck, its colours alone earn little
    result = grade(LESSON, HERE / "publishes_only_when_the_side_changes.py")
    failures = failed(result)
    assert {"centre", "right half"} <= failures["time_moving"]
    assert {"centre", "right half"} <= failures["pen_colour_by_side"]
    assert result.score <= 2.0
    text = feedback(result, "pen_colour_by_side")
    assert "never drove on the left side of x = 5.5; " + STOOD_STILL in text
    assert "with the set_pen call beside it, not around it" in feedback(result, "time_moving")


def test_awaiting_the_answer_in_the_pose_callback_stops_the_node_and_is_told_why(grade):
    # rclpy holds the default callback group while the coroutine waits, and
    # hands the answer over in that same group: the node waits for ever
    result = grade(LESSON, HERE / "awaits_the_answer_in_the_callback.py")
    assert result.score == 0.0
    assert STOOD_STILL in feedback(result, "pen_colour_by_side")
    text = feedback(result, "time_moving")
    assert "moving 8% of the run" in text and "an await of client.call_async(request) inside the callback" in text


def test_a_side_read_from_y_is_shown_where_the_pen_changed(grade):
    result = grade(LESSON, HERE / "side_from_y_not_x.py")
    assert "pen_colour_by_side" in failed_checks(result)
    assert result.score == 0.0
    text = feedback(result, "pen_colour_by_side")
    assert "the pen changed colour at x = 1.4, 9.7, 3.6 (the line is x = 5.5)" in text


def test_a_timer_that_sets_the_pen_every_tick_is_a_flood_too(grade):
    result = grade(LESSON, HERE / "timer_sets_the_pen_every_tick.py")
    assert failed_checks(result) == {"calls_per_side_change"}
    assert result.score == 6.0
    text = feedback(result, "calls_per_side_change")
    assert "119 calls of /turtle1/set_pen for 3 crossings" in text and "nor from every tick of a timer" in text


def test_a_wait_with_a_timeout_in_the_callback_runs_as_in_ros_and_is_named(grade):
    # rclpy spins again inside the callback and returns at the timeout (no deadlock,
    # no crash): each side change freezes the node for 1 s, at 5 m/s, into the wall
    # https://github.com/ros2/rclpy/issues/1018
    result = grade(LESSON, HERE / "waits_with_a_timeout_in_the_callback.py")
    assert {"pen_colour_by_side", "wall_hits"} <= failed_checks(result)
    assert result.score < 5.0
    text = "\n".join(feedback_of(result, "wall_hits"))
    assert "with spin_until_future_complete(), for a service's response that could only be handled" in text
    assert "give the client a callback group of its own" in text


def test_the_course_package_is_graded_by_its_turtle_controller_without_naming_it(tmp_path):
    # Part 7 grows Part 6's turtle_controller in the same my_robot_controller
    # package, beside test_node: without the lesson's default every package
    # hand-in was "several possible controllers" until --executable was given
    import json

    from support.grading import grade_cli
    from support.ros_package import EXECUTABLE, PACKAGE, write_package

    reference = Path(__file__).parents[2] / "plugins" / "reference" / "turtle_controller_pen.py"
    package = write_package(tmp_path / "alice", reference.read_text())
    result = grade_cli(package, "--lesson", LESSON, "--format", "json", "--results", tmp_path / "res", "--same-user")
    assert result.exit_code == 0, result.stderr
    (sub,) = json.loads(result.stdout)["submissions"]
    assert sub["error"] is None, sub["error"]
    assert sub["graded"] == f"{PACKAGE}/{EXECUTABLE}.py ({PACKAGE} {EXECUTABLE}: main())"
    assert sub["score"] == sub["max_score"] == 10.0
