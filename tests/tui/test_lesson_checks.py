"""The app's check key and replays: the lesson's checks run on the controller
being watched, and a recorded run plays in the arena."""

from __future__ import annotations

import json
from pathlib import Path

from support.pilot import SIZE, pilot_test, wait_for

from turtletui.runtime.loader import ControllerSpec
from turtletui.tui.app import TurtleApp
from turtletui.tui.lesson_checks import CheckProgress, describe_report, results_dir

LESSON = """\
+++
id = "drive-a-bit"
title = "Drive a bit"

[[scenarios]]
name = "centre"
duration = 2.0

[[checks]]
name = "distance"
thresholds = {min = 1.0}
feedback = "Publish a forward speed."

[[checks]]
name = "no_crash"
+++
# Drive a bit

Make the turtle move.
"""

NODE = """\
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Mover(Node):
    def __init__(self):
        super().__init__("mover")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.send)

    def send(self):
        cmd = Twist()
        cmd.linear.x = {speed}
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Mover())
"""


def report(tests, **extra) -> dict:
    submission = {"score": 1.0, "max_score": 2.0, "error": None, "tests": tests, "recordings": [], **extra}
    return {"lesson": "x", "submissions": [submission]}


def test_describe_groups_failures_by_check_with_the_first_feedback():
    tests = [
        {"check": "wall_hits", "scenario": "a", "status": "passed", "output": "wall hits: 0"},
        {"check": "wall_hits", "scenario": "b", "status": "failed", "output": "wall hits: 2\nTurn earlier."},
        {"check": "no_crash", "scenario": "a", "status": "passed", "output": ""},
    ]
    text = describe_report(report(tests, recordings=["r/b.jsonl"]))
    assert "**Score: 1 / 2**" in text
    assert "- ✗ `wall_hits`: failed in 1 of 2 runs (b)" in text
    assert "  > wall hits: 2\n  >\n  > Turn earlier." in text
    assert "- ✓ `no_crash`: passed in its only run" in text
    assert "- `turtletui replay r/b.jsonl`" in text


def test_progress_is_read_line_by_line_and_says_why_checks_could_not_run():
    progress = CheckProgress()
    assert progress.running().endswith("*Running the lesson's scenarios...*\n")
    assert progress.feed('{"run": {"done": 1, "of": 3, "scenario": "centre", "passed": true}}\n')
    assert progress.feed('{"run": {"done": 2, "of": 3, "scenario": "corner", "passed": false}}')
    assert not progress.feed("a stray warning\n")
    assert "2 of 3 done" in progress.running() and "✓ centre ✗ corner" in progress.running()
    failed = CheckProgress()
    failed.feed(json.dumps({"error": "lessons/x.md:3: check 'nope' is not a registered check"}))
    assert "**The checks could not run:** lessons/x.md:3: check 'nope' is not a registered check" in failed.result(2)
    crashed = CheckProgress()
    crashed.feed("Traceback (most recent call last):")
    crashed.feed("MemoryError")
    assert "**The checks could not run:** MemoryError" in crashed.result(1)
    assert "not readable" in describe_report({"lesson": "x"})


def test_describe_counts_runs_in_the_singular_and_the_plural():
    tests = [
        {"check": "circle", "scenario": "a", "status": "failed", "output": "no circle"},
        {"check": "no_crash", "scenario": "a", "status": "passed", "output": ""},
        {"check": "no_crash", "scenario": "b", "status": "passed", "output": ""},
    ]
    text = describe_report(report(tests))
    assert "- ✗ `circle`: failed in 1 of 1 run (a)" in text
    assert "- ✓ `no_crash`: passed in all 2 runs" in text


def test_check_results_are_kept_in_the_users_cache(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    assert results_dir(Path("/lessons/drive.md")) == tmp_path / "cache" / "turtletui" / "checks" / "drive"


def test_the_check_key_grades_the_running_file_and_shows_the_result(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))  # the grading child writes there
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))  # and the progress goes here
    _check_key_scenario(tmp_path)


