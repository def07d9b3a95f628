"""``turtletui run`` as a user runs it: ``python -m turtletui`` in a subprocess,
judged by exit status, stdout and stderr (README, "Running nodes")."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import turtletui

PACKAGE_ROOT = Path(turtletui.__file__).resolve().parents[1]

ROS_LINE = re.compile(r"^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[\d{10}\.\d{9}\] \[[\w/]+\]: ")
SUMMARY = re.compile(
    r"^sim time (?P<sim>\d+\.\d{3}) s, wall time (?P<wall>\d+\.\d{3}) s, "
    r"distance (?P<distance>\d+\.\d{2}) m, wall hits (?P<hits>\d+): (?P<status>.+)$"
)

PARAM_NODE = """
import rclpy
from rclpy.node import Node


class ParamNode(Node):
    def __init__(self):
        super().__init__("param_node")
        self.declare_parameter("speed", 1.0)
        self.get_logger().info(f"speed={self.get_parameter('speed').value!r}")


def main():
    rclpy.init()
    node = ParamNode()
    rclpy.spin(node)
    rclpy.shutdown()
"""

CRASHING_NODE = """
import rclpy
from rclpy.node import Node


class Crasher(Node):
    def __init__(self):
        super().__init__("crasher")
        self.create_timer(0.5, self.tick)

    def tick(self):
        raise ValueError("boom at half a second")


def main():
    rclpy.init()
    rclpy.spin(Crasher())
"""


def turtletui_cli(*args: str, cwd: Path, timeout: float = 60) -> subprocess.CompletedProcess[str]:
    """``python -m turtletui ARGS`` with no terminal, as CI and pipes run it."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(PACKAGE_ROOT), env.get("PYTHONPATH")) if p)
    return subprocess.run(
        [sys.executable, "-m", "turtletui", *args],
        cwd=cwd,
        env=env,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def write(folder: Path, name: str, source: str) -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(source).lstrip(), encoding="utf-8")
    return path


def assert_one_line_error(proc: subprocess.CompletedProcess[str], code: int = 2) -> str:
    assert proc.returncode == code, (proc.returncode, proc.stdout, proc.stderr)
    assert "Traceback" not in proc.stderr and "Traceback" not in proc.stdout
    # log lines of nodes that ran before the error was found go to stderr first, as under ROS
    lines = [line for line in proc.stderr.splitlines() if not ROS_LINE.match(line)]
    assert len(lines) == 1, proc.stderr
    assert lines[0].startswith("turtletui: error: "), lines[0]
    assert proc.stderr.endswith(lines[0] + "\n")
    return lines[0]


# -- the default run: the course's Part 6 controller ---------------------------


@pytest.fixture(scope="module")
def default_runs(tmp_path_factory) -> list[subprocess.CompletedProcess[str]]:
    cwd = tmp_path_factory.mktemp("default")
    return [turtletui_cli("run", "--headless", "--duration", "5", cwd=cwd) for _ in range(2)]


def test_default_run_prints_turtlesim_start_lines_in_ros_format(default_runs):
    proc = default_runs[0]
    assert proc.returncode == 0, proc.stderr
    # as under ROS, log lines go to stderr; stdout has only the summary
    assert len(proc.stdout.splitlines()) == 1
    lines = proc.stderr.splitlines()
    assert lines[0] == "[INFO] [1700000000.000000000] [turtlesim]: Starting turtlesim with node name /turtlesim"
    assert lines[1].startswith("[INFO] [1700000000.000000000] [turtlesim]: Spawning turtle [turtle1] at x=[5.544445]")
    assert (
        "[INFO] [1700000000.000000000] [turtle_controller]: "
        "Turtle autonomous driving controller has started! (Collision Avoidance Mode)"
    ) in lines
    # The controller reacts to the wall: its warning appears, stamped in lockstep time.
    assert any(line.endswith("[turtle_controller]: Warning: Approaching wall detected! Changing direction.") for line in lines)
    for line in lines:
        assert ROS_LINE.match(line), line


def test_default_run_ends_with_one_summary_line(default_runs):
    lines = default_runs[0].stdout.splitlines()
    summary = SUMMARY.match(lines[-1])
    assert summary, lines[-1]
    assert summary["sim"] == "5.000"
    assert summary["hits"] == "0"
    assert summary["status"] == "ok"
    assert float(summary["distance"]) > 5.0  # it drove
    assert sum(1 for line in lines if SUMMARY.match(line)) == 1


