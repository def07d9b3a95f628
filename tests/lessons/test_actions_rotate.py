"""Actions: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

from support.lessons import SOLUTIONS, failed_checks, feedback_of

LESSON = "actions-rotate"
HERE = SOLUTIONS / "actions_rotate"
CORPUS = Path(__file__).parent / "corpus" / LESSON
STARTER = Path(__file__).parents[2] / "lessons" / "actions_rotate_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "rotate_action_client")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_waiting_in_main_with_spin_until_future_complete_passes_too(grade):
    result = grade(LESSON, HERE / "send_goal_in_main.py")
    assert result.score == result.max_score


def test_goals_sent_all_at_once_replace_each_other(grade):
    result = grade(LESSON, HERE / "fire_and_forget.py")
    assert {"goals_reached", "headings_faced"} <= failed_checks(result)
    assert "goals_sent" not in failed_checks(result)
    assert any("result callback" in text for text in feedback_of(result, "goals_reached"))
    assert any("1 of 4 goals reached" in text for text in feedback_of(result, "goals_reached"))


def test_a_timer_that_does_not_wait_for_results_fails_goals_reached(grade):
    result = grade(LESSON, HERE / "timer_no_wait.py")
    assert "goals_reached" in failed_checks(result)
    assert any("not all at once or from a timer" in text for text in feedback_of(result, "goals_reached"))


def test_headings_in_degrees_wait_properly_but_face_the_wrong_ways(grade):
    result = grade(LESSON, HERE / "degrees.py")
    assert failed_checks(result) == {"headings_faced"}
    text = feedback_of(result, "headings_faced")[0]
    assert "never stopped facing 1.57 rad" in text and "radians" in text


def test_the_starter_runs_and_sends_one_goal(grade):
    result = grade(LESSON, STARTER)
    assert "no_crash" not in failed_checks(result)
    assert "goals_sent" in failed_checks(result)


def test_a_first_goal_sent_before_discovery_is_lost_and_told_so(grade):
    # as in ROS 2: the goal goes out before the client has discovered the
    # action's server and is never answered, so the chain of goals never starts
    result = grade(LESSON, HERE / "skips_wait_for_server.py")
    assert "goals_reached" in failed_checks(result)
    text = feedback_of(result, "goals_reached")[0]
    assert "before it had discovered the action's server, so the goal was lost" in text
    assert text.count("Wait with action_client.wait_for_server() before the first goal.") == 1


def test_the_feedback_logged_in_other_words_scores_full_marks(grade):
    # "0.42 rad to go": the number is the feedback, whatever the words around it
    result = grade(LESSON, CORPUS / "right_feedback_in_other_words.py")
    assert result.score == result.max_score


def test_a_node_that_never_logs_the_feedback_fails_only_that(grade):
    # its "Sending goal: theta = 1.57 rad" and "Goal done" lines carry other numbers
    result = grade(LESSON, HERE / "feedback_not_logged.py")
    assert failed_checks(result) == {"log_feedback"}
    assert "log lines with the feedback: 0 (needs >= 3)" in feedback_of(result, "log_feedback")[0]
    assert result.score == 9.0


def test_velocity_commands_that_abort_the_goals_are_named(grade):
    result = grade(LESSON, HERE / "zero_twist_timer.py")
    assert "goals_reached" in failed_checks(result)
    text = feedback_of(result, "goals_reached")[0]
    assert "velocity commands on /turtle1/cmd_vel while a goal was in progress" in text
    assert "any message on /turtle1/cmd_vel (a zero Twist too)" in text
    assert result.score < 5.0


def test_an_action_without_its_turtles_namespace_is_named_with_the_one_meant(grade):
    result = grade(LESSON, HERE / "action_without_namespace.py")
    assert result.score == 0.0
    text = feedback_of(result, "goals_sent")[0]
    assert "is an action client of /rotate_absolute, but nothing serves it (did you mean /turtle1/rotate_absolute?)" in text


def test_feedback_read_without_its_feedback_field_crashes_and_is_told_the_field(grade):
    result = grade(LESSON, HERE / "feedback_msg_remaining.py")
    assert "no_crash" in failed_checks(result)
    assert result.score == 0.0  # it stops at the first feedback, one goal sent
    text = feedback_of(result, "no_crash")[0]
    assert "AttributeError: 'RotateAbsolute_FeedbackMessage' object has no attribute 'remaining'" in text
    assert "feedback_msg.feedback.remaining" in text


def test_the_goals_heading_logged_as_the_remaining_angle_fails_log_feedback(grade):
    # the words match, the number does not follow the turn: the feedback was never read
    result = grade(LESSON, HERE / "logs_the_goal_as_remaining.py")
    assert failed_checks(result) == {"log_feedback"}
    assert result.score == 9.0


def test_awaiting_goals_in_a_timer_of_the_client_s_own_group_never_hears_back(grade):
    result = grade(LESSON, HERE / "async_await_in_the_default_group.py")
    assert "goals_sent" in failed_checks(result)
    assert "goals sent to /turtle1/rotate_absolute: 1 (needs >= 4" in feedback_of(result, "goals_sent")[0]
    assert result.score < 5.0
