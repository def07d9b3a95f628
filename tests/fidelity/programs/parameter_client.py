"""rclpy.parameter_client.AsyncParameterClient against another node of the program: list, get,
describe, types, set (refused for a wrong type, a range, read-only, an on-set callback, an
undeclared name), atomically, delete, and a parameter file."""
import os
import tempfile

import rclpy
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient


def main():
    rclpy.init()
    server = Node("driver")
    server.declare_parameter("speed", 1.5)
    server.declare_parameter("gain", 4, ParameterDescriptor(
        description="loop gain", integer_range=[IntegerRange(from_value=0, to_value=10, step=2)]))
    server.declare_parameter("robot", "turtle1", ParameterDescriptor(read_only=True))
    server.declare_parameter("pid.kp", 0.5)
    server.declare_parameter("pid.ki", 0.1)
    server.declare_parameter("extra", 7, ParameterDescriptor(dynamic_typing=True))
    server.add_on_set_parameters_callback(
        lambda params: SetParametersResult(
            successful=all(p.name != "speed" or p.value < 5.0 for p in params), reason="too fast"))
    tuner = Node("tuner")
    executor = SingleThreadedExecutor()
    executor.add_node(server)
    executor.add_node(tuner)
    client = AsyncParameterClient(tuner, "driver")
    print("ready", client.wait_for_services(timeout_sec=10.0))

    def answer(future):
        executor.spin_until_future_complete(future, timeout_sec=10.0)
        return future.result()

    # every rclpy node also has use_sim_time and start_type_description_service (not compared here)
    print("list", sorted(set(answer(client.list_parameters()).result.names) - {"use_sim_time", "start_type_description_service"}))
    listed = answer(client.list_parameters(["pid"], 1)).result
    print("list pid", sorted(listed.names), list(listed.prefixes))
    values = answer(client.get_parameters(["speed", "gain", "robot"])).values
    print("get", [(v.type, v.double_value, v.integer_value, v.string_value) for v in values])
    print("get unknown", list(answer(client.get_parameters(["speed", "nope"])).values))
    print("types", list(answer(client.get_parameter_types(["speed", "gain", "robot", "pid.kp"])).types))
    print("types unknown", list(answer(client.get_parameter_types(["nope"])).types))
    [gain] = answer(client.describe_parameters(["gain"])).descriptors
    print("describe", gain.name, gain.type, gain.description, gain.integer_range[0].to_value, gain.read_only)
    print("describe unknown", list(answer(client.describe_parameters(["nope"])).descriptors))
    results = answer(client.set_parameters([
        Parameter("speed", value=2.5),
        Parameter("speed", value=3),
        Parameter("gain", value=11),
        Parameter("gain", value=5),
        Parameter("gain", value=10),
        Parameter("robot", value="turtle2"),
        Parameter("speed", value=9.0),
        Parameter("nope", value=1),
        Parameter("speed"),
    ])).results
    for result in results:
        print("set", result.successful, result.reason)
    print("speed now", server.get_parameter("speed").value, "gain now", server.get_parameter("gain").value)
    result = answer(client.set_parameters_atomically([Parameter("speed", value=1.0), Parameter("gain", value=3)]))
    print("atomic", result.result.successful, result.result.reason, server.get_parameter("speed").value)
    result = answer(client.set_parameters_atomically([Parameter("speed", value=1.0), Parameter("gain", value=4)]))
    print("atomic", result.result.successful, result.result.reason, server.get_parameter("speed").value)
    print("extra", [r.successful for r in answer(client.set_parameters([Parameter("extra", value="seven")])).results],
          server.get_parameter("extra").value)
    deleted = answer(client.delete_parameters(["extra", "speed"])).results
    print("delete", [(r.successful, r.reason) for r in deleted], server.has_parameter("extra"))
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as stream:
        stream.write("/driver:\n  ros__parameters:\n    speed: 4.0\n    pid:\n      kp: 2.0\n")
    try:
        loaded = answer(client.load_parameter_file(stream.name)).results
    finally:
        os.unlink(stream.name)
    print("file", [r.successful for r in loaded], server.get_parameter("speed").value,
          server.get_parameter("pid.kp").value)
    server.destroy_node()
    tuner.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
