"""Spinning without waiting: spin_once(timeout_sec=0) with nothing ready returns at once, and
runs one ready callback (a triggered guard condition, a due timer) per call;
spin_until_future_complete on a future already done or with timeout_sec=0, and an
executor's wake(), which runs nothing."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def main():
    rclpy.init()
    node = Node("no_wait")
    ran = []
    guard = node.create_guard_condition(lambda: ran.append("guard"))
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0)
    print("nothing ready:", ran)
    guard.trigger()
    guard.trigger()
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0)
        print("after one spin:", ran)
    ran.clear()
    timer = node.create_timer(0.05, lambda: ran.append("timer"))
    rclpy.spin_once(node, timeout_sec=0)
    print("timer not yet due:", ran)
    while not ran:
        rclpy.spin_once(node, timeout_sec=1.0)
    timer.cancel()
    print("timer due:", ran)
    done = Future()
    done.set_result("already")
    rclpy.spin_until_future_complete(node, done)
    print("done future:", done.result())
    pending = Future()
    rclpy.spin_until_future_complete(node, pending, timeout_sec=0)
    print("timeout 0:", pending.done())
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    executor.wake()
    executor.spin_once(timeout_sec=0)
    print("after wake:", ran)
    guard.trigger()
    executor.spin_once(timeout_sec=0)
    print("guard on the executor:", ran[-1])
    later = Future()
    node.create_timer(0.2, lambda: later.done() or later.set_result("from a timer"))
    executor.spin_until_future_complete(later, timeout_sec=5.0)
    print("future:", later.result())
    executor.shutdown()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
