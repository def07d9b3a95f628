"""Right, written differently: headings in degrees through math.radians, goals and results
awaited with spin_once loops in main(), the result's status checked."""
import math

import rclpy
from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    node = rclpy.create_node("turner")
    client = ActionClient(node, RotateAbsolute, "/turtle1/rotate_absolute")
    while not client.wait_for_server(timeout_sec=1.0):
        node.get_logger().info("waiting for the server")
    for degrees in (90, 180, -90, 0):
        goal = RotateAbsolute.Goal()
        goal.theta = math.radians(degrees)
        sent = client.send_goal_async(goal, feedback_callback=lambda m: node.get_logger().info(
            "remaining: %.2f" % m.feedback.remaining))
        while not sent.done():
            rclpy.spin_once(node, timeout_sec=0.1)
        result = sent.result().get_result_async()
        while not result.done():
            rclpy.spin_once(node, timeout_sec=0.1)
        ok = result.result().status == GoalStatus.STATUS_SUCCEEDED
        node.get_logger().info(f"{degrees} deg: {'ok' if ok else 'failed'}")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
