"""``ros2 bag record | info | play`` as the official tutorial uses them, over a
simulation (the library functions the app's command line runs); the bag is
read back with rosbags."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from rosbags.highlevel import AnyReader
from rosbags.typesys import Stores, get_typestore

from turtletui.graph.core import DISCOVERY_NS, NS_PER_S
from turtletui.interfaces.geometry_msgs import Twist
from turtletui.recording.bag import BagError, BagPlayback, BagRecording, bag_info, default_bag_name
from turtletui.runtime.simulation import Simulation


def drive(sim: Simulation, seconds: float, linear: float = 1.5, angular: float = 0.7) -> None:
    """turtle_teleop_key's way: a Twist every 100 ms."""
    node = sim.graph.add_node("teleop_turtle")
    pub = sim.graph.add_publisher(node, "/turtle1/cmd_vel", Twist, 10)
    end = sim.graph.now_ns + round(seconds * NS_PER_S)
    while sim.graph.now_ns < end:
        msg = Twist()
        msg.linear.x, msg.angular.z = linear, angular
        sim.graph.publish(pub.topic, msg)
        sim.run_until(sim.graph.now_ns + 100_000_000)


@pytest.fixture
def subset(tmp_path: Path) -> tuple[Path, Simulation]:
    logs: list = []
    sim = Simulation(log_sinks=[logs.append])
    sim.logs = logs
    sim.run_until(NS_PER_S)
    recording = BagRecording(sim, ["/turtle1/cmd_vel", "/turtle1/pose"], tmp_path / "subset")
    drive(sim, 3.0)
    recording.stop()
    return tmp_path / "subset", sim


def test_record_keeps_only_the_topics_asked_for(subset):
    bag, sim = subset
    times: dict[str, list[int]] = {}
    with AnyReader([bag], default_typestore=get_typestore(Stores.EMPTY)) as reader:
        for connection, timestamp, raw in reader.messages():
            reader.deserialize(raw, connection.msgtype)
            times.setdefault(connection.topic, []).append(timestamp)
    assert set(times) == {"/turtle1/cmd_vel", "/turtle1/pose"} and len(times["/turtle1/cmd_vel"]) == 30
    poses = times["/turtle1/pose"]
    assert {b - a for a, b in zip(poses, poses[1:], strict=False)} == {16_000_000} and len(poses) > 180
    said = [(record.node, record.msg) for record in sim.logs if record.node == "rosbag2_recorder"]
    assert said[2:5] == [
        ("rosbag2_recorder", "Subscribed to topic '/turtle1/cmd_vel'"),
        ("rosbag2_recorder", "Subscribed to topic '/turtle1/pose'"),
        ("rosbag2_recorder", "Recording..."),
    ]


def test_recording_into_an_existing_folder_is_refused(tmp_path: Path):
    (tmp_path / "subset").mkdir()
    with pytest.raises(BagError, match="Output folder '.*subset' already exists."):
        BagRecording(Simulation(), None, tmp_path / "subset")
    assert re.fullmatch(r"rosbag2_\d{4}_\d\d_\d\d-\d\d_\d\d_\d\d", default_bag_name())


def test_info_prints_what_ros2_bag_info_prints(subset):
    bag, _ = subset
    text = bag_info(bag)
    lines = text.split("\n")
    assert lines[0] == "" and lines[1] == "Files:             subset_0.mcap"
    assert re.fullmatch(r"Bag size:          \d+\.\d KiB", lines[2])
    assert lines[3:5] == ["Storage id:        mcap", "ROS Distro:        jazzy"]
    assert lines[5] == "Duration:          3.000000000s"  # cmd_vel from t=1 s, the last pose at t=4 s
    assert re.fullmatch(r"Start:             \w{3} [ \d]\d \d{4} \d\d:\d\d:\d\d\.\d{9} \(1700000001\.\d{9}\)", lines[6])
    pose_count = int(re.search(r"Topic: /turtle1/pose .* Count: (\d+)", text).group(1))
    assert lines[8] == f"Messages:          {30 + pose_count}"
    assert lines[9].startswith("Topic information: Topic: /turtle1/cmd_vel | Type: geometry_msgs/msg/Twist | Count: 30 |")
    assert lines[10].startswith(" " * 19 + "Topic: /turtle1/pose | Type: turtlesim/msg/Pose | Count: ")
    assert lines[11:] == ["Service:           0", "Service information: ", ""]
    with pytest.raises(BagError, match="no such bag"):
        bag_info(bag.parent / "nope")


