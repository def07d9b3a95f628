"""`turtletui replay RECORDING`: a failed grading scenario's recording (MCAP,
the default, or JSON Lines), played headless, drives the turtle along the
graded path again; a malformed recording is a one-line error naming the file
(and, for JSON Lines, the line). MCAP recordings are read back here with
mcap_ros2's decoder, not turtletui's code."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from support.grading import WALL_HITTER, grade_cli, make_class, one_line_error, write_lesson
from typer.testing import CliRunner

from turtletui.api import run
from turtletui.cli import app
from turtletui.runtime.replay import install_replay, read_recording

WALL_LOG = re.compile(r"Oh no! I hit the wall! \(Clamping from \[x=[-\d.]+, y=[-\d.]+\]\)")


def replay(*args: str | Path):
    return CliRunner().invoke(app, ["replay", *map(str, args)])


_GRADED: dict[str, tuple[dict, Path]] = {}


def _graded(tmp_path_factory: pytest.TempPathFactory, recording_format: str) -> tuple[dict, Path]:
    """A student whose visible scenario fails, graded by `turtletui grade`:
    their JSON result and the recording it kept (once per format)."""
    if recording_format not in _GRADED:
        tmp = tmp_path_factory.mktemp(f"replay_{recording_format}")
        lesson = write_lesson(tmp)
        klass = make_class(tmp / "class", {"ben": WALL_HITTER})
        options = ["--same-user", "-j", "1", "--format", "json"]
        if recording_format != "mcap":  # the default
            options += ["--recording-format", recording_format]
        result = grade_cli(klass, "--lesson", lesson, "--results", tmp / "results", *options)
        assert result.exit_code == 0, result.stderr
        (ben,) = json.loads(result.stdout)["submissions"]
        stored = json.loads((tmp / "results" / "ben.json").read_text())["result"]
        (recording,) = stored["recordings"]
        _GRADED[recording_format] = ben, Path(recording)
    return _GRADED[recording_format]


@pytest.fixture(scope="module", params=["mcap", "jsonl"])
def graded(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[dict, Path]:
    return _graded(tmp_path_factory, request.param)


@pytest.fixture(scope="module")
def graded_mcap(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict, Path]:
    return _graded(tmp_path_factory, "mcap")


@pytest.fixture(scope="module")
def graded_jsonl(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict, Path]:
    return _graded(tmp_path_factory, "jsonl")


def recorded_events(recording: Path) -> list[dict]:
    """The recording's events as JSON Lines has them (an MCAP file decoded by mcap_ros2)."""
    if recording.suffix == ".jsonl":
        return [json.loads(line) for line in recording.read_text().splitlines()]
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    events = []
    with recording.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        for _, channel, message, msg in reader.iter_decoded_messages(log_time_order=True):
            t = round((message.log_time - 1_700_000_000_000_000_000) / 1e9, 9)
            if channel.topic == "/rosout":
                events.append({"t": t, "log": {"msg": msg.msg}})
            elif channel.topic == "/turtle1/pose":
                events.append({"t": t, "topic": channel.topic, "msg": {"x": msg.x, "y": msg.y, "theta": msg.theta}})
    return events


def recorded_poses(recording: Path) -> list[tuple[float, float, float, float]]:
    poses = []
    for event in recorded_events(recording):
        if event.get("topic") == "/turtle1/pose":
            msg = event["msg"]
            poses.append((event["t"], msg["x"], msg["y"], msg["theta"]))
    return poses


def recorded_wall_logs(recording: Path) -> list[str]:
    return [
        f"{event['t']:.3f} {event['log']['msg']}"
        for event in recorded_events(recording)
        if "log" in event and WALL_LOG.fullmatch(event["log"]["msg"])
    ]


