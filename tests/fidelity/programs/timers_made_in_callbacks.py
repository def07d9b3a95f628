"""Timers and subscriptions made and destroyed inside callbacks, as course code does for a
one-shot delay: a timer that creates a one-shot timer which cancels and destroys itself in its
own callback, a subscription made in a callback that hears the next message, a timer destroyed
by another's callback, and node.timers as they come and go."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32


class Sequencer(Node):
    def __init__(self):
        super().__init__("sequencer")
        self.steps = []
        self.pub = self.create_publisher(Int32, "numbers", 10)
        self.count = 0
        self.ticker = self.create_timer(0.1, self.tick)
        self.doomed = self.create_timer(0.25, self.never)
        self.listener = None

    def tick(self):
        self.count += 1
        self.steps.append(f"tick {self.count} timers={len(list(self.timers))}")
        if self.count == 1:
            self.one_shot = self.create_timer(0.15, self.fire_once)
        if self.count == 2:
            self.destroyed = self.destroy_timer(self.doomed)
            self.steps.append(f"destroyed doomed: {self.destroyed}")
        if self.count == 3:
            self.listener = self.create_subscription(Int32, "numbers", self.heard, 10)
        if self.count >= 4:
            self.pub.publish(Int32(data=self.count))
        if self.count == 7:
            self.ticker.cancel()
            self.steps.append(f"ticker cancelled: {self.ticker.is_canceled()}")

    def fire_once(self):
        self.steps.append("one shot")
        self.one_shot.cancel()
        self.steps.append(f"destroy one shot in its callback: {self.destroy_timer(self.one_shot)}")

    def never(self):
        self.steps.append("doomed fired")

    def heard(self, msg):
        self.steps.append(f"heard {msg.data}")


def main():
    rclpy.init()
    node = Sequencer()
    for _ in range(40):
        rclpy.spin_once(node, timeout_sec=0.05)
        if node.ticker.is_canceled() and len([s for s in node.steps if s.startswith("heard")]) == 4:
            break
    for step in node.steps:
        print(step)
    print("timers at the end:", len(list(node.timers)))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
