"""ROS arguments that rclpy refuses or that change logging: --log-level for all loggers and
for one, a -p whose type differs from the declared default, and malformed --ros-args
(a flag without its value, an unknown flag, a log level that is none) as rclpy.init reports them.
(A rule without := is left out: rcl's text there is its lexer's, "Expected lexeme type (19)".)"""
import rclpy
from rclpy.exceptions import InvalidParameterTypeException
from rclpy.logging import get_logger
from rclpy.node import Node


def try_init(args):
    try:
        rclpy.init(args=args)
        print("init", args[1:], "-> ok")
        rclpy.shutdown()
    except Exception as err:
        print("init", args[1:], "->", type(err).__name__)
        print("  ", str(err).split(", at ")[0])  # rcl's source locations left out


def main():
    rclpy.init(args=["prog", "--ros-args", "--log-level", "warn", "--log-level", "loud:=debug", "-p", "count:=2"])
    quiet = Node("quiet")
    loud = Node("loud")
    for node in (quiet, loud):
        log = node.get_logger()
        print(log.name, log.get_effective_level())
        log.debug("debug line")
        log.info("info line")
        log.warning("warning line")
    print("free logger:", get_logger("free").get_effective_level())
    try:
        quiet.declare_parameter("count", 0.0)
    except InvalidParameterTypeException as err:
        print(type(err).__name__, str(err).split(" (")[0])  # turtletui adds a hint in parentheses
    quiet.destroy_node()
    loud.destroy_node()
    rclpy.shutdown()
    for args in (
        ["prog", "--ros-args", "-r"],
        ["prog", "--ros-args", "--remap"],
        ["prog", "--ros-args", "-p"],
        ["prog", "--ros-args", "--params-file"],
        ["prog", "--ros-args", "--log-level"],
        ["prog", "--ros-args", "--log-level", "node:=loudest"],
        ["prog", "--ros-args", "--frobnicate", "--verbose"],
        ["prog", "--ros-args", "--frobnicate"],
        ["prog", "--ros-args", "--log-level", "loudest"],
        ["prog", "--ros-args"],
        ["prog", "--ros-args", "--"],
    ):
        try_init(args)


if __name__ == "__main__":
    main()