def test_headless_replay_drives_the_graded_path_again(graded: tuple[dict, Path]):
    ben, recording = graded
    assert recording.name in ("centre.mcap", "centre.jsonl")
    graded_hits = next(t["output"] for t in ben["tests"] if t["name"] == "wall_hits [centre]")
    hits = int(re.match(r"wall hits: (\d+)", graded_hits).group(1))
    assert hits >= 1

    result = replay(recording, "--headless")
    assert result.exit_code == 0, result.stderr
    assert result.stderr == (
        f"replaying {recording} (lesson tiny-walls, scenario centre; start 5.500, 5.500, 0.000; 3 s)\n"
    )
    lines = result.stdout.splitlines()
    summary = lines[-1]
    assert summary.startswith("sim time 3.000 s, ")
    assert f"wall hits {hits}: ok" in summary
    # the turtle meets the wall where and when it did in the graded run
    replayed_walls = [
        f"{float(m.group(1)) - 1700000000:.3f} {m.group(2)}"
        for m in (re.match(r"\[WARN\] \[([\d.]+)\] \[turtlesim\]: (.*)", line) for line in lines)
        if m and WALL_LOG.fullmatch(m.group(2))
    ]
    assert replayed_walls and replayed_walls == recorded_wall_logs(recording)

    quiet = replay(recording, "--headless", "--quiet")
    # the same summary but for the wall time it took
    without_wall_time = re.compile(r"wall time [\d.]+ s, ")
    assert quiet.exit_code == 0 and [without_wall_time.sub("", line) for line in quiet.stdout.splitlines()] == [
        without_wall_time.sub("", summary)
    ]


def test_the_replayed_trajectory_is_the_recorded_one_to_the_last_pose(graded: tuple[dict, Path]):
    _, recording = graded
    found = read_recording(recording)
    result = run(
        [], duration=found.duration, seed=int(found.header["seed"]), keep_poses=True,
        setup=lambda sim: install_replay(sim, found),
    )
    recorded = recorded_poses(recording)
    replayed = [(round(t, 9), x, y, theta) for t, x, y, theta in result.poses["turtle1"]]
    assert len(replayed) == len(recorded) > 100
    assert replayed[-1] == pytest.approx(recorded[-1], abs=1e-6)
    assert replayed == pytest.approx(recorded, abs=1e-6)
    assert result.turtles["turtle1"].wall_hits >= 1


def test_without_a_terminal_the_app_replay_says_to_use_headless(graded: tuple[dict, Path]):
    _, recording = graded
    stderr = one_line_error(replay(recording))
    assert "--headless" in stderr


def test_a_malformed_recording_is_a_one_line_error_naming_file_and_line(
    graded_jsonl: tuple[dict, Path], tmp_path: Path
):
    _, recording = graded_jsonl
    good = recording.read_text().splitlines()
    cases = {
        "not_json.jsonl": (good[:3] + ['{"t": 0.5, "topic": '] + good[3:], 4, "not a JSON line"),
        "no_time.jsonl": (good[:2] + ['{"topic": "/turtle1/cmd_vel"}'], 3, "field 't' must be a time"),
        "array.jsonl": (good[:5] + ["[1, 2, 3]"], 6, "expected a JSON object"),
        "bad_twist.jsonl": (
            good[:2]
            + ['{"t": 0.1, "topic": "/turtle1/cmd_vel", "type": "geometry_msgs/msg/Twist", "msg": {"linear": 5}}'],
            3,
            "cannot replay this topic event",
        ),
    }
    for name, (lines, number, words) in cases.items():
        path = tmp_path / name
        path.write_text("\n".join(lines) + "\n")
        stderr = one_line_error(replay(path, "--headless"))
        assert stderr.startswith(f"turtletui: error: {path}:{number}: {words}"), stderr
    stderr = one_line_error(replay(tmp_path / "missing.jsonl", "--headless"))
    assert f"{tmp_path / 'missing.jsonl'}: no such recording" in stderr
    binary = tmp_path / "binary.jsonl"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    stderr = one_line_error(replay(binary, "--headless"))
    assert str(binary) in stderr


def test_a_malformed_mcap_recording_is_a_one_line_error_naming_the_file(
    graded_mcap: tuple[dict, Path], tmp_path: Path
):
    _, recording = graded_mcap
    data = recording.read_bytes()
    cases = {
        "empty.mcap": b"",
        "garbage.mcap": b"\x89MCAP0\r\n" + b"\xff" * 64,
        "text.mcap": b"not an mcap file at all\n",
        "truncated.mcap": data[: len(data) // 2],
    }
    for name, content in cases.items():
        path = tmp_path / name
        path.write_bytes(content)
        stderr = one_line_error(replay(path, "--headless"))
        assert stderr.startswith(f"turtletui: error: {path}: "), stderr
    empty_folder = tmp_path / "not_a_bag"
    empty_folder.mkdir()
    stderr = one_line_error(replay(empty_folder, "--headless"))
    assert stderr.startswith(f"turtletui: error: {empty_folder}: no .mcap file"), stderr
