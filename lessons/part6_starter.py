#!/usr/bin/env python3
"""Part 6 starter: closed-loop control. Fill in pose_callback.

Run it with:  turtletui run part6_starter.py
(or on a real ROS 2 turtlesim:  python3 part6_starter.py)
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(
            Pose, "/turtle1/pose", self.pose_callback, 10
        )
        self.get_logger().info("Turtle controller has started")

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        # TODO 1: decide whether the turtle is near a wall. The arena runs from
        #         0 to 11.09 m on both axes; the safe zone is 2 m to 9 m
        #         (look at pose.x and pose.y).
        # TODO 2: near a wall, drive slowly and turn:
        #         set cmd.linear.x and cmd.angular.z.
        # TODO 3: in open space, drive straight ahead at full speed.
        # Until you fill these in, cmd stays all zeros: the turtle sits still.
        self.cmd_vel_publisher_.publish(cmd)


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
