"""Hostile submissions graded in one batch with an honest student: none of them
gains anything, each is reported clearly, and the honest student's result is
the one it gets when graded alone.

The grader here runs student code as its own user (``--same-user``, or a
grader that is not root): what is checked is what that mode guarantees.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

from support.grading import (
    HONEST,
    grade_cli,
    make_class,
    stored_results,
    wait_until_gone,
)

from turtletui.grading.batch import ResultStore, grade_submissions, store_key
from turtletui.grading.engine import prepare
from turtletui.grading.reports import render_report
from turtletui.grading.submissions import find_submissions
from turtletui.lessons.loader import load_lesson
from turtletui.runtime.sandbox import Limits

LESSON = """+++
id = "hostile-drive"
title = "Drive three metres, touch no wall"

[[scenarios]]
name = "centre"
start = {x = 5.5, y = 5.5, theta = 0.0}
duration = 3.0

[[checks]]
name = "distance"
weight = 1.0
thresholds = {min = 3.0}

[[checks]]
name = "wall_hits"
weight = 1.0
thresholds = {max = 0}

[[checks]]
name = "no_crash"
weight = 1.0
+++
# Drive
"""
LIMITS = Limits(step_timeout=1.0, start_timeout=10.0, cpu_seconds=20, memory_bytes=512 * 1024**2)

_IMPORTS = """\
import json, os, signal, subprocess, sys, time
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
"""

_SIT_STILL = """
def main():
    rclpy.init()
    rclpy.spin(Node("sitter"))
"""

HOSTILE = {
    # an endless loop in a callback
    "never_returns": _IMPORTS
    + """
class Stuck(Node):
    def __init__(self):
        super().__init__("stuck")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        while True:
            pass


def main():
    rclpy.init()
    rclpy.spin(Stuck())
""",
    # allocates without bound
    "allocates": _IMPORTS
    + """
def main():
    rclpy.init()
    node = Node("hog")
    hog = []
    while True:
        hog.append(bytearray(64 * 1024 * 1024))
""",
    # kills the process that grades it
    "kills_parent": _IMPORTS
    + """
def main():
    rclpy.init()
    node = Node("killer")
    os.kill(os.getppid(), signal.SIGKILL)
    rclpy.spin(node)
""",
    # starts processes meant to outlive it: a plain fork, a double-forked daemon
    # in a session of its own, and a subprocess in a new session
    "forks": _IMPORTS
    + """
def main():
    rclpy.init()
    node = Node("forker")
    subprocess.Popen([sys.executable, "-c", "import time\\nwhile True: time.sleep(0.5)"], start_new_session=True)
    if os.fork() == 0:
        os.setsid()
        if os.fork() == 0:
            while True:
                time.sleep(0.5)
        os._exit(0)
    if os.fork() == 0:
        while True:
            time.sleep(0.5)
    rclpy.spin(node)
""",
    # writes result files: the honest student's, and a report next to them
    "writes_results": _IMPORTS
    + """
RESULTS = "RESULTS_FOLDER"
FORGED = {"store": 1, "key": "forged", "result": {"student": "honest", "score": 0.0, "max_score": 3.0}}


def main():
    rclpy.init()
    node = Node("writer")
    for name in ("honest.json", "writes_results.json", "results.json", "report.json"):
        try:
            with open(os.path.join(RESULTS, name), "w") as f:
                json.dump(FORGED, f)
        except OSError as err:
            print("could not write", name, err)
    rclpy.spin(node)
""",
    # prints a full-marks report and leaves
    "prints_fake_result": _IMPORTS
    + """
FAKE = {"lesson": "hostile-drive", "max_score": 3.0, "submissions": [
    {"student": "prints_fake_result", "score": 3.0, "max_score": 3.0, "error": None, "tests": []}]}


def main():
    print(json.dumps(FAKE))
    print(json.dumps({"score": 3.0, "output": "all checks passed"}))
    sys.stdout.flush()
    os._exit(0)
""",
    # patches the simulator and the grader in its own process, and publishes
    # poses that say it is in the middle of the arena while it drives into a wall
    "patches_simulator": _IMPORTS
    + """
