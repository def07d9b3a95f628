"""The record (``--record FILE.jsonl``, README "The record"): strict JSON Lines
of topic messages, log lines and service calls in simulated seconds, written
to a temporary name and renamed when the run ends."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import textwrap
from collections import Counter
from pathlib import Path
from typing import Any

import pytest

import turtletui
from turtletui.api import run
from turtletui.runtime.recorder import Recorder
from turtletui.runtime.simulation import Simulation

PACKAGE_ROOT = Path(turtletui.__file__).resolve().parents[1]
REFERENCE = Path(__file__).resolve().parents[2] / "plugins" / "reference"
PEN_CONTROLLER = REFERENCE / "turtle_controller_pen.py"
POSE_PERIOD = 0.016  # s: turtlesim publishes the pose every update (62.5 Hz)


def refuse_constant(name: str) -> Any:
    raise ValueError(f"not strict JSON: {name}")


def read_record(path: Path) -> list[dict[str, Any]]:
    """Every line, parsed strictly (NaN / Infinity refused)."""
    text = path.read_text(encoding="utf-8")
    assert text.endswith("\n")
    return [json.loads(line, parse_constant=refuse_constant) for line in text.splitlines()]


def write(folder: Path, name: str, source: str) -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(source).lstrip(), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def pen_record(tmp_path_factory) -> tuple[Path, list[dict[str, Any]]]:
    """The pen controller (calls /turtle1/set_pen), recorded by the CLI, sandboxed."""
    folder = tmp_path_factory.mktemp("record")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(PACKAGE_ROOT), env.get("PYTHONPATH")) if p)
    proc = subprocess.run(
        [sys.executable, "-m", "turtletui", "run", str(PEN_CONTROLLER), "--headless",
         "--duration", "3", "--quiet", "--record", "run.jsonl"],
        cwd=folder, env=env, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60,
    )
    assert proc.returncode == 0, proc.stderr
    return folder, read_record(folder / "run.jsonl")


def kind(event: dict[str, Any]) -> str:
    kinds = {"topic", "log", "service"} & event.keys()
    assert len(kinds) == 1, event
    return kinds.pop()


def test_every_line_is_one_of_the_three_documented_kinds(pen_record):
    _, events = pen_record
    shapes = {
        "topic": {"t", "topic", "type", "msg"},
        "log": {"t", "log"},
        "service": {"t", "service", "request", "response"},
    }
    counts = Counter(kind(e) for e in events)
    assert counts["topic"] > 100 and counts["log"] >= 3 and counts["service"] >= 1, counts
    for event in events:
        assert set(event) == shapes[kind(event)], event


def test_t_is_simulated_seconds(pen_record):
    _, events = pen_record
    times = [e["t"] for e in events]
    assert all(isinstance(t, (int, float)) for t in times)
    assert times == sorted(times)
    assert times[0] == 0.0
    assert 2.9 < times[-1] <= 3.0  # a 3 s simulated run, whatever the wall time
    for event in events:
        if event.get("topic") == "/turtle1/pose":
            steps = event["t"] / POSE_PERIOD
            assert abs(steps - round(steps)) < 1e-6, event["t"]


def test_topic_messages_are_nested_dicts_with_ros_type_names(pen_record):
    _, events = pen_record
    twists = [e for e in events if e.get("topic") == "/turtle1/cmd_vel"]
    assert twists, "the controller's commands are recorded"
    first = twists[0]
    assert first["type"] == "geometry_msgs/msg/Twist"
    assert first["msg"] == {"linear": {"x": 5.0, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}
    pose = next(e for e in events if e.get("topic") == "/turtle1/pose")
    assert pose["type"] == "turtlesim/msg/Pose"
    assert set(pose["msg"]) == {"x", "y", "theta", "linear_velocity", "angular_velocity"}
    assert math.isclose(pose["msg"]["y"], 5.544444561004639)


def test_poses_at_62_5_hz_and_color_sensor_recorded(pen_record):
    _, events = pen_record
    poses_in_second_one = [e for e in events if e.get("topic") == "/turtle1/pose" and 1.0 <= e["t"] < 2.0]
    assert len(poses_in_second_one) in (62, 63)
    colors = [e for e in events if e.get("topic") == "/turtle1/color_sensor"]
    assert len(colors) > 100
    assert colors[0]["type"] == "turtlesim/msg/Color"
    assert set(colors[0]["msg"]) == {"r", "g", "b"}
    # Unpainted ground under the turtle at the start: turtlesim's pen image is transparent white.
    assert colors[0]["msg"] == {"r": 255, "g": 255, "b": 255}


def test_log_lines_include_turtlesim_start_and_the_controller(pen_record):
    _, events = pen_record
    logs = [e["log"] for e in events if "log" in e]
    for log in logs:
        assert set(log) == {"level", "node", "msg"}
    assert logs[0] == {"level": "INFO", "node": "turtlesim", "msg": "Starting turtlesim with node name /turtlesim"}
    assert {"level": "INFO", "node": "turtle_controller", "msg": "Turtle controller has been started."} in logs
    assert {"level": "INFO", "node": "turtle_controller", "msg": "Set color to red!"} in logs


def test_service_calls_have_request_and_response(pen_record):
    _, events = pen_record
    calls = [e for e in events if "service" in e]
    assert calls
    first = calls[0]
    assert first["service"] == "/turtle1/set_pen"
    assert first["request"] == {"r": 255, "g": 0, "b": 0, "width": 3, "off": 0}
    assert first["response"] == {}
    said_red = next(e["t"] for e in events if "log" in e and e["log"]["msg"] == "Set color to red!")
    assert first["t"] >= said_red


def test_no_temporary_file_is_left_beside_the_record(pen_record):
    folder, _ = pen_record
    assert sorted(p.name for p in folder.iterdir()) == ["run.jsonl"]


def test_non_finite_floats_are_strings_and_the_file_stays_strict_json(tmp_path):
    node = write(tmp_path, "weird.py", """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import Float64


        def main():
            rclpy.init()
            node = Node("weird")
            pub = node.create_publisher(Float64, "/weird", 10)
            rclpy.spin_once(node, timeout_sec=0.1)  # discovered (by the recorder too) after 50 ms
            for value in (float("inf"), float("-inf"), float("nan"), 1.5):
                pub.publish(Float64(data=value))
            node.get_logger().info("sent")
            rclpy.spin_once(node, timeout_sec=0.1)
            rclpy.shutdown()
    """)
    record = tmp_path / "weird.jsonl"
    run([node], duration=0.5, sandbox=False, record=record)
    raw = record.read_text(encoding="utf-8")
    assert "Infinity" not in raw and "NaN" not in raw
    values = [e["msg"]["data"] for e in read_record(record) if e.get("topic") == "/weird"]
    assert values == ["inf", "-inf", "nan", 1.5]


def test_the_record_appears_only_when_the_run_ends(tmp_path):
    """While the run goes on, the final name does not exist yet; afterwards only it does."""
    record = tmp_path / "out" / "run.jsonl"
    record.parent.mkdir()
    node = write(tmp_path, "peek.py", f"""
        import os

        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("peek")
            rclpy.spin_once(node, timeout_sec=0.5)
            node.get_logger().info(f"exists={{os.path.exists({str(record)!r})}}")
            node.get_logger().info(f"files={{len(os.listdir({str(record.parent)!r}))}}")
            rclpy.shutdown()
    """)
    result = run([node], duration=1.0, sandbox=False, record=record)
    said = [r.msg for r in result.logs if r.node == "peek"]
    assert said == ["exists=False", "files=1"]  # only the temporary file, under another name
    assert [p.name for p in record.parent.iterdir()] == ["run.jsonl"]
    logs = [e["log"]["msg"] for e in read_record(record) if "log" in e]
    assert "exists=False" in logs


def test_recorder_writes_under_a_temporary_name_until_closed(tmp_path):
    sim = Simulation()
    record = tmp_path / "direct.jsonl"
    recorder = Recorder(sim.graph, record)
    sim.run_until(500_000_000)
    assert not record.exists()
    assert len(list(tmp_path.iterdir())) == 1  # the temporary file, under another name
    recorder.close(keep=True)
    assert [p.name for p in tmp_path.iterdir()] == ["direct.jsonl"]
    poses = [e for e in read_record(record) if e.get("topic") == "/turtle1/pose"]
    assert len(poses) == 30  # 0.032 s ... 0.496 s, every 16 ms


def test_a_dropped_record_leaves_nothing(tmp_path):
    sim = Simulation()
    recorder = Recorder(sim.graph, tmp_path / "dropped.jsonl")
    sim.run_until(100_000_000)
    recorder.close(keep=False)
    assert list(tmp_path.iterdir()) == []


def test_a_crashed_run_is_still_recorded_with_the_crash(tmp_path):
    node = write(tmp_path, "crasher.py", """
        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("crasher")
            node.create_timer(0.25, lambda: 1 / 0)
            rclpy.spin(node)
    """)
    record = tmp_path / "crash.jsonl"
    result = run([node], duration=1.0, sandbox=False, record=record)
    assert len(result.crashes) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["crash.jsonl", "crasher.py"]
    errors = [e for e in read_record(record) if "log" in e and e["log"]["level"] == "ERROR"]
    assert errors and errors[0]["t"] == 0.25
    assert errors[0]["log"]["node"] == "turtletui"
    assert "ZeroDivisionError" in errors[0]["log"]["msg"]


def test_same_run_gives_the_same_record(tmp_path):
    records = []
    for name in ("a.jsonl", "b.jsonl"):
        run([PEN_CONTROLLER], duration=2.0, sandbox=False, record=tmp_path / name)
        records.append((tmp_path / name).read_bytes())
    assert records[0] == records[1]
    assert len(records[0]) > 10_000
