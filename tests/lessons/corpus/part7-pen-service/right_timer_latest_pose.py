"""Right, written differently: a 20 Hz timer drives from the latest pose and
sets the pen (blue right, yellow left) when the side it is on changes."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class PenDriver(Node):
    def __init__(self):
        super().__init__("pen_driver")
        self.pose = None
        self.side = None
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pen = self.create_client(SetPen, "/turtle1/set_pen")
        self.create_subscription(Pose, "/turtle1/pose", self.store, 10)
        self.create_timer(0.05, self.step)

    def store(self, pose):
        self.pose = pose

    def step(self):
        if self.pose is None:
            return
        p = self.pose
        twist = Twist()
        if p.x > 9.0 or p.x < 2.0 or p.y > 9.0 or p.y < 2.0:
            twist.linear.x, twist.angular.z = 1.0, 1.8
        else:
            twist.linear.x = 4.0
        self.cmd.publish(twist)
        side = "right" if p.x > 5.5 else "left"
        if side != self.side:
            self.side = side
            colour = (0, 0, 255) if side == "right" else (255, 255, 0)
            request = SetPen.Request(r=colour[0], g=colour[1], b=colour[2], width=3, off=0)
            self.pen.call_async(request)
            self.get_logger().info(f"now on the {side}: pen {colour}")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PenDriver())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
