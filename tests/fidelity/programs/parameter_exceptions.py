"""Parameter errors a course node meets: undeclared, declared twice, and the exception texts."""
import rclpy
from rclpy.exceptions import (
    InvalidParameterValueException,
    ParameterAlreadyDeclaredException,
    ParameterException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
    ROSInterruptException,
)
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("params")
    try:
        node.get_parameter("speed")
    except ParameterNotDeclaredException as err:
        print(type(err).__name__, err)
    node.declare_parameter("speed", 1.0)
    try:
        node.declare_parameter("speed", 2.0)
    except ParameterAlreadyDeclaredException as err:
        print(type(err).__name__, err)
    print("speed:", node.get_parameter("speed").value)
    for err in (
        InvalidParameterValueException("speed", 99, "too fast"),
        ParameterImmutableException("speed"),
        ParameterUninitializedException("speed"),
        ROSInterruptException(),
    ):
        print(type(err).__name__, isinstance(err, ParameterException), err)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
