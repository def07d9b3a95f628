#!/usr/bin/env python3
"""Parameters starter: Part 6's wall avoider, its numbers as node parameters.

Run it with:  turtletui run parameters_starter.py --ros-args -p speed:=2.0
(or on a real ROS 2 turtlesim:  python3 parameters_starter.py --ros-args -p speed:=2.0)
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        # A parameter: a name and a default. Its type comes from the default:
        # write 5.0, not 5, or -p speed:=2.0 will be refused.
        self.declare_parameter("speed", 5.0)
        # TODO 1: declare slow_speed (1.0), turn_rate (1.5), box_min (2.0)
        #         and box_max (9.0) the same way.
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(
            Pose, "/turtle1/pose", self.pose_callback, 10
        )
        self.get_logger().info(f"Wall avoider started, speed {self.get_parameter('speed').value}")

    def pose_callback(self, pose: Pose):
        speed = self.get_parameter("speed").value
        # TODO 2: read the other four parameters here, like speed, and use
        #         them below instead of the constants 1.0, 1.5, 2.0 and 9.0.
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = speed
            cmd.angular.z = 0.0
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
