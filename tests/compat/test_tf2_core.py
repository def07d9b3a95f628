"""tf2's lookup semantics (BufferCore, checked against buffer_core.cpp and
cache.cpp): interpolation, the latest common time, chains through a common
parent, static frames, cache time, and the errors' texts."""

from __future__ import annotations

import math

import pytest

from turtletui.compat.tf2.buffer_core import BufferCore
from turtletui.compat.tf2.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformException,
)
from turtletui.compat.time import Duration, Time
from turtletui.interfaces.geometry_msgs import TransformStamped

S = 1_000_000_000


def stamped(parent: str, child: str, t: float, x: float = 0.0, y: float = 0.0, z: float = 0.0, yaw: float = 0.0):
    msg = TransformStamped()
    msg.header.frame_id, msg.child_frame_id = parent, child
    msg.header.stamp.sec, msg.header.stamp.nanosec = int(t), round((t - int(t)) * S)
    msg.transform.translation.x, msg.transform.translation.y, msg.transform.translation.z = float(x), float(y), float(z)
    msg.transform.rotation.z, msg.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return msg


def at(seconds: float) -> Time:
    return Time(nanoseconds=round(seconds * S))


def xyz(msg) -> tuple[float, float, float]:
    t = msg.transform.translation
    return (round(t.x, 9), round(t.y, 9), round(t.z, 9))


def yaw(msg) -> float:
    q = msg.transform.rotation
    return 2 * math.atan2(q.z, q.w)


