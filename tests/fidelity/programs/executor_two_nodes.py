"""Two nodes in one SingleThreadedExecutor run both nodes' callbacks; the same nodes spun
separately with rclpy.spin_once run only the spun node's; spin_once(timeout_sec=0) over two
nodes alternately, each with a triggered guard condition; an executor with no nodes while
other nodes have work runs nothing (but runs a task made with its create_task)."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def main():
    rclpy.init()
    a = Node("left")
    b = Node("right")
    ran = []
    guard_a = a.create_guard_condition(lambda: ran.append("a"))
    guard_b = b.create_guard_condition(lambda: ran.append("b"))

    guard_a.trigger()
    guard_b.trigger()
    executor = SingleThreadedExecutor()
    executor.add_node(a)
    executor.add_node(b)
    for _ in range(4):
        executor.spin_once(timeout_sec=0.2)
    print("one executor with both:", sorted(ran))
    executor.remove_node(a)
    executor.remove_node(b)

    ran.clear()
    guard_a.trigger()
    guard_b.trigger()
    for _ in range(3):
        rclpy.spin_once(a, timeout_sec=0.2)
    print("spin_once(left) only:", ran)
    for _ in range(3):
        rclpy.spin_once(b, timeout_sec=0.2)
    print("then spin_once(right):", ran)

    ran.clear()
    for _ in range(3):
        guard_a.trigger()
        guard_b.trigger()
        rclpy.spin_once(a, timeout_sec=0.5)
        rclpy.spin_once(b, timeout_sec=0.5)
    print("alternating with a timeout:", ran.count("a"), ran.count("b"))

    empty = SingleThreadedExecutor()
    ran.clear()
    guard_a.trigger()
    ticks = []
    timer = a.create_timer(0.05, lambda: ticks.append(1))
    empty.spin_once(timeout_sec=0.3)
    print("empty executor ran:", ran, len(ticks))
    task = empty.create_task(lambda: "task result")
    empty.spin_once(timeout_sec=0.3)
    print("empty executor's task:", task.done(), task.result() if task.done() else None, ran, len(ticks))
    done = Future()
    empty.create_task(lambda: done.set_result("set by a task"))
    empty.spin_until_future_complete(done, timeout_sec=1.0)
    print("empty executor future:", done.done(), done.result() if done.done() else None)
    timer.cancel()
    rclpy.spin_once(a, timeout_sec=0.2)
    print("left spun again:", ran)
    empty.shutdown()
    executor.shutdown()
    a.destroy_node()
    b.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
