"""Controller source shared by the runtime and grading tests."""

from __future__ import annotations

import textwrap

WALL_TIME = """
import socket
import time


def block(seconds):
    # wall time without CPU: a socket's timeout is real (sleeps and waits are simulated)
    waiting, _ = socket.socketpair()
    waiting.settimeout(seconds)
    try:
        waiting.recv(1)
    except TimeoutError:
        pass


def work(seconds):
    # CPU time: the clocks a controller reads in lockstep are simulated
    end = time.process_time() + seconds
    while time.process_time() < end:
        pass
"""
"""``block(seconds)`` and ``work(seconds)``: a controller that takes wall time."""

_SPIN_IN_A_THREAD = """
import threading, time
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class Controller(Node):
    def __init__(self):
        super().__init__("threaded")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.pose = None

    def on_pose(self, pose):
        self.pose = pose


def main():
    rclpy.init()
    node = Controller()
    spinner = threading.Thread(target=rclpy.spin, args=(node,), daemon=True)
    spinner.start()
    rate = node.create_rate(RATE)
    while rclpy.ok():
        cmd = Twist()
        pose = node.pose
STEER
        node.pub.publish(cmd)
        WAIT
    spinner.join()


if __name__ == "__main__":
    main()
"""


def spin_in_a_thread(steer: str, wait: str = "rate.sleep()", rate: int = 20) -> str:
    """A controller whose node is spun by ``rclpy.spin`` in a thread while
    main() publishes ``cmd`` in a loop, set by ``steer`` from ``pose`` (the
    latest pose, None before the first), then waits with ``wait``."""
    return (
        _SPIN_IN_A_THREAD.replace("RATE", str(rate))
        .replace("STEER", textwrap.indent(textwrap.dedent(steer).strip("\n"), " " * 8))
        .replace("WAIT", wait)
    )
