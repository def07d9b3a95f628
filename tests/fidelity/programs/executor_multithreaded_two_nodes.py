"""A MultiThreadedExecutor with two nodes: a callback of one node waiting for an event that the
other node's timer sets gets it (different nodes' default groups are different groups); two
timers of one node sharing a mutually exclusive group never overlap, reentrant ones do; the
executor with one node removed runs only the other's. Sandboxed only: threads need turtletui's
sandbox."""
import threading

import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def overlap(executor, node, group):
    """Two busy timers of ``group`` on ``node``: how many calls ran at once at most, and how many ran."""
    running, most, calls = [0], [0], [0]
    lock = threading.Lock()
    finished = Future()

    def busy():
        with lock:
            running[0] += 1
            calls[0] += 1
            most[0] = max(most[0], running[0])
            if calls[0] >= 6 and not finished.done():
                finished.set_result(True)
        threading.Event().wait(0.25)
        with lock:
            running[0] -= 1

    timers = [node.create_timer(0.1, busy, callback_group=group) for _ in range(2)]
    executor.spin_until_future_complete(finished, timeout_sec=10.0)
    for timer in timers:
        timer.cancel()
    executor.spin_until_future_complete(Future(), timeout_sec=0.6)
    return most[0], calls[0]


def main():
    rclpy.init()
    waiter = Node("mt_waiter")
    setter = Node("mt_setter")
    event = threading.Event()
    done = Future()
    got = []

    def wait_for_it():
        wait_timer.cancel()
        got.append(event.wait(timeout=2.0))
        done.set_result(True)

    def set_it():
        set_timer.cancel()
        event.set()

    wait_timer = waiter.create_timer(0.1, wait_for_it)
    set_timer = setter.create_timer(0.3, set_it)
    executor = MultiThreadedExecutor(num_threads=3)
    executor.add_node(waiter)
    executor.add_node(setter)
    executor.spin_until_future_complete(done, timeout_sec=5.0)
    print("other node's timer set the event:", got)

    for name, group in (("exclusive", MutuallyExclusiveCallbackGroup()), ("reentrant", ReentrantCallbackGroup())):
        most, calls = overlap(executor, waiter, group)
        print(name, "overlapped:", most > 1, "calls enough:", calls >= 6)

    executor.remove_node(waiter)
    ticks = {"waiter": 0, "setter": 0}
    waiter.create_timer(0.1, lambda: ticks.__setitem__("waiter", ticks["waiter"] + 1))
    setter.create_timer(0.1, lambda: ticks.__setitem__("setter", ticks["setter"] + 1))
    executor.spin_until_future_complete(Future(), timeout_sec=0.55)
    print("waiter removed:", ticks["waiter"], ticks["setter"] > 0)
    executor.shutdown()
    waiter.destroy_node()
    setter.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
