"""rclpy's helpers for names and arguments that course code and launch-less scripts call
directly: rclpy.utilities (ok, remove_ros_args, timeout_sec_to_nsec, get_default_context,
try_shutdown), the validate_* modules (what they return and raise), expand_topic_name (~,
relative and absolute names, substitutions, refusals) and topic_or_service_is_hidden."""
import rclpy
from rclpy.exceptions import NameValidationException
from rclpy.expand_topic_name import expand_topic_name
from rclpy.topic_or_service_is_hidden import topic_or_service_is_hidden
from rclpy.utilities import (
    get_default_context,
    ok,
    remove_ros_args,
    timeout_sec_to_nsec,
    try_shutdown,
)
from rclpy.validate_full_topic_name import validate_full_topic_name
from rclpy.validate_namespace import validate_namespace
from rclpy.validate_node_name import validate_node_name
from rclpy.validate_topic_name import validate_topic_name
from std_msgs.msg import String


def attempt(label, call):
    try:
        print(f"{label}: {call()!r}")
    except (NameValidationException, ValueError, TypeError) as err:
        print(f"{label}: {type(err).__name__}: {err}")


def main():
    print("ok before init:", ok(), rclpy.utilities.ok())
    print(type(get_default_context()).__name__)
    for args in (
        ["prog.py", "--speed", "2"],
        ["prog.py", "--ros-args", "-p", "speed:=2.0", "--", "--verbose"],
        ["prog.py", "--ros-args", "-r", "__node:=other", "--ros-args", "--log-level", "debug"],
        ["prog.py", "--ros-args"],
        [],
    ):
        print(f"remove_ros_args({args}) = {remove_ros_args(args)}")
    for timeout in (None, -1, -0.5, 0, 0.5, 1e-10, 2):
        print(f"timeout_sec_to_nsec({timeout}) = {timeout_sec_to_nsec(timeout)}")

    for name in ("turtle_controller", "my-node", "2fast", "_hidden", ""):
        attempt(f"validate_node_name({name!r})", lambda name=name: validate_node_name(name))
    for namespace in ("/lab", "/lab/turtles", "lab", "/lab/", "/2nd", "/a//b"):
        attempt(f"validate_namespace({namespace!r})", lambda namespace=namespace: validate_namespace(namespace))
    for topic in ("cmd_vel", "/turtle1/cmd_vel", "~/out", "{node}/x", "bad topic", "a/~b", "1st"):
        attempt(f"validate_topic_name({topic!r})", lambda topic=topic: validate_topic_name(topic))
    attempt("validate_topic_name('bad topic', is_service=True)",
            lambda: validate_topic_name("bad topic", is_service=True))
    for topic in ("/turtle1/cmd_vel", "cmd_vel", "/a//b", "/"):
        attempt(f"validate_full_topic_name({topic!r})", lambda topic=topic: validate_full_topic_name(topic))

    for topic, node, namespace in (
        ("chatter", "talker", "/"),
        ("chatter", "talker", "/lab"),
        ("/chatter", "talker", "/lab"),
        ("~/status", "talker", "/lab"),
        ("~", "talker", "/"),
        ("{node}/debug", "talker", "/lab"),
        ("{ns}/x", "talker", "/lab"),
        ("{other}/x", "talker", "/lab"),
        ("bad topic", "talker", "/"),
        ("chatter", "bad-node", "/"),
        ("chatter", "talker", "lab"),
    ):
        attempt(f"expand_topic_name({topic!r}, {node!r}, {namespace!r})",
                lambda topic=topic, node=node, namespace=namespace: expand_topic_name(topic, node, namespace))

    for name in ("/turtle1/pose", "/_hidden", "/a/_b/c", "/rotate/_action/feedback", "/a_b", ""):
        print(f"topic_or_service_is_hidden({name!r}) = {topic_or_service_is_hidden(name)}")

    rclpy.init(args=["prog.py", "--ros-args", "-p", "x:=1"])
    print("ok after init:", ok(), get_default_context().ok())
    node = rclpy.create_node("talker", namespace="/lab")
    for topic in ("{node}/debug", "{ns}/status", "~/{node}", "{bad}/x", "a/2b"):
        attempt(f"create_publisher(String, {topic!r})", lambda topic=topic: node.create_publisher(String, topic, 1).topic_name)
    node.destroy_node()
    try_shutdown()
    try_shutdown()
    print("ok after try_shutdown twice:", ok())


if __name__ == "__main__":
    main()
