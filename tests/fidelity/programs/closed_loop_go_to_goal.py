"""A closed loop as the course writes it, against a toy turtle in the same program: a
"sim" node integrates each turtlesim_msgs/Pose from the last Twist it got (a fixed step per
command, so the run is the same every time) and publishes the pose (on toy/ topics:
turtletui's own turtlesim has turtle1's); a proportional
go-to-goal controller subscribed to the pose publishes a Twist for each pose, stops within
a tolerance, and logs when it arrives. Printed: the iterations, the final pose, the last
command, the log line, and the first poses as the controller got them (Pose's fields are
float32: what arrives is rounded to float32, not the float the toy turtle set)."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from turtlesim_msgs.msg import Pose

DT = 0.05


class ToyTurtle(Node):
    def __init__(self):
        super().__init__("toy_turtle")
        self.pose = Pose(x=5.5, y=5.5, theta=0.0)
        self.pub = self.create_publisher(Pose, "toy/pose", 10)
        self.create_subscription(Twist, "toy/cmd_vel", self.on_cmd, 10)
        self.start = self.create_timer(0.1, self.kick_off)

    def kick_off(self):
        self.start.cancel()
        self.pub.publish(self.pose)

    def on_cmd(self, cmd):
        p = self.pose
        theta = p.theta + cmd.angular.z * DT
        theta = math.atan2(math.sin(theta), math.cos(theta))
        self.pose = Pose(x=p.x + cmd.linear.x * math.cos(theta) * DT, y=p.y + cmd.linear.x * math.sin(theta) * DT,
                         theta=theta, linear_velocity=cmd.linear.x, angular_velocity=cmd.angular.z)
        self.pub.publish(self.pose)


class GoToGoal(Node):
    def __init__(self, goal):
        super().__init__("go_to_goal")
        self.goal = goal
        self.iterations = 0
        self.arrived = False
        self.last = None
        self.heard = []
        self.cmd_pub = self.create_publisher(Twist, "toy/cmd_vel", 10)
        self.create_subscription(Pose, "toy/pose", self.on_pose, 10)

    def on_pose(self, pose):
        if self.arrived:
            return
        self.iterations += 1
        if self.iterations <= 6:
            self.heard.append((pose.x, pose.y, pose.theta))
        dx, dy = self.goal[0] - pose.x, self.goal[1] - pose.y
        distance = math.hypot(dx, dy)
        cmd = Twist()
        if distance < 0.05:
            self.arrived = True
            self.get_logger().info(f"arrived at ({pose.x:.2f}, {pose.y:.2f}) after {self.iterations} poses")
        else:
            heading = math.atan2(dy, dx)
            error = math.atan2(math.sin(heading - pose.theta), math.cos(heading - pose.theta))
            cmd.angular.z = 4.0 * error
            cmd.linear.x = min(1.5 * distance, 2.0) if abs(error) < 0.5 else 0.0
        self.last = cmd
        self.cmd_pub.publish(cmd)


def main():
    rclpy.init()
    turtle = ToyTurtle()
    controller = GoToGoal((8.0, 3.0))
    executor = SingleThreadedExecutor()
    executor.add_node(turtle)
    executor.add_node(controller)
    for _ in range(5000):
        executor.spin_once(timeout_sec=0.5)
        if controller.arrived:
            break
    pose = turtle.pose
    print("arrived:", controller.arrived, "iterations:", controller.iterations)
    print(f"final pose: x={pose.x:.4f} y={pose.y:.4f} theta={pose.theta:.4f}")
    print("last command:", controller.last)
    for x, y, theta in controller.heard:
        print("heard:", x, y, theta)
    executor.shutdown()
    turtle.destroy_node()
    controller.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
