"""A timer of a node added to a spinning executor later: its periods missed while no executor
had the node run once when it is added (rcl's timer is ready or not), also when the timer was
due again, and queued, after its first call began to wait."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


def main():
    rclpy.init()
    a = Node("a")
    b = Node("b")
    calls = []
    a.create_timer(0.2, lambda: calls.append("a"))
    b.create_timer(0.3, lambda: calls.append("b"))
    executor = SingleThreadedExecutor()
    executor.add_node(a)
    for _ in range(3):
        executor.spin_once(timeout_sec=1.0)
    print("before b is added:", calls)
    calls.clear()
    executor.add_node(b)
    for _ in range(4):
        executor.spin_once(timeout_sec=1.0)
    print("after:", calls)
    executor.shutdown()
    a.destroy_node()
    b.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
