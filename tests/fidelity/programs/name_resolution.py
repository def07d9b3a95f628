"""Node.resolve_topic_name and resolve_service_name: expansion, remapping and bad names;
and the rclpy submodules a program can reach as attributes after ``import rclpy`` and
``from rclpy.node import Node`` (rclpy.exceptions.X works; rclpy.action does not until imported)."""

import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("resolver", namespace="/ns", cli_args=["--ros-args", "-r", "chatter:=/remapped", "-r", "srv:=other_srv"])
    for resolve in (node.resolve_topic_name, node.resolve_service_name):
        for name in (
            "chatter", "srv", "~/private", "/absolute", "{node}/sub", "{ns}/x", "a/b/c", "bad name", "1abc", "", "a//b",
            "~", "~bad", "{foo}/x", "a/", "/a/", "rt/x", None, 5,
        ):
            for only_expand in (False, True):
                try:
                    print(resolve.__name__, repr(name), only_expand, "->", resolve(name, only_expand=only_expand))
                except Exception as err:  # noqa: BLE001 - the error is what is compared
                    print(resolve.__name__, repr(name), only_expand, "->", type(err).__name__, err)
    from std_msgs.msg import String

    for name in ("~bad", "1abc/", "a/{4x}", "a/{b/c}", "a/{{b}}", "}x", "a/{b", "{b c}", "~/1x", "a/2", "~1", "a~b", "é"):
        for make in (
            lambda name=name: node.create_publisher(String, name, 1),
            lambda name=name: node.create_service(String, name, None),
        ):
            try:
                make()
                print("made", repr(name))
            except Exception as err:  # noqa: BLE001 - the error is what is compared
                print("make", repr(name), "->", type(err).__name__, err)
        try:
            print("resolve", repr(name), "->", node.resolve_topic_name(name))
        except Exception as err:  # noqa: BLE001
            print("resolve", repr(name), "->", type(err).__name__, err)
    for attribute in ("exceptions", "constants", "guard_condition", "impl", "publisher", "timer", "subscription", "action"):
        print(attribute, hasattr(rclpy, attribute))
    try:
        node.declare_parameter("x", 1)
        node.get_parameter("undeclared")
    except rclpy.exceptions.ParameterNotDeclaredException as err:
        print("caught rclpy.exceptions.ParameterNotDeclaredException:", err)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
