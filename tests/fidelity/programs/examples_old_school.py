"""ros2/examples' old-school publisher and subscriber together: rclpy.create_node, a module-level
global node used by a plain function callback, a `while rclpy.ok():` loop that publishes,
sleeps with time.sleep and spins the subscriber's node with spin_once, as ROS 1 code did."""
from time import sleep

import rclpy
from rclpy.executors import ExternalShutdownException
from std_msgs.msg import String

g_node = None
heard = []


def chatter_callback(msg):
    global g_node
    g_node.get_logger().info(f'I heard: "{msg.data}"')
    heard.append(msg.data)


def main(args=None):
    global g_node
    try:
        with rclpy.init(args=args):
            node = rclpy.create_node("minimal_publisher")
            g_node = rclpy.create_node("minimal_subscriber")
            subscription = g_node.create_subscription(String, "topic", chatter_callback, 10)
            print("subscription topic:", subscription.topic_name)
            publisher = node.create_publisher(String, "topic", 10)
            while publisher.get_subscription_count() == 0:
                sleep(0.05)
            msg = String()
            i = 0
            while rclpy.ok():
                msg.data = f"Hello World: {i}"
                i += 1
                node.get_logger().info(f'Publishing: "{msg.data}"')
                publisher.publish(msg)
                sleep(0.05)
                while len(heard) < i:
                    rclpy.spin_once(g_node, timeout_sec=1.0)
                if i == 4:
                    break
            g_node.destroy_subscription(subscription)
            print("heard:", heard)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
