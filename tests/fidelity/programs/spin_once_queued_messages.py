"""Messages that queue up between spins, as in a control loop that sleeps between
spin_once() calls: each spin_once() runs one callback with the oldest queued message (so
a slow loop reads stale poses), a subscription of depth 2 keeps only the newest two, and two
subscriptions with queued messages take turns. One node, its own publishers."""
import rclpy
from geometry_msgs.msg import Point
from rclpy.node import Node
from std_msgs.msg import Int32


def main():
    rclpy.init()
    node = Node("loop")
    heard = []
    pose_pub = node.create_publisher(Point, "pose", 10)
    node.create_subscription(Point, "pose", lambda msg: heard.append(("pose", msg.x)), 10)
    for x in range(5):
        pose_pub.publish(Point(x=float(x)))
    for step in range(3):
        rclpy.spin_once(node, timeout_sec=0.5)
        print(f"after spin_once {step + 1}: the loop sees pose x={heard[-1][1]} ({len(heard)} heard)")
    while len(heard) < 5:
        rclpy.spin_once(node, timeout_sec=0.5)
    print("all:", [x for _, x in heard])
    heard.clear()
    short_pub = node.create_publisher(Int32, "short", 10)
    node.create_subscription(Int32, "short", lambda msg: heard.append(("short", msg.data)), 2)
    for i in range(5):
        short_pub.publish(Int32(data=i))
    for _ in range(4):
        rclpy.spin_once(node, timeout_sec=0.2)
    print("depth 2 kept:", heard)
    heard.clear()
    for i in range(3):
        pose_pub.publish(Point(x=10.0 + i))
        short_pub.publish(Int32(data=20 + i))
    for _ in range(6):
        rclpy.spin_once(node, timeout_sec=0.5)
    print("two subscriptions:", heard)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