def test_default_run_repeats_bit_for_bit_apart_from_wall_time(default_runs):
    first, second = (re.sub(r"wall time \d+\.\d{3} s", "wall time X s", p.stdout) for p in default_runs)
    assert first.count("wall time X s") == 1
    assert first == second


# -- controller files ------------------------------------------------------------


@pytest.mark.parametrize("mode", [[], ["--in-process"]], ids=["sandboxed", "in-process"])
def test_ros_args_parameter_reaches_a_controller_file(tmp_path, mode):
    write(tmp_path, "param_node.py", PARAM_NODE)
    proc = turtletui_cli(
        "run", "param_node.py", "--headless", "--duration", "1", *mode, "--ros-args", "-p", "speed:=2.0",
        cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    assert "[INFO] [1700000000.000000000] [param_node]: speed=2.0" in proc.stderr.splitlines()
    assert SUMMARY.match(proc.stdout.splitlines()[-1])


def test_controller_file_without_ros_args_keeps_its_default(tmp_path):
    write(tmp_path, "param_node.py", PARAM_NODE)
    proc = turtletui_cli("run", "param_node.py", "--headless", "--duration", "1", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert "[param_node]: speed=1.0" in proc.stderr


def test_malformed_ros_args_is_a_one_line_error(tmp_path):
    write(tmp_path, "param_node.py", PARAM_NODE)
    proc = turtletui_cli(
        "run", "param_node.py", "--headless", "--duration", "1", "--ros-args", "-p", "speed", cwd=tmp_path
    )
    line = assert_one_line_error(proc)
    assert "speed" in line
    assert "sim time" not in proc.stdout


def bad_inputs(folder: Path) -> dict[str, tuple[str, list[str]]]:
    """name -> (file argument, words the error must show)."""
    (folder / "a_folder").mkdir()
    (folder / "binary.py").write_bytes(b"\x7fELF\x00\x01\x02\x00")
    write(folder, "broken.py", "import rclpy\n\ndef main(:\n    pass\n")
    write(folder, "no_entry.py", "import rclpy\n\nSPEED = 2.0\n")
    return {
        "missing": ("missing_node.py", ["missing_node.py"]),
        "folder": ("a_folder", ["a_folder", "folder"]),
        "binary": ("binary.py", ["binary.py", "binary"]),
        "syntax": ("broken.py", ["broken.py:3", "def main(:"]),
        "no-main": ("no_entry.py", ["no_entry.py", "main"]),
    }


@pytest.mark.parametrize("mode", [[], ["--in-process"]], ids=["sandboxed", "in-process"])
@pytest.mark.parametrize("case", ["missing", "folder", "binary", "syntax", "no-main"])
def test_bad_controller_file_is_a_one_line_error(tmp_path, case, mode):
    argument, words = bad_inputs(tmp_path)[case]
    proc = turtletui_cli("run", argument, "--headless", "--duration", "1", *mode, cwd=tmp_path)
    line = assert_one_line_error(proc)
    for word in words:
        assert word in line, line


@pytest.mark.parametrize("mode", [[], ["--in-process"]], ids=["sandboxed", "in-process"])
def test_crashing_controller_exits_1_with_summary_and_its_own_file_and_line(tmp_path, mode):
    path = write(tmp_path, "crasher.py", CRASHING_NODE)
    raise_line = 1 + path.read_text().splitlines().index('        raise ValueError("boom at half a second")')
    proc = turtletui_cli("run", "crasher.py", "--headless", "--duration", "2", *mode, cwd=tmp_path)
    assert proc.returncode == 1, (proc.stdout, proc.stderr)
    summary = SUMMARY.match(proc.stdout.splitlines()[-1])
    assert summary and summary["sim"] == "2.000", proc.stdout
    assert summary["status"] == "1 controller(s) failed"
    assert "Traceback" not in proc.stderr
    assert proc.stderr.count("ValueError: boom at half a second") == 1  # said once, as the log had it
    assert "t=0.500 s" in proc.stderr
    assert f'File "{path.resolve()}", line {raise_line}, in tick' in proc.stderr
    assert 'raise ValueError("boom at half a second")' in proc.stderr
    # Only the student's own frames: nothing of turtletui's internals.
    assert "turtletui/" not in proc.stderr.replace(str(tmp_path), "")
    # --quiet prints no log, and still says why the run failed, once
    quiet = turtletui_cli("run", "crasher.py", "--headless", "--duration", "2", "-q", *mode, cwd=tmp_path)
    assert quiet.returncode == 1 and quiet.stderr.count("ValueError: boom at half a second") == 1, quiet.stderr
    assert f'File "{path.resolve()}", line {raise_line}, in tick' in quiet.stderr


def test_duration_must_be_positive(tmp_path):
    assert_one_line_error(turtletui_cli("run", "--headless", "--duration", "0", cwd=tmp_path))


# -- no terminal -------------------------------------------------------------------


@pytest.mark.parametrize("args", [[], ["node.py"]], ids=["default", "file"])
def test_without_terminal_and_headless_says_how_to_run_headless(tmp_path, args):
    write(tmp_path, "node.py", PARAM_NODE)
    proc = turtletui_cli("run", *args, cwd=tmp_path, timeout=120)
    line = assert_one_line_error(proc)
    assert "--headless" in line
    assert proc.stdout == ""


# -- --record errors -----------------------------------------------------------------


def test_unwritable_record_path_is_a_one_line_error(tmp_path):
    proc = turtletui_cli(
        "run", "--headless", "--duration", "1", "--record", "/nonexistent/dir/x.jsonl", cwd=tmp_path
    )
    line = assert_one_line_error(proc)
    assert "/nonexistent/dir/x.jsonl" in line
    assert "sim time" not in proc.stdout


def test_record_path_that_is_a_folder_is_refused_and_leaves_nothing(tmp_path):
    (tmp_path / "records").mkdir()
    proc = turtletui_cli("run", "--headless", "--duration", "1", "--record", "records", cwd=tmp_path)
    assert "records" in assert_one_line_error(proc)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["records"]
    assert list((tmp_path / "records").iterdir()) == []


@pytest.mark.parametrize("name", ["run.txt", "run"])
def test_a_record_name_that_says_no_format_is_refused_with_the_names_that_do(tmp_path, name):
    proc = turtletui_cli("run", "--headless", "--duration", "1", "--record", name, cwd=tmp_path)
    line = assert_one_line_error(proc)
    assert f"{name}: cannot tell which kind of recording" in line
    assert "run.jsonl" in line and "run.mcap" in line and "run/" in line
    assert list(tmp_path.iterdir()) == []


def test_a_record_name_in_capitals_is_the_format_it_names(tmp_path):
    proc = turtletui_cli("run", "--headless", "--duration", "1", "-q", "--record", "RUN.MCAP", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "RUN.MCAP").read_bytes()[:8] == b"\x89MCAP0\r\n"
    replayed = turtletui_cli("replay", "RUN.MCAP", "--headless", "-q", cwd=tmp_path)
    assert replayed.returncode == 0, replayed.stderr


# -- the command line itself -----------------------------------------------------


def test_help_lists_the_commands(tmp_path):
    proc = turtletui_cli("--help", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert "run" in proc.stdout and "plugins" in proc.stdout


def test_closed_stdout_ends_quietly(tmp_path):
    """``turtletui run node.py --headless | head -1``: no error message about the pipe."""
    write(tmp_path, "chatty.py", (
        "import rclpy\nfrom rclpy.node import Node\n\n\ndef main():\n    rclpy.init()\n"
        "    node = Node('chatty')\n    node.create_timer(0.01, lambda: print('tick', flush=True))\n"
        "    rclpy.spin(node)\n"
    ))
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(PACKAGE_ROOT), env.get("PYTHONPATH")) if p)
    proc = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "run", "chatty.py", "--headless", "--duration", "300"],
        cwd=tmp_path,
        env=env,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None and proc.stderr is not None
    assert proc.stdout.readline() == "tick\n"
    proc.stdout.close()
    stderr = proc.stderr.read()
    assert proc.wait(timeout=30) != 0
    assert "Traceback" not in stderr
    assert "error" not in stderr.lower(), stderr


@pytest.mark.parametrize("host", [[], ["--in-process"]], ids=["sandboxed", "in-process"])
def test_prints_go_to_stdout_and_logs_to_stderr_as_with_rclpy(tmp_path, host):
    node = tmp_path / "talker.py"
    node.write_text(
        "import rclpy\nfrom rclpy.node import Node\n\n\ndef main():\n    rclpy.init()\n"
        "    node = Node('talker')\n    print('printed')\n    node.get_logger().warning('logged')\n"
        "    rclpy.shutdown()\n"
    )
    proc = turtletui_cli("run", str(node), "--headless", "--duration", "0.5", *host, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    out = proc.stdout.splitlines()
    assert out[0] == "printed" and SUMMARY.match(out[1]) and len(out) == 2
    assert "[WARN] [1700000000.000000000] [talker]: logged" in proc.stderr.splitlines()
    assert "printed" not in proc.stderr
