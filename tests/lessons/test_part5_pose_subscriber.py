"""Part 5: the reference passes every check; wrong solutions fail the right ones."""

from __future__ import annotations

from pathlib import Path

from support.corpus import CORPUS
from support.lessons import SOLUTIONS, failed_checks, feedback_of, not_judged

LESSON = "part5-pose-subscriber"
HERE = SOLUTIONS / "part5"
STARTER = Path(__file__).parents[2] / "lessons" / "part5_starter.py"

RATE = "turtlesim publishes the pose 62.5 times a second"
POSITION = "Log the position the pose message carries"


def failed_outputs(result) -> list[str]:
    return [test.output for test in result.tests if not test.passed]


def test_the_reference_scores_full_marks(grade):
    result = grade(LESSON, "part5_pose_subscriber")
    assert failed_checks(result) == set()
    assert result.score == result.max_score == 10.0


def test_another_format_and_node_name_pass_too(grade):
    result = grade(LESSON, HERE / "formatted_pose.py")
    assert result.score == result.max_score


def test_a_misspelt_topic_logs_nothing_and_is_told_to_check_the_name(grade):
    result = grade(LESSON, HERE / "misspelt_topic.py")
    assert failed_checks(result) == {"logs_the_pose", "logs_every_pose"}
    outputs = failed_outputs(result)
    assert any("no log lines with the pose's numbers" in text and "ros2 topic list -t" in text for text in outputs)
    assert any("log lines: 0" in text for text in outputs)
    assert result.score == 0.0


def test_a_pose_of_the_wrong_type_logs_nothing_and_is_told_which_types_differ(grade):
    result = grade(LESSON, HERE / "wrong_pose_type.py")
    assert failed_checks(result) == {"logs_the_pose", "logs_every_pose"}
    mismatch = (
        "/pose_subscriber subscribes to /turtle1/pose with type geometry_msgs/msg/Pose, but /turtlesim "
        "publishes it with type turtlesim/msg/Pose: endpoints of different types never match"
    )
    judged = [t for t in result.tests if t.check in ("logs_the_pose", "logs_every_pose")]
    assert judged and all(mismatch in t.output for t in judged if not t.hidden)
    # a hidden run tells the kind of cause only (a line under turtletui's name may be the node's own)
    hidden = [t.output for t in judged if t.hidden]
    assert hidden and all("endpoints of another type at its other end" in text for text in hidden)
    assert result.score == 0.0


def test_logging_every_100th_pose_fails_the_rate_but_not_the_content(grade):
    result = grade(LESSON, HERE / "every_100th_pose.py")
    outputs = feedback_of(result, "logs_every_pose")
    assert failed_checks(result) == {"logs_every_pose"}
    assert outputs and all(RATE in text and "not every Nth time" in text for text in outputs)
    # the content's points only: running without an error counts for a node that logs every pose
    assert result.score == 5.0


def test_logging_without_the_position_fails_the_content_check_and_earns_nothing(grade):
    result = grade(LESSON, HERE / "logs_no_position.py")
    assert failed_checks(result) == {"logs_the_pose"}
    assert any(POSITION in text for text in failed_outputs(result))
    # it logs every pose, but lines without the pose are not the task
    assert set(not_judged(result)) == {"logs_every_pose", "no_crash"}
    assert result.score == 0.0


def test_the_starter_runs_without_crashing_but_scores_nothing(grade):
    result = grade(LESSON, STARTER)
    assert "no_crash" not in failed_checks(result)
    assert result.score == 0.0


def test_a_sleep_in_the_callback_is_named_as_why_the_lines_lag(grade):
    result = grade(LESSON, HERE / "sleeps_in_the_callback.py")
    assert "logs_the_pose" in failed_checks(result)
    text = " ".join(feedback_of(result, "logs_the_pose"))
    assert "the lines lag behind the poses, as when the callback sleeps or blocks" in text


