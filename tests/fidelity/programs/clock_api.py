"""Clocks as course code reads them: Clock() is system time, ROSClock and a node's clock are ROS
time, repr and types, now() times ordered and subtracted into a Duration, comparing times of
different clocks, sleep_for/sleep_until (a time already past, a wrong clock type, after
shutdown), and Clock(clock_type=...) with something that is not a ClockType."""
import rclpy
from rclpy.clock import Clock, ClockType, ROSClock
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    rclpy.init()
    node = Node("clocks")
    clocks = {
        "Clock()": Clock(),
        "ROSClock()": ROSClock(),
        "steady": Clock(clock_type=ClockType.STEADY_TIME),
        "ROS_TIME": Clock(clock_type=ClockType.ROS_TIME),
        "node": node.get_clock(),
    }
    for label, clock in clocks.items():
        print(label, repr(clock), type(clock).__name__, clock.clock_type, isinstance(clock, ROSClock))
    print("ros time active:", ROSClock().ros_time_is_active, node.get_clock().ros_time_is_active)
    first = node.get_clock().now()
    second = node.get_clock().now()
    elapsed = second - first
    print("now:", type(first).__name__, first.clock_type, second >= first, type(elapsed).__name__, elapsed >= Duration())
    print("positive:", first.nanoseconds > 1_000_000_000, first.to_msg().sec > 0)
    steady_now = clocks["steady"].now()
    attempt("ros < steady:", lambda: first < steady_now)
    attempt("ros - steady:", lambda: first - steady_now)
    attempt("ros == system:", lambda: first == Clock().now())
    attempt("clock type as an int:", lambda: Clock(clock_type=1))
    attempt("clock type as a str:", lambda: Clock(clock_type="ROS_TIME"))
    attempt("sleep_for 0.05 s:", lambda: node.get_clock().sleep_for(Duration(seconds=0.05)))
    attempt("sleep_until the past:", lambda: node.get_clock().sleep_until(first))
    attempt("sleep_until of another clock:", lambda: node.get_clock().sleep_until(steady_now))
    attempt("sleep_for a number:", lambda: node.get_clock().sleep_for(0.1))
    attempt("sleep_for negative:", lambda: node.get_clock().sleep_for(Duration(seconds=-1)))
    after = node.get_clock().now()
    print("slept at least 0.05 s:", (after - first).nanoseconds >= 50_000_000)
    print("Time() of the node clock's type:", Time().clock_type == node.get_clock().clock_type)
    node.destroy_node()
    rclpy.shutdown()
    attempt("sleep_for after shutdown:", lambda: Clock().sleep_for(Duration(seconds=0.01)))
    attempt("now after shutdown:", lambda: type(Clock().now()).__name__)


if __name__ == "__main__":
    main()
