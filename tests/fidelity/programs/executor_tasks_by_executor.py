"""Tasks belong to the executor that made them: a task of an executor nobody spins waits
while another executor (rclpy.spin_once's) spins, and runs once its own spins; a Future's done
callbacks run by its executor; an async timer callback of one node that awaits a future goes
on only while an executor with that node spins."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def main():
    rclpy.init()
    node = Node("tasker")
    other = Node("other_tasker")
    mine = SingleThreadedExecutor()
    ran = []
    task = mine.create_task(lambda: ran.append("mine's task") or "result")
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0.1)
    print("while the global executor spins:", ran, task.done())
    mine.spin_once(timeout_sec=0.1)
    print("mine spun:", ran, task.done(), task.result() if task.done() else None)

    ran.clear()
    future = Future(executor=mine)
    future.add_done_callback(lambda f: ran.append("done callback " + f.result()))
    future.set_result("x")
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0.1)
    print("done callback, global executor spun:", ran)
    mine.spin_until_future_complete(Future(), timeout_sec=0.2)
    print("done callback, mine spun:", ran)

    ran.clear()
    gate = Future()
    steps = []

    async def waits():
        steps.append("started")
        timer.cancel()
        value = await gate
        steps.append("resumed with " + value)

    timer = other.create_timer(0.1, waits)
    executor = SingleThreadedExecutor()
    executor.add_node(other)
    executor.spin_until_future_complete(Future(), timeout_sec=0.3)
    print("async callback:", steps)
    gate.set_result("gate")
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0.1)
    print("after the gate, only tasker spun:", steps)
    executor.spin_until_future_complete(Future(), timeout_sec=0.3)
    print("after the gate, other spun:", steps)
    executor.shutdown()
    mine.shutdown()
    node.destroy_node()
    other.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
