"""What a student sees of their program's end and output is the truth, and
the same under both hosts: a clean ``sys.exit(0)``, a deadlock, a crash in a
helper module of their package, what they write to stderr."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from support.hosts import HOSTS, write_controller

from turtletui.api import RunResult, run
from turtletui.runtime import forkserver
from turtletui.runtime.sandbox import Limits

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX processes")

TICKING = """
import sys, threading, warnings
import rclpy
from rclpy.node import Node


class Ticker(Node):
    def __init__(self):
        super().__init__("ticker")
        self.n = 0
        self.create_timer(0.5, self.tick)

    def tick(self):
        self.n += 1
        self.get_logger().info(f"tick {{self.n}}")
        if self.n == 2:
{misbehave}


def main():
    rclpy.init()
    rclpy.spin(Ticker())
    print("after spin")


if __name__ == "__main__":
    main()
"""


def ticking(folder: Path, misbehave: str, filename: str = "ticker.py") -> Path:
    body = "\n".join("            " + line for line in misbehave.strip().splitlines())
    return write_controller(folder, TICKING.format(misbehave=body), filename)


def go(path: Path, host: str, duration: float = 3.0) -> RunResult:
    result = run([path], duration=duration, sandbox=host == "sandboxed")
    assert result.sim_time == pytest.approx(duration)
    return result


def line_of(path: Path, marker: str) -> int:
    (line,) = [i for i, text in enumerate(path.read_text().splitlines(), 1) if marker in text]
    return line


def turtletui_says(result: RunResult) -> list[str]:
    return [r.msg for r in result.logs if r.node == "turtletui"]


# -- sys.exit(0) in a callback ----------------------------------------------------------------


@pytest.mark.parametrize("host", HOSTS)
@pytest.mark.parametrize("call", ["sys.exit(0)", "sys.exit()"])
def test_sys_exit_0_in_a_callback_is_a_clean_exit_at_its_line(tmp_path: Path, host: str, call: str) -> None:
    # Under rclpy (Kilted) SystemExit goes out of rclpy.spin: the program ends
    # with status 0, the code after spin never runs.
    path = ticking(tmp_path, call)
    result = go(path, host)
    assert result.crashes == []
    assert not [r for r in result.logs if r.level_name == "ERROR"]
    assert [r.msg for r in result.logs if r.node == "ticker"] == ["tick 1", "tick 2"]
    (note,) = turtletui_says(result)
    assert note.startswith(
        f'{path} exited with status 0 at t=1.000 s (File "{path.resolve()}", line {line_of(path, call)}, in tick)'
    )
    assert "spin" not in note  # no advice to spin: it did, and chose to leave
    assert "after spin" not in "".join(r.msg for r in result.logs)


# -- a course package: the helper module's line is named ---------------------------------------

CONTROLLER = """
import rclpy
from rclpy.node import Node
from my_robot_controller import helpers


class Controller(Node):
    def __init__(self):
        super().__init__("controller")
        self.n = 0
        self.create_timer(0.5, self.tick)

    def tick(self):
        self.n += 1
        self.get_logger().info(f"v {helpers.compute(self.n)}")


def main():
    rclpy.init()
    rclpy.spin(Controller())
"""

HELPERS = """
import json


def compute(n):
    if n == 2:
        {misbehave}
    return n
