"""``ros2 bag record | info | play`` typed in the console, as the official
"Recording and playing back data" tutorial types them: the bag is read back
with rosbags, an independent reader."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from rosbags.highlevel import AnyReader
from rosbags.typesys import Stores, get_typestore

from turtletui.graph.core import NS_PER_S
from turtletui.ros2cli import Ros2Cli, Terminal
from turtletui.ros2cli.terminal import Line
from turtletui.runtime.simulation import Simulation

DRIVE = "ros2 topic pub -r 10 /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: 1.5}, angular: {z: 0.7}}'"
RECORD = "ros2 bag record /turtle1/cmd_vel /turtle1/pose -o subset"


@pytest.fixture(autouse=True)
def _in_a_folder(tmp_path: Path, monkeypatch) -> None:
    """Bags go in the folder turtletui runs in, as ros2 bag's do."""
    monkeypatch.chdir(tmp_path)


@pytest.fixture
def sim() -> Simulation:
    return Simulation()


@pytest.fixture
def term(sim: Simulation) -> Terminal:
    return Terminal(Ros2Cli(sim))


def step(sim: Simulation, seconds: float) -> None:
    sim.run_until(sim.graph.now_ns + round(seconds * NS_PER_S))


def texts(lines: list[Line]) -> list[str]:
    return [line.text for line in lines]


def node_names(sim: Simulation) -> list[str]:
    return sorted(node.name for node in sim.graph.nodes)


def record_subset(sim: Simulation, term: Terminal) -> list[Line]:
    """The tutorial: record two topics while the turtle drives, then Ctrl+C."""
    step(sim, 1.0)
    term.run(DRIVE + " &")
    started = term.run(RECORD)
    step(sim, 3.0)
    return started + term.poll() + term.interrupt()


def read_back(bag: Path) -> dict[str, list[int]]:
    """Log times of every message, by topic, decoded by rosbags."""
    times: dict[str, list[int]] = {}
    with AnyReader([bag], default_typestore=get_typestore(Stores.EMPTY)) as reader:
        for connection, timestamp, raw in reader.messages():
            reader.deserialize(raw, connection.msgtype)
            times.setdefault(connection.topic, []).append(timestamp)
    return times


def test_record_runs_until_ctrl_c_then_the_bag_is_written(sim, term):
    out = record_subset(sim, term)
    shown = texts(out)
    assert shown[0] == "$ " + RECORD
    said = [re.sub(r"^\[INFO\] \[\d+\.\d{9}\] \[rosbag2_recorder\]: ", "", text) for text in shown[1:]]
    assert said == [
        "Opened database 'subset/subset_0.mcap' for READ_WRITE.",
        "Listening for topics...",
        "Subscribed to topic '/turtle1/cmd_vel'",
        "Subscribed to topic '/turtle1/pose'",
        "Recording...",
        "^C",
        "Recording stopped",
    ]
    assert out[-2] == Line("^C", "note")
    assert sorted(p.name for p in Path("subset").iterdir()) == ["metadata.yaml", "subset_0.mcap"]
    times = read_back(Path("subset"))
    assert set(times) == {"/turtle1/cmd_vel", "/turtle1/pose"} and len(times["/turtle1/cmd_vel"]) == 30
    assert {b - a for a, b in zip(times["/turtle1/pose"], times["/turtle1/pose"][1:], strict=False)} == {16_000_000}
    assert "rosbag2_recorder" not in node_names(sim) and term.foreground is None


def test_while_recording_the_recorder_is_a_node_subscribed_to_its_topics(sim, term):
    term.run(RECORD)
    assert "/rosbag2_recorder" in texts(term.run("ros2 node list"))  # the recording goes to the background
    assert texts(term.run("ros2 topic info /turtle1/pose"))[-1] == "Subscription count: 1"
    jobs = texts(term.run("jobs"))
    assert jobs[1] == f"[1]  Running  {RECORD}  (to subset/)"
    stopped = texts(term.run("kill %1"))
    assert stopped[1] == f"[1]  Stopped  {RECORD}  (to subset/)" and stopped[2].endswith("Recording stopped")
    assert Path("subset/metadata.yaml").is_file()


