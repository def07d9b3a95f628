"""sensor_msgs a robot publishes: a LaserScan, an Image, an Imu, a JointState, a NavSatFix, round-tripped."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image, Imu, JointState, LaserScan, NavSatFix, NavSatStatus


class Sensors(Node):
    def __init__(self):
        super().__init__("sensors")
        self.kinds = [LaserScan, Image, Imu, JointState, NavSatFix]
        self.pubs = {k: self.create_publisher(k, k.__name__.lower(), 10) for k in self.kinds}
        for kind in self.kinds:
            self.create_subscription(kind, kind.__name__.lower(), self.received, 10)
        self.count = 0

    def send(self):
        self.pubs[LaserScan].publish(LaserScan(angle_min=-1.5, angle_max=1.5, ranges=[1.0, 2.0, float("inf")]))
        self.pubs[Image].publish(Image(height=1, width=3, encoding="mono8", step=3, data=b"\x00\x7f\xff"))
        imu = Imu()
        imu.orientation.w = 1.0
        imu.linear_acceleration.z = 9.81
        imu.orientation_covariance[0] = -1.0
        self.pubs[Imu].publish(imu)
        self.pubs[JointState].publish(JointState(name=["left", "right"], position=[0.5, -0.5]))
        fix = NavSatFix(latitude=48.1, longitude=11.5, position_covariance_type=NavSatFix.COVARIANCE_TYPE_UNKNOWN)
        fix.status.status = NavSatStatus.STATUS_FIX
        self.pubs[NavSatFix].publish(fix)

    def received(self, msg):
        kind = type(msg).__name__
        if kind == "LaserScan":
            text = f"ranges={list(msg.ranges)} min={msg.angle_min}"
        elif kind == "Image":
            text = f"{msg.width}x{msg.height} {msg.encoding} data={list(msg.data)}"
        elif kind == "Imu":
            text = f"w={msg.orientation.w} az={msg.linear_acceleration.z:.2f} cov0={msg.orientation_covariance[0]}"
        elif kind == "JointState":
            text = f"{list(msg.name)} {list(msg.position)} velocity={list(msg.velocity)}"
        else:
            text = f"lat={msg.latitude} status={msg.status.status} cov_type={msg.position_covariance_type}"
        self.get_logger().info(f"{kind}: {text}")
        self.count += 1


def main():
    rclpy.init()
    node = Sensors()
    while any(p.get_subscription_count() == 0 for p in node.pubs.values()):
        rclpy.spin_once(node, timeout_sec=0.1)
    node.send()
    while node.count < 5:
        rclpy.spin_once(node, timeout_sec=1.0)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
