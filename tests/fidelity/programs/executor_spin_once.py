"""A SingleThreadedExecutor driven by hand: add_node, spin_once(timeout_sec) in a loop,
spin_until_future_complete on a future a timer completes, get_nodes, shutdown."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


class Ticker(Node):
    def __init__(self):
        super().__init__("ticker")
        self.ticks = 0
        self.third = Future()
        self.create_timer(0.2, self.tick)

    def tick(self):
        self.ticks += 1
        self.get_logger().info(f"tick {self.ticks}")
        if self.ticks == 3:
            self.third.set_result("third tick")


def main():
    rclpy.init()
    node = Ticker()
    executor = SingleThreadedExecutor()
    print("added:", executor.add_node(node), "again:", executor.add_node(node))
    print("nodes:", [n.get_name() for n in executor.get_nodes()])
    executor.spin_once(timeout_sec=0.05)
    print("after a short spin_once:", node.ticks)
    while node.ticks < 2:
        executor.spin_once(timeout_sec=1.0)
    print("after spinning for two:", node.ticks)
    executor.spin_until_future_complete(node.third, timeout_sec=5.0)
    print("future:", node.third.done(), node.third.result())
    executor.remove_node(node)
    print("nodes left:", executor.get_nodes())
    print("shutdown:", executor.shutdown())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