import turtletui

for name, module in list(sys.modules.items()):
    if name.startswith("turtletui"):
        for attr in ("wall_hits", "judge", "grade_run", "no_crash", "distance", "step"):
            if hasattr(module, attr):
                setattr(module, attr, lambda *args, **kwargs: None)
sys.modules["turtletui.grading.checks"] = sys.modules["json"]


class Liar(Node):
    def __init__(self):
        super().__init__("liar")
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.fake = self.create_publisher(Pose, "/turtle1/pose", 10)
        self.create_timer(0.016, self.tick)

    def tick(self):
        cmd = Twist()
        cmd.linear.x = 5.0
        self.cmd.publish(cmd)
        fake = Pose()
        fake.x, fake.y = 5.5, 5.5
        self.fake.publish(fake)


def main():
    rclpy.init()
    rclpy.spin(Liar())
""",
}


def test_hostile_submissions_gain_nothing_and_change_no_other_result(tmp_path: Path):
    lesson = tmp_path / "hostile.md"
    lesson.write_text(LESSON)
    plan = prepare(load_lesson(lesson))
    results = tmp_path / "results"
    students = {"honest": HONEST, **HOSTILE}
    students["writes_results"] = students["writes_results"].replace("RESULTS_FOLDER", str(results))
    klass = make_class(tmp_path / "class", students)

    alone = grade_submissions(plan, find_submissions([klass / "honest"]), jobs=1, limits=LIMITS)
    (alone_result,) = alone.submissions
    assert alone_result.score == 3.0

    store = ResultStore(results, store_key(plan))
    report = grade_submissions(plan, find_submissions([klass]), store=store, jobs=2, limits=LIMITS)
    by_name = {s.student: s for s in report.submissions}
    assert sorted(by_name) == sorted(students)  # the grader survived to report everyone

    def outputs(student: str) -> str:
        return "\n".join(t.output for t in by_name[student].tests)

    def failed(student: str) -> set[str]:
        return {t.check for t in by_name[student].tests if not t.passed}

    honest = by_name["honest"]
    assert honest.score == alone_result.score
    assert [(t.name, t.status, t.output) for t in honest.tests] == [
        (t.name, t.status, t.output) for t in alone_result.tests
    ]

    assert by_name["never_returns"].score == 0.0
    assert "did not answer within 1 s of wall time" in outputs("never_returns")

    assert by_name["allocates"].score == 0.0
    assert "MemoryError: ran out of its memory limit of 512 MiB" in outputs("allocates")

    assert by_name["kills_parent"].score == 0.0
    assert "the process grading this run was killed" in outputs("kills_parent")

    # sitting still while doing it: the points a turtle that stays put earns, no more
    for student in ("forks", "writes_results"):
        assert failed(student) == {"distance"}, (student, outputs(student))
        assert by_name[student].score == 2.0

    assert by_name["prints_fake_result"].score == 0.0
    assert "exited with status 0 without finishing its run" in outputs("prints_fake_result")

    # judged on the turtle's real path, which runs into the east wall
    assert failed("patches_simulator") == {"wall_hits"}
    assert by_name["patches_simulator"].score == 2.0

    # nothing any of them started is still running
    assert wait_until_gone([klass]) == []

    # only the grader's results are in its files: the forged ones were put back
    kept = stored_results(results)
    assert {name: r["score"] for name, r in kept.items() if name in students} == {
        name: r.score for name, r in by_name.items()
    }
    assert kept["honest"]["tests"] == json.loads(json.dumps([t.__dict__ for t in honest.tests]))
    report_json = json.loads(render_report(report, "json"))
    assert {s["student"]: s["score"] for s in report_json["submissions"]} == {
        name: r.score for name, r in by_name.items()
    }
    # a rerun trusts those files: every result is kept, with the same scores
    rerun = grade_submissions(
        plan, find_submissions([klass]), store=ResultStore(results, store_key(plan)), jobs=2, limits=LIMITS
    )
    assert {s.student: s.score for s in rerun.submissions} == {name: r.score for name, r in by_name.items()}


def test_a_fake_result_printed_or_written_does_not_reach_the_report(tmp_path: Path):
    lesson = tmp_path / "hostile.md"
    lesson.write_text(LESSON)
    results = tmp_path / "results"
    out = tmp_path / "out" / "report.json"
    out.parent.mkdir()
    writer = HOSTILE["writes_results"].replace("RESULTS_FOLDER", str(out.parent))
    klass = make_class(
        tmp_path / "class",
        {"honest": HONEST, "prints_fake_result": HOSTILE["prints_fake_result"], "writes_results": writer},
    )
    result = grade_cli(
        klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "2", "--format", "json",
        "--output", out,
    )
    assert result.exit_code == 0, result.stderr
    assert result.stdout == ""  # the student's print() never reaches the grader's output
    report = json.loads(out.read_text())
    assert {s["student"]: s["score"] for s in report["submissions"]} == {
        "honest": 3.0, "prints_fake_result": 0.0, "writes_results": 2.0,
    }
    assert report["lesson"] == "hostile-drive" and report["max_score"] == 3.0


SLOW_LESSON = LESSON.replace('id = "hostile-drive"', 'id = "slow-drive"').replace(
    "duration = 3.0",
    'duration = 6.0\n\n[[scenarios]]\nname = "corner"\nstart = {x = 8.8, y = 8.8, theta = 0.785}\nduration = 6.0',
)


def _slowed(code: str) -> str:
    """The honest controller, with ``code`` at the start of every pose callback."""
    return (
        "import queue, select, threading, time\n"
        + HONEST.replace("    def on_pose(self, pose):\n", f"    def on_pose(self, pose):\n        {code}\n", 1)
    )


SLOW = {
    # 30 ms of CPU for a pose every 16 ms (1013 s of wall time and "out of memory" before)
    "thirty_ms_of_cpu": _slowed("end = time.process_time() + 0.03\n        while time.process_time() < end: pass"),
    # blocking waits: 31.6 s of wall time per simulated second, or 20 h a submission, before
    "event_wait": _slowed("threading.Event().wait(0.5)"),
    "select_wait": _slowed("select.select([], [], [], 1.9)"),
    "queue_wait": _slowed("try:\n            queue.Queue().get(timeout=0.5)\n        except queue.Empty: pass"),
    "busy_loop": _slowed("while True: pass"),
}


def test_slow_controllers_are_graded_in_minutes_with_verdicts_that_say_why(tmp_path: Path):
    lesson = tmp_path / "slow.md"
    lesson.write_text(SLOW_LESSON)
    plan = prepare(load_lesson(lesson))
    klass = make_class(tmp_path / "class", {"honest": HONEST, **SLOW})
    started = time.monotonic()
    report = grade_submissions(plan, find_submissions([klass]), jobs=2, limits=Limits())
    took = time.monotonic() - started
    by_name = {s.student: s for s in report.submissions}

    def outputs(student: str, check: str) -> list[str]:
        return [t.output for t in by_name[student].tests if t.check == check]

    [alone] = grade_submissions(plan, find_submissions([klass / "honest"]), jobs=1).submissions
    assert by_name["honest"].score == alone.score == plan.max_score

    for text in outputs("thirty_ms_of_cpu", "no_crash"):
        assert "could not keep up with real time" in text
        assert "your on_pose takes" in text and "a message on /turtle1/pose arrives every 16 ms" in text
        assert "on a real robot this node falls behind" in text

    # a blocked callback blocks its node in simulated time, as on a robot: it
    # runs to the end and is judged on what its turtle did
    for student in ("event_wait", "select_wait", "queue_wait"):
        assert all(t.passed for t in by_name[student].tests if t.check == "no_crash"), student

    for text in outputs("busy_loop", "no_crash"):
        assert "did not answer within 2 s of wall time" in text

    # six submissions of two 6 s runs: minutes at most, even on a busy machine
    assert took < 300, f"the batch took {took:.0f} s"
    assert wait_until_gone([klass]) == []
