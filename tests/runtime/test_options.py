"""Runtime options travel in a frozen object (Limits), not in module globals
other modules overwrite: how long the two sides of a sandbox poll for each
other changes nothing in the run, fresh or forked, and setting it for one run
leaves the process as it was."""

from __future__ import annotations

import dataclasses
import os
import textwrap
from pathlib import Path

import pytest
from support.grading import write_lesson

from turtletui.api import run
from turtletui.grading import batch
from turtletui.runtime import forkserver, wire
from turtletui.runtime.sandbox import Limits

NODE = """
import random

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("driver")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)

    def tick():
        msg = Twist()
        msg.linear.x = 1.0 + random.random()
        msg.angular.z = random.uniform(-1.0, 1.0)
        pub.publish(msg)
        node.get_logger().info(f"turn {msg.angular.z:.6f}")

    node.create_timer(0.05, tick)
    rclpy.spin(node)
"""


def controller(folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "node.py"
    path.write_text(textwrap.dedent(NODE))
    return path


def test_limits_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        Limits().spin_seconds = 0.0  # type: ignore[misc]
    assert dataclasses.replace(Limits(), spin_seconds=0.0).spin_seconds == 0.0


@pytest.mark.parametrize("forked", [False, True], ids=["fresh", "forked"])
def test_polling_or_not_gives_the_same_run(tmp_path, forked):
    path = controller(tmp_path)
    runs = []
    for spin in (0.0, 0.001, None):
        if forked:
            with forkserver.serving():
                runs.append(run([path], duration=1.0, seed=7, keep_poses=True, limits=Limits(spin_seconds=spin)))
        else:
            runs.append(run([path], duration=1.0, seed=7, keep_poses=True, limits=Limits(spin_seconds=spin)))
    assert all(r.ok for r in runs), [r.crashes for r in runs]
    assert runs[0].poses == runs[1].poses == runs[2].poses
    assert runs[0].logs == runs[1].logs == runs[2].logs
    assert runs[0].distance > 1.0 and len(runs[0].logs) > 10


def test_the_default_reads_the_environment_when_a_run_starts(monkeypatch):
    """``$TURTLETUI_SPIN_SECONDS`` counts when a sandbox starts, not only when
    turtletui was imported (the app sets it before grading)."""
    monkeypatch.setenv(wire.SPIN_ENV, "0")
    assert wire.default_spin_seconds() == 0.0
    monkeypatch.setenv(wire.SPIN_ENV, "0.0005")
    assert wire.default_spin_seconds() == 0.0005
    monkeypatch.setenv(wire.SPIN_ENV, "not a number")
    assert wire.default_spin_seconds() == (0.0002 if wire.available_cpus() > 1 else 0.0)


def test_a_worker_on_shared_cpus_changes_its_limits_not_the_process(tmp_path, monkeypatch):
    """A grading worker whose runs share the CPUs stops polling through its own
    limits; nothing global (environment, modules) changes for other code."""
    lesson = write_lesson(tmp_path)
    monkeypatch.setattr(batch, "_worker", None)  # this process's worker setup, put back after
    environment = dict(os.environ)
    module_state = dict(vars(wire))
    with forkserver.serving():  # set_up_worker would start this process's fork servers
        plan = batch.set_up_worker(str(lesson), [], Limits(cpu_seconds=30), shared_cpus=True)
        student, outcome, _ = batch.run_task("ann", str(controller(tmp_path / "ann")), 0, None, "mcap")
    assert plan.lesson.path == lesson
    assert student == "ann" and outcome.tests, outcome
    assert dict(os.environ) == environment
    assert vars(wire) == module_state


PIPES = """
import os

import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("pipes")

    def look():
        blocking = []
        for fd in range(3, 64):
            try:
                if os.readlink(f"/proc/self/fd/{fd}").startswith("pipe:"):
                    blocking.append(os.get_blocking(fd))
            except OSError:
                pass
        node.get_logger().info(f"blocking {sorted(set(blocking))}")

    node.create_timer(0.1, look)
    rclpy.spin(node)
"""


@pytest.mark.skipif(not os.path.isdir("/proc/self/fd"), reason="reads /proc (Linux)")
@pytest.mark.parametrize("forked", [False, True], ids=["fresh", "forked"])
def test_the_child_polls_its_pipe_only_when_told(tmp_path, forked):
    """A reader that polls makes its pipe non-blocking (wire.FrameReader): what
    the controller's process shows of its pipe follows the run's limits."""
    path = tmp_path / "pipes.py"
    path.write_text(textwrap.dedent(PIPES))

    def pipes(spin: float) -> str:
        if forked:
            with forkserver.serving():
                result = run([path], duration=0.15, limits=Limits(spin_seconds=spin))
        else:
            result = run([path], duration=0.15, limits=Limits(spin_seconds=spin))
        [line] = [record.msg for record in result.logs if record.node == "pipes"]
        return line

    assert pipes(0.0) == "blocking [True]"
    assert pipes(0.001) == "blocking [False, True]"
