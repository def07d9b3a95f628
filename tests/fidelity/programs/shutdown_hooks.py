"""Shutting down: context.on_shutdown callbacks run once, rclpy.ok() and context.ok() after,
try_shutdown twice, init twice, an executor's spin_once after shutdown, and a second init with a new context."""
import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


def main():
    rclpy.init()
    context = rclpy.get_default_context()
    print("default context:", type(context).__name__, context.ok())
    context.on_shutdown(lambda: print("on_shutdown callback ran"))
    try:
        rclpy.init()
    except RuntimeError as err:
        print("init twice:", type(err).__name__, err)
    node = Node("hooks")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    rclpy.shutdown()
    print("ok after shutdown:", rclpy.ok(), context.ok())
    try:
        executor.spin_once(timeout_sec=0.1)
        print("an executor's spin_once after shutdown returned")
    except Exception as err:
        print("an executor's spin_once after shutdown:", type(err).__name__, err)
    print("try_shutdown:", rclpy.try_shutdown())
    own = Context()
    rclpy.init(context=own)
    print("own context ok:", own.ok(), "default ok:", rclpy.ok())
    other = Node("other", context=own)
    print("node in own context:", other.get_name(), other.context is own)
    other.destroy_node()
    rclpy.shutdown(context=own)
    print("own context after shutdown:", own.ok())
    rclpy.init()
    print("again:", rclpy.ok())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
