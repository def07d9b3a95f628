"""Destroying entities then spinning: a destroyed subscription, timer and service run no more
callbacks, destroying twice returns False, destroying another node's entity, and using a
destroyed publisher."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Empty


def main():
    rclpy.init()
    node = Node("destroyer")
    other = Node("other")
    heard = []
    ticks = []
    pub = node.create_publisher(String, "talk", 10)
    sub = node.create_subscription(String, "talk", lambda msg: heard.append(msg.data), 10)
    timer = node.create_timer(0.05, lambda: ticks.append(1))
    srv = node.create_service(Empty, "srv", lambda request, response: response)
    pub.publish(String(data="first"))
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=0.1)
    print("before:", heard, len(ticks) > 0)
    print("destroy sub:", node.destroy_subscription(sub), "again:", node.destroy_subscription(sub))
    print("destroy timer:", node.destroy_timer(timer), "again:", node.destroy_timer(timer))
    print("destroy srv:", node.destroy_service(srv), "again:", node.destroy_service(srv))
    print("other's publisher:", other.destroy_publisher(pub))
    count = len(ticks)
    pub.publish(String(data="second"))
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=0.05)
    print("after:", heard, len(ticks) == count)
    print("destroy pub:", node.destroy_publisher(pub))
    try:
        pub.publish(String(data="third"))
        print("published on a destroyed publisher")
    except Exception as err:
        print("destroyed publisher:", type(err).__name__, err)
    try:
        print("count on destroyed:", pub.get_subscription_count())
    except Exception as err:
        print("count on destroyed:", type(err).__name__, err)
    other.destroy_node()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
