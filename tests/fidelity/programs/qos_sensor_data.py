"""A subscription with qos_profile_sensor_data (best effort) hearing a reliable publisher in
the same program (a compatible pair), and a reliable subscription on the same topic: the
publisher's get_subscription_count(), each subscription's get_publisher_count(), what both
receive, and the counts after one subscription is destroyed."""
import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from std_msgs.msg import Int32


def main():
    rclpy.init()
    node = Node("sensor_qos")
    pub = node.create_publisher(Int32, "reading", 10)
    sensor_heard, reliable_heard = [], []
    sensor = node.create_subscription(Int32, "reading", lambda msg: sensor_heard.append(msg.data), qos_profile_sensor_data)
    node.create_subscription(Int32, "reading", lambda msg: reliable_heard.append(msg.data), 10)
    for _ in range(50):
        if pub.get_subscription_count() == 2:
            break
        rclpy.spin_once(node, timeout_sec=0.1)
    print("subscriptions matched:", pub.get_subscription_count())
    print("publishers seen by the sensor subscription:", sensor.get_publisher_count())
    print("sensor qos:", sensor.qos_profile.reliability.name, sensor.qos_profile.depth)
    for value in range(3):
        pub.publish(Int32(data=value))
        for _ in range(50):
            if len(sensor_heard) > value and len(reliable_heard) > value:
                break
            rclpy.spin_once(node, timeout_sec=0.1)
    print("sensor heard:", sensor_heard)
    print("reliable heard:", reliable_heard)
    print("destroyed:", node.destroy_subscription(sensor))
    for _ in range(50):
        if pub.get_subscription_count() == 1:
            break
        rclpy.spin_once(node, timeout_sec=0.1)
    print("subscriptions after destroy:", pub.get_subscription_count(), node.count_subscribers("reading"))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
