"""Parameters from YAML files, as launch files and `--ros-args --params-file` give them:
a section for one node, a namespaced node and the `/**` wildcard, nested names (gains.kp),
every YAML type (int, float, string, bool, lists), an empty list (a parameter not set), a
later file or a -p winning over an earlier one, automatically declared overrides, what a node
that declares nothing sees, and the files and -p values rclpy.init refuses (a list mixing
integers and floats, a file that does not exist)."""
import os
import tempfile

import rclpy
from rclpy.exceptions import InvalidParameterTypeException, ParameterUninitializedException
from rclpy.node import Node

FIRST = """
/**:
  ros__parameters:
    use_colors: true
    rate: 10
turtle_controller:
  ros__parameters:
    speed: 1.5
    name: "leonardo"
    gains:
      kp: 2.0
      ki: 0.1
    waypoints: [1.0, 2.5, 4.0]
    ids: [1, 2, 3]
    labels: ["a", "b"]
    flags: [true, false]
    limit: 3
    empty: []
/lab/watcher:
  ros__parameters:
    period: 0.5
    rate: 20
"""
SECOND = """
turtle_controller:
  ros__parameters:
    speed: 2.0
"""


MIXED = """
turtle_controller:
  ros__parameters:
    speed: 1.0
    waypoints:
      - 1.0
      - 2
"""


def write(name, text):
    with open(name, "w") as file:  # by a relative name: rcl's errors name the path given
        file.write(text)
    return name


def show(node, names):
    for name in names:
        if not node.has_parameter(name):
            print(f"  {node.get_name()}.{name} not declared")
            continue
        try:
            parameter = node.get_parameter(name)
            print(f"  {node.get_name()}.{name} = {parameter.value!r} ({parameter.type_.name})")
        except ParameterUninitializedException as err:
            print(f"  {node.get_name()}.{name}: {type(err).__name__}: {err}")


def main():
    # a folder of its own: the files it writes are not left where it was run from
    os.chdir(tempfile.mkdtemp())
    first, second, mixed = write("first.yaml", FIRST), write("second.yaml", SECOND), write("mixed.yaml", MIXED)
    for args in (["--params-file", mixed], ["--params-file", "missing.yaml"], ["-p", "waypoints:=[1, 2.5]"],
                 ["-p", "flags:=[true, 0]"]):
        try:
            rclpy.init(args=["prog", "--ros-args", *args])
            print("init accepted", args)
            rclpy.shutdown()
        except RuntimeError as err:
            print(f"init refused {args}: {type(err).__name__}: {err}")
    rclpy.init(args=["prog", "--ros-args", "--params-file", first, "--params-file", second, "-p", "turtle_controller:limit:=5"])

    controller = Node("turtle_controller")
    controller.declare_parameter("speed", 0.5)
    controller.declare_parameter("name", "turtle")
    controller.declare_parameters("gains", [("kp", 1.0), ("ki", 0.0), ("kd", 0.05)])
    controller.declare_parameter("waypoints", [0.0])
    controller.declare_parameter("ids", [0])
    controller.declare_parameter("labels", ["x"])
    controller.declare_parameter("flags", [False])
    controller.declare_parameter("limit", 1)
    controller.declare_parameter("empty", [1.0])
    controller.declare_parameter("use_colors", False)
    controller.declare_parameter("rate", 1)
    show(controller, ["speed", "name", "gains.kp", "gains.ki", "gains.kd", "waypoints", "ids", "labels", "flags",
                      "limit", "empty", "use_colors", "rate", "period"])
    print("  by prefix:", {k: v.value for k, v in sorted(controller.get_parameters_by_prefix("gains").items())})
    try:
        controller.declare_parameter("not_a_float", 1.0)
        print("  not_a_float declared:", controller.get_parameter("not_a_float").value)
    except InvalidParameterTypeException as err:
        print("  ", type(err).__name__, err)

    watcher = Node("watcher", namespace="lab", automatically_declare_parameters_from_overrides=True)
    print("watcher declared:", sorted(watcher._parameters))
    show(watcher, ["period", "rate", "use_colors", "speed"])

    other = Node("other")
    print("other declared:", sorted(other._parameters))
    other.declare_parameter("speed", 0.25)
    show(other, ["speed"])
    try:
        other.declare_parameter("rate", "fast")
    except InvalidParameterTypeException as err:
        print("other rate:", type(err).__name__, err)

    for node in (controller, watcher, other):
        node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
