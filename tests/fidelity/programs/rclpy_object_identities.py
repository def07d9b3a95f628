"""What printing rclpy's own objects shows, as students print them while debugging: a node,
its publisher, subscription, timer, rate, service, client, guard condition, clock, logger,
context, a parameter, executors, callback groups, a Future, Duration and Time, their
type()s, and the last line of a traceback of rclpy's exceptions (the classes' modules are
rclpy's: rclpy.node, rclpy.publisher, rclpy.exceptions, ...)."""
import traceback

import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.duration import Duration
from rclpy.exceptions import ParameterNotDeclaredException
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile
from rclpy.task import Future
from rclpy.time import Time
from std_msgs.msg import String
from std_srvs.srv import Trigger


def main():
    rclpy.init()
    node = Node("shown")
    things = {
        "node": node,
        "publisher": node.create_publisher(String, "chatter", 10),
        "subscription": node.create_subscription(String, "chatter", lambda msg: None, 10),
        "timer": node.create_timer(1.0, lambda: None),
        "rate": node.create_rate(1.0),
        "service": node.create_service(Trigger, "~/reset", lambda request, response: response),
        "client": node.create_client(Trigger, "~/reset"),
        "guard": node.create_guard_condition(lambda: None),
        "clock": node.get_clock(),
        "logger": node.get_logger(),
        "context": node.context,
        "parameter": node.get_parameter("use_sim_time"),
        "executor": SingleThreadedExecutor(),
        "multi": MultiThreadedExecutor(num_threads=2),
        "reentrant": ReentrantCallbackGroup(),
        "exclusive": MutuallyExclusiveCallbackGroup(),
        "future": Future(),
        "qos": QoSProfile(depth=10),
        "duration": Duration(seconds=1.5),
        "time": Time(seconds=2),
    }
    for label, thing in things.items():
        print(f"{label}: {thing!r} | {thing} | {type(thing)}")
    for error in (lambda: node.get_parameter("missing"), lambda: node.create_publisher(String, "bad name", 10)):
        try:
            error()
        except Exception as err:
            print("traceback ends:", traceback.format_exception_only(type(err), err)[-1].rstrip())
    print("caught as:", type(ParameterNotDeclaredException("x")))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