def test_record_all_takes_topics_that_appear_later(sim, term):
    term.run("ros2 bag record -a -o everything")
    step(sim, 0.5)
    term.run("ros2 service call /spawn turtlesim/srv/Spawn \"{x: 2.0, y: 2.0, theta: 0.0, name: ''}\"")
    step(sim, 0.5)
    term.run("kill %1")  # the recording went to the background with the call
    topics = set(read_back(Path("everything")))
    assert {"/turtle1/pose", "/turtle2/pose", "/rosout"} <= topics


def test_info_prints_rosbag2s_layout(sim, term):
    record_subset(sim, term)
    shown = texts(term.run("ros2 bag info subset"))
    assert shown[:3] == ["$ ros2 bag info subset", "", "Files:             subset_0.mcap"]
    assert re.fullmatch(r"Bag size:          \d+\.\d KiB", shown[3])
    assert shown[4:6] == ["Storage id:        mcap", "ROS Distro:        jazzy"]
    assert re.fullmatch(r"Duration:          \d\.\d{9}s", shown[6])
    assert re.fullmatch(r"Start:             \w{3} [ \d]\d \d{4} \d\d:\d\d:\d\d\.\d{9} \(\d+\.\d{9}\)", shown[7])
    assert shown[8].startswith("End:               ")
    poses = int(re.search(r"Topic: /turtle1/pose .* Count: (\d+)", "\n".join(shown)).group(1))
    assert shown[9] == f"Messages:          {30 + poses}"
    topic_lines = sorted(line.strip().removeprefix("Topic information: ") for line in shown[10:12])
    assert topic_lines == [
        "Topic: /turtle1/cmd_vel | Type: geometry_msgs/msg/Twist | Count: 30 | Serialization Format: cdr",
        f"Topic: /turtle1/pose | Type: turtlesim/msg/Pose | Count: {poses} | Serialization Format: cdr",
    ]
    assert sorted(texts(term.run("ros2 bag info -t subset"))[1:]) == ["/turtle1/cmd_vel", "/turtle1/pose"]


def test_play_drives_the_turtle_along_the_recorded_path(sim, term):
    record_subset(sim, term)
    term.run("kill all")
    step(sim, 1.5)  # turtlesim stops 1 s after the last command
    recorded = sim.world.turtles["turtle1"]
    fresh = Simulation()
    player = Terminal(Ros2Cli(fresh))
    # Play from the sim time of the bag's first message, so that the commands
    # come at the same instants between turtlesim's ticks as when recorded.
    first = min(min(times) for times in read_back(Path("subset")).values())
    fresh.run_until(first - fresh.graph.epoch_ns)
    out = texts(player.run("ros2 bag play subset"))
    assert re.fullmatch(r"\[INFO\] \[\d+\.\d{9}\] \[rosbag2_player\]: Playing subset: \d+ messages, \d\.\d{9} s", out[1])
    step(fresh, 2.0)
    assert player.poll() == [] and player.foreground is not None  # still playing, at the recorded pace
    step(fresh, 1.1)
    player.poll()
    assert player.foreground is None and "rosbag2_player" not in node_names(fresh)  # played to its end
    step(fresh, 1.5)
    turtle = fresh.world.turtles["turtle1"]
    assert (turtle.x, turtle.y, turtle.theta) == pytest.approx((recorded.x, recorded.y, recorded.theta), abs=1e-5)
    assert turtle.distance > 4


