"""Executors a program subclasses, as rclpy's docs tell a custom executor to: a
SingleThreadedExecutor whose spin_once counts itself (spin() and rclpy.spin() call it,
spin_until_future_complete does not), and an Executor whose spin_once takes work with
wait_for_ready_callbacks and runs each handler itself: what it returns (a Task, the entity,
the node; a task of create_task first; a guard condition, a service and a client's response),
its timeout, a callback's error kept in the handler, spin_until_future_complete refused, and
wait_for_ready_callbacks after shutdown."""
import rclpy
from rclpy.executors import (
    Executor,
    ShutdownException,
    SingleThreadedExecutor,
    TimeoutException,
)
from rclpy.node import Node
from rclpy.task import Future
from std_msgs.msg import String
from std_srvs.srv import Trigger


class CountingExecutor(SingleThreadedExecutor):
    def __init__(self):
        super().__init__()
        self.spins = 0

    def spin_once(self, timeout_sec=None):
        self.spins += 1
        super().spin_once(timeout_sec)


class HandExecutor(Executor):
    def __init__(self):
        super().__init__()
        self.ran = []

    def spin_once(self, timeout_sec=None):
        try:
            handler, entity, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)
        except TimeoutException:
            self.ran.append("timeout")
            return
        name = node.get_name() if node is not None else None
        self.ran.append((type(handler).__name__, type(entity).__name__, name))
        handler()
        error = handler.exception()
        if error is not None:
            self.ran.append(f"kept {type(error).__name__}: {error}")


class Ticker(Node):
    def __init__(self, name, executor=None, stop_at=None, shutdown_at=None):
        super().__init__(name)
        self.ticks = 0
        self.to_stop = executor
        self.stop_at = stop_at
        self.shutdown_at = shutdown_at
        self.third = Future()
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        self.ticks += 1
        if self.ticks == 3:
            self.third.set_result("third")
        if self.ticks == self.stop_at:
            self.to_stop.shutdown()
        if self.ticks == self.shutdown_at:
            rclpy.shutdown()


def counting():
    executor = CountingExecutor()
    node = Ticker("counted", executor, stop_at=4)
    executor.add_node(node)
    executor.spin()
    print("spin(): ticks", node.ticks, "spin_once calls", executor.spins)
    node.destroy_node()

    executor = CountingExecutor()
    node = Ticker("awaited")
    executor.add_node(node)
    executor.spin_until_future_complete(node.third, timeout_sec=5.0)
    print("spin_until_future_complete:", node.third.result(), "spin_once calls", executor.spins)
    executor.spin_once_until_future_complete(Future(), timeout_sec=0.15)
    print("spin_once_until_future_complete: ticks", node.ticks, "spin_once calls", executor.spins)
    executor.shutdown()
    node.destroy_node()


def by_hand():
    executor = HandExecutor()
    node = Ticker("hand", executor, stop_at=5)
    pub = node.create_publisher(String, "words", 10)
    heard = []
    sub = node.create_subscription(String, "words", lambda msg: heard.append(msg.data), 10)
    executor.add_node(node)
    print("nodes:", [n.get_name() for n in executor.get_nodes()], executor.context is node.context)
    node.timer.cancel()  # the timeout, not the timer, however long the start took
    executor.spin_once(timeout_sec=0.05)
    node.timer.reset()
    task = executor.create_task(lambda: "task done")
    handler, entity, owner = executor.wait_for_ready_callbacks(timeout_sec=1.0)
    print("first ready:", handler is task, entity, owner)
    handler()
    print("task:", task.done(), task.result())
    handler, entity, owner = executor.wait_for_ready_callbacks(timeout_sec=1.0)
    print("then:", type(handler).__name__, entity is node.timer, owner is node, handler.done())
    handler()
    print("ran:", handler.done(), handler.result(), node.ticks)
    pub.publish(String(data="hello"))
    handler, entity, owner = executor.wait_for_ready_callbacks(timeout_sec=1.0)
    print("message:", entity is sub, heard)
    handler()
    print("heard:", heard)

    def fail():
        raise ValueError("no good")

    node.timer.callback = fail
    executor.spin_once(timeout_sec=1.0)
    node.timer.callback = node.tick
    for attempt in (
        lambda: executor.spin_until_future_complete(node.third, timeout_sec=1.0),
        lambda: executor.spin_once_until_future_complete(node.third, timeout_sec=1.0),
    ):
        try:
            attempt()
            print("no error")
        except NotImplementedError as error:
            print("NotImplementedError", error)
    executor.spin()
    print("spin() until a callback shut the executor down: ticks", node.ticks)
    for entry in executor.ran:
        print(" ", entry)
    try:
        executor.wait_for_ready_callbacks(timeout_sec=1.0)
    except ShutdownException:
        print("after shutdown: ShutdownException")
    node.destroy_node()


def served():
    executor = HandExecutor()
    node = Node("served")
    node.create_service(Trigger, "ask", lambda request, response: response)
    guard = node.create_guard_condition(lambda: None)
    client = node.create_client(Trigger, "ask")
    print("service ready:", client.wait_for_service(timeout_sec=2.0))
    executor.add_node(node)
    guard.trigger()
    executor.spin_once(timeout_sec=1.0)
    future = client.call_async(Trigger.Request())
    while not future.done():
        executor.spin_once(timeout_sec=1.0)
    print("served:", executor.ran)
    executor.shutdown()
    node.destroy_node()


def spun_by_rclpy():
    executor = CountingExecutor()
    node = Ticker("spun", shutdown_at=3)
    rclpy.spin(node, executor)
    print("rclpy.spin until shutdown: ticks", node.ticks, "spin_once calls", executor.spins)


def main():
    rclpy.init()
    try:
        Executor().spin_once(timeout_sec=0.1)
    except NotImplementedError:
        print("a bare Executor: NotImplementedError")
    counting()
    by_hand()
    served()
    spun_by_rclpy()


if __name__ == "__main__":
    main()
