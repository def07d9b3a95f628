"""Right, written differently: no class, a closure for the callback, and print(..., flush=True)
instead of the logger, with x= and y= labels."""
import rclpy
from turtlesim.msg import Pose


def main():
    rclpy.init()
    node = rclpy.create_node("pose_printer")

    def on_pose(msg):
        print(f"x={msg.x:.3f} y={msg.y:.3f}", flush=True)

    node.create_subscription(Pose, "/turtle1/pose", on_pose, 10)
    rclpy.spin(node)


if __name__ == "__main__":
    main()