"""


def course_package(folder: Path, misbehave: str) -> tuple[Path, Path]:
    package = folder / "my_robot_controller"
    package.mkdir()
    (package / "__init__.py").write_text("")
    helpers = write_controller(package, HELPERS.replace("{misbehave}", misbehave), "helpers.py")
    return write_controller(package, CONTROLLER, "turtle_controller.py"), helpers


@pytest.mark.parametrize("host", HOSTS)
def test_an_exception_in_a_helper_module_names_the_helper_s_line(tmp_path: Path, host: str) -> None:
    controller, helpers = course_package(tmp_path, "return json.loads('{')")
    result = go(controller, host)
    (crash,) = result.crashes
    assert crash.kind == "exception" and crash.t == pytest.approx(1.0)
    # as Python's traceback: the call site in the controller, then the helper's
    # line (innermost), never json's or turtletui's own frames
    assert [frame.splitlines()[0] for frame in crash.frames][-2:] == [
        f'  File "{controller.resolve()}", line {line_of(controller, "helpers.compute")}, in tick',
        f'  File "{helpers.resolve()}", line {line_of(helpers, "json.loads")}, in compute',
    ]
    assert not [frame for frame in crash.frames if "json" + "/" in frame or "turtletui" + "/" in frame]
    assert crash.summary().endswith(f'(File "{helpers.resolve()}", line {line_of(helpers, "json.loads")}, in compute)')


def test_a_helper_module_stuck_in_a_loop_is_named_at_its_line(tmp_path: Path) -> None:
    # Sandboxed only: in this process nothing stops an endless loop (trusted code).
    controller, helpers = course_package(tmp_path, "while True:\n            pass")
    result = go(controller, "sandboxed")
    (crash,) = result.crashes
    assert crash.kind == "timeout"
    loop = line_of(helpers, "while True")
    assert [frame.splitlines()[0] for frame in crash.frames] in (
        [f'  File "{helpers.resolve()}", line {loop}, in compute'],
        [f'  File "{helpers.resolve()}", line {loop + 1}, in compute'],
    )


# -- deadlocks ----------------------------------------------------------------------------------
# Sandboxed only: in this process the locks are the interpreter's own, and a
# deadlock hangs the program as it does under ROS (in-process code is trusted).


def test_a_callback_taking_its_lock_twice_is_a_deadlock_at_that_line(tmp_path: Path) -> None:
    # Under rclpy (Kilted) the program hangs after "tick 2", even on SIGTERM.
    path = ticking(tmp_path, """
self.lock = getattr(self, "lock", threading.Lock())
with self.lock:
    self.get_logger().info("holding it")
    with self.lock:  # taken twice
        self.get_logger().info("never")
""")
    result = go(path, "sandboxed")
    (crash,) = result.crashes
    assert crash.kind == "deadlock" and crash.t == pytest.approx(1.0)
    assert "deadlock" in crash.message and "release unlocked lock" not in crash.message
    assert crash.frames == [f'  File "{path.resolve()}", line {line_of(path, "taken twice")}, in tick\n'
                            "    with self.lock:  # taken twice"]
    assert [r.msg for r in result.logs if r.node == "ticker"] == ["tick 1", "tick 2", "holding it"]


def test_two_threads_each_waiting_for_the_other_s_lock_are_a_deadlock_naming_both(tmp_path: Path) -> None:
    path = write_controller(tmp_path, """
        import threading, time
        import rclpy
        from rclpy.node import Node

        a, b = threading.Lock(), threading.Lock()


        def worker():
            with b:
                time.sleep(1.0)
                with a:  # the worker waits here
                    pass


        class Holder(Node):
            def __init__(self):
                super().__init__("holder")
                self.create_timer(0.5, self.tick)

            def tick(self):
                with a:
                    time.sleep(1.0)
                    with b:  # the callback waits here
                        pass


        def main():
            rclpy.init()
            node = Holder()
            threading.Thread(target=worker, daemon=True).start()
            rclpy.spin(node)
    """, "holder.py")
    result = go(path, "sandboxed")
    (crash,) = result.crashes
    assert crash.kind == "deadlock", crash.details()
    assert crash.t == pytest.approx(1.5)  # the callback took a at 0.5 and waits for b from 1.5
    assert "2 threads" in crash.message
    lines = sorted(frame.splitlines()[0] for frame in crash.frames)
    assert lines == sorted([
        f'  File "{path.resolve()}", line {line_of(path, "worker waits")}, in worker',
        f'  File "{path.resolve()}", line {line_of(path, "callback waits")}, in tick',
    ])


def test_a_lock_another_thread_releases_later_is_no_deadlock(tmp_path: Path) -> None:
    path = write_controller(tmp_path, """
        import threading, time
        import rclpy
        from rclpy.node import Node

        lock = threading.Lock()


        def worker():
            with lock:
                time.sleep(1.0)


        class Waiter(Node):
            def __init__(self):
                super().__init__("waiter")
                self.create_timer(0.5, self.tick)

            def tick(self):
                with lock:
                    self.get_logger().info("got it")


        def main():
            rclpy.init()
            node = Waiter()
            threading.Thread(target=worker).start()
            rclpy.spin(node)
    """, "waiter.py")
    result = go(path, "sandboxed", duration=2.0)
    assert result.crashes == []
    assert [r.t for r in result.logs if r.node == "waiter"][:2] == [pytest.approx(1.0), pytest.approx(1.0)]


# -- stdout and stderr ----------------------------------------------------------------------------

WRITER = """
import sys, warnings
import rclpy
from rclpy.node import Node


