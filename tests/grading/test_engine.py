"""Preparing a lesson for grading, and grading controllers against it."""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

from turtletui.grading.engine import (
    GradingError,
    grade_controllers,
    prepare,
    random_start,
    scenario_runs,
    twin_start,
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


GATED = """
[[checks]]
name = "distance"
thresholds = {min = 3.0}

[[checks]]
name = "wall_hits"
weight = 2.0
requires = ["distance"]
feedback = "Stop before the wall."

[[checks]]
name = "no_crash"
requires = ["distance"]
"""


def test_a_check_whose_requirement_failed_earns_nothing_and_gives_no_advice(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + GATED)))
    # it stands still: no wall hit, no crash, but no task either
    result = grade_controllers(plan, [driver(tmp_path, "return")])
    assert result.score == 0.0
    walls = {t.scenario: t for t in result.tests if t.check == "wall_hits"}
    assert not walls["east"].passed
    assert walls["east"].output == "not judged: wall_hits counts only in runs where distance passes; here it did not"
    assert all("Stop before the wall." not in t.output for t in walls.values())
    # the reason holds no measurement, so a hidden run shows it too
    assert walls["hidden 1"].output == walls["east"].output


def test_a_check_whose_requirements_passed_is_judged_as_usual(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + GATED)))
    result = grade_controllers(plan, [driver(tmp_path)])  # 2 m/s east from x = 2 for 6 s: a wall
    by_name = {t.name: t for t in result.tests}
    assert by_name["distance [east]"].passed and by_name["no_crash [east]"].passed
    assert not by_name["wall_hits [east]"].passed
    assert "Stop before the wall." in by_name["wall_hits [east]"].output


FORBIDDEN = """forbidden_services = ["/*/teleport_*"]
""" + SCENARIOS + """
[[checks]]
name = "no_crash"

[[checks]]
name = "distance"
"""


def test_calling_a_forbidden_service_fails_every_check_of_the_run(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, FORBIDDEN)))
    srv = "__import__('turtlesim.srv').srv.TeleportRelative"
    body = (
        f"self.__dict__.setdefault('tp', self.create_client({srv}, '/turtle1/teleport_relative'))"
        f"; self.tp.service_is_ready() and self.tp.call_async({srv}.Request(linear=0.1))"
    )
    result = grade_controllers(plan, [driver(tmp_path, body)])
    assert result.score == 0.0
    # the client is made on the first pose the driver hears (64 ms, after
    # discovery), finds the service 50 ms later and calls on the next pose
    shown = {t.output for t in result.tests if not t.hidden}
    assert shown == {"not judged: the controller called /turtle1/teleport_relative at t=0.128 s, a service this lesson forbids"}
    hidden = {t.output for t in result.tests if t.hidden}
    assert hidden == {"not judged: the controller called /turtle1/teleport_relative, a service this lesson forbids"}


def test_a_crash_names_the_students_file_not_the_folder_it_ran_from(tmp_path):
    private = tmp_path / "turtletui-grade-x1y2" / "00000"
    private.mkdir(parents=True)
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + CHECKS)))
    spec = driver(private, "speed = spede * 2", name="alice_node.py")
    result = grade_controllers(plan, [spec])
    crash = next(t for t in result.tests if t.check == "no_crash" and not t.hidden)
    assert str(private) not in crash.output and "turtletui-grade" not in crash.output
    assert "controller alice_node.py crashed" in crash.output
    assert 'File "alice_node.py", line 14, in on_pose' in crash.output
    assert "speed = spede * 2" in crash.output  # the line itself


DRIVEN = """
[[scenarios]]
name = "driven"
start = {x = 5.0, y = 5.0, theta = 0.0}
duration = 2.0
drive = {linear = 1.0, angular = 0.0}

[[checks]]
name = "distance"
thresholds = {min = 1.9}

[[checks]]
name = "commands_per_pose"
thresholds = {max = 0}
"""

WATCHER = """\
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    rclpy.spin(Node("watcher"))
"""


