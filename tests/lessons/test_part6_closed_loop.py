"""Part 6: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

import pytest
from support.lessons import SOLUTIONS, failed_checks, feedback_of, not_judged

LESSON = "part6-closed-loop"
HERE = SOLUTIONS / "part6"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "part6_wall_avoider")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_other_numbers_that_keep_off_the_walls_pass_too(grade):
    result = grade(LESSON, HERE / "fast_turn_tight_box.py")
    assert result.score == result.max_score


def test_the_slow_turn_passes_the_centre_start_but_hits_a_wall_from_others(grade):
    result = grade(LESSON, HERE / "slow_turn.py")
    hits = {t.scenario: t.passed for t in result.tests if t.check == "wall_hits"}
    assert hits["centre"] is True
    assert hits["corner"] is False
    assert failed_checks(result) == {"wall_hits"}
    assert any("turning radius" in text for text in feedback_of(result, "wall_hits"))
    assert 0 < result.score < result.max_score


def test_an_open_loop_timer_fails_the_closed_loop_check(grade):
    result = grade(LESSON, HERE / "open_loop_timer.py")
    assert "closed_loop" in failed_checks(result)
    text = feedback_of(result, "closed_loop")[0]
    assert "the same" in text and "at the same times" in text and "an open loop" in text
    assert "pose callback" in text
    # running without a crash is not the task: only driving round the arena scores
    assert "no_crash" in not_judged(result) and result.score == 1.0


def test_a_crash_near_the_wall_fails_no_crash_with_the_students_line(grade):
    result = grade(LESSON, HERE / "crashes_near_wall.py")
    assert "no_crash" in failed_checks(result)
    crash = feedback_of(result, "no_crash")[0]
    assert "NameError" in crash and "crashes_near_wall.py" in crash


def test_hidden_scenarios_are_graded_but_not_described(grade):
    result = grade(LESSON, HERE / "slow_turn.py")
    hidden = [t for t in result.tests if t.hidden]
    assert hidden and all(t.scenario.startswith("hidden ") for t in hidden)
    assert not any("101" in t.name or "seed" in t.name for t in hidden)


def test_turning_in_the_open_and_racing_near_the_walls_scores_little(grade):
    # a closed loop (its twin, facing a wall, races where it circles here), and
    # 60 m of driving, but round and round its start: it never crosses the arena
    result = grade(LESSON, HERE / "turns_in_the_open.py")
    assert "coverage" in failed_checks(result) and "closed_loop" not in failed_checks(result)
    assert any("the condition is not the wrong way round" in text for text in feedback_of(result, "coverage"))
    assert result.score <= 0.3 * result.max_score


def test_the_wrong_turtles_pose_is_named_not_the_publisher(grade):
    # the node publishes on the right topic; its pose callback never runs
    result = grade(LESSON, HERE / "wrong_turtles_pose.py")
    assert result.score == 0.0
    text = feedback_of(result, "distance")[0]
    assert "your node has a publisher on it but never published" in text
    assert "subscribes to /turtle2/pose, but nothing publishes it (did you mean /turtle1/pose?)" in text


def test_a_turn_that_never_starts_is_told_it_pushes_against_the_wall(grade):
    # it drives at full speed - into the first wall, where it stays: not "hardly drove"
    result = grade(LESSON, HERE / "and_instead_of_or.py")
    assert result.score == 0.0
    text = feedback_of(result, "distance")[0]
    assert "to the end the turtle was pushing against a wall" in text
    assert "did the condition that should turn it away ever hold?" in text
    assert "join the four comparisons with `or`, not `and`" in text


@pytest.mark.parametrize("in_process", [False, True], ids=["sandboxed", "in-process"])
def test_a_publisher_made_per_message_is_told_its_messages_are_lost(grade, in_process):
    # the callback runs and publishes, each time through a publisher too young to be matched
    result = grade(LESSON, HERE / "publisher_per_message.py", in_process=in_process)
    assert result.score == 0.0
    text = feedback_of(result, "distance")[0]
    assert "never published" not in text
    assert "publishers on it, a new one for each message" in text
    assert "create the publisher once, in __init__" in text


def test_a_turn_that_never_brings_the_turtle_back_is_told_it_circles(grade):
    # from the corner start, outside its own box, its tight turn never gets back in
    result = grade(LESSON, HERE / "circles_outside_its_box.py")
    assert result.score < 0.9 * result.max_score
    assert failed_checks(result) == {"coverage"}
    corner = [t.output for t in result.tests if t.check == "coverage" and t.scenario == "corner"][0]
    assert "to the end the turtle went round and round in circles 1.0 m across at (9.1, 8.4)" in corner
    assert "did the condition that ends it ever hold again?" in corner


def test_a_turn_rate_divided_by_the_speed_is_caught_circling_after_a_crossing(grade):
    # 7.5 rad/s at 1 m/s: a circle 0.27 m across just outside the safe zone, for good
    result = grade(LESSON, HERE / "turn_rate_divided_by_speed.py")
    assert "coverage" in failed_checks(result)
    centre = [t.output for t in result.tests if t.check == "coverage" and t.scenario == "centre"][0]
    assert "from t=2.5 s to the end the turtle went round and round in circles 0.3 m across" in centre
