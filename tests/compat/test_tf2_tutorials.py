"""The official turtle_tf2_py tutorials, their programs as separate files run
together sandboxed (as `ros2 launch` starts them): tests/compat/turtle_tf2/."""

from __future__ import annotations

import math
from pathlib import Path

from support.hosts import node_logs, write_controller

from turtletui.api import run

TUTORIAL = Path(__file__).with_name("turtle_tf2")
DEMO = ("launch_broadcaster1.py", "launch_broadcaster2.py")


def run_tutorial(*files: str, duration: float, ros_args: tuple[str, ...] = ()):
    paths = [TUTORIAL / f if (TUTORIAL / f).exists() else Path(f) for f in files]
    result = run(paths, duration=duration, sandbox=True, distro="jazzy", ros_args=list(ros_args))
    assert result.ok, result.crashes
    return result


def gap(result, a: str, b: str, offset: tuple[float, float] = (0.0, 0.0)) -> float:
    one, two = result.turtles[a], result.turtles[b]
    return math.hypot(two.x - one.x - offset[0], two.y - one.y - offset[1])


def test_writing_a_listener_turtle2_follows_turtle1():
    result = run_tutorial(*DEMO, "turtle_tf2_listener.py", duration=20.0)
    assert node_logs(result, "turtle_tf2_frame_listener") == ["Successfully spawned turtle2"]
    assert gap(result, "turtle1", "turtle2") < 0.05
    assert result.turtles["turtle2"].distance > 3.0
    # every TransformListener subscribes to /tf_static: nothing publishing there is no typo to warn of
    assert [r.msg for r in result.logs if "/tf" in r.msg] == []


def test_adding_a_fixed_frame_turtle2_goes_to_the_carrot():
    result = run_tutorial(*DEMO, "fixed_frame_tf2_broadcaster.py", "launch_listener_carrot.py", duration=20.0)
    assert node_logs(result, "turtle_tf2_frame_listener") == ["Successfully spawned turtle2"]
    assert gap(result, "turtle1", "turtle2", offset=(0.0, 2.0)) < 0.05  # turtle1 faces +x: its left is +y


def test_adding_a_dynamic_frame_turtle2_keeps_chasing_the_carrot():
    result = run_tutorial(*DEMO, "dynamic_frame_tf2_broadcaster.py", "launch_listener_carrot.py", duration=12.0)
    assert node_logs(result, "turtle_tf2_frame_listener") == ["Successfully spawned turtle2"]
    assert result.turtles["turtle2"].distance > 20.0


def test_using_time_fails_with_one_thread_and_follows_with_several():
    one = run_tutorial(*DEMO, "turtle_tf2_listener_time.py", "turtle1_circles.py", duration=6.0)
    logs = node_logs(one, "turtle_tf2_frame_listener")
    assert logs[0] == "Successfully spawned turtle2"
    assert len(logs) >= 3 and all(
        line.startswith("Could not transform turtle2 to turtle1: Lookup would require extrapolation into the future.")
        for line in logs[1:]
    ), logs
    assert one.turtles["turtle2"].distance == 0.0
    several = run_tutorial(
        *DEMO, "turtle_tf2_listener_time.py", "turtle1_circles.py", duration=12.0, ros_args=("-p", "threads:=true")
    )
    assert node_logs(several, "turtle_tf2_frame_listener") == ["Successfully spawned turtle2"]
    assert several.turtles["turtle2"].distance > 8.0


def test_traveling_in_time_turtle2_goes_where_turtle1_was_five_seconds_ago():
    result = run_tutorial(*DEMO, "turtle_tf2_listener_time_travel.py", "turtle1_circles.py", duration=30.0)
    logs = node_logs(result, "turtle_tf2_frame_listener")
    past = [line for line in logs if "extrapolation into the past" in line]
    assert logs[0] == "Successfully spawned turtle2" and len(past) == 3 and len(logs) == 4, logs
    # turtle1 circles with a 2 m radius (1 m/s, 0.5 rad/s); turtle2 trails it by 5 s
    assert 1.0 < gap(result, "turtle1", "turtle2") < 4.5
    assert result.turtles["turtle2"].distance > 10.0


def test_a_static_broadcaster_s_frame_reaches_a_listener_in_another_process(tmp_path):
    listener = write_controller(
        tmp_path,
        """
import rclpy
from rclpy.node import Node
from tf2_ros import Buffer, TransformListener


def main():
    rclpy.init()
    node = Node('static_listener')
    rclpy.spin_once(node, timeout_sec=1.0)  # join late: /tf_static is transient local
    buffer = Buffer()
    TransformListener(buffer, node)
    rclpy.spin_once(node, timeout_sec=0.5)
    t = buffer.lookup_transform('world', 'mystaticturtle', rclpy.time.Time())
    node.get_logger().info(f'z={t.transform.translation.z}')
""",
        "static_listener.py",
    )
    result = run_tutorial("static_turtle_tf2_broadcaster.py", str(listener), duration=2.0)
    assert node_logs(result, "static_listener") == ["z=1.0"]


def test_another_file_s_transient_local_publisher_matches_a_transient_local_listener(tmp_path):
    listener = write_controller(
        tmp_path,
        """
import rclpy
from rclpy.node import Node
from tf2_ros import Buffer, TransformListener


def main():
    rclpy.init()
    node = Node('static_listener')
    TransformListener(Buffer(), node)
    rclpy.spin(node)
""",
        "static_listener.py",
    )
    result = run_tutorial("static_turtle_tf2_broadcaster.py", str(listener), duration=2.0)
    # another process's endpoint carries its QoS: /tf_static's publisher is transient local, as asked
    assert [r.msg for r in result.logs if "incompatible QoS" in r.msg] == []
