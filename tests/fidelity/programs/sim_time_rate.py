"""Rate on /clock time (use_sim_time), the loop in main and rclpy.spin in a thread: the
rate's sleep returns as /clock passes each period, and a clock sleep_for waits for /clock
too. A simulator node (on wall time) publishes /clock, 0.1 s of it every 0.05 s.
Sandboxed only: threads need turtletui's sandbox."""
import threading

import rclpy
from builtin_interfaces.msg import Time
from rclpy.duration import Duration
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rosgraph_msgs.msg import Clock


class Simulator(Node):
    def __init__(self):
        super().__init__("simulator")
        self.publisher = self.create_publisher(Clock, "/clock", 10)
        self.tenths = 0
        self.timer = self.create_timer(0.05, self.tick, autostart=False)

    def tick(self):
        self.tenths += 1
        sec, tenth = divmod(self.tenths, 10)
        self.publisher.publish(Clock(clock=Time(sec=sec, nanosec=tenth * 100_000_000)))


def spin(executor, spinning):
    # Spinning stops before rclpy.shutdown(): the real rclpy raises in a spin
    # thread still waiting when the context ends (RCLError: failed to
    # initialize wait set), executor.shutdown() during a spin races too, and
    # a callback still running then fails to publish.
    while spinning.is_set():
        executor.spin_once(timeout_sec=0.05)


def main():
    rclpy.init()
    node = Node("paced", parameter_overrides=[Parameter("use_sim_time", value=True)])
    simulator = Simulator()
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(node)
    executor.add_node(simulator)
    spinning = threading.Event()
    spinning.set()
    spinner = threading.Thread(target=spin, args=(executor, spinning), daemon=True)
    spinner.start()
    clock = node.get_clock()
    rate = node.create_rate(2)
    print("rate made at", clock.now().nanoseconds)
    while simulator.publisher.get_subscription_count() == 0:
        pass
    simulator.timer.reset()
    for _ in range(3):
        rate.sleep()
        # the period ends at a /clock instant; reading it may come one message later
        print("woke near", round(clock.now().nanoseconds / 5e8) / 2)
    print("slept", clock.sleep_for(Duration(seconds=1)), "until near", round(clock.now().nanoseconds / 5e8) / 2)
    simulator.timer.cancel()
    spinning.clear()
    spinner.join()
    executor.shutdown()  # waits for the callbacks still running in its threads
    rclpy.shutdown()


if __name__ == "__main__":
    main()
