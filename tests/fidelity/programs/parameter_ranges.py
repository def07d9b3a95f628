"""Parameters with descriptors: declare_parameters in list form under a namespace, ranges that
refuse a set (and the result's reason), read-only, get_parameter_or, has_parameter,
get_parameters_by_prefix, describe_parameter and set_parameters' results, and a parameter
declared with a type and no value (uninitialized until set)."""
import rclpy
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.exceptions import ParameterNotDeclaredException, ParameterUninitializedException
from rclpy.node import Node
from rclpy.parameter import Parameter


def main():
    rclpy.init()
    node = Node("tuning")
    speed = ParameterDescriptor(
        description="linear speed", floating_point_range=[FloatingPointRange(from_value=0.0, to_value=2.0, step=0.5)]
    )
    laps = ParameterDescriptor(integer_range=[IntegerRange(from_value=1, to_value=10, step=1)])
    fixed = ParameterDescriptor(read_only=True)
    declared = node.declare_parameters(
        namespace="ctrl",
        parameters=[("speed", 1.0, speed), ("laps", 3, laps), ("name", "turtle1", fixed), ("gain", Parameter.Type.DOUBLE)],
    )
    print("declared:", [(p.name, p.type_, p.value) for p in declared])
    print("has:", node.has_parameter("ctrl.speed"), node.has_parameter("speed"))
    for value in (1.5, 1.7, 2.5, -0.5, 2.0):
        [result] = node.set_parameters([Parameter("ctrl.speed", value=value)])
        print(f"set speed {value}: {result.successful} {result.reason!r}")
    print("speed now:", node.get_parameter("ctrl.speed").value)
    [result] = node.set_parameters([Parameter("ctrl.laps", value=11)])
    print("laps 11:", result.successful, repr(result.reason))
    [result] = node.set_parameters([Parameter("ctrl.name", value="turtle2")])
    print("read only:", result.successful, repr(result.reason))
    [result] = node.set_parameters([Parameter("ctrl.laps", value=2.0)])
    print("wrong type:", result.successful, repr(result.reason))
    print("or:", node.get_parameter_or("ctrl.missing", Parameter("fallback", value=7)).value)
    print("or declared:", node.get_parameter_or("ctrl.laps").value)
    try:
        node.get_parameter("ctrl.gain")
    except ParameterUninitializedException as err:
        print(type(err).__name__, err)
    print("or uninitialized:", node.get_parameter_or("ctrl.gain", Parameter("fallback", value=0.5)).value)
    node.set_parameters([Parameter("ctrl.gain", value=0.25)])
    print("gain:", node.get_parameter("ctrl.gain").type_, node.get_parameter("ctrl.gain").value)
    prefixed = node.get_parameters_by_prefix("ctrl")
    print("by prefix:", sorted((k, v.value) for k, v in prefixed.items()))
    d = node.describe_parameter("ctrl.speed")
    print("described:", d.name, d.type, d.description, d.floating_point_range, d.read_only)
    try:
        node.describe_parameter("nope")
    except ParameterNotDeclaredException as err:
        print(type(err).__name__, err)
    try:
        node.set_parameters([Parameter("nope", value=1)])
    except ParameterNotDeclaredException as err:
        print(type(err).__name__, err)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
