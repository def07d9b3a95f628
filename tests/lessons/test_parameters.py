"""Parameters: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

from support.lessons import SOLUTIONS, failed, feedback, not_judged

LESSON = "parameters"
HERE = SOLUTIONS / "parameters"
STARTER = Path(__file__).parents[2] / "lessons" / "parameters_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "parameters_wall_avoider")
    assert failed(result) == {}
    assert result.score == result.max_score == 10.0


def test_reading_the_parameters_once_in_init_passes_too(grade):
    result = grade(LESSON, HERE / "read_once_in_init.py")
    assert result.score == result.max_score


def test_declared_but_ignored_parameters_change_nothing(grade):
    result = grade(LESSON, HERE / "ignores_parameters.py")
    failures = failed(result)
    assert failures["mean_speed"] == {"slow"}
    assert "small box" in failures["min_clearance"] and "tight turns" in failures["min_clearance"]
    assert "no_crash" not in failures and "wall_hits" not in failures
    assert 'self.get_parameter("speed").value' in feedback(result, "mean_speed")
    # it keeps off the walls only with Part 6's numbers: where it ignored the
    # run's parameters, keeping off the walls earns nothing
    assert {"slow", "small box", "tight turns"} <= not_judged(result)["wall_hits"]
    assert result.score <= 3.0


def test_an_integer_default_refuses_a_float_override(grade):
    result = grade(LESSON, HERE / "integer_default.py")
    failures = failed(result)
    assert failures["no_crash"] == {"slow"}
    text = feedback(result, "no_crash")
    assert "InvalidParameterTypeException" in text and "declare it with 5.0" in text


def test_the_starter_runs_with_speed_done_and_the_rest_to_do(grade):
    result = grade(LESSON, STARTER)
    failures = failed(result)
    assert set(failures) == {"min_clearance", "coordinate_range"}
    assert result.score <= 3.0  # the points are for the parameters it leaves to do


def test_a_box_applied_to_x_only_fails_every_box(grade):
    # the small box starts on a diagonal: a box checked on one axis only lets
    # the turtle run as close to the other axis's walls as with Part 6's numbers
    # (and past both bounds of the boxes off the middle)
    result = grade(LESSON, HERE / "box_in_x_only.py")
    assert failed(result) == {"min_clearance": {"small box"}, "coordinate_range": {"low box", "high box"}}
    assert "Compare pose.x and pose.y with the box_min and box_max" in feedback(result, "min_clearance")
    assert result.score < 7.0


def test_a_box_max_worked_out_from_box_min_fails_the_low_box(grade):
    # box_max = 11 - box_min holds for every symmetric box: only a box off the
    # middle shows that the box_max parameter is never used
    result = grade(LESSON, HERE / "box_max_from_box_min.py")
    assert failed(result) == {"coordinate_range": {"low box"}}
    text = feedback(result, "coordinate_range")
    assert text.startswith("highest x or y: ")
    assert "did not respect the box's upper bound, box_max" in text and "not 11 - box_min" in text
    assert result.score < 9.0


def test_a_box_min_worked_out_from_box_max_fails_the_high_box(grade):
    result = grade(LESSON, HERE / "box_min_from_box_max.py")
    assert failed(result) == {"coordinate_range": {"high box"}}
    text = feedback(result, "coordinate_range")
    assert text.startswith("lowest x or y: ")
    assert "did not respect the box's lower bound, box_min" in text and "not 11 - box_max" in text
    assert result.score < 9.0


def test_a_box_test_that_is_always_true_is_told_every_command_was_the_same(grade):
    result = grade(LESSON, HERE / "box_test_inverted.py")
    assert "closed_loop" in failed(result)
    assert result.score <= 1.0
    text = feedback(result, "closed_loop")
    assert "every one was the same Twist (linear.x=1, angular.z=1.5)" in text
    assert "that comparison came out the same on every pose" in text


def test_a_misnamed_parameter_fails_its_run_by_a_hair_and_says_so_in_digits(grade):
    result = grade(LESSON, HERE / "turn_rate_misnamed.py")
    assert set(failed(result)) == {"min_clearance"}
    assert result.score < 7.5
    text = feedback(result, "min_clearance")
    assert "closest to a wall or obstacle: 1.496 m (needs >= 1.50 m)" in text
    assert 'a parameter declared as "turning_rate" at its default' in text


def test_declaring_in_the_callback_crashes_on_the_second_pose_and_is_told_why(grade):
    result = grade(LESSON, HERE / "declares_in_the_callback.py")
    assert result.score == 0.0
    text = feedback(result, "no_crash")
    assert "ParameterAlreadyDeclaredException: Parameter(s) already declared: ['speed']" in text
    assert "a declare_parameter that runs twice" in text


def test_a_slow_timer_that_circles_outside_the_box_is_not_told_its_defaults_are_wrong(grade):
    result = grade(LESSON, HERE / "slow_timer_circles_outside_the_box.py")
    assert failed(result)["mean_speed"] == {"defaults"}
    assert result.score < 9.0
    text = feedback(result, "mean_speed")
    assert "mean speed: 1.50 m/s (needs >= 2.20 m/s)" in text
    assert "With those defaults and still slow, the turtle spent the run circling slowly outside the box" in text