def test_a_scenario_can_drive_the_turtle_for_a_node_that_only_watches(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, DRIVEN)))
    path = tmp_path / "watcher.py"
    path.write_text(WATCHER)
    result = grade_controllers(plan, [ControllerSpec(name="watcher", path=path)])
    by_name = {t.check: t for t in result.tests}
    assert by_name["distance"].passed, by_name["distance"].output  # 1 m/s for 2 s
    # the scenario's own commands are not the controller's
    assert by_name["commands_per_pose"].passed and "commands per pose: 0" in by_name["commands_per_pose"].output


SLOW_LOOP = """\
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class SlowAvoider(Node):
    def __init__(self):
        super().__init__("slow_avoider")
        self.pose = None
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_timer(1.0, self.decide)

    def on_pose(self, pose):
        self.pose = pose

    def decide(self):
        if self.pose is None:
            return
        cmd = Twist()
        if 2.0 < self.pose.x < 9.0 and 2.0 < self.pose.y < 9.0:
            cmd.linear.x = 5.0
        else:
            cmd.linear.x, cmd.angular.z = 1.0, 1.5
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(SlowAvoider())
"""


def test_a_twin_run_starts_facing_a_wall_where_a_slow_closed_loop_reacts_at_once(tmp_path):
    from turtletui.grading.engine import TWIN_WALL_DISTANCE
    from turtletui.sim.constants import ARENA_SIZE

    for seed in range(40):
        x, y, theta = twin_start(seed, (5.5, 5.5, 0.0))
        from_wall = min(x, y, ARENA_SIZE - x, ARENA_SIZE - y)
        assert from_wall == pytest.approx(TWIN_WALL_DISTANCE)
        wall = (x + TWIN_WALL_DISTANCE * math.cos(theta), y + TWIN_WALL_DISTANCE * math.sin(theta))
        assert min(wall[0], wall[1], ARENA_SIZE - wall[0], ARENA_SIZE - wall[1]) < TWIN_WALL_DISTANCE / 2  # facing it
    # one of two fixed Twists, chosen once a second from the latest pose: ten
    # commands in the window, the same ten from a start in the open (6 of 9
    # Part 6 runs called it an open loop), never from one facing a wall
    path = tmp_path / "slow_loop.py"
    path.write_text(SLOW_LOOP)
    random_starts = '[[scenarios]]\nname = "r"\nstart = "random"\nseeds = [1, 2, 7, 101, 102, 103]\nduration = 10.0\n'
    plan = prepare(load_lesson(lesson(tmp_path, random_starts + '[[checks]]\nname = "closed_loop"\n')))
    result = grade_controllers(plan, [ControllerSpec(name="slow_loop", path=path)])
    assert all(test.passed for test in result.tests), [t.output for t in result.tests]


def test_a_twin_run_starts_elsewhere_with_the_same_seed(tmp_path):
    from turtletui.grading.engine import grade_run, twin_start

    twin = '\n[[checks]]\nname = "closed_loop"\nthresholds = {window = 1.0}\n'
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + twin)))
    run = plan.runs[0]
    assert run.twin_start == twin_start(run.seed, run.start) and math.dist(run.twin_start[:2], run.start[:2]) >= 2.0
    assert twin_start(run.seed + 1, run.start) != run.twin_start
    assert plan.twin_window(run) == 1.0
    # a node that ignores the pose: its commands are the same from the twin's start
    outcome = grade_run(plan, 0, [driver(tmp_path)])
    ((_, test),) = outcome.tests
    # one per pose heard in the 1 s window: from 64 ms (the first pose after
    # discovery, 50 ms) to 992 ms
    assert not test.passed and "the same 59 commands" in test.output
    turning = "self.pub.publish(Twist(angular=__import__('geometry_msgs.msg').msg.Vector3(z=pose.x)))"
    ((_, test),) = grade_run(plan, 0, [driver(tmp_path, turning, name="turning.py")]).tests
    assert test.passed and "differed from t=0.064 s" in test.output


