"""The pytest plugin (README, "From Python and pytest"): a student's test file
using the ``turtlesim_run`` fixture, run by pytest's own ``pytester``."""

from __future__ import annotations

from importlib.metadata import entry_points
from pathlib import Path

import pytest

import turtletui

pytest_plugins = ["pytester"]

PACKAGE_ROOT = Path(turtletui.__file__).resolve().parents[1]
PART6 = Path(__file__).resolve().parents[1] / "plugins" / "reference" / "turtle_controller.py"


def installed() -> bool:
    return any(ep.value == "turtletui.testing.pytest_plugin" for ep in entry_points(group="pytest11"))


@pytest.fixture(autouse=True)
def student_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    """A student's pytest is its own process; from a source checkout it finds
    turtletui through PYTHONPATH."""
    if not installed():
        monkeypatch.setenv("PYTHONPATH", str(PACKAGE_ROOT))


def run_pytest(pytester: pytest.Pytester, *args: str) -> pytest.RunResult:
    # A subprocess, not runpytest(): inline runs drop the modules they imported
    # (numpy cannot be imported twice) and share plugins' process-wide state.
    return pytester.runpytest_subprocess("-p", "no:cacheprovider", *args, timeout=120)


def run_student_tests(pytester: pytest.Pytester, source: str) -> pytest.RunResult:
    """Installed, pytest loads the plugin from its ``pytest11`` entry point (what
    students get); from a source checkout it has to be named."""
    pytester.makepyfile(test_student=source)
    return run_pytest(pytester, *([] if installed() else ["-p", "turtletui.testing.pytest_plugin"]))


def test_student_test_of_the_part6_node_passes(pytester):
    result = run_student_tests(pytester, f"""
        def test_part6_stays_off_the_wall(turtlesim_run):
            result = turtlesim_run({str(PART6)!r}, duration=5)
            assert result.ok, result.crashes
            assert result.wall_hits == 0
            assert result.sim_time == 5.0
            t, x, y, theta = result.poses["turtle1"][-1]
            assert 1.0 < x < 10.0 and 1.0 < y < 10.0
    """)
    result.assert_outcomes(passed=1)


def test_student_test_in_process_passes(pytester):
    result = run_student_tests(pytester, f"""
        def test_part6_in_process(turtlesim_run):
            result = turtlesim_run({str(PART6)!r}, duration=2, in_process=True)
            assert result.ok and result.wall_hits == 0 and result.distance > 1.0
    """)
    result.assert_outcomes(passed=1)


def test_failing_student_test_fails(pytester):
    result = run_student_tests(pytester, f"""
        def test_part6_drives_nowhere(turtlesim_run):
            result = turtlesim_run({str(PART6)!r}, duration=2)
            assert result.distance == 0.0
    """)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*assert * == 0.0*"])


def test_fixture_missing_without_the_plugin(pytester):
    """The outcomes above come from the plugin: without it the fixture is unknown."""
    pytester.makepyfile(test_student="""
        def test_uses_fixture(turtlesim_run):
            pass
    """)
    result = run_pytest(pytester, "-p", "no:turtletui")
    result.assert_outcomes(errors=1)
    result.stdout.fnmatch_lines(["*fixture 'turtlesim_run' not found*"])


NONDETERMINISTIC = '''
import random

import rclpy
from geometry_msgs.msg import Twist, Vector3
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("driver")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    rng = random.Random()  # unseeded: another run, another path
    node.create_timer(0.1, lambda: pub.publish(Twist(angular=Vector3(z=rng.uniform(-1, 1)))))
    rclpy.spin(node)
'''


def test_check_controller_in_a_student_test(pytester):
    """A failed check is a test failure (an AssertionError) showing the student's
    line and the one-line reason, not turtletui's frames."""
    node = pytester.path / "wobbly.py"
    node.write_text(NONDETERMINISTIC)
    result = run_student_tests(pytester, f"""
        from turtletui.testing import check_controller

        def test_part6_is_deterministic():
            report = check_controller({str(PART6)!r}, seconds=1, distro="jazzy")
            assert report.poses["turtle1"] == 61

        def test_wobbly_is_deterministic():
            check_controller({str(node)!r}, seconds=1)
    """)
    result.assert_outcomes(passed=1, failed=1)
    result.stdout.fnmatch_lines([
        "*check_controller(*wobbly.py*",
        "E*turtletui.testing.ControllerCheckError: *wobbly.py: two runs (sandboxed, seed 0) differ: first at tick *",
    ])
    result.stdout.no_fnmatch_line("*turtletui/testing/checker.py*")
