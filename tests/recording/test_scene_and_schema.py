"""The scene's thinned pen trail and the schema texts, checked against the
rules they follow (turtlesim's pixels, rosbag2's definition layout)."""

from __future__ import annotations

import math

import pytest
from mcap_ros2._dynamic import generate_dynamic

from turtletui.recording.scene import TOLERANCE, Scene
from turtletui.recording.schema import SEPARATOR, message_definition


def _distance_to_polyline(p: tuple[float, float], line: list) -> float:
    best = math.inf
    for a, b in zip(line, line[1:], strict=False):
        dx, dy = b.x - a.x, b.y - a.y
        length2 = dx * dx + dy * dy or 1e-18
        u = max(0.0, min(1.0, ((p[0] - a.x) * dx + (p[1] - a.y) * dy) / length2))
        best = min(best, math.hypot(p[0] - a.x - u * dx, p[1] - a.y - u * dy))
    return best


@pytest.mark.parametrize("radius", [0.3, 1.0, 4.0])
def test_a_thinned_trail_stays_within_half_a_pixel_of_every_pose(radius: float):
    scene = Scene((), (69, 86, 255), ["turtle1"])
    path = [(5.5 + radius * math.sin(a), 5.5 - radius * math.cos(a)) for a in (i * 0.024 for i in range(600))]
    path += [(x + 3.0, y) for x, y in [(path[-1][0] + i * 0.016, path[-1][1]) for i in range(1, 200)]]
    for x, y in path:
        scene.pose("turtle1", x, y)
    (stroke,) = [m for m in scene.snapshot(0, 0).markers if m.ns == "pen"]
    assert len(stroke.points) < len(path) / 3  # thinned...
    assert max(_distance_to_polyline(p, stroke.points) for p in path) <= TOLERANCE + 1e-9  # ...within half a pixel


def test_pen_changes_clear_and_kill_shape_the_strokes():
    scene = Scene((), (69, 86, 255), ["turtle1"])
    for i in range(5):
        scene.pose("turtle1", 1.0 + i * 0.1, 1.0)
    scene.set_pen("turtle1", 255, 0, 0, 2, 0)
    for i in range(5, 10):
        scene.pose("turtle1", 1.0 + i * 0.1, 1.0)
    scene.set_pen("turtle1", 0, 0, 0, 2, 1)  # off: nothing drawn
    for i in range(10, 15):
        scene.pose("turtle1", 1.0 + i * 0.1, 1.0)
    strokes = [m for m in scene.snapshot(0, 0).markers if m.ns == "pen"]
    assert [(m.color.r, m.color.g, len(m.points)) for m in strokes] == [
        (pytest.approx(179 / 255), pytest.approx(184 / 255), 2),
        (1.0, 0.0, 2),
    ]
    assert strokes[1].points[0].x == pytest.approx(1.4)  # the red line starts where the pen changed
    scene.cleared()
    assert not [m for m in scene.snapshot(0, 0).markers if m.ns == "pen"]
    scene.killed("turtle1")
    assert not [m for m in scene.snapshot(0, 0).markers if m.ns == "turtles"]


def test_snapshots_are_sent_once_a_second_unless_something_big_changed():
    scene = Scene((), (69, 86, 255), ["turtle1"])
    assert scene.due(0)  # the first
    scene.snapshot(0, 0)
    scene.pose("turtle1", 1.0, 1.0)
    scene.pose("turtle1", 2.0, 1.0)
    assert not scene.due(500_000_000) and scene.due(1_000_000_000)
    scene.snapshot(1_000_000_000, 0)
    scene.cleared()
    assert scene.due(1_016_000_000)


def test_definitions_follow_rosbag2s_layout():
    text = message_definition("geometry_msgs/msg/TransformStamped")
    sections = text.split(f"\n{SEPARATOR}\n")
    headers = [section.split("\n", 1)[0] for section in sections[1:]]
    # sorted dependencies of each type, depth first, each once
    assert headers == [
        "MSG: geometry_msgs/Transform",
        "MSG: geometry_msgs/Quaternion",
        "MSG: geometry_msgs/Vector3",
        "MSG: std_msgs/Header",
        "MSG: builtin_interfaces/Time",
    ]
    assert sections[0].startswith("# This expresses a transform from coordinate frame header.frame_id")
    assert message_definition("turtlesim/msg/Pose") == (
        "float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity"
    )
    assert message_definition("turtlesim/msg/Spawn_Request").endswith("if this is empty\n")


def test_every_recorded_definition_parses_in_mcap_ros2_with_turtletuis_fields():
    from turtletui.interfaces import get_interface

    for name in ["turtlesim/msg/Pose", "tf2_msgs/msg/TFMessage", "visualization_msgs/msg/MarkerArray",
                 "rcl_interfaces/msg/Log", "sensor_msgs/msg/LaserScan", "turtlesim/msg/SetPen_Request",
                 "turtlesim/action/RotateAbsolute_Goal"]:
        assert name in generate_dynamic(name, message_definition(name))
    assert [s.name for s in get_interface("visualization_msgs/msg/Marker")._FIELDS][-3:] == [
        "mesh_resource", "mesh_file", "mesh_use_embedded_materials"]


def test_type_hashes_are_ros_2s():
    from turtletui.recording.type_hash import type_hash

    # as rclpy (Kilted) reports them and the ROS packages' type description files hold them
    assert type_hash("geometry_msgs/msg/Twist") == (
        "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a")
    assert type_hash("rcl_interfaces/msg/Log") == (
        "RIHS01_e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac")
    assert type_hash("geometry_msgs/msg/Vector3") == (
        "RIHS01_cc12fe83e4c02719f1ce8070bfd14aecd40f75a96696a67a2a1f37f7dbb0765d")
