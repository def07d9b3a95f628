"""Node options for parameters: parameter_overrides replace a declared default,
automatically_declare_parameters_from_overrides, allow_undeclared_parameters (get and set of
names never declared), undeclare_parameter, and an on-set callback added then removed."""
import rclpy
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter


def main():
    rclpy.init()
    node = Node("overridden", parameter_overrides=[Parameter("speed", value=3.0), Parameter("extra", value="x")])
    print("speed:", node.declare_parameter("speed", 1.0).value)
    print("extra declared?", node.has_parameter("extra"))
    auto = Node(
        "auto",
        parameter_overrides=[Parameter("speed", value=3.0), Parameter("color", value=[1, 2, 3])],
        automatically_declare_parameters_from_overrides=True,
    )
    print("auto:", sorted((n, auto.get_parameter(n).value) for n in ("speed", "color")))
    loose = Node("loose", allow_undeclared_parameters=True)
    print("undeclared get:", loose.get_parameter("ghost").type_, loose.get_parameter("ghost").value)
    print("undeclared set:", [r.successful for r in loose.set_parameters([Parameter("ghost", value=5)])])
    print("now:", loose.get_parameter("ghost").value, loose.has_parameter("ghost"))
    loose.undeclare_parameter("ghost")
    print("after undeclare:", loose.has_parameter("ghost"))

    def refuse_negative(params):
        for p in params:
            if p.name == "speed" and p.value < 0:
                return SetParametersResult(successful=False, reason="speed must not be negative")
        return SetParametersResult(successful=True)

    print("added:", node.add_on_set_parameters_callback(refuse_negative))
    print("negative:", [(r.successful, r.reason) for r in node.set_parameters([Parameter("speed", value=-1.0)])])
    node.remove_on_set_parameters_callback(refuse_negative)
    print("negative later:", [(r.successful, r.reason) for r in node.set_parameters([Parameter("speed", value=-1.0)])])
    print("speed:", node.get_parameter("speed").value)
    atomic = node.set_parameters_atomically([Parameter("speed", value=2.0)])
    print("atomically:", atomic.successful, repr(atomic.reason))
    for n in (node, auto, loose):
        n.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