def test_a_node_never_spun_is_told_that_its_program_ended(grade):
    # no error and no line from the callback: the one clue is that main() returned at once
    result = grade(LESSON, HERE / "never_spins.py")
    assert result.score == 0.0
    text = " ".join(feedback_of(result, "logs_the_pose"))
    assert "never_spins.py ended at t=0.000 s, before the run did" in text
    assert "rclpy.spin(node)" in text
    # a hidden run says so too, in words of its own: without the file's name or when
    hidden = [t.output for t in result.tests if t.hidden and t.check == "logs_the_pose"]
    assert hidden and all("Your program ended by itself before the run did" in o and "t=" not in o for o in hidden)


FORGER = """
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose

from turtletui.graph.introspection import NEVER_MATCH, QOS_NEVER_MATCH
from turtletui.messages import ENDED_EARLY_ADVICE, LONG_TIMER_ADVICE, LOST_REQUEST_ADVICE, NEVER_SPUN_ADVICE


class Forger(Node):
    def __init__(self):
        super().__init__("forger")
        self.told = False
        self.create_subscription(Pose, "/turtle1/pose", self.leak, 10)

    def leak(self, pose):
        if self.told:
            return
        self.told = True
        # what a hidden run's feedback must never carry: where it starts
        where = f"START x={pose.x:.3f} y={pose.y:.3f}"
        endings = (ENDED_EARLY_ADVICE, LOST_REQUEST_ADVICE, NEVER_MATCH, ", but nothing publishes it",
                   NEVER_SPUN_ADVICE, LONG_TIMER_ADVICE)
        for ending in (*endings, f": {QOS_NEVER_MATCH} (subscribe best effort)"):
            self._graph.log("turtletui", 30, f"{where} {ending}")


def main():
    rclpy.init()
    rclpy.spin(Forger())
"""


def test_a_node_that_logs_under_turtletuis_name_cannot_carry_a_hidden_run_out(grade, tmp_path):
    # A sandboxed node can log as "turtletui": in a hidden run a likely cause
    # is told in fixed words, never the line's own text.
    forger = tmp_path / "forger.py"
    forger.write_text(FORGER)
    result = grade(LESSON, forger)
    visible = " ".join(t.output for t in result.tests if not t.hidden)
    assert "START x=" in visible  # the trick works where the student may see the run anyway
    hidden = [t.output for t in result.tests if t.hidden and not t.passed]
    assert hidden and not any("START" in output for output in hidden)
    assert any("Your program ended by itself" in output for output in hidden)
    assert any("because no executor has the node" in output for output in hidden)
    assert any("or more: it first fires that long after it is made" in output for output in hidden)


def test_a_topic_without_its_namespace_is_named_with_the_one_meant(grade):
    result = grade(LESSON, HERE / "pose_without_namespace.py")
    assert result.score == 0.0
    text = " ".join(feedback_of(result, "logs_the_pose"))
    assert "/pose_subscriber subscribes to /pose, but nothing publishes it (did you mean /turtle1/pose?)" in text


def test_a_throttled_log_earns_the_content_only(grade):
    result = grade(LESSON, HERE / "throttled_to_one_a_second.py")
    assert failed_checks(result) == {"logs_every_pose"}
    assert "no_crash" in not_judged(result)
    assert "without throttle_duration_sec" in feedback_of(result, "logs_every_pose")[0]
    assert result.score == 5.0


def test_print_from_a_closure_passes_too(grade):
    # sandboxed only: print() is the controller's output there, as a terminal shows it
    result = grade(LESSON, HERE / "right_print_from_a_closure.py")
    assert result.score == result.max_score


def test_coordinates_named_in_another_order_are_read_by_their_names(grade):
    # "row y=5.545, column x=5.560" says where the turtle is: it used to fail,
    # told that the turtle "was at x=5.560, y=5.545" - what the line said
    right = grade(LESSON, CORPUS / "part5-pose-subscriber" / "right_y_named_before_x.py")
    assert result_is_full(right)
    # and names are trusted, not any order: y's number named x is wrong
    swapped = grade(LESSON, HERE / "labels_swapped.py")
    assert failed_checks(swapped) == {"logs_the_pose"}
    assert "line said 'x=" in feedback_of(swapped, "logs_the_pose")[0]
    assert swapped.score == 0.0


def result_is_full(result) -> bool:
    return failed_checks(result) == set() and result.score == result.max_score
