"""Go to goal: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

from support.lessons import SOLUTIONS, failed, feedback

LESSON = "go-to-goal"
HERE = SOLUTIONS / "go_to_goal"
STARTER = Path(__file__).parents[2] / "lessons" / "go_to_goal_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "go_to_goal")
    assert failed(result) == {}
    assert result.score == result.max_score == 10.0


def test_turning_first_and_other_gains_pass_too(grade):
    result = grade(LESSON, HERE / "drive_then_turn.py")
    assert result.score == result.max_score


def test_atan_instead_of_atan2_misses_goals_to_the_left(grade):
    result = grade(LESSON, HERE / "atan_not_atan2.py")
    failures = failed(result)
    assert "goal to the left" in failures["time_to_goal"]
    assert "default goal" not in failures["time_to_goal"]  # up and right: atan is right there
    assert "math.atan2(dy, dx)" in feedback(result, "time_to_goal")
    # straight below the turtle, dy / dx divides by zero
    assert failures["no_crash"] == {"goal behind"}
    assert "ZeroDivisionError" in feedback(result, "no_crash")


def test_no_tolerance_reaches_the_goal_but_circles_it(grade):
    result = grade(LESSON, HERE / "no_tolerance.py")
    failures = failed(result)
    assert set(failures) == {"final_error"}
    assert "tolerance" in feedback(result, "final_error")
    assert 0 < result.score < result.max_score


def test_a_huge_linear_gain_runs_into_the_wall(grade):
    result = grade(LESSON, HERE / "high_gain.py")
    assert "wall_hits" in failed(result)
    assert "linear gain is too high" in feedback(result, "wall_hits")


def test_the_starter_runs_but_goes_nowhere(grade):
    result = grade(LESSON, STARTER)
    failures = failed(result)
    assert "no_crash" not in failures and "wall_hits" not in failures
    assert set(failures) == {"time_to_goal", "final_error"}


def test_an_error_never_wrapped_spins_when_the_goal_is_due_west(grade):
    result = grade(LESSON, HERE / "no_wrap.py")
    failures = failed(result)
    assert failures["time_to_goal"] == {"goal due west"}
    assert "math.atan2(math.sin(e), math.cos(e))" in feedback(result, "time_to_goal")
    assert result.score < result.max_score


def test_a_plan_made_from_the_first_pose_and_driven_by_the_clock_is_lost_when_the_turtle_is_moved(grade):
    result = grade(LESSON, HERE / "timed_from_first_pose.py")
    failures = failed(result)
    # undisturbed, the plan arrives: the default goal and the one to the left are reached
    assert "default goal" not in failures.get("time_to_goal", set())
    assert "goal to the left" not in failures.get("time_to_goal", set())
    # the hidden runs teleport the turtle on its way: the plan drives on and misses
    assert {"hidden 1", "hidden 2"} <= failures["time_to_goal"] & failures["final_error"]
    assert "never from a plan made from the first pose" in feedback(result, "time_to_goal")
    # it stops where its plan ends: the hidden runs' final_error says why, not only "circling"
    assert "ends where the plan ends" in feedback(result, "final_error")


def test_a_node_that_stops_for_good_at_the_goal_is_moved_before_it_arrives(grade):
    # brisk gains reach hidden 1's goal (1.6 m off) in about 1.3 s; the
    # scenario's teleport must come before that, or it moves a turtle whose
    # node has rightly stopped for good
    result = grade(LESSON, HERE / "latched_brisk_gains.py")
    assert failed(result) == {}
    assert result.score == result.max_score


HEADING_ERROR = "math.atan2(dy, dx) - pose.theta"


def test_atan2_with_its_arguments_swapped_is_told_dy_comes_first(grade):
    result = grade(LESSON, HERE / "atan2_arguments_swapped.py")
    assert "default goal" in failed(result)["time_to_goal"]
    assert result.score == 0.0
    assert "atan2 takes dy first" in feedback(result, "time_to_goal")


def test_a_heading_error_the_wrong_way_round_steers_away_and_is_told_so(grade):
    result = grade(LESSON, HERE / "error_sign_flipped.py")
    assert "default goal" in failed(result)["time_to_goal"]
    assert result.score == 0.0
    text = feedback(result, "time_to_goal")
    assert HEADING_ERROR in text and "pose.theta - math.atan2(dy, dx) steers away from the goal" in text


def test_the_heading_from_the_wrong_pose_field_is_told_which_field(grade):
    result = grade(LESSON, HERE / "angular_velocity_for_theta.py")
    assert "default goal" in failed(result)["time_to_goal"]
    assert result.score == 0.0
    assert "pose.angular_velocity only how fast it turns" in feedback(result, "time_to_goal")


def test_goal_parameters_declared_but_ignored_reach_only_the_default_goal(grade):
    result = grade(LESSON, HERE / "goal_parameters_ignored.py")
    failures = failed(result)
    assert "default goal" not in failures["time_to_goal"]
    assert {"goal to the left", "goal behind", "goal due west"} <= failures["time_to_goal"]
    assert result.score < 2.0
    text = feedback(result, "time_to_goal")
    assert "This run sets the goal with -p goal_x:=2.0 -p goal_y:=6.0" in text
    assert 'self.get_parameter("goal_x").value' in text


def test_a_tolerance_wider_than_the_goals_stops_short_and_is_told_so(grade):
    result = grade(LESSON, HERE / "tolerance_half_a_metre.py")
    failures = failed(result)
    assert {"default goal", "goal to the left"} <= failures["time_to_goal"] & failures["final_error"]
    assert result.score == 0.0
    text = feedback(result, "time_to_goal")
    assert "your node stopped it 0.49 m from the goal with zero Twists: it stops further out than 0.1 m" in text
    assert "stops further out than 0.1 m" in feedback(result, "final_error")


def test_a_speed_from_dx_backs_away_from_goals_to_the_left(grade):
    result = grade(LESSON, HERE / "linear_speed_from_dx.py")
    failures = failed(result)
    assert "default goal" not in failures["time_to_goal"]  # dx > 0 there: it works
    assert {"goal to the left", "goal due west"} <= failures["time_to_goal"]
    assert result.score < 2.0
    assert "linear.x was negative in 100% of the commands: the turtle drove backwards" in feedback(result, "time_to_goal")


def test_a_callback_that_sleeps_is_told_its_commands_come_late(grade):
    result = grade(LESSON, HERE / "sleeps_in_the_pose_callback.py")
    assert "default goal" in failed(result)["time_to_goal"]
    assert result.score == 0.0
    assert "your node sent a command only every 0.20 s" in feedback(result, "time_to_goal")


def test_a_wrap_by_pi_fails_the_hidden_starts_and_their_feedback_names_it(grade):
    result = grade(LESSON, HERE / "wraps_by_pi_not_two_pi.py")
    assert {"hidden 1", "hidden 2"} <= failed(result)["time_to_goal"]
    assert result.score < 8.0
    assert "adding or taking away pi (not 2 pi)" in feedback(result, "time_to_goal")


def test_degrees_against_radians_is_named_in_the_feedback(grade):
    result = grade(LESSON, HERE / "degrees_minus_radians.py")
    assert "default goal" in failed(result)["time_to_goal"]
    assert result.score == 0.0
    assert "Both angles are in radians: math.degrees() on one of them" in feedback(result, "time_to_goal")


def test_a_goal_read_as_0_0_is_told_where_the_node_stopped_not_that_its_tolerance_is_wide(grade):
    # .double_value of an INTEGER parameter is 0.0: without -p the node drives
    # to the corner and stops there; with -p goal_x:=2.0 it cannot even start
    result = grade(LESSON, HERE / "integer_default_read_as_double.py")
    assert result.score == 0.0
    text = feedback(result, "time_to_goal")
    assert "your node stopped it with zero Twists at (0.04, 0.03), 11.26 m from the goal: does it steer to another goal?" in text
    assert "stops further out than" not in text
    assert "declare it with 8.0, not 8" in feedback(result, "no_crash")


def test_an_error_wrapped_into_zero_to_two_pi_turns_the_long_way_and_is_told_so(grade):
    # brisk gains make the long way round quick: every goal is still reached
    # in time, and only the turning shows the wrap
    result = grade(LESSON, HERE / "wraps_into_zero_to_two_pi.py")
    failures = failed(result)
    assert set(failures) == {"longest_turn"}
    # the default goal is up and to the left: the wrap does no harm on the way there
    assert failures["longest_turn"] == {"goal to the left", "goal behind", "goal due west", "hidden 1", "hidden 2"}
    assert result.score < 9.0
    text = feedback(result, "longest_turn")
    assert "longest turn one way on its way to the goal: " in text and "(needs <= 4.71 rad)" in text
    assert "e % (2 * math.pi) gives [0, 2 pi)" in text


def test_an_error_wrapped_on_one_side_only_spins_due_west_and_is_told_so(grade):
    result = grade(LESSON, HERE / "wraps_one_side_only.py")
    assert failed(result) == {"longest_turn": {"goal due west"}}
    assert result.score < result.max_score
    assert "leaves errors below -pi unwrapped" in feedback(result, "longest_turn")
