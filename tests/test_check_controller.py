"""turtletui.testing.check_controller: deterministic controllers pass; each way
of not being deterministic fails with a message naming it and where."""

from __future__ import annotations

import textwrap
import uuid
from pathlib import Path

import pytest

from turtletui.errors import TurtletuiError
from turtletui.runtime.sandbox import Limits
from turtletui.testing import ControllerCheck, ControllerCheckError, check_controller

REFERENCE = Path(__file__).resolve().parents[1] / "plugins" / "reference"

NODE = """
import random
import sys
import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
{imports}


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        {setup}
        self.create_timer(0.1, self.tick)

    def tick(self):
        msg = Twist()
        msg.linear.x = 1.0
        msg.angular.z = {turn}
        self.pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(Driver())
"""


def controller(folder: Path, *, turn: str = "0.5", setup: str = "pass", imports: str = "", name: str = "node") -> Path:
    """A small controller file driving turtle1 forward, turning by ``turn``."""
    path = folder / f"{name}.py"
    path.write_text(textwrap.dedent(NODE).format(turn=turn, setup=setup, imports=imports))
    return path


def test_a_deterministic_controller_passes(tmp_path):
    report = check_controller(controller(tmp_path), seconds=2.0)
    assert isinstance(report, ControllerCheck)
    assert report.poses == {"turtle1": 124}  # one pose per 16 ms tick after the first
    assert report.log_lines >= 2
    assert not report.seed_changes_trajectory
    assert "nothing in the run draws on the seed" in report.summary()
    assert "seed 0 twice bit for bit, sandboxed = in-process" in report.summary()


def test_random_numbers_from_the_seeded_generators_pass_and_follow_the_seed(tmp_path):
    """turtletui seeds ``random`` and ``numpy.random`` with the run's seed, as a
    reproducible experiment would: same seed, same run; another seed, another."""
    path = controller(tmp_path, turn="random.uniform(-1.0, 1.0)")
    report = check_controller(path, seconds=1.0, seed=3)
    assert report.seed_changes_trajectory
    assert (report.seed, report.other_seed) == (3, 4)
    assert "seed 4 gives another trajectory" in report.summary()


@pytest.mark.parametrize(
    ("setup", "turn", "imports"),
    [
        ("self.rng = random.Random()", "self.rng.uniform(-1.0, 1.0)", ""),
        ("self.rng = np.random.default_rng()", "float(self.rng.uniform(-1.0, 1.0))", "import numpy as np"),
    ],
    ids=["random.Random()", "numpy default_rng()"],
)
def test_an_unseeded_generator_fails_as_not_reproducible(tmp_path, setup, turn, imports):
    path = controller(tmp_path, setup=setup, turn=turn, imports=imports)
    with pytest.raises(ControllerCheckError) as caught:
        check_controller(path, seconds=1.0)
    err = caught.value
    assert err.check == "reproducible"
    message = str(err)
    assert message.startswith(f"{path}: two runs (sandboxed, seed 0) differ: first at tick ")
    assert "turtle1 " in message and "unseeded generator" in message
    # the first difference: the first pose after the first command turned the turtle
    assert err.turtle == "turtle1" and err.first != err.second
    assert f"tick {err.tick} (t={err.t:.3f} s)" in message
    assert 0.0 < err.t < 1.0
    assert "\n" not in message


def test_real_time_in_the_controller_fails_as_not_reproducible(tmp_path):
    """Lockstep clocks read simulated time (time.time() is fine); CPU time is real."""
    path = controller(tmp_path, turn="(time.process_time_ns() % 1000) / 1000.0")
    with pytest.raises(ControllerCheckError, match=r"two runs \(sandboxed, seed 0\) differ.* real time") as caught:
        check_controller(path, seconds=1.0)
    assert caught.value.check == "reproducible"


