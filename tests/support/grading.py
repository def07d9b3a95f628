"""Shared pieces of the batch-grading tests: a tiny lesson written to a temporary
folder (two 3 s scenarios, one of them hidden) and small controllers, honest
and otherwise, to put in a class folder.

tests/grading/conftest.py makes ``lesson`` a fixture; tests/cli uses them too.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from collections.abc import Iterable
from pathlib import Path

from typer.testing import CliRunner

import turtletui
from turtletui.cli import app

REPO = Path(turtletui.__file__).resolve().parents[1]
LESSON_ID = "tiny-walls"
HIDDEN_NAME = "secret corner"
HIDDEN_START = (3.25, 2.75, 1.125)
"""The hidden scenario's start: no report may mention these numbers or its name."""

TINY_LESSON = f"""+++
id = "{LESSON_ID}"
title = "Tiny lesson for grading tests"
world = "empty"

[[scenarios]]
name = "centre"
start = {{x = 5.5, y = 5.5, theta = 0.0}}
duration = 3.0

[[scenarios]]
name = "{HIDDEN_NAME}"
start = {{x = {HIDDEN_START[0]}, y = {HIDDEN_START[1]}, theta = {HIDDEN_START[2]}}}
duration = 3.0
hidden = true

[[checks]]
name = "wall_hits"
weight = 2.0
thresholds = {{max = 0}}
feedback = "The turtle touched a wall: turn earlier."

[[checks]]
name = "no_crash"
weight = 1.0
+++
# Tiny lesson

Drive for three seconds without touching a wall.
"""
MAX_SCORE = 3.0

_HEADER = """\
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
"""

HONEST = (
    _HEADER
    + '''

class Avoider(Node):
    """Full speed in the open, a slow turn near a wall: passes every check."""

    def __init__(self):
        super().__init__("avoider")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Avoider())
'''
)

WALL_HITTER = (
    _HEADER
    + '''

class Curver(Node):
    """A gentle left curve, too fast: it meets the wall from the centre (at
    about 1.5 s) and from the hidden start (at about 2.2 s), so it fails
    wall_hits in both scenarios with time to spare, whenever discovery lets
    its first commands through."""

    def __init__(self):
        super().__init__("curver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        cmd = Twist()
        cmd.linear.x = 4.0
        cmd.angular.z = 0.4 if pose.y < 9.5 else 0.0
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Curver())
'''
)

CRASH_WITH_POSE = (
    _HEADER
    + '''

class Leaker(Node):
    """Crashes on its first pose with the pose in the message: a hidden
    scenario's feedback must not pass it on."""

    def __init__(self):
        super().__init__("leaker")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        raise RuntimeError(f"start was x={pose.x:.4f} y={pose.y:.4f} theta={pose.theta:.4f}")


def main():
    rclpy.init()
    rclpy.spin(Leaker())
'''
)

SYNTAX_ERROR = "def main(:\n    pass\n"


def sleeper(seconds: float) -> str:
    """A controller that passes and takes ``seconds`` of wall time on its first
    pose (inside the step timeout): makes a batch slow enough to interrupt.
    (Sleeps and waits are simulated time in the sandbox; a socket's timeout
    is wall time.)"""
    return HONEST.replace(
        "    def on_pose(self, pose):\n",
        f"    def on_pose(self, pose):\n        if not hasattr(self, 'slept'):\n"
        f"            self.slept = True\n"
        f"            waiting, _ = __import__('socket').socketpair()\n"
        f"            waiting.settimeout({seconds})\n"
        f"            try:\n                waiting.recv(1)\n            except OSError:\n                pass\n",
        1,
    )


def write_lesson(folder: Path) -> Path:
    """The tiny lesson's file, written in ``folder``/lesson."""
    path = folder / "lesson" / "tiny_walls.md"
    path.parent.mkdir()
    path.write_text(TINY_LESSON, encoding="utf-8")
    return path


def make_class(root: Path, students: dict[str, str | bytes]) -> Path:
    """A class folder: one subfolder per student holding ``controller.py``."""
    root.mkdir(parents=True, exist_ok=True)
    for name, source in students.items():
        folder = root / name
        folder.mkdir()
        target = folder / "controller.py"
        if isinstance(source, bytes):
            target.write_bytes(source)
        else:
            target.write_text(source, encoding="utf-8")
    return root


def grade_cli(*args: str | Path, env: dict[str, str] | None = None):
    """``turtletui grade ARGS`` in this process (typer's CliRunner); stderr apart."""
    return CliRunner().invoke(app, ["grade", *map(str, args)], env=env)


def grade_subprocess(*args: str | Path, **popen) -> subprocess.Popen:
    """``python -m turtletui grade ARGS`` in a child process."""
    env = dict(os.environ, PYTHONPATH=str(REPO))
    return subprocess.Popen(
        [sys.executable, "-m", "turtletui", "grade", *map(str, args)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        **popen,
    )


def one_line_error(result, code: int = 2) -> str:
    """The CLI failed with ``code`` and one ``turtletui: error:`` line, no traceback."""
    assert result.exit_code == code, (result.exit_code, result.stdout, result.stderr)
    assert result.stderr.startswith("turtletui: error: "), result.stderr
    assert result.stderr.count("\n") == 1, result.stderr
    assert "Traceback" not in result.stdout + result.stderr
    return result.stderr


def stored_results(folder: Path) -> dict[str, dict]:
    """Student -> the result the grader keeps for them (each file must parse)."""
    return {p.stem: json.loads(p.read_text(encoding="utf-8"))["result"] for p in sorted(folder.glob("*.json"))}


def sandbox_processes(marks: Iterable[str | Path]) -> list[str]:
    """Live processes started for the students under ``marks`` (their folders):
    the sandbox child names its controller's path in its command line, and
    whatever the controller starts inherits its working folder."""
    found = []
    me = os.getpid()
    marks = [str(m) for m in marks]
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == me:
            continue
        try:
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                cmdline = f.read().replace(b"\0", b" ").decode("utf-8", "replace")
            with open(f"/proc/{entry}/stat", "rb") as f:
                state = f.read().rpartition(b")")[2].split()[0]
            cwd = os.readlink(f"/proc/{entry}/cwd")
        except OSError:
            continue
        if state == b"Z":
            continue  # a zombie runs nothing: it waits for its parent to reap it
        if any(m in cmdline or cwd.startswith(m) for m in marks):
            found.append(f"{entry} (in {cwd}): {cmdline[:200]}")
    return found


def wait_until_gone(marks: Iterable[str], seconds: float = 30.0) -> list[str]:
    """The processes of :func:`sandbox_processes` still there after ``seconds``."""
    deadline = time.monotonic() + seconds
    while True:
        left = sandbox_processes(marks)
        if not left or time.monotonic() > deadline:
            return left
        time.sleep(0.1)