class Writer(Node):
    def __init__(self):
        super().__init__("writer")
        self.n = 0
        self.create_timer(0.5, self.tick)

    def tick(self):
        self.n += 1
        print(f"out {self.n}")
        print(f"err {self.n}", file=sys.stderr)
        if self.n == 1:
            warnings.warn("careful")
            self.get_logger().warn("old warn")  # rclpy: a DeprecationWarning, on stderr
        print(f"out {self.n} again")


def main():
    rclpy.init()
    rclpy.spin(Writer())
"""
STDOUT = ["out 1", "out 1 again", "out 2", "out 2 again"]


def stderr_of_writer(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.startswith("err ") or "Warning" in line]


@pytest.mark.parametrize("host", HOSTS)
def test_what_a_program_writes_to_stderr_goes_to_stderr(tmp_path: Path, host: str) -> None:
    path = write_controller(tmp_path, WRITER, "writer.py")
    command = ["run", str(path), "--headless", "--duration", "1.2", *(["--in-process"] if host == "in-process" else [])]
    # as a student runs it (pytest would catch the warnings of a run in its own process)
    result = subprocess.run(
        [sys.executable, "-m", "turtletui", *command], capture_output=True, text=True, timeout=120, check=False
    )
    assert result.returncode == 0, result.stderr
    assert [line for line in result.stdout.splitlines() if line.startswith("out ")] == STDOUT
    assert "err" not in result.stdout and "Warning" not in result.stdout
    errors = stderr_of_writer(result.stderr)
    assert errors[0] == "err 1" and errors[-1] == "err 2"
    assert any(line.endswith("UserWarning: careful") for line in errors)
    assert any("DeprecationWarning" in line for line in errors)


@pytest.mark.parametrize("launcher", ["fresh", "forked"])
@pytest.mark.parametrize("lockstep", [True, False], ids=["lockstep", "fast-path"])
def test_a_sandboxed_program_s_stderr_lines_are_told_from_its_stdout_lines_at_their_instants(
    tmp_path: Path, launcher: str, lockstep: bool
) -> None:
    path = write_controller(tmp_path, WRITER, "writer.py")
    limits = Limits(lockstep=lockstep)
    if launcher == "forked":
        with forkserver.serving():
            result = run([path], duration=1.2, limits=limits)
    else:
        result = run([path], duration=1.2, limits=limits)
    printed = [(r.t, r.node, r.msg) for r in result.logs if r.node.startswith("writer:")]
    out = [(t, msg) for t, node, msg in printed if node == "writer:stdout"]
    err = [(t, msg) for t, node, msg in printed if node == "writer:stderr"]
    assert out == [(0.5, "out 1"), (0.5, "out 1 again"), (1.0, "out 2"), (1.0, "out 2 again")]
    assert [msg for _, msg in err if msg.startswith("err")] == ["err 1", "err 2"]
    assert [t for t, msg in err if msg.startswith("err")] == [0.5, 1.0]
    assert any(msg.endswith("UserWarning: careful") for _, msg in err)
    assert len(out) + len(err) == len(printed)
    # within an instant, what it printed comes before what it logged, as in lockstep before
    (warned,) = [i for i, r in enumerate(result.logs) if r.node == "writer" and r.msg == "old warn"]
    assert all(i < warned for i, r in enumerate(result.logs) if r.node.startswith("writer:") and r.t == 0.5)
