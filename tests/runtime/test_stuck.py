"""Reading where a stuck controller is from its faulthandler dump
(turtletui.runtime.stuck): the end-to-end runs are in test_sandbox.py."""

from __future__ import annotations

from pathlib import Path

from turtletui.runtime import stuck

RUNTIME = Path(stuck.__file__).resolve().parent


def test_the_busy_thread_s_innermost_frame_of_the_controller_file_is_named(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text("import rclpy\n\ndef on_pose(msg):\n    while True:\n        step(msg)\n")
    dump = (
        # a thread of the controller waiting for its turn: not the one stuck
        f"Thread 0x00007f01 (most recent call first):\n"
        f'  File "{RUNTIME}/scheduler.py", line 120 in wait\n'
        f'  File "{node}", line 3 in on_pose\n'
        "\n"
        f"Current thread 0x00007f02 (most recent call first):\n"
        f'  File "/usr/lib/python3.11/json/encoder.py", line 200 in encode\n'
        f'  File "{node}", line 5 in on_pose\n'
        f'  File "{node}", line 4 in outer\n'
    )
    assert stuck.stuck_frame(dump, node) == [f'  File "{node}", line 5, in on_pose\n    step(msg)']


def test_a_dump_with_nothing_of_the_controller_or_garbage_names_nothing(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text("x = 1\n")
    waiting = f'Current thread 0x1 (most recent call first):\n  File "{RUNTIME}/child.py", line 90 in exchange\n'
    assert stuck.stuck_frame(waiting, node) == []
    assert stuck.stuck_frame(f'  File "{node}", line x in f\n\0\xff garbage', node) == []
    assert stuck.stuck_frame("", node) == []