def test_simulated_clocks_are_deterministic(tmp_path):
    path = controller(tmp_path, turn="(time.time() % 2.0) - 1.0")
    assert check_controller(path, seconds=1.0).poses["turtle1"]


def test_a_global_kept_between_runs_fails_the_fresh_run_check(tmp_path):
    """A module-level global the controller changes in a module it imports: each
    sandboxed run starts a new process, but in-process the module stays loaded."""
    module = f"state_{uuid.uuid4().hex}"  # a name no other test has imported
    (tmp_path / f"{module}.py").write_text("runs = 0\n")
    path = controller(
        tmp_path,
        imports=f"import {module}",
        setup=f"{module}.runs += 1",
        turn=f"0.25 * {module}.runs",
    )
    with pytest.raises(ControllerCheckError) as caught:
        check_controller(path, seconds=1.0)
    err = caught.value
    assert err.check == "fresh"
    assert "a second run (in-process, seed 0) differs from the first" in str(err)
    assert "module-level global" in str(err)
    assert "theta" in str(err)


def test_behaving_differently_in_process_fails_the_hosts_check(tmp_path):
    path = controller(tmp_path, turn="1.0 if 'pytest' in sys.modules else 0.5")
    with pytest.raises(ControllerCheckError) as caught:
        check_controller(path, seconds=1.0)
    err = caught.value
    assert err.check == "hosts"
    assert "the sandboxed, seed 0 and in-process, seed 0 runs differ" in str(err)
    # both turn from the same pose with different speeds: theta differs, bit for bit named
    assert f"theta {err.first[3]!r} vs {err.second[3]!r}" in str(err)


def test_a_log_only_difference_names_the_log_line(tmp_path):
    path = controller(
        tmp_path,
        setup='self.get_logger().info(f"token {random.Random().random()}")',
    )
    with pytest.raises(ControllerCheckError) as caught:
        check_controller(path, seconds=0.5)
    err = caught.value
    assert err.check == "reproducible" and err.turtle is None
    assert "same trajectory, but log line 3 (t=0.000 s) is '[INFO] [" in str(err)
    assert "[driver]: token 0." in str(err)


def test_a_crashing_controller_is_reported_not_checked(tmp_path):
    path = controller(tmp_path, turn="1 / 0")
    with pytest.raises(ControllerCheckError, match=r"crashed at t=.*ZeroDivisionError.*\(sandboxed, seed 0\)") as caught:
        check_controller(path, seconds=1.0)
    assert caught.value.check == "crash"


def test_a_controller_that_never_returns_is_stopped_by_the_sandbox_first(tmp_path):
    """The in-process runs come after a clean sandboxed run: a hang never reaches them."""
    path = controller(tmp_path, setup="while True: pass")
    with pytest.raises(ControllerCheckError, match="only a controller that runs cleanly can be checked") as caught:
        check_controller(path, seconds=1.0, limits=Limits(start_timeout=3.0, step_timeout=1.0))
    assert caught.value.check == "crash"


def test_a_lesson_scenario_runs_as_graded_and_a_random_start_follows_the_seed():
    report = check_controller(
        REFERENCE / "turtle_controller.py", lesson="part6-closed-loop", scenario="random starts", seconds=1.0
    )
    assert report.scenario == "random starts"
    assert report.seed_changes_trajectory
    assert report.poses["turtle1"] == 61


TELEPORTER = """
import rclpy
from rclpy.node import Node
from turtlesim.srv import TeleportAbsolute


def main():
    rclpy.init()
    node = Node("jumper")
    client = node.create_client(TeleportAbsolute, "/turtle1/teleport_absolute")
    client.wait_for_service()
    rclpy.spin_until_future_complete(node, client.call_async(TeleportAbsolute.Request(x=3.0, y=3.0)))
    rclpy.spin(node)
"""


