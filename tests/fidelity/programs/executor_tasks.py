"""executor.create_task(): a coroutine that returns a value, a plain function with arguments,
a coroutine that awaits a timer-completed Future, one that raises; spin_until_future_complete
on each task, and the task's done(), result() and exception() afterwards."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


async def add(a, b):
    return a + b


def multiply(a, b):
    return a * b


async def fails():
    raise ValueError("task failed")


def main():
    rclpy.init()
    node = Node("tasks")
    executor = SingleThreadedExecutor()
    executor.add_node(node)

    task = executor.create_task(add, 2, 3)
    print("before spinning:", task.done(), task.result())
    executor.spin_until_future_complete(task, timeout_sec=5.0)
    print("coroutine task:", task.done(), task.result(), task.exception())

    plain = executor.create_task(multiply, 4, 5)
    executor.spin_until_future_complete(plain, timeout_sec=5.0)
    print("function task:", plain.done(), plain.result())

    gate = Future()
    timer = node.create_timer(0.1, lambda: gate.done() or gate.set_result("opened"))

    async def waits():
        value = await gate
        return "got " + value

    waiting = executor.create_task(waits)
    executor.spin_until_future_complete(waiting, timeout_sec=5.0)
    print("awaiting task:", waiting.done(), waiting.result())
    node.destroy_timer(timer)

    failing = executor.create_task(fails)
    try:
        executor.spin_until_future_complete(failing, timeout_sec=5.0)
        print("failing task: spin returned")
    except Exception as err:
        print("failing task: spin raised", type(err).__name__, err)
    print("failing task:", failing.done(), repr(failing.exception()))
    try:
        failing.result()
    except ValueError as err:
        print("result raises:", err)

    executor.shutdown()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
