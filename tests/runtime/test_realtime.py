"""Real-time runs: 16 ms of wall time per tick; a slow controller is late, not waited for."""

import textwrap
import time
from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.runtime.sandbox import Limits

SLOW = """
import socket
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class Slow(Node):
    def __init__(self):
        super().__init__("slow")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.handled = 0

    def on_pose(self, pose):
        self.handled += 1
        # a blocking call that takes wall time (a socket's timeout is real)
        waiting, _ = socket.socketpair()
        waiting.settimeout({delay})
        try:
            waiting.recv(1)
        except TimeoutError:
            pass
        msg = Twist()
        msg.linear.x = 1.0
        self.pub.publish(msg)
        self.get_logger().info(f"handled {{self.handled}}")
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "node.py"
    path.write_text(textwrap.dedent(text))
    return path


def timed_run(path: Path, **kwargs):
    started = time.monotonic()
    result = run([path], realtime=True, **kwargs)
    return result, time.monotonic() - started


def test_real_time_runs_at_wall_clock_speed():
    path = Path(__file__).resolve().parents[2] / "plugins" / "reference" / "turtle_controller.py"
    result, wall = timed_run(path, duration=1.0)
    assert result.crashes == []
    assert wall > 0.95  # never faster than the wall clock (a busy machine may be slower)
    lockstep = run([path], duration=1.0)
    # The controller drove the turtle as in lockstep, but for commands that
    # missed their tick (a few on a busy machine).
    assert result.turtles["turtle1"].distance > 0.5 * lockstep.turtles["turtle1"].distance


def test_a_slow_controller_is_late_and_the_world_does_not_wait(tmp_path: Path):
    result, _ = timed_run(write(tmp_path, SLOW.format(delay=0.05)), duration=1.0)
    assert result.crashes == []
    handled = [r for r in result.logs if r.node == "slow"]
    poses = int(1.0 / 0.016) - 1
    # About 20 callbacks of 50 ms fit in a second; the rest of the 61 poses
    # were dropped by the keep-last queue or came too late. A simulation
    # that waited for the controller would have handed it every one.
    assert 5 <= len(handled) < poses // 2
    assert result.turtles["turtle1"].distance > 0.5


def test_a_hung_controller_is_stopped_while_the_world_goes_on(tmp_path: Path):
    result, _ = timed_run(
        write(tmp_path, SLOW.format(delay=30)), duration=1.5, limits=Limits(step_timeout=0.4)
    )
    assert result.sim_time == pytest.approx(1.5)
    [crash] = result.crashes
    assert crash.kind == "timeout"
    assert "did not answer within 0.4 s" in crash.message
    # the world went on while the controller hung (it blocked at its first pose)
    assert crash.t >= 0.3
