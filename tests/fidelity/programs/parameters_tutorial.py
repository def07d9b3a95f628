"""docs.ros.org's "Using parameters in a class (Python)" as a student varies it: a string
parameter with a ParameterDescriptor (description), a timer that reads it with
get_parameter().get_parameter_value().string_value and sets it back with set_parameters, an
on-set callback that refuses one value, describe_parameter and get_parameters, a typed
get_parameter_value() of each kind, and the ParameterDescriptor's repr."""
import rclpy
import rclpy.node
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult


class MinimalParam(rclpy.node.Node):
    def __init__(self):
        super().__init__("minimal_param_node")
        my_parameter_descriptor = ParameterDescriptor(description="This parameter is mine!")
        self.declare_parameter("my_parameter", "world", my_parameter_descriptor)
        self.declare_parameter("speed", 1.5)
        self.declare_parameter("count", 3)
        self.declare_parameter("names", ["a", "b"])
        self.add_on_set_parameters_callback(self.on_set)
        self.ticks = 0
        self.timer = self.create_timer(0.1, self.timer_callback)

    def on_set(self, params):
        for param in params:
            if param.name == "my_parameter" and param.value == "forbidden":
                return SetParametersResult(successful=False, reason="not that one")
        return SetParametersResult(successful=True)

    def timer_callback(self):
        my_param = self.get_parameter("my_parameter").get_parameter_value().string_value
        self.get_logger().info(f"Hello {my_param}!")
        new = ["world", "forbidden", "turtle"][self.ticks % 3]
        results = self.set_parameters([rclpy.parameter.Parameter("my_parameter", rclpy.Parameter.Type.STRING, new)])
        print("set", new, "->", [(r.successful, r.reason) for r in results])
        self.ticks += 1


def main():
    rclpy.init()
    node = MinimalParam()
    while node.ticks < 4:
        rclpy.spin_once(node, timeout_sec=1.0)
    print(node.describe_parameter("my_parameter"))
    print([p.value for p in node.get_parameters(["speed", "count", "names"])])
    for name in ("speed", "count", "names"):
        value = node.get_parameter(name).get_parameter_value()
        print(name, value.type, value.double_value, value.integer_value, list(value.string_array_value))
    print(repr(node.get_parameter("speed")), node.get_parameter("speed").type_)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
