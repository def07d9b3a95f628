"""Another ROS 2 process (the real rclpy) with an action server of its own:
/other/rotate (turtlesim's RotateAbsolute) sends two feedbacks and succeeds
with delta = 0.5. Runs for SECONDS."""

import sys
import time

import rclpy
from rclpy.action import ActionServer

try:
    from turtlesim.action import RotateAbsolute
except ImportError:  # Kilted on
    from turtlesim_msgs.action import RotateAbsolute


def execute(goal_handle):
    # A client's feedback subscription may not be matched yet when its goal is
    # accepted (Fast DDS discovers each topic on its own): on a busy machine the
    # first feedback was lost. Real clients meet the same race; give it time.
    time.sleep(0.5)
    for remaining in (0.75, 0.25):
        goal_handle.publish_feedback(RotateAbsolute.Feedback(remaining=remaining))
        time.sleep(0.1)
    goal_handle.succeed()
    return RotateAbsolute.Result(delta=0.5)


def main() -> None:
    rclpy.init()
    node = rclpy.create_node("other")
    ActionServer(node, RotateAbsolute, "/other/rotate", execute)
    end = time.monotonic() + float(sys.argv[1])
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
