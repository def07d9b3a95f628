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


def test_a_helper_module_of_the_student_s_package_is_named_but_installed_and_outside_files_are_not(
    tmp_path: Path,
) -> None:
    package = tmp_path / "my_robot_controller"
    package.mkdir()
    (package / "__init__.py").write_text("")
    node = package / "turtle_controller.py"
    node.write_text("from my_robot_controller import helpers\n\ndef tick():\n    helpers.spin()\n")
    helpers = package / "helpers.py"
    helpers.write_text("def spin():\n    while True:\n        pass\n")
    installed = tmp_path / "venv" / "lib" / "python3.11" / "site-packages" / "numpy"
    installed.mkdir(parents=True)
    (installed / "core.py").write_text("def f():\n    x = 1\n")
    secret = tmp_path.parent / f"{tmp_path.name}-grader-only.txt"
    secret.write_text("the answer key\n")
    (package / "linked.py").symlink_to(secret)

    def dump(*innermost: tuple[Path, int]) -> str:
        frames = "".join(f'  File "{file}", line {line} in f\n' for file, line in innermost)
        return f'Current thread 0x1 (most recent call first):\n{frames}  File "{node}", line 4 in tick\n'

    assert stuck.stuck_frame(dump((helpers, 3)), node) == [f'  File "{helpers}", line 3, in f\n    pass']
    # a venv beside the package, a link to a file outside the folder: not the student's
    assert stuck.stuck_frame(dump((installed / "core.py", 2)), node) == [
        f'  File "{node}", line 4, in tick\n    helpers.spin()'
    ]
    assert stuck.stuck_frame(dump((package / "linked.py", 1)), node) == [
        f'  File "{node}", line 4, in tick\n    helpers.spin()'
    ]