def test_a_controller_that_teleports_away_from_the_random_start_still_starts_there(tmp_path):
    # The teleport comes once the service is discovered (50 ms): until then the
    # turtle stands where the seed put it, as on a robot.
    path = tmp_path / "jumper.py"
    path.write_text(TELEPORTER)
    report = check_controller(path, lesson="part6-closed-loop", scenario="random starts", seconds=0.5)
    assert report.seed_changes_trajectory
    assert report.end_poses["turtle1"] == (3.0, 3.0, 0.0)


def test_a_controller_reading_a_file_runs_in_the_same_folder_in_both_hosts(tmp_path, monkeypatch):
    # a relative path is the caller's in both hosts, as python3 FILE: the hosts check agrees
    here = tmp_path / "here"
    here.mkdir()
    (here / "target.txt").write_text("3.0 3.0")
    path = tmp_path / "jumper.py"
    path.write_text(TELEPORTER.replace("x=3.0, y=3.0", "x=float(open('target.txt').read().split()[0]), y=3.0"))
    monkeypatch.chdir(here)
    report = check_controller(path, lesson="part6-closed-loop", scenario="random starts", seconds=0.5)
    assert report.end_poses["turtle1"] == (3.0, 3.0, 0.0)


NOISY_WORLD = """
[[circles]]
x = 8.0
y = 5.5
r = 0.6

[lidar]
samples = 36
noise_std = 0.05
"""


def test_lidar_noise_follows_the_seed_and_is_named_when_ignored(tmp_path):
    world = tmp_path / "noisy.toml"
    world.write_text(NOISY_WORLD)
    avoider = check_controller(REFERENCE / "lidar_obstacle_avoider.py", world=world, seconds=3.0)
    assert avoider.seed_changes_trajectory
    ignorer = check_controller(controller(tmp_path), world=world, seconds=0.5)
    assert not ignorer.seed_changes_trajectory
    assert "although the LiDAR's noise is drawn from the seed" in ignorer.seed_note


def test_ros_args_and_distro_reach_the_controller():
    report = check_controller(
        REFERENCE / "parameters_wall_avoider.py", ros_args=["-p", "speed:=1.0"], seconds=1.0, distro="jazzy"
    )
    x, y, theta = report.end_poses["turtle1"]
    assert 6.3 < x < 6.6 and theta == 0.0  # 1 m/s, not the default 5 m/s


def test_a_world_by_name_is_built_for_every_run():
    """The LiDAR node drives only where there is a LiDAR (the world's) to read."""
    avoider = REFERENCE / "lidar_obstacle_avoider.py"
    in_the_course = check_controller(avoider, world="lidar-course", seconds=1.0)
    in_the_empty_arena = check_controller(avoider, seconds=1.0)
    x, y, theta = in_the_empty_arena.end_poses["turtle1"]
    assert x == y and theta == 0.0  # never moved
    assert in_the_course.end_poses["turtle1"] != in_the_empty_arena.end_poses["turtle1"]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"other_seed": 0}, "other_seed must differ from seed, both are 0"),
        ({"scenario": "x"}, "scenario 'x' needs a lesson"),
        ({"lesson": "part6-closed-loop", "world": "lidar-course"}, "give a lesson or a world, not both"),
        ({"lesson": "part6-closed-loop", "scenario": "nowhere"}, "no scenario 'nowhere'; its scenarios: "),
        ({"lesson": "no-such-lesson"}, "no lesson 'no-such-lesson'"),
        ({"seconds": -1.0}, "duration must be a positive number of seconds"),
    ],
)
def test_bad_input_is_a_one_line_turtletui_error(tmp_path, kwargs, message):
    with pytest.raises(TurtletuiError, match=message) as caught:
        check_controller(controller(tmp_path), **kwargs)
    assert not isinstance(caught.value, ControllerCheckError)
    assert "\n" not in str(caught.value)


def test_a_missing_file_is_a_one_line_error(tmp_path):
    with pytest.raises(TurtletuiError, match=str(tmp_path / "nope.py")):
        check_controller(tmp_path / "nope.py")
