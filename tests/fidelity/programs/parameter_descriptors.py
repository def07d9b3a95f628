"""Parameter descriptors and bookkeeping: dynamic_typing lets a parameter change type, a
static one refuses; undeclare of a read-only or unknown
one, a parameter declared None with dynamic typing, ignore_override, get_parameters with a missing name, describe_parameters and
get_parameter_types, set_descriptor, and a read-only parameter set by an override."""
import rclpy
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, err)


def main():
    rclpy.init()
    node = Node("described", parameter_overrides=[Parameter("mode", value="fast"), Parameter("fixed", value=7)])
    node.declare_parameter("anything", 1, ParameterDescriptor(dynamic_typing=True))
    node.declare_parameter("count", 1)
    for name, value in (("anything", "now a string"), ("anything", [1.5]), ("count", "two"), ("count", 2)):
        [result] = node.set_parameters([Parameter(name, value=value)])
        print(f"set {name} to {value!r}:", result.successful, repr(result.reason), node.get_parameter(name).value)
    attempt("declare None, dynamic:", lambda: node.declare_parameter("loose", None, ParameterDescriptor(dynamic_typing=True)).type_)
    attempt("get loose:", lambda: node.get_parameter("loose").value)
    attempt("mode (overridden):", lambda: node.declare_parameter("mode", "slow").value)
    attempt("ignore_override:", lambda: node.declare_parameter("mode2", "slow", ignore_override=True).value)
    attempt("fixed read-only:", lambda: node.declare_parameter("fixed", 1, ParameterDescriptor(read_only=True)).value)
    attempt("set fixed:", lambda: [(r.successful, r.reason) for r in node.set_parameters([Parameter("fixed", value=8)])])
    attempt("undeclare fixed:", lambda: node.undeclare_parameter("fixed"))
    attempt("undeclare unknown:", lambda: node.undeclare_parameter("ghost"))
    attempt("undeclare count:", lambda: node.undeclare_parameter("count"))
    attempt("count after:", lambda: node.has_parameter("count"))
    attempt("get_parameters:", lambda: [p.value for p in node.get_parameters(["mode", "anything"])])
    attempt("get_parameters missing:", lambda: node.get_parameters(["mode", "ghost"]))
    attempt("types:", lambda: node.get_parameter_types(["mode", "anything", "fixed", "ghost"]))
    attempt("describe:", lambda: [(d.name, d.type, d.read_only, d.dynamic_typing) for d in node.describe_parameters(["mode", "fixed"])])
    attempt("describe missing:", lambda: node.describe_parameters(["ghost"]))
    laps = ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=5, step=1)])
    node.declare_parameter("laps", 3)
    attempt("set_descriptor:", lambda: node.set_descriptor("laps", laps).integer_range)
    attempt("laps 9:", lambda: [(r.successful, r.reason) for r in node.set_parameters([Parameter("laps", value=9)])])
    attempt("set_descriptor type change:", lambda: node.set_descriptor("laps", ParameterDescriptor(type=3)))
    attempt("descriptor:", lambda: node.describe_parameter("laps").type)
    attempt("set NOT_SET:", lambda: [(r.successful, r.reason) for r in node.set_parameters([Parameter("laps")])])
    attempt("laps after:", lambda: node.has_parameter("laps"))
    attempt("set NOT_SET dynamic:", lambda: [(r.successful, r.reason) for r in node.set_parameters([Parameter("anything")])])
    attempt("anything after:", lambda: node.has_parameter("anything"))
    attempt("list:", lambda: sorted(node.list_parameters([], 0).names))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
