"""`turtletui run --record run.mcap | run/`: recordings read back with
independent readers (mcap's and mcap_ros2's for the file, rosbags for the
rosbag2 folder), never with turtletui's own code."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbags.highlevel import AnyReader
from rosbags.typesys import Stores, get_typestore
from ruamel.yaml import YAML
from support.grading import one_line_error
from typer.testing import CliRunner

from turtletui.cli import app

DRAWER = '''\
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.srv import SetPen, Spawn


class Drawer(Node):
    def __init__(self):
        super().__init__("drawer")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pen = self.create_client(SetPen, "/turtle1/set_pen")
        self.spawner = self.create_client(Spawn, "/spawn")
        self.timer = self.create_timer(0.1, self.tick)
        self.ticks = 0

    def tick(self):
        self.ticks += 1
        msg = Twist()
        msg.linear.x = 1.0
        msg.angular.z = 0.8
        self.pub.publish(msg)
        self.get_logger().info(f"tick {self.ticks}")
        if self.ticks == 10:
            self.pen.call_async(SetPen.Request(r=255, g=0, b=0, width=5, off=0))
        if self.ticks == 20:
            self.spawner.call_async(Spawn.Request(x=2.0, y=2.0, theta=0.0, name="turtle2"))


def main():
    rclpy.init()
    rclpy.spin(Drawer())
'''

DURATION = 4.0
EPOCH_NS = 1_700_000_000 * 1_000_000_000
YAML_LOADER = YAML(typ="safe")


def record(tmp: Path, target: str, *extra: str) -> Path:
    controller = tmp / "drawer.py"
    controller.write_text(DRAWER)
    result = CliRunner().invoke(
        app, ["run", str(controller), "--headless", "-q", "--duration", str(DURATION), "--record", target, *extra]
    )
    assert result.exit_code == 0, result.stderr
    return Path(target)


@pytest.fixture(scope="module")
def mcap_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    tmp = tmp_path_factory.mktemp("mcap")
    return record(tmp, str(tmp / "run.mcap"))


@pytest.fixture(scope="module")
def bag(tmp_path_factory: pytest.TempPathFactory) -> Path:
    tmp = tmp_path_factory.mktemp("bag")
    return record(tmp, str(tmp / "subset") + "/")


def decoded(path: Path) -> list[tuple]:
    with path.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        return list(reader.iter_decoded_messages(log_time_order=True))


def test_every_message_decodes_with_the_right_schema_and_qos(mcap_file: Path):
    with mcap_file.open("rb") as stream:
        reader = make_reader(stream)
        assert reader.get_header().profile == "ros2"
        summary = reader.get_summary()
    for channel in summary.channels.values():
        schema = summary.schemas[channel.schema_id]
        assert channel.message_encoding == "cdr" and schema.encoding == "ros2msg"
        (profile,) = YAML_LOADER.load(channel.metadata["offered_qos_profiles"])
        assert profile["reliability"] == "reliable" and profile["history"] == "unknown"
        assert re.fullmatch(r"RIHS01_[0-9a-f]{64}", channel.metadata["topic_type_hash"])
    types = {channel.topic: summary.schemas[channel.schema_id].name for channel in summary.channels.values()}
    assert types == {
        "/turtle1/pose": "turtlesim/msg/Pose",
        "/turtle1/cmd_vel": "geometry_msgs/msg/Twist",
        "/turtle1/color_sensor": "turtlesim/msg/Color",
        "/turtle2/pose": "turtlesim/msg/Pose",
        "/turtle2/color_sensor": "turtlesim/msg/Color",
        "/rosout": "rcl_interfaces/msg/Log",
        "/tf": "tf2_msgs/msg/TFMessage",
        "/turtlesim/scene": "visualization_msgs/msg/MarkerArray",
        "/turtle1/set_pen/_request": "turtlesim/msg/SetPen_Request",
        "/turtle1/set_pen/_response": "turtlesim/msg/SetPen_Response",
        "/spawn/_request": "turtlesim/msg/Spawn_Request",
        "/spawn/_response": "turtlesim/msg/Spawn_Response",
    }
    messages = decoded(mcap_file)
    counts = Counter(channel.topic for _, channel, _, _ in messages)
    assert sum(counts.values()) == summary.statistics.message_count
    assert counts["/turtle1/cmd_vel"] == 40 and counts["/spawn/_request"] == 1


def test_one_pose_per_16_ms_with_a_tf_frame_each(mcap_file: Path):
    messages = decoded(mcap_file)
    poses = [(m.log_time, msg) for _, channel, m, msg in messages if channel.topic == "/turtle1/pose"]
    times = [t for t, _ in poses]
    assert {b - a for a, b in zip(times, times[1:], strict=False)} == {16_000_000}
    assert len(poses) == int(DURATION / 0.016) - 1  # turtlesim's first tick only starts the clock
    assert all(m.publish_time == m.log_time for _, _, m, _ in messages)
    frames = {}
    for _, channel, m, msg in messages:
        if channel.topic == "/tf":
            (transform,) = msg.transforms
            assert transform.header.frame_id == "world"
            stamp = transform.header.stamp.sec * 1_000_000_000 + transform.header.stamp.nanosec
            assert stamp == m.log_time
            frames[(transform.child_frame_id, m.log_time)] = transform.transform
    for t, pose in poses:
        transform = frames[("turtle1", t)]
        assert (transform.translation.x, transform.translation.y) == (pose.x, pose.y)
        assert 2 * math.atan2(transform.rotation.z, transform.rotation.w) == pytest.approx(pose.theta, abs=1e-6)
    assert any(child == "turtle2" for child, _ in frames)


def test_rosout_service_calls_and_the_scene(mcap_file: Path):
    messages = decoded(mcap_file)
    logs = [msg for _, channel, _, msg in messages if channel.topic == "/rosout"]
    assert logs[0].name == "turtlesim" and logs[0].msg == "Starting turtlesim with node name /turtlesim"
    assert [log.msg for log in logs if log.name == "drawer"] == [f"tick {n}" for n in range(1, 41)]
    assert all(log.level == 20 for log in logs)
    (pen,) = [msg for _, channel, _, msg in messages if channel.topic == "/turtle1/set_pen/_request"]
    assert (pen.r, pen.g, pen.b, pen.width, pen.off) == (255, 0, 0, 5, 0)
    (spawned,) = [msg for _, channel, _, msg in messages if channel.topic == "/spawn/_response"]
    assert spawned.name == "turtle2"
    scenes = [msg for _, channel, _, msg in messages if channel.topic == "/turtlesim/scene"]
    assert len(scenes) <= DURATION + 3  # at most one a second, and on changes
    last = scenes[-1].markers
    assert last[0].action == 3  # DELETEALL: each message is the whole scene
    by_ns = Counter(marker.ns for marker in last)
    assert by_ns["arena"] == by_ns["walls"] == 1 and by_ns["turtles"] == 2
    pens = [marker for marker in last if marker.ns == "pen"]
    assert [(round(p.color.r, 3), round(p.color.g, 3), round(p.color.b, 3)) for p in pens] == [
        (round(179 / 255, 3), round(184 / 255, 3), 1.0),
        (1.0, 0.0, 0.0),
    ]  # turtle2 never moves: it draws nothing
    assert pens[1].scale.x == pytest.approx(5 / 45)  # 5 px of turtlesim's image (45 px a metre)


def test_a_recording_is_the_same_bytes_every_time(mcap_file: Path, tmp_path: Path):
    again = record(tmp_path, str(tmp_path / mcap_file.name))  # the name is in rosbag2's metadata
    assert again.read_bytes() == mcap_file.read_bytes()


def test_a_bag_folder_reads_with_rosbags_and_its_metadata_is_rosbag2s(bag: Path, mcap_file: Path):
    assert sorted(p.name for p in bag.iterdir()) == ["metadata.yaml", "subset_0.mcap"]
    counts: Counter[str] = Counter()
    with AnyReader([bag], default_typestore=get_typestore(Stores.EMPTY)) as reader:
        for connection, _, raw in reader.messages():
            reader.deserialize(raw, connection.msgtype)
            counts[connection.topic] += 1
        assert reader.start_time == EPOCH_NS
    meta = YAML_LOADER.load((bag / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    assert meta["version"] == 9 and meta["storage_identifier"] == "mcap" and meta["ros_distro"] == "jazzy"
    assert meta["relative_file_paths"] == ["subset_0.mcap"]
    assert meta["message_count"] == sum(counts.values()) == meta["files"][0]["message_count"]
    assert meta["starting_time"]["nanoseconds_since_epoch"] == EPOCH_NS
    assert meta["duration"]["nanoseconds"] == DURATION * 1e9
    assert meta["compression_format"] == "" and meta["custom_data"] is None
    topics = {t["topic_metadata"]["name"]: t for t in meta["topics_with_message_count"]}
    assert {name: t["message_count"] for name, t in topics.items()} == dict(counts)
    rosout = topics["/rosout"]["topic_metadata"]
    assert rosout["type"] == "rcl_interfaces/msg/Log" and rosout["serialization_format"] == "cdr"
    assert rosout["type_description_hash"] == "RIHS01_e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac"
    (qos,) = rosout["offered_qos_profiles"]
    assert qos["durability"] == "transient_local" and qos["lifespan"] == {"sec": 10, "nsec": 0}
    assert qos["deadline"] == {"sec": 9223372036, "nsec": 854775807}
    # the same messages as the single file, in a folder
    assert counts == Counter(channel.topic for _, channel, _, _ in decoded(mcap_file))


def test_bad_record_paths_are_one_line_errors(tmp_path: Path):
    full = tmp_path / "full"
    full.mkdir()
    (full / "something").write_text("x")
    controller = tmp_path / "drawer.py"
    controller.write_text(DRAWER)

    def run(target: str):
        return CliRunner().invoke(app, ["run", str(controller), "--headless", "-q", "-d", "1", "--record", target])

    assert f"{full}/: cannot write the bag (the folder exists and is not empty)" in one_line_error(run(f"{full}/"))
    missing = tmp_path / "no" / "such" / "run.mcap"
    assert "cannot write the recording" in one_line_error(run(str(missing)))
    assert not missing.parent.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["drawer.py", "full"]


def test_a_headless_run_without_mcap_recording_does_not_import_mcap(tmp_path: Path):
    code = (
        "import sys; from turtletui.api import run; from turtletui.runtime.resolve import resolve_controllers; "
        f"run(resolve_controllers(['part6_wall_avoider']), duration=1, record={str(tmp_path / 'r.jsonl')!r}); "
        "print(sorted(m for m in sys.modules if m.split('.')[0] in ('mcap', 'mcap_ros2', 'foxglove')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_apps_session_records_what_it_shows(tmp_path: Path):
    from turtletui.tui.session import LiveSession

    session = LiveSession([], record=str(tmp_path / "app.mcap"))
    clock = 100.0
    session.advance(clock)
    for _ in range(5):  # a key pressed before turtlesim discovered the teleop node would be lost
        clock += 0.016
        session.advance(clock)
    session.teleop.drive(linear=1.0)
    for _ in range(60):
        clock += 0.016
        session.advance(clock)
    session.clear()
    clock += 0.016
    session.advance(clock)
    session.close()
    messages = decoded(tmp_path / "app.mcap")
    topics = Counter(channel.topic for _, channel, _, _ in messages)
    assert topics["/turtle1/pose"] >= 50 and topics["/turtle1/cmd_vel"] == 1 and topics["/clear/_request"] == 1
    twist = next(msg for _, channel, _, msg in messages if channel.topic == "/turtle1/cmd_vel")
    assert twist.linear.x == 2.0  # turtle_teleop_key's scale

    broken = LiveSession([], record=str(tmp_path / "no" / "such" / "dir" / "app.mcap"))
    assert any("not recording" in record.msg for record in broken.logs)
    broken.close()