@pilot_test
async def _check_key_scenario(tmp_path: Path) -> None:
    lesson = tmp_path / "drive.md"
    lesson.write_text(LESSON)
    node = tmp_path / "mover.py"
    node.write_text(NODE.replace("{speed}", "0.0"))
    app = TurtleApp([ControllerSpec(name="mover", path=node)], lesson=lesson)
    seen = []
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("k")
        panel = app.query_one("#lesson")
        assert app.query_one("#side").current == "lesson"
        # every text the pane shows, not just those a poll happens to see: the
        # last run's progress and the score can come in one read
        show = panel.update
        panel.update = lambda text: (seen.append(text), show(text))[-1]

        def finished() -> bool:
            return "Score:" in panel.source or "could not" in panel.source

        await wait_for(pilot, finished, timeout=120)
        assert any("*Running the lesson's scenarios: 1 of 1 done*" in text for text in seen)
        assert "**Score: 1 / 2**" in panel.source
        assert "✗ `distance`" in panel.source and "Publish a forward speed." in panel.source
        assert "Make the turtle move." in panel.source  # the lesson is still there below
        # the student fixes the file and checks again: a new result, not the kept one
        assert not app.progress.get("drive-a-bit").passed
        node.write_text(NODE.replace("{speed}", "1.0"))
        await pilot.press("k")
        await wait_for(pilot, lambda: "**Score: 2 / 2**" in panel.source, timeout=120)
        assert app.progress.get("drive-a-bit").passed
    # kept for the next run of the app, under the user's data folder
    saved = json.loads((tmp_path / "data" / "turtletui" / "progress.json").read_text())
    assert saved["lessons"]["drive-a-bit"]["passed"] is True


@pilot_test
async def test_checking_without_a_lesson_says_how_to_open_one() -> None:
    app = TurtleApp([])
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("k")
        assert "no lesson is open" in app.query_one("#lesson").source


@pilot_test
async def test_turtletuis_own_node_is_neither_checked_as_yours_nor_edited() -> None:
    """turtletui run with no file: the course's Part 6 node drives; k must not
    mark Part 6 passed with it, nor E open it."""
    from turtletui.lessons.loader import find_lesson
    from turtletui.runtime.resolve import resolve_controllers
    from turtletui.tui.widgets.keybar import KeyBar

    app = TurtleApp(resolve_controllers(["part6_wall_avoider"]), lesson=find_lesson("part6-closed-loop").path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert "E" not in app.query_one(KeyBar).shown
        await pilot.press("k")
        await pilot.pause()
        assert ("**Nothing to check:** part6_wall_avoider is a node that comes with turtletui: write yours with"
                " `turtletui new --lesson part6-closed-loop my_node.py`") in app.query_one("#lesson").source
        assert app.progress.lessons == {}
        await pilot.press("E")
        await pilot.pause(0.1)
        assert not app.query("#editor")
        assert any("Nothing to edit: part6_wall_avoider" in str(n.message) for n in app._notifications)


@pilot_test
async def test_a_recording_replays_in_the_arena(tmp_path: Path) -> None:
    from turtletui.api import run
    from turtletui.runtime.replay import read_recording

    node = tmp_path / "mover.py"
    node.write_text(NODE.replace("{speed}", "1.5"))
    record = tmp_path / "run.jsonl"
    recorded = run([node], duration=2.0, record=record)
    app = TurtleApp([], replay=read_recording(record))
    async with app.run_test(size=SIZE) as pilot:
        await wait_for(pilot, lambda: app.session.paused, timeout=60)
        turtle = app.session.sim.world.turtles["turtle1"]
        # the recording's end holds its last frame: where the recorded turtle
        # ended, however late the app's ticks came
        assert app.session.t == 2.0
        assert turtle.x == recorded.turtles["turtle1"].x
        assert turtle.distance > 2.0
        assert "replaying run.jsonl" in "".join(r.msg for r in app.session.logs)
        assert "replay finished: space resumes the simulation" in "".join(r.msg for r in app.session.logs)


def test_the_check_key_is_on_the_key_bar():
    from turtletui.tui.widgets.keybar import APP_KEYS, fit_keys

    bindings = {b.key: b for b in TurtleApp.BINDINGS}
    assert bindings["k"].action == "check_lesson"
    assert "k" in [hint.key for hint in fit_keys(APP_KEYS, 80)]


def test_describe_shows_a_runs_failure_not_another_runs_reason_for_not_judging():
    waiting = "not judged: no_crash counts only in runs where time_to_goal passes; here it did not"
    tests = [
        {"check": "no_crash", "scenario": "left", "status": "failed", "output": waiting},
        {"check": "no_crash", "scenario": "behind", "status": "failed", "output": "crashed: ZeroDivisionError"},
    ]
    text = describe_report(report(tests))
    assert "- ✗ `no_crash`: failed in 1 of 2 runs (behind), not judged in 1 (left)" in text
    assert "  > crashed: ZeroDivisionError" in text and "counts only in runs" not in text
