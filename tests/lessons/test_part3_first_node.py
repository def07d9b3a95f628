"""Part 3: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.lessons import SOLUTIONS, failed_checks, feedback_of, not_judged

LESSON = "part3-first-node"
HERE = SOLUTIONS / "part3"
STARTER = Path(__file__).parents[2] / "lessons" / "part3_starter.py"


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "part3_first_node")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_another_period_start_and_wording_pass_too(grade):
    result = grade(LESSON, HERE / "fast_timer_other_words.py")
    assert result.score == result.max_score


def test_a_counter_never_incremented_fails_the_counter_check(grade):
    result = grade(LESSON, HERE / "counter_never_incremented.py")
    assert failed_checks(result) == {"log_counter"}
    (text,) = feedback_of(result, "log_counter")
    assert "went from 0 to 0" in text
    assert "self.counter_ += 1" in text


def test_a_local_counter_fails_the_counter_check_and_is_told_why(grade):
    result = grade(LESSON, HERE / "local_counter.py")
    assert failed_checks(result) == {"log_counter"}
    (text,) = feedback_of(result, "log_counter")
    assert "went from 1 to 1" in text
    assert "A local variable set to 0 inside the callback" in text


def test_logging_once_from_init_fails_the_timer_check(grade):
    result = grade(LESSON, HERE / "logs_once_from_init.py")
    assert "log_period" in failed_checks(result)
    (text,) = feedback_of(result, "log_period")
    assert "1 log line matching" in text and "from a timer callback" in text and "__init__ runs once" in text
    # it did not crash, but running without a timer is not the task: no points for it
    assert "no_crash" not in failed_checks(result) and "no_crash" in not_judged(result)
    assert result.score == 0.0


def test_a_period_in_milliseconds_is_told_that_create_timer_takes_seconds(grade):
    result = grade(LESSON, HERE / "timer_in_milliseconds.py")
    assert result.score == 0.0
    for text in feedback_of(result, "log_period") + feedback_of(result, "log_counter"):
        assert "a timer with a period of 1000 s first fires 1000 s after it is made" in text
        assert "create_timer() takes seconds, not milliseconds" in text


def test_a_timer_on_a_node_nothing_spins_is_told_which_node_waits(grade):
    result = grade(LESSON, HERE / "second_node_never_spun.py")
    assert result.score == 0.0
    (text,) = feedback_of(result, "log_period")
    assert text.startswith("0 log lines")
    assert "/first_node: a callback of this node is ready, but no executor has this node" in text


@pytest.mark.parametrize("in_process", [False, True], ids=["sandboxed", "in-process"])
@pytest.mark.parametrize("solution", ["sleep_loop_in_main.py", "spin_once_loop.py"])
def test_a_counter_logged_by_a_loop_in_main_is_not_a_timer(grade, solution, in_process):
    result = grade(LESSON, HERE / solution, in_process=in_process)
    assert failed_checks(result) == {"log_period"}
    (text,) = feedback_of(result, "log_period")
    assert "were logged outside any callback" in text and "time.sleep(1.0) prints the same lines" in text
    assert "sleeps or calls spin_once between lines" in text  # the spin_once loop is told of too
    assert result.score == 0.0


def test_the_starter_runs_without_crashing_but_scores_nothing(grade):
    result = grade(LESSON, STARTER)
    # its start-up line "First node has started" ends with no number: not a counter line
    assert failed_checks(result) == {"log_period", "log_counter"}
    assert "0 log lines" in feedback_of(result, "log_period")[0]
    assert result.score == 0.0


@pytest.mark.parametrize(
    "solution",
    [
        "right_rclpy_logging_in_timer.py",
        "right_multithreaded_executor.py",
        "right_spin_in_a_thread.py",
        "right_async_timer_callback.py",
        "right_spin_once_loop_timer_logs.py",
        "right_task_from_timer.py",
    ],
)
def test_a_timer_callback_logs_from_any_executor_thread_or_task(grade, solution):
    # log_period's in_callback must hold wherever an executor runs the callback:
    # worker threads, a spin thread, a task's steps, a spin_once loop
    result = grade(LESSON, HERE / solution)
    assert failed_checks(result) == set()
    assert result.score == result.max_score


def test_printed_lines_do_not_count_as_a_timers_log(grade):
    # sandboxed, a printed line becomes a log line of "<name>:stdout", and a
    # pipe cannot say which callback printed it: only the logger's lines count
    result = grade(LESSON, HERE / "print_sleep_loop.py")
    assert failed_checks(result) == {"log_period"}
    (text,) = feedback_of(result, "log_period")
    assert "printed lines do not count" in text and "self.get_logger().info" in text
    assert result.score == 0.0


@pytest.mark.parametrize(
    ("solution", "quoted"),
    [("string_without_its_f.py", "'Hello {self.counter_}'"), ("counter_in_mid_line.py", "'Hello 9 from first_node'")],
)
def test_timer_lines_without_a_number_at_the_end_are_quoted(grade, solution, quoted):
    # the timer and the counter are right, the line is not a counter line: the
    # student is shown the line the grader could not read, not only "0 lines"
    result = grade(LESSON, HERE / solution)
    assert failed_checks(result) == {"log_period", "log_counter"}
    assert result.score == 0.0
    (text,) = feedback_of(result, "log_period")
    assert f"10 lines logged from callbacks did not match it, such as {quoted}" in text
    assert "with the number in the middle" in text and "a string without its f" in text


def test_a_callback_called_instead_of_passed_logs_once_from_init_and_is_told_so(grade):
    # create_timer(1.0, self.timer_callback()) runs the callback once and hands
    # the timer None, which rclpy's executor skips: one line, from __init__
    result = grade(LESSON, HERE / "callback_called_not_passed.py")
    assert failed_checks(result) == {"log_period", "log_counter"}
    assert result.score == 0.0
    (text,) = feedback_of(result, "log_period")
    assert "1 log line matching" in text
    assert "logged outside any callback (t=0.000 s): by code that runs once, such as __init__ or main()" in text


@pytest.mark.parametrize("in_process", [False, True], ids=["sandboxed", "in-process"])
def test_a_loop_that_sleeps_inside_the_timer_callback_is_no_timer(grade, in_process):
    # the timer fires once and its callback never returns: evenly spaced lines,
    # from a callback, counting up - it used to score 10/10
    result = grade(LESSON, HERE / "loop_in_the_timer_callback.py", in_process=in_process)
    assert failed_checks(result) == {"log_period"}
    assert result.score == 0.0
    text = feedback_of(result, "log_period")[0]
    assert "10 of the 10 log lines were logged by one call of a callback" in text
    assert "the timer fires once and its callback never returns" in text