def test_ctrl_c_stops_a_playback_and_loop_plays_until_then(sim, term):
    record_subset(sim, term)
    term.run("kill all")
    term.run("ros2 bag play subset --loop --rate 2 --topics /turtle1/cmd_vel")
    assert "rosbag2_player" in node_names(sim)
    step(sim, 5.0)  # more than three passes of 1.5 s
    assert term.foreground is not None
    commands = sim.graph.topics["/turtle1/cmd_vel"].count
    assert term.interrupt()[0] == Line("^C", "note")
    step(sim, 2.0)
    assert sim.graph.topics["/turtle1/cmd_vel"].count == commands
    assert "rosbag2_player" not in node_names(sim) and term.foreground is None


def test_a_playback_goes_to_the_background_and_says_when_it_is_done(sim, term):
    record_subset(sim, term)
    term.run("kill all")
    term.run("ros2 bag play subset")
    out = texts(term.run("ros2 topic list"))
    assert out[0].startswith("[1] ros2 bag play subset: goes on in the background")
    step(sim, 4.0)
    done = texts(term.poll())
    assert len(done) == 1 and re.fullmatch(r"\[1\]  Done     ros2 bag play subset  \(\d+ published\)", done[0])


ERRORS = [
    ("ros2 bag record",
     "[ERROR] [ros2bag]: Need to specify at least one option out of --all, --all-topics or --topics"
     " (or topics: ros2 bag record /turtle1/cmd_vel /turtle1/pose)"),
    ("ros2 bag record -a -s sqlite3",
     "[ERROR] [ros2bag]: turtletui records with the mcap storage only, not sqlite3 (-s mcap)"),
    ("ros2 bag record -a -s db", "ros2 bag record: error: invalid choice: 'db' (choose from mcap, sqlite3)"),
    ("ros2 bag info nope", "ros2 bag info: error: argument bag_path: Bag path 'nope' does not exist!"),
    ("ros2 bag play nope", "ros2 bag play: error: argument bag_path: Bag path 'nope' does not exist!"),
    ("ros2 bag lay subset", "ros2 bag: error: invalid choice: 'lay' (did you mean 'play'?)"),
]


@pytest.mark.parametrize(("line", "message"), ERRORS)
def test_mistakes_are_one_line(term, line, message):
    out = term.run(line)
    assert out[1:] == [Line(message, "error")]
    assert term.foreground is None and term.jobs == []


def test_bad_bags_and_folders_are_one_line(sim, term):
    Path("taken").mkdir()
    assert texts(term.run("ros2 bag record -a -o taken"))[1:] == [
        "[ERROR] [ros2bag]: Output folder 'taken' already exists."]
    assert texts(term.run("ros2 bag info taken"))[1:] == [
        "ros2 bag info: taken: no .mcap file in this folder (not a rosbag2 bag with the mcap storage)"]
    Path("broken").mkdir()
    Path("broken/broken_0.mcap").write_bytes(b"\x89MCAP0\r\n cut short")
    for verb in ("info", "play"):
        out = term.run(f"ros2 bag {verb} broken")
        assert out[1].kind == "error" and out[1].text.startswith(f"ros2 bag {verb}: broken") and len(out) == 2
    assert texts(term.run("ros2 bag play -r 0 taken"))[1:] == [
        "ros2 bag play: error: argument -r/--rate: 0 is not in the valid range (> 0.0)"]
    assert node_names(sim) == ["turtlesim"]


def test_a_typo_in_a_topic_to_record_is_pointed_out(sim, term):
    out = texts(term.run("ros2 bag record /turtle1/pos -o typo"))
    assert out[1] == ("[WARN] [ros2bag]: '/turtle1/pos' is not published yet: it is recorded once it is"
                      " (did you mean /turtle1/pose?)")
    term.interrupt()


def test_a_graph_without_a_simulation_cannot_record():
    cli = Ros2Cli(Simulation().graph)
    result = cli.run("ros2 bag record -a")
    assert result.error and result.lines == ["ros2 bag record: needs a simulation (this console only has a graph)"]
