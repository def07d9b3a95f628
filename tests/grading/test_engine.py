"""Preparing a lesson for grading, and grading controllers against it."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from turtletui.grading.engine import (
    GradingError,
    grade_controllers,
    prepare,
    random_start,
    scenario_runs,
)
from turtletui.lessons.loader import load_lesson
from turtletui.runtime.loader import ControllerSpec

HEAD = """\
+++
id = "tiny"
title = "Tiny"
"""

DRIVER = """\
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        {body}
        cmd = Twist()
        cmd.linear.x = 2.0
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Driver())
"""


def lesson(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "tiny.md"
    path.write_text(HEAD + textwrap.dedent(body) + "+++\n# Tiny\n")
    return path


def driver(tmp_path: Path, body: str = "pass", name: str = "driver.py") -> ControllerSpec:
    path = tmp_path / name
    path.write_text(DRIVER.replace("{body}", body))
    return ControllerSpec(name=path.stem, path=path)


SCENARIOS = """
[[scenarios]]
name = "east"
start = {x = 2.0, y = 5.0, theta = 0.0}
duration = 6.0

[[scenarios]]
name = "secret"
start = "random"
seeds = [4, 5]
duration = 2.0
hidden = true
"""


def test_an_unknown_check_is_named_with_its_line_and_a_suggestion(tmp_path):
    path = lesson(tmp_path, SCENARIOS + '\n[[checks]]\nname = "wall_hit"\n')
    with pytest.raises(GradingError) as err:
        prepare(load_lesson(path))
    message = str(err.value)
    assert message.startswith(f"{path}:17: check 'wall_hit' is not a registered check")
    assert "did you mean 'wall_hits'?" in message and "\n" not in message


def test_a_misspelt_threshold_is_an_error(tmp_path):
    path = lesson(tmp_path, SCENARIOS + '\n[[checks]]\nname = "wall_hits"\nthresholds = {mx = 0}\n')
    with pytest.raises(GradingError, match="check 'wall_hits' takes no threshold 'mx'"):
        prepare(load_lesson(path))


def test_a_lesson_without_scenarios_or_checks_cannot_be_graded(tmp_path):
    with pytest.raises(GradingError, match="has no \\[\\[scenarios\\]\\]"):
        prepare(load_lesson(lesson(tmp_path, '[[checks]]\nname = "no_crash"\n')))
    with pytest.raises(GradingError, match="has no \\[\\[checks\\]\\]"):
        prepare(load_lesson(lesson(tmp_path, SCENARIOS)))


def test_random_starts_depend_on_the_seed_only_and_keep_off_the_walls():
    assert random_start(7) == random_start(7) != random_start(8)
    for seed in range(200):
        x, y, _ = random_start(seed)
        assert 2.0 <= x <= 9.09 and 2.0 <= y <= 9.09


def test_runs_are_labelled_and_hidden_ones_numbered(tmp_path):
    path = lesson(tmp_path, SCENARIOS + '\n[[checks]]\nname = "no_crash"\n')
    runs = scenario_runs(load_lesson(path))
    assert [r.label for r in runs] == ["east", "hidden 1", "hidden 2"]
    assert runs[0].start == (2.0, 5.0, 0.0)
    assert runs[1].start == random_start(4)


CHECKS = """
[[checks]]
name = "wall_hits"
weight = 3.0
feedback = "Stop before the wall."

[[checks]]
name = "no_crash"
weight = 1.0

[[checks]]
name = "distance"
weight = 2.0
thresholds = {min = 3.0}
scenarios = ["east"]
"""


def test_points_are_shared_over_the_runs_a_check_judges(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + CHECKS)))
    result = grade_controllers(plan, [driver(tmp_path)])
    assert plan.max_score == result.max_score == 6.0
    by_name = {t.name: t for t in result.tests}
    assert by_name["distance [east]"].max_score == 2.0
    assert by_name["wall_hits [east]"].max_score == 1.0
    assert "distance [hidden 1]" not in by_name
    # 2 m/s for 6 s from x = 2 reaches the wall at x = 11.09: it hits it
    assert not by_name["wall_hits [east]"].passed
    assert "Stop before the wall." in by_name["wall_hits [east]"].output
    assert [t.check for t in result.tests][:3] == ["wall_hits"] * 3


def test_grading_is_deterministic(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + CHECKS)))
    spec = driver(tmp_path, "import random; self.pub.publish(Twist()) if random.random() < 0.3 else None")
    first = grade_controllers(plan, [spec])
    second = grade_controllers(plan, [spec])
    assert [(t.name, t.status, t.output) for t in first.tests] == [
        (t.name, t.status, t.output) for t in second.tests
    ]


def test_a_crash_fails_the_runs_other_checks_too(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + CHECKS)))
    result = grade_controllers(plan, [driver(tmp_path, "1 / 0", name="crasher.py")])
    assert result.score == 0.0
    walls = [t for t in result.tests if t.check == "wall_hits"]
    assert all(not t.passed for t in walls)
    assert all("not judged: the controller stopped" in t.output for t in walls if not t.hidden)
    # a check that was not judged gives no advice on what it judges, and in a
    # hidden run no reason that could tell where (or when) the run went wrong
    assert not any("Stop before the wall." in t.output for t in walls)
    assert {t.output for t in walls if t.hidden} == {
        "not judged: the controller stopped before the end of the run (exception)"
    }
    crash = next(t for t in result.tests if t.check == "no_crash")
    assert "ZeroDivisionError" in crash.output and "crasher.py" in crash.output


def test_a_plugin_check_is_used_and_its_failure_is_contained(tmp_path):
    plugin = tmp_path / "my_checks.py"
    plugin.write_text(
        textwrap.dedent(
            """
            from turtletui.plugins import hookimpl

            def far_east(trace, thresholds):
                x = trace.pose_array()[-1, 1]
                return x > thresholds["x"], f"ended at x = {x:.1f}"

            def broken(trace, thresholds):
                raise RuntimeError("oops")

            @hookimpl
            def turtletui_register_checks(register):
                register("far_east", far_east, "ends east of x")
                register("broken", broken)
            """
        )
    )
    checks = '\n[[checks]]\nname = "far_east"\nthresholds = {x = 5.0}\n\n[[checks]]\nname = "broken"\n'
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS.split("[[scenarios]]\nname = \"secret\"")[0] + checks)),
                   plugins=[plugin])
    result = grade_controllers(plan, [driver(tmp_path)])
    by_check = {t.check: t for t in result.tests}
    assert by_check["far_east"].passed and "ended at x = 11.1" in by_check["far_east"].output
    assert not by_check["broken"].passed
    assert "the check itself failed: RuntimeError: oops" in by_check["broken"].output


def test_random_starts_keep_clear_of_a_worlds_obstacles():
    from turtletui.sim.obstacles import Circle, nearest_distance

    pillar = (Circle(5.5, 5.5, 3.0),)
    starts = [random_start(seed, obstacles=pillar) for seed in range(100)]
    assert all(nearest_distance(pillar, x, y) >= 0.5 for x, y, _ in starts)
    # a start that was clear already stays where the seed put it
    free = [seed for seed in range(100) if nearest_distance(pillar, *random_start(seed)[:2]) >= 0.5]
    assert free and all(random_start(seed, obstacles=pillar) == random_start(seed) for seed in free)
