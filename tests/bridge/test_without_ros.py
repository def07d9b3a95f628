"""What --ros does where there is no ROS 2, and the interface files the
real-ROS environment is built from (no real ROS 2 needed here)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from turtletui.bridge.process import RosUnavailable, candidate_pythons, start_twin
from turtletui.interfaces import turtlesim

INTERFACES = Path(__file__).resolve().parents[2] / "scripts" / "real_ros" / "interfaces"


def test_interface_files_are_turtletuis_own_definitions_byte_for_byte() -> None:
    written = sorted(p.relative_to(INTERFACES).as_posix() for p in INTERFACES.rglob("*.*"))
    expected = []
    for name in turtlesim.__all__:
        cls = getattr(turtlesim, name)
        _, kind, short = cls._TYPE_NAME.split("/")
        path = f"{kind}/{short}.{kind}"
        expected.append(path)
        assert (INTERFACES / path).read_bytes() == cls._DEFINITION.encode(), path
    assert written == sorted(expected)


def test_a_python_without_rclpy_is_one_line_saying_how_to_source_ros(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text("def main():\n    pass\n")
    done = subprocess.run(
        [sys.executable, "-m", "turtletui", "run", str(node), "--headless", "--ros", "--ros-python", sys.executable],
        capture_output=True, text=True, timeout=120,
    )
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("turtletui: error: no ROS 2 here (")
    assert "cannot import rclpy" in lines[0] and "source /opt/ros/" in lines[0] and "--ros-python" in lines[0]


def test_a_missing_ros_python_is_named() -> None:
    with pytest.raises(RosUnavailable, match="--ros-python /no/such/python: no such program"):
        candidate_pythons("/no/such/python")


def test_the_environment_variable_names_the_ros_python(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("TURTLETUI_ROS_PYTHON", sys.executable)
    assert candidate_pythons() == [sys.executable]
    with pytest.raises(RosUnavailable, match="cannot import rclpy"):
        start_twin()


def test_ros_options_that_mean_nothing_on_a_real_graph_are_refused(tmp_path: Path) -> None:
    for extra, word in ((["--in-process"], "--in-process"), (["--record", str(tmp_path / "r.mcap")], "ros2 bag"),
                        (["--foxglove", "127.0.0.1:8765"], "foxglove_bridge"),
                        (["--distro", "humble"], "its own distro")):
        done = subprocess.run(
            [sys.executable, "-m", "turtletui", "run", "--headless", "--ros", *extra],
            capture_output=True, text=True, timeout=60,
        )
        assert done.returncode == 2 and word in done.stderr, done.stderr
    done = subprocess.run([sys.executable, "-m", "turtletui", "run", "--headless", "--ros-python", "python3"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "--ros-python goes with --ros" in done.stderr


def test_sim_ros_without_ros_2_is_one_line_saying_how_to_source_it() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "turtletui", "sim", "--ros", "--headless", "--ros-python", sys.executable],
        capture_output=True, text=True, timeout=120,
    )
    assert done.returncode == 2 and done.stdout == ""
    [line] = done.stderr.strip().splitlines()
    assert line.startswith("turtletui: error: no ROS 2 here (") and "source /opt/ros/" in line
    done = subprocess.run([sys.executable, "-m", "turtletui", "sim", "--headless", "--ros-python", "python3"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "--ros-python goes with --ros" in done.stderr
