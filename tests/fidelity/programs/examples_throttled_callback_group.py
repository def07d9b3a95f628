"""ros2/examples' custom_callback_group: a CallbackGroup subclass (a token bucket) whose
can_execute and beginning_execution hold a fast timer back until a slower timer refills it,
spun by rclpy.spin() inside the tutorials' `with rclpy.init():` / ExternalShutdownException
pattern, and ended by rclpy.shutdown() from the throttled callback."""
import threading

import rclpy
from rclpy.callback_groups import CallbackGroup
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import String


class ThrottledCallbackGroup(CallbackGroup):
    def __init__(self, node):
        super().__init__()
        self.timer = node.create_timer(0.3, self.timer_callback)
        self.bucket = 3
        self.bucket_max = 3
        self.lock = threading.Lock()
        self.refills = 0

    def can_execute(self, entity):
        return self.bucket > 0

    def beginning_execution(self, entity):
        with self.lock:
            if self.bucket > 0:
                self.bucket -= 1
                return True
            return False

    def ending_execution(self, entity):
        pass

    def timer_callback(self):
        with self.lock:
            if self.bucket < self.bucket_max:
                self.bucket += 1
                self.refills += 1


class ThrottledTalker(Node):
    def __init__(self):
        super().__init__("intermittent_talker")
        self.i = 0
        self.pub = self.create_publisher(String, "chatter", 10)
        self.group = ThrottledCallbackGroup(self)
        self.timer = self.create_timer(0.05, self.timer_callback, callback_group=self.group)
        print("group of the timer:", type(self.timer.callback_group).__name__)
        print("default group:", type(self.default_callback_group).__name__)

    def timer_callback(self):
        msg = String()
        msg.data = f"Hello World: {self.i}"
        self.i += 1
        self.get_logger().info(f'Publishing: "{msg.data}"')
        self.pub.publish(msg)
        if self.i == 5:
            print("refills before the fifth:", self.group.refills >= 1)
            rclpy.shutdown()


def main(args=None):
    try:
        with rclpy.init(args=args):
            talker = ThrottledTalker()
            rclpy.spin(talker)
            print("spin returned, ok:", rclpy.ok())
    except (KeyboardInterrupt, ExternalShutdownException) as err:
        print("caught", type(err).__name__)
    print("published", talker.i)


if __name__ == "__main__":
    main()