def test_play_drives_a_fresh_turtle_along_the_recorded_path(subset):
    bag, recorded = subset
    sim = Simulation()
    sim.run_until(NS_PER_S)
    playback = BagPlayback(sim, bag)
    assert playback.messages > 200 and not playback.done
    # the recording ran from t=1 s to t=4 s: so does the playback, in a fresh turtlesim
    sim.run_until(4 * NS_PER_S + 1)
    assert playback.done
    # but the first command went before turtlesim discovered the player's
    # publisher (as on ROS 2): the turtle starts 100 ms late and drives the
    # rest of the path, 1.5 m/s and 0.7 rad/s for those 100 ms short
    turtle, original = sim.world.turtles["turtle1"], recorded.world.turtles["turtle1"]
    assert turtle.distance == pytest.approx(original.distance - 0.15, abs=0.03) and turtle.distance > 4
    assert turtle.theta == pytest.approx(original.theta - 0.07, abs=0.015)
    assert playback.published == playback.messages
    # the player's node went with the end of the bag, as ros2 bag play exits
    assert [node.name for node in sim.graph.nodes if node.name.startswith("rosbag2")] == []


def test_play_publishes_from_a_player_node_on_the_recorded_topics(subset):
    bag, _ = subset
    sim = Simulation()
    playback = BagPlayback(sim, bag)
    sim.run_until(NS_PER_S // 2)
    assert {p.topic.name for t in sim.graph.topics.values() for p in t.publishers if p.node is playback.node} == {
        "/turtle1/cmd_vel", "/turtle1/pose", "/rosout", "/parameter_events"}  # and what every rclcpp node has
    playback.stop()
    assert playback.done and playback.node not in sim.graph.nodes
    published = playback.published
    sim.run_until(5 * NS_PER_S)
    assert playback.published == published  # Ctrl-C: nothing more


def received(sim: Simulation, topic: str, cls: type) -> list[int]:
    """When (graph ns) each message on ``topic`` arrives."""
    stamps: list[int] = []
    node = sim.graph.add_node("listener")
    sim.graph.add_subscription(node, topic, cls, 10, lambda msg: stamps.append(sim.graph.now_ns))
    return stamps


def test_rate_plays_faster_and_topics_choose_what_is_played(subset):
    bag, _ = subset
    sim = Simulation()
    commands = received(sim, "/turtle1/cmd_vel", Twist)
    sim.run_until(DISCOVERY_NS)
    playback = BagPlayback(sim, bag, rate=2.0, topics=["/turtle1/cmd_vel"])
    assert playback.messages == 30
    sim.run_until(DISCOVERY_NS + 2 * NS_PER_S)
    # the first message went before the listener discovered the player's publisher
    assert playback.done and len(commands) == 29 and commands[0] == 2 * DISCOVERY_NS + 1
    # recorded every 100 ms: played every 50 ms
    assert {b - a for a, b in zip(commands, commands[1:], strict=False)} == {50_000_000}
    with pytest.raises(BagError, match="rate must be a positive number"):
        BagPlayback(sim, bag, rate=0.0)


def test_loop_plays_the_bag_again_until_stopped(subset):
    bag, _ = subset
    sim = Simulation()
    commands = received(sim, "/turtle1/cmd_vel", Twist)
    playback = BagPlayback(sim, bag, loop=True, topics=["/turtle1/cmd_vel"])
    sim.run_until(10 * NS_PER_S)
    assert not playback.done and len(commands) > 60  # 2.9 s a pass: three passes and more
    playback.stop()
    count = len(commands)
    sim.run_until(12 * NS_PER_S)
    assert len(commands) == count


def test_a_damaged_bag_is_one_line(tmp_path: Path):
    folder = tmp_path / "broken"
    folder.mkdir()
    (folder / "broken_0.mcap").write_bytes(b"\x89MCAP0\r\n not really")
    for attempt in (lambda: bag_info(folder), lambda: BagPlayback(Simulation(), folder)):
        with pytest.raises(BagError, match="broken") as caught:
            attempt()
        assert "\n" not in str(caught.value)


def test_the_recorder_is_a_node_that_subscribes_to_what_it_records(tmp_path: Path):
    sim = Simulation()
    recording = BagRecording(sim, ["/turtle1/pose", "/turtle1/pose", "/not_yet"], tmp_path / "bag")
    pose = sim.graph.topics["/turtle1/pose"]
    assert [s.node.name for s in pose.subscriptions] == ["rosbag2_recorder"]
    recording.stop()
    recording.stop()  # twice is once
    assert pose.subscriptions == [] and recording.node not in sim.graph.nodes


def test_a_bag_stopped_during_a_live_recording_leaves_the_colour_sensor_on(tmp_path: Path):
    from turtletui.recording.recorder import McapRecorder

    sim = Simulation()
    whole = McapRecorder(sim, tmp_path / "whole.mcap")
    bag = BagRecording(sim, ["/turtle1/pose"], tmp_path / "bag")
    bag.stop()
    assert sim.graph.record_everything  # the whole recording still wants every topic
    whole.close()
    assert not sim.graph.record_everything


def test_play_offers_what_the_recorded_publishers_offered(tmp_path: Path):
    """rosbag2 records each publisher's offered QoS and plays with it: a
    best-effort topic plays best effort, so a reliable subscriber hears
    nothing and the player warns in rclcpp's words."""
    from turtletui.graph.qos import Policies
    from turtletui.interfaces.std_msgs import String

    sim = Simulation()
    talker = sim.graph.add_node("talker")
    fast = sim.graph.add_publisher(talker, "/chatter", String, 10, qos=Policies.named("best_effort", "volatile"))
    recording = BagRecording(sim, ["/chatter"], tmp_path / "chatter")
    for i in range(5):
        sim.graph.publish(fast.topic, String(data=f"hello {i}"), None, fast)
        sim.run_until(sim.graph.now_ns + 100_000_000)
    recording.stop()

    logs: list = []
    sim = Simulation(log_sinks=[logs.append])
    listener = sim.graph.add_node("listener")
    heard: dict[str, list[str]] = {"reliable": [], "best_effort": []}
    for reliability in heard:
        qos = Policies.named(reliability, "volatile")
        sim.graph.add_subscription(listener, "/chatter", String, 10, lambda m, r=reliability: heard[r].append(m.data), qos=qos)
    sim.run_until(DISCOVERY_NS)
    playback = BagPlayback(sim, tmp_path / "chatter")
    [publisher] = sim.graph.publishers_of("/chatter")
    assert publisher.node is playback.node and publisher.depth == 10
    assert (publisher.qos.reliability, publisher.qos.durability) == Policies.named("best_effort", "volatile")[:2]
    sim.run_until(DISCOVERY_NS + NS_PER_S)
    # recorded: hello 1 to 4 (nobody had discovered the talker at hello 0);
    # played: hello 1 went before anyone discovered the player
    assert heard == {"reliable": [], "best_effort": ["hello 2", "hello 3", "hello 4"]}
    assert [(r.node, r.level, r.msg) for r in logs if "incompatible" in r.msg] == [(
        "rosbag2_player", 30,
        "New subscription discovered on topic '/chatter', requesting incompatible QoS. "
        "No messages will be sent to it. Last incompatible policy: RELIABILITY_QOS_POLICY",
    )]
