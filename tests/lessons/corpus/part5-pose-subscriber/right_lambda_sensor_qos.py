"""Right: rclpy.create_node, a lambda callback, sensor-data QoS, rounded to 2 decimals."""
import rclpy
from rclpy.qos import qos_profile_sensor_data
from turtlesim.msg import Pose


def main():
    rclpy.init()
    node = rclpy.create_node("pose_logger")
    log = node.get_logger()
    node.create_subscription(
        Pose, "turtle1/pose", lambda p: log.info("x=%.2f y=%.2f theta=%.2f" % (p.x, p.y, p.theta)),
        qos_profile_sensor_data)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