class Recorder:
    """Stands for the "tf2" logger: keeps what BufferCore logs."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def error(self, text: str) -> None:
        self.lines.append(f"ERROR {text}")

    def warning(self, text: str) -> None:
        self.lines.append(f"WARN {text}")


@pytest.fixture
def logged(monkeypatch) -> list[str]:
    recorder = Recorder()
    monkeypatch.setattr("turtletui.compat.tf2.buffer_core._logger", lambda: recorder)
    return recorder.lines


@pytest.fixture
def turtles() -> BufferCore:
    """world -> turtle1 at 10 s and 12 s (moving +2 in x, turning a quarter), world -> turtle2 at 11 s."""
    core = BufferCore()
    core.set_transform(stamped("world", "turtle1", 10, x=1, y=2), "a")
    core.set_transform(stamped("world", "turtle1", 12, x=3, y=2, yaw=math.pi / 2), "a")
    core.set_transform(stamped("world", "turtle2", 11, x=5, y=5, yaw=math.pi / 2), "a")
    return core


def test_between_two_stamps_translation_is_linear_and_rotation_slerped(turtles):
    msg = turtles.lookup_transform_core("world", "turtle1", at(11.5))
    assert xyz(msg) == (2.5, 2.0, 0.0)
    assert yaw(msg) == pytest.approx(3 * math.pi / 8)
    assert (msg.header.stamp.sec, msg.header.stamp.nanosec) == (11, 500_000_000)
    assert (msg.header.frame_id, msg.child_frame_id) == ("world", "turtle1")


def test_time_zero_is_the_latest_time_both_chains_have_and_chains_meet_at_the_common_parent(turtles):
    msg = turtles.lookup_transform_core("turtle2", "turtle1", Time())
    # at 11 s turtle1 is at (2, 2) in world; turtle2 at (5, 5) facing +y: turtle1 is 3 m
    # behind it (-y of world is turtle2's -x) and 3 m to its right
    assert msg.header.stamp.sec == 11
    assert (round(msg.transform.translation.x, 9), round(msg.transform.translation.y, 9)) == (-3.0, 3.0)
    assert yaw(msg) == pytest.approx(math.pi / 4 - math.pi / 2)
    back = turtles.lookup_transform_core("turtle1", "turtle2", Time())
    assert yaw(back) == pytest.approx(math.pi / 4)
    down = turtles.lookup_transform_core("turtle1", "world", Time())  # the source is the target's parent
    assert down.header.stamp.sec == 12 and xyz(down) == (-2.0, 3.0, 0.0)


def test_extrapolation_errors_have_tf2s_texts(turtles):
    with pytest.raises(ExtrapolationException) as future:
        turtles.lookup_transform_core("world", "turtle1", at(13))
    assert str(future.value) == (
        "Lookup would require extrapolation into the future.  Requested time 13.000000 but the latest data is at"
        " time 12.000000, when looking up transform from frame [turtle1] to frame [world]"
    )
    with pytest.raises(ExtrapolationException) as past:
        turtles.lookup_transform_core("turtle1", "world", at(9))
    assert str(past.value) == (
        "Lookup would require extrapolation into the past.  Requested time 9.000000 but the earliest data is at"
        " time 10.000000, when looking up transform from frame [world] to frame [turtle1]"
    )
    with pytest.raises(ExtrapolationException) as single:
        turtles.lookup_transform_core("turtle2", "turtle1", at(12))
    assert str(single.value) == (
        "Lookup would require extrapolation at time 12.000000, but only time 11.000000 is in the buffer,"
        " when looking up transform from frame [turtle1] to frame [turtle2]"
    )
    assert turtles.can_transform_core("world", "turtle1", at(13)) == (False, str(future.value))
    assert turtles.can_transform_core("world", "turtle1", at(11)) == (True, "")


def test_frames_that_do_not_exist_and_unconnected_trees(turtles):
    with pytest.raises(LookupException) as missing:
        turtles.lookup_transform_core("turtle3", "turtle1", Time())
    assert str(missing.value) == '"turtle3" passed to lookupTransform argument target_frame does not exist. '
    with pytest.raises(LookupException, match='"turtle3" passed to lookupTransform argument source_frame'):
        turtles.lookup_transform_core("turtle1", "turtle3", Time())
    assert turtles.can_transform_core("turtle1", "turtle3", Time()) == (
        False, 'Invalid frame ID "turtle3" passed to canTransform argument source_frame - frame does not exist'
    )
    with pytest.raises(InvalidArgumentException) as slash:
        turtles.lookup_transform_core("/world", "turtle1", Time())
    assert str(slash.value) == (
        "Invalid argument \"/world\" passed to lookupTransform argument target_frame - in tf2 frame_ids cannot"
        " start with a '/'"
    )
    turtles.set_transform(stamped("map", "robot", 11), "b")
    with pytest.raises(ConnectivityException) as apart:
        turtles.lookup_transform_core("robot", "turtle1", Time())
    assert str(apart.value) == (
        "Could not find a connection between 'robot' and 'turtle1' because they are not part of the same tree."
        "Tf has two or more unconnected trees."
    )
    assert all(issubclass(e, TransformException) for e in (LookupException, ConnectivityException))
    identity = turtles.lookup_transform_core("nowhere", "nowhere", Time())  # never validated, as in tf2
    assert xyz(identity) == (0.0, 0.0, 0.0)


def test_static_frames_hold_at_every_time_and_leave_the_common_time_to_the_others(turtles):
    turtles.set_transform_static(stamped("turtle1", "carrot", 0, y=2), "s")
    turtles.set_transform_static(stamped("world", "mystatic", 5, z=1), "s")
    assert xyz(turtles.lookup_transform_core("world", "mystatic", at(1e6))) == (0.0, 0.0, 1.0)
    carrot = turtles.lookup_transform_core("world", "carrot", Time())
    assert carrot.header.stamp.sec == 12  # turtle1's latest: the static link adds no time of its own
    assert xyz(carrot) == (1.0, 2.0, 0.0)  # 2 m along turtle1's y, which faces -x in world at 12 s
    assert xyz(turtles.lookup_transform_core("mystatic", "carrot", at(10))) == (1.0, 4.0, -1.0)
    assert turtles.lookup_transform_core("world", "mystatic", Time()).header.stamp.sec == 0


def test_lookup_full_goes_through_the_fixed_frame_at_two_times(turtles):
    # where turtle1 was at 10 s, seen from turtle1 at 12 s, with world fixed
    msg = turtles.lookup_transform_full_core("turtle1", at(12), "turtle1", at(10), "world")
    assert (round(msg.transform.translation.x, 9), round(msg.transform.translation.y, 9)) == (0.0, 2.0)
    assert yaw(msg) == pytest.approx(-math.pi / 2)
    assert turtles.can_transform_full_core("turtle1", at(12), "turtle1", at(9), "world")[0] is False
    with pytest.raises(LookupException, match="fixed_frame does not exist"):
        turtles.lookup_transform_full_core("turtle1", at(12), "turtle1", at(10), "map")


def test_the_cache_keeps_cache_time_behind_its_newest_and_refuses_older_data(logged):
    core = BufferCore(Duration(seconds=2))
    for t in range(10, 16):
        assert core.set_transform(stamped("world", "turtle1", t, x=t), "a")
    # pruned as each transform comes, against the newest before it (as cache.cpp)
    with pytest.raises(ExtrapolationException, match="the earliest data is at time 12.000000"):
        core.lookup_transform_core("world", "turtle1", at(11.5))
    assert core.set_transform(stamped("world", "turtle1", 12, x=12), "a") is False
    assert logged == [
        "WARN TF_OLD_DATA ignoring data from the past for frame turtle1 at time 12.000000 according to authority a\n"
        "Possible reasons are listed at http://wiki.ros.org/tf/Errors%20explained"
    ]
    assert core.set_transform(stamped("world", "turtle1", 13.5, x=13.5), "a")  # late but kept
    assert xyz(core.lookup_transform_core("world", "turtle1", at(13.25)))[0] == 13.25
    with pytest.raises(ExtrapolationException, match="the earliest data is at time 13.000000"):
        core.lookup_transform_core("world", "turtle1", at(12.5))


def test_bad_transforms_are_refused_with_tf2s_errors(logged):
    core = BufferCore()
    assert core.set_transform(stamped("world", "world", 1), "a") is False
    assert core.set_transform(stamped("", "turtle1", 1), "a") is False
    bad = stamped("world", "turtle1", 1)
    bad.transform.rotation.w = 2.0
    assert core.set_transform(bad, "a") is False
    assert logged == [
        'ERROR TF_SELF_TRANSFORM: Ignoring transform from authority "a" with frame_id and  child_frame_id "world"'
        " because they are the same",
        'ERROR TF_NO_FRAME_ID: Ignoring transform with child_frame_id "turtle1"  from authority "a" because'
        " frame_id not set",
        'ERROR TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "turtle1" from authority "a"'
        " because of an invalid quaternion in the transform (0.000000 0.000000 0.000000 2.000000)",
    ]
    assert core.all_frames_as_string() == ""
    assert core.all_frames_as_yaml() == "[]"


def test_frames_described_as_tf2_does(turtles):
    assert turtles.all_frames_as_string() == "Frame turtle1 exists with parent world.\nFrame turtle2 exists with parent world.\n"
    yaml = turtles.all_frames_as_yaml()
    assert yaml.startswith(
        "turtle1: \n  parent: 'world'\n  broadcaster: 'a'\n  rate: 1.000\n  most_recent_transform: 12.000000\n"
        "  oldest_transform: 10.000000\n  buffer_length: 2.000\n"
    )


def test_a_loop_in_the_tree_is_an_error_not_a_hang():
    core = BufferCore()
    core.set_transform(stamped("a", "b", 1), "x")
    core.set_transform(stamped("b", "a", 1), "x")
    core.set_transform(stamped("c", "d", 1), "x")
    with pytest.raises(LookupException, match="The tf tree is invalid because it contains a loop."):
        core.lookup_transform_core("d", "a", Time())


def test_buffer_transform_moves_stamped_geometry_msgs_into_a_frame(turtles):
    from turtletui.compat.tf2 import geometry_msgs as tf2_geometry_msgs
    from turtletui.compat.tf2.buffer import Buffer
    from turtletui.compat.tf2.buffer_interface import TypeException
    from turtletui.interfaces.geometry_msgs import Point, PointStamped, PoseStamped, Vector3Stamped
    from turtletui.interfaces.std_msgs import Header

    buffer = Buffer()
    buffer.set_transform(stamped("world", "turtle2", 11, x=5, y=5, yaw=math.pi / 2), "a")
    header = Header(frame_id="world")
    header.stamp.sec = 11
    point = buffer.transform(PointStamped(header=header, point=Point(x=2.0, y=2.0)), "turtle2")
    assert (point.header.frame_id, round(point.point.x, 9), round(point.point.y, 9)) == ("turtle2", -3.0, 3.0)
    vector = Vector3Stamped(header=header)
    vector.vector.x = 1.0
    moved = buffer.transform(vector, "turtle2")  # a direction: rotated, not translated
    assert (round(moved.vector.x, 9), round(moved.vector.y, 9)) == (0.0, -1.0)
    pose = PoseStamped(header=header)
    pose.pose.orientation.w = 1.0
    turned = buffer.transform(pose, "turtle2").pose
    assert (round(turned.position.x, 9), round(turned.position.y, 9)) == (-5.0, 5.0)
    assert 2 * math.atan2(turned.orientation.z, turned.orientation.w) == pytest.approx(-math.pi / 2)
    assert tf2_geometry_msgs.do_transform_pose(pose.pose, buffer.lookup_transform("turtle2", "world", at(11))) == turned
    with pytest.raises(TypeException, match="is not loaded or supported"):
        buffer.transform(header, "turtle2")


def test_a_timeout_that_is_not_a_duration_and_a_time_that_is_not_a_time_are_named():
    from turtletui.compat.tf2.buffer import Buffer

    buffer = Buffer()
    with pytest.raises(TypeError, match=r"timeout must be an rclpy.duration.Duration, got 1.0 \(e.g. timeout="):
        buffer.lookup_transform("a", "b", Time(), timeout=1.0)
    with pytest.raises(TypeError, match="time must have sec and nanosec, or nanoseconds."):
        buffer.lookup_transform("a", "b", 0)
    with pytest.raises(TypeError, match="duration must have sec and nanosec, or nanoseconds."):
        Buffer(cache_time=5)
