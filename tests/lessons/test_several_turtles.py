"""Several turtles: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

from support.lessons import SOLUTIONS, failed, failed_checks, feedback, feedback_of

LESSON = "several-turtles"
HERE = SOLUTIONS / "several_turtles"
STARTER = Path(__file__).parents[2] / "lessons" / "several_turtles_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "turtle_chaser")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_named_targets_chased_by_their_pose_topic_pass_too(grade):
    result = grade(LESSON, HERE / "named_targets.py")
    assert result.score == result.max_score


def test_never_killing_leaves_the_caught_turtles_in_the_arena(grade):
    result = grade(LESSON, HERE / "never_kills.py")
    assert failed_checks(result) == {"turtles_caught", "turtles_caught: other targets", "turtles_caught: hidden targets"}
    assert any("turtles caught: 0" in text and "/kill it" in text for text in feedback_of(result, "turtles_caught"))
    assert result.score == 0.0


def test_killing_turtle2_every_time_catches_one_turtle(grade):
    result = grade(LESSON, HERE / "kills_turtle2_always.py")
    # a /kill of a turtle that is not there is no kill
    shown = [t.output for t in result.tests if t.check.startswith("turtles_caught") and not t.hidden]
    assert any("turtles caught: 1 " in text and "kills of turtles that did not exist" in text for text in shown)
    assert any("by the name /spawn answered" in text for text in shown)
    assert result.score == 0.0


def test_counting_names_from_one_kills_the_chaser(grade):
    result = grade(LESSON, HERE / "kills_itself.py")
    assert "turtles_caught" in failed_checks(result)
    assert any("killed the chaser turtle1 itself" in text for text in feedback_of(result, "turtles_caught"))


def test_the_starter_runs_and_spawns_one_turtle(grade):
    result = grade(LESSON, STARTER)
    assert "no_crash" not in failed_checks(result)
    assert "turtles_caught" in failed_checks(result)
    assert result.score == 0.0


def test_killing_on_every_pose_catches_them_all_but_loses_the_kill_once_points(grade):
    result = grade(LESSON, HERE / "kills_on_every_pose.py")
    assert failed(result) == {"kills_once": {"centre", "corner", "other targets", "hidden 1"}}
    assert "calls of /kill: 667 (needs <= 16)" in feedback(result, "kills_once")
    assert "set the target to None as soon as you call /kill" in feedback(result, "kills_once")
    assert result.score == 9.0


def test_an_unwrapped_heading_error_catches_them_but_turns_the_long_way(grade):
    result = grade(LESSON, HERE / "chase_without_wrap.py")
    # with the other targets it turned 5.25 rad chasing a sixth one it never caught: not judged
    assert failed(result) == {"longest_turn": {"centre", "corner", "hidden 1"}}
    text = feedback(result, "longest_turn")
    assert "longest turn one way up to each call of /kill" in text
    assert "Wrap the heading error into [-pi, pi]" in text
    assert result.score == 10.0 - 1.5 * 3 / 4