EAGER = DRIVER.replace(
    '        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)',
    '        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)\n'
    "        self.pub.publish(Twist())  # before turtlesim has discovered it: lost",
)


def test_the_trace_leaves_out_commands_lost_before_discovery_in_both_hosts(tmp_path):
    from turtletui.grading.engine import run_scenario

    path = tmp_path / "eager.py"
    path.write_text(EAGER.replace("{body}", "pass"))
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + CHECKS)))
    commands = []
    for trusted in (True, False):
        trace, _ = run_scenario(plan, plan.runs[0], [ControllerSpec(name="eager", path=path, trusted=trusted)])
        commands.append(trace.command_array())
    in_process, sandboxed = commands
    # the first command the trace (and turtlesim) has is the one sent on the
    # first pose heard, at 64 ms; the one of t=0 reached no one
    assert in_process[0].tolist() == [0.064, 2.0, 0.0, 0.0]
    assert np.array_equal(in_process, sandboxed)


def test_a_crash_is_still_reported_by_a_no_crash_that_requires_other_checks(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + GATED)))
    result = grade_controllers(plan, [driver(tmp_path, "1 / 0", name="crasher.py")])
    by_name = {t.name: t for t in result.tests}
    assert "ZeroDivisionError" in by_name["no_crash [east]"].output
    assert by_name["wall_hits [east]"].output.startswith("not judged: the controller stopped at t=")


def test_the_twin_run_is_run_only_where_a_check_that_needs_it_is_judged(tmp_path, monkeypatch):
    from turtletui.grading import engine

    checks = '\n[[checks]]\nname = "distance"\nthresholds = {min = 3.0}\n'
    checks += '\n[[checks]]\nname = "closed_loop"\nrequires = ["distance"]\nthresholds = {window = 1.0}\n'
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + checks)))
    starts = []
    real = engine.run_scenario

    def counting(plan, run, controllers, **options):
        starts.append(options.get("start"))
        return real(plan, run, controllers, **options)

    monkeypatch.setattr(engine, "run_scenario", counting)
    outcome = engine.grade_run(plan, 0, [driver(tmp_path, "return")])  # stands still: distance fails
    assert starts == [None]
    assert all(not test.passed for _, test in outcome.tests)
    engine.grade_run(plan, 0, [driver(tmp_path)])  # drives: the loop is judged against its twin
    assert starts[1:] == [None, plan.runs[0].twin_start]



def test_a_run_killed_from_outside_is_run_again_and_one_that_kills_itself_is_not_forgiven(tmp_path):
    plan = prepare(load_lesson(lesson(tmp_path, SCENARIOS + CHECKS)))
    marks = tmp_path / "marks"
    marks.mkdir()
    # every first attempt of a run is killed (SIGKILL), as the OOM killer or a stray kill would
    body = "\n        ".join([
        "import os, signal",
        "if not hasattr(self, 'seen'):",
        "    self.seen = n = len(os.listdir(MARKS))",
        "    open(os.path.join(MARKS, str(n)), 'w').close()",
        "    if n % 2 == 0:",
        "        os.kill(os.getpid(), signal.SIGKILL)",
    ]).replace("MARKS", repr(str(marks)))
    once = driver(tmp_path, body, name="killed_once.py")
    killed_once = grade_controllers(plan, [once])
    assert len(list(marks.iterdir())) == 2 * len(plan.runs)  # each run, killed, was run again
    assert killed_once.score == grade_controllers(plan, [driver(tmp_path)]).score > 0
    assert not any("SIGKILL" in t.output for t in killed_once.tests)
    always = driver(tmp_path, "import os, signal; os.kill(os.getpid(), signal.SIGKILL)", name="suicide.py")
    result = grade_controllers(plan, [always])
    assert result.score == 0.0
    crash = next(t for t in result.tests if t.check == "no_crash" and not t.hidden)
    assert "SIGKILL" in crash.output
