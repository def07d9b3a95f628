#!/usr/bin/env python3
"""Part 7 starter: a service client. Part 6's wall avoider is done; make it
change the pen colour when the turtle crosses x = 5.5.

Run it with:  turtletui run part7_starter.py
(or on a real ROS 2 turtlesim:  python3 part7_starter.py)
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.previous_x_ = 0.0
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(
            Pose, "/turtle1/pose", self.pose_callback, 10
        )
        self.get_logger().info("Turtle controller has started")

    def pose_callback(self, pose: Pose):
        # Part 6: closed-loop driving, already done.
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
            cmd.angular.z = 0.0
        self.cmd_vel_publisher_.publish(cmd)

        # TODO 3: only when the turtle has changed side of x = 5.5 since the
        #         last call (compare pose.x with self.previous_x_), remember the
        #         new x and call self.call_set_pen_service with one colour for
        #         the right side, e.g. (255, 0, 0, 3, 0), and another for the left.

    def call_set_pen_service(self, r, g, b, width, off):
        client = self.create_client(SetPen, "/turtle1/set_pen")
        while not client.wait_for_service(1.0):
            self.get_logger().warn("Waiting for service...")

        request = SetPen.Request()
        # TODO 1: fill in the request: request.r = r, and so on for g, b,
        #         width and off.

        # TODO 2: send it without waiting for the answer:
        #         future = client.call_async(request)
        #         future.add_done_callback(self.callback_set_pen)
        del request  # remove this line when you send the request

    def callback_set_pen(self, future):
        try:
            future.result()
        except Exception as e:
            self.get_logger().error(f"Service call failed: {e!r}")


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
