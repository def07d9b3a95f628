"""A misbehaving student controller is contained by the sandbox.

Each test writes a small controller file, runs it sandboxed with
turtletui.api.run and checks that the misbehaviour is stopped and reported
(kind, a one-line summary naming the file, frames from the student's file),
that its turtle stops, that the simulation still reaches its full duration,
and that no process the controller started is left running.
"""

from __future__ import annotations

import json
import math
import os
import signal
import struct
import sys
import textwrap
import time
import tracemalloc
from pathlib import Path

import pytest
from support.controllers import WALL_TIME
from support.hosts import HOSTS, ControllerHost, node_logs

from turtletui.api import RunResult, run
from turtletui.runtime import forkserver
from turtletui.runtime.sandbox import Limits

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX processes")

ARENA = 11.088889122009277
"""turtlesim's arena size, as the float32 its poses carry."""
CRASH_TICK = 5
"""The timer tick (0.1 s apart) at which the controllers below misbehave."""
CRASH_T = CRASH_TICK * 0.1

PRELUDE = WALL_TIME + f"""\
import os, signal, subprocess, sys, threading, time
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


def note(name, value):
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    with open(path + ".tmp", "w") as f:
        f.write(str(value))
    os.replace(path + ".tmp", path)


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.n = 0
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.n += 1
        msg = Twist()
        msg.linear.x = 1.0
        msg.angular.z = 0.5
        self.pub.publish(msg)
        if self.n == {CRASH_TICK}:
            misbehave(self)


def main():
    note("pid", os.getpid())
    rclpy.init()
    before_spin()
    rclpy.spin(Driver())


def before_spin():
    pass

"""


# -- helpers ----------------------------------------------------------------------


def write(tmp_path: Path, body: str, *, prelude: bool = True, name: str = "student_node.py") -> Path:
    path = tmp_path / name
    path.write_text((PRELUDE if prelude else "") + textwrap.dedent(body))
    return path


def line_of(path: Path, marker: str) -> int:
    """Line number (1-based) of the only line of ``path`` holding ``marker``."""
    lines = [i for i, line in enumerate(path.read_text().splitlines(), 1) if marker in line]
    assert len(lines) == 1, lines
    return lines[0]


def read_pid(tmp_path: Path, name: str = "pid", timeout: float = 0.0) -> int:
    path = tmp_path / name
    deadline = time.monotonic() + timeout
    while not path.exists() and time.monotonic() < deadline:
        time.sleep(0.01)
    return int(path.read_text())


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:  # a zombie is dead, only not reaped yet (by init, for an orphan)
        with open(f"/proc/{pid}/stat") as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return True
    return state not in ("Z", "X")


def assert_gone(pid: int, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while _alive(pid):
        if time.monotonic() > deadline:
            pytest.fail(f"process {pid} is still running after the run ended")
        time.sleep(0.02)


@pytest.fixture(autouse=True, params=["fresh", "forked"])
def _launcher(request):
    """Every behaviour holds for a child started afresh (turtletui run) and for
    one forked from its submission's fork server (grading workers)."""
    if request.param == "fresh":
        yield
        return
    with forkserver.serving():
        yield


@pytest.fixture(autouse=True)
def _kill_leftovers(tmp_path: Path):
    """Whatever a failing test leaves behind is killed at teardown."""
    yield
    for file in tmp_path.glob("*pid"):
        try:
            pid = int(file.read_text())
        except ValueError:
            continue
        if pid > 1 and pid != os.getpid() and _works_in(pid, tmp_path):
            try:
                os.kill(pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass


def _works_in(pid: int, folder: Path) -> bool:
    """Whether process ``pid`` is still one this test started (a controller's
    processes work in its folder). A noted pid whose process ended may belong
    to another test's process by now (pids wrap at 32768 on many machines):
    killing it would kill a run of another pytest worker."""
    try:
        return Path(os.readlink(f"/proc/{pid}/cwd")).is_relative_to(folder.resolve())
    except OSError:
        return False


class Hang(Exception):
    pass


def _alarm(signum, frame):
    raise Hang("the run hung")


HANG_SECONDS = 180
"""A run that takes this long has hung: a deadline no busy machine reaches
(a run here takes a second or two of wall time when the machine is quiet)."""


def go(path: Path, duration: float = 2.0, **limits: float) -> RunResult:
    """Run ``path`` sandboxed; a hang fails the test (SIGALRM) instead of stalling it."""
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(HANG_SECONDS)
    try:
        result = run([path], duration=duration, keep_poses=True, limits=Limits(**limits) if limits else None)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    assert result.sim_time == pytest.approx(duration), "the run must reach its full duration"
    return result


def only_crash(result: RunResult, kind: str, path: Path):
    assert len(result.crashes) == 1, result.crashes
    crash = result.crashes[0]
    assert crash.kind == kind, crash.details()
    summary = crash.summary()
    assert "\n" not in summary
    assert str(path) in summary
    # The user sees the summary in the run's log, from turtletui, as an error.
    assert any(r.node == "turtletui" and r.level_name == "ERROR" and r.msg == summary for r in result.logs)
    return crash


def assert_frames(crash, path: Path, line: int) -> None:
    where = f'File "{path.resolve()}", line {line}'
    assert crash.frames, crash.details()
    assert where in crash.frames[-1], crash.frames
    assert where in crash.summary()


def assert_stopped(result: RunResult, after: float) -> None:
    """The turtle moved before ``after`` and has not moved since (its last
    command lasts 1 s in turtlesim unless the sandbox stops the turtle)."""
    poses = result.poses["turtle1"]
    first = poses[0][1:]
    before = [p[1:] for p in poses if p[0] <= after]
    later = [p[1:] for p in poses if p[0] > after + 0.02]
    assert before and later
    assert before[-1] != first, "the turtle should have moved before the failure"
    assert all(p == later[0] for p in later), "the turtle kept moving after its controller failed"
    final = result.turtles["turtle1"]
    assert (final.x, final.y) == pytest.approx(later[0][:2])


def stdout_lines(result: RunResult) -> list[str]:
    return [r.msg for r in result.logs if r.node.endswith(":stdout")]


# -- exceptions and load errors ------------------------------------------------------


def test_exception_in_callback(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            raise RuntimeError("boom in a callback")  # <- here
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert crash.message == "RuntimeError: boom in a callback"
    assert crash.t == pytest.approx(CRASH_T)
    assert_frames(crash, path, line_of(path, "# <- here"))
    assert all(str(path.resolve()) in frame for frame in crash.frames)
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


def test_exception_at_import(tmp_path: Path) -> None:
    path = write(tmp_path, """
        note("pid", os.getpid())
        settings = {"speed": 1.0}
        SPEED = settings["sped"]  # <- here

        def misbehave(node):
            pass
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert crash.message == "KeyError: 'sped'"
    assert_frames(crash, path, line_of(path, "# <- here"))
    assert crash.t == 0.0
    assert result.turtles["turtle1"].distance == 0.0
    assert_gone(read_pid(tmp_path))


def test_no_entry_point_is_a_load_error(tmp_path: Path) -> None:
    path = write(tmp_path, """
        import os
        SPEED = 1.0
        open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "pid"), "w").write(str(os.getpid()))
    """, prelude=False)
    result = go(path)
    crash = only_crash(result, "load", path)
    assert "no main() function and no rclpy Node subclass" in crash.message
    assert_gone(read_pid(tmp_path))


def test_import_error_names_the_missing_module(tmp_path: Path) -> None:
    path = write(tmp_path, """
        note("pid", os.getpid())
        import no_such_module_for_turtles  # <- here

        def misbehave(node):
            pass
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert "ModuleNotFoundError" in crash.message
    assert "no_such_module_for_turtles" in crash.message
    assert_frames(crash, path, line_of(path, "# <- here"))
    assert_gone(read_pid(tmp_path))


def test_multi_line_message_gives_a_one_line_summary(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            raise ValueError("first line\\nsecond line")
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert "first line" in crash.summary() and "second line" in crash.summary()


# -- hangs -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("body", "stuck_at", "stuck_in"),
    [
        (
            """
            def misbehave(node):
                while True: pass
            """,
            "while True: pass",
            "misbehave",
        ),
        (
            """
            def misbehave(node):
                block(10)
            """,
            "waiting.recv(1)",
            "block",
        ),
    ],
    ids=["endless-loop", "blocking-wait"],
)
@pytest.mark.parametrize("lockstep", [True, False], ids=["lockstep", "fast-path"])
def test_hung_callback_times_out_where_it_is_stuck(
    tmp_path: Path, body: str, stuck_at: str, stuck_in: str, lockstep: bool
) -> None:
    path = write(tmp_path, body)
    result = go(path, step_timeout=0.5, lockstep=lockstep)
    crash = only_crash(result, "timeout", path)  # the step deadline, not the CPU limit, stopped it
    assert "did not answer within 0.5 s" in crash.message
    # the report names the line it was stuck on, as an exception's names where it was raised
    assert crash.summary().endswith(f'(File "{path.resolve()}", line {line_of(path, stuck_at)}, in {stuck_in})')
    assert crash.t == pytest.approx(CRASH_T)
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


def test_sleep_in_a_callback_blocks_the_node_in_simulated_time(tmp_path: Path) -> None:
    """time.sleep is simulated: the node is blocked for 1.5 simulated seconds, as
    on a real robot, while the world goes on; nothing is stopped."""
    path = write(tmp_path, """
        def misbehave(node):
            node.get_logger().info("sleeping")
            time.sleep(1.5)
            node.get_logger().info("awake")
    """)
    result = go(path, duration=3.0)
    assert result.crashes == []
    lines = {r.msg: r.t for r in result.logs if r.node == "driver"}
    assert lines["sleeping"] == pytest.approx(CRASH_T)
    # simulated time passed during the sleep: a sleep in wall time would have
    # held lockstep's clock, and the node would wake at the same instant
    assert lines["awake"] == pytest.approx(CRASH_T + 1.5)
    # The last command before the sleep times out after 1 s: the turtle stops
    # before the node wakes up.
    poses = result.poses["turtle1"]
    still = [p for p in poses if CRASH_T + 1.1 < p[0] < CRASH_T + 1.5]
    assert still and len({p[1:] for p in still}) == 1


@pytest.mark.parametrize("lockstep", [True, False], ids=["lockstep", "fast-path"])
def test_endless_loop_in_main_before_spin(tmp_path: Path, lockstep: bool) -> None:
    path = write(tmp_path, """
        def before_spin():
            while True: pass

        def misbehave(node):
            pass
    """)
    result = go(path, step_timeout=0.5, start_timeout=2.0, lockstep=lockstep)
    crash = only_crash(result, "timeout", path)
    # it was given the start's 2 s, not a step's 0.5 s, and was in no callback:
    # the report names where it was stuck, and says neither
    assert crash.message.startswith("did not answer within 2 s of wall time while starting")
    assert "callback" not in crash.message
    assert crash.summary().endswith(f'(File "{path.resolve()}", line {line_of(path, "while True")}, in before_spin)')
    assert result.turtles["turtle1"].distance == 0.0
    assert_gone(read_pid(tmp_path))


# -- exits -----------------------------------------------------------------------------------


def test_sys_exit_with_status(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            sys.exit(3)
    """)
    result = go(path)
    crash = only_crash(result, "exit", path)
    assert "status 3" in crash.message
    assert crash.t == pytest.approx(CRASH_T)
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


@pytest.mark.parametrize(
    "body",
    [
        """
        def misbehave(node):
            sys.exit(0)
        """,
        """
        def before_spin():
            node = Driver()
            node.get_logger().info("leaving early")
            return main_returns()

        def main_returns():
            raise SystemExit  # the same as returning from main()

        def misbehave(node):
            pass
        """,
        """
        def main():
            note("pid", os.getpid())
            rclpy.init()
            node = Driver()
            node.get_logger().info("leaving early")
            return

        def misbehave(node):
            pass
        """,
    ],
    ids=["sys-exit-0", "system-exit", "main-returns"],
)
def test_clean_exit_is_not_a_crash(tmp_path: Path, body: str) -> None:
    path = write(tmp_path, body)
    result = go(path)
    assert result.crashes == []
    assert not any(r.level_name == "ERROR" for r in result.logs), [r.msg for r in result.logs]
    assert_gone(read_pid(tmp_path))


def test_os_exit_dies_without_a_report(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            os._exit(1)
    """)
    result = go(path)
    crash = only_crash(result, "exit", path)
    assert "status 1" in crash.message
    assert crash.t == pytest.approx(CRASH_T)
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


def test_killed_by_a_signal(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            os.kill(os.getpid(), signal.SIGKILL)
    """)
    result = go(path)
    crash = only_crash(result, "killed", path)
    assert "SIGKILL" in crash.message
    assert crash.t == pytest.approx(CRASH_T)
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


def test_closing_the_reply_pipe_and_looping(tmp_path: Path) -> None:
    path = write(tmp_path, """
        from turtletui.compat import context

        def misbehave(node):
            os.close(context.current_host().fd_out)
            while True:
                pass
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)  # noticed at once, not at the step deadline
    assert "closed its connection" in crash.message
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


def test_closing_stdout_and_working_slowly(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            os.close(1)
            os.close(2)
            node.create_timer(0.1, lambda: time.sleep(0.05))
    """)
    started = time.process_time()
    result = go(path)
    assert result.crashes == []
    assert time.process_time() - started < 1.0, "the parent busy-waited on a closed stdout"
    assert_gone(read_pid(tmp_path))


# -- floods -------------------------------------------------------------------------------------


def test_print_flood_is_truncated(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            for i in range(200_000):
                print("spam line", i)
            node.get_logger().info("still here")
    """)
    tracemalloc.start()
    try:
        result = go(path, output_lines=500)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    lines = stdout_lines(result)
    assert len(lines) == 500
    assert lines[0] == "spam line 0" and lines[-1] == "spam line 499"
    notices = [r.msg for r in result.logs if "output over its budget" in r.msg]
    assert len(notices) == 1 and str(path) in notices[0] and "500 lines per run" in notices[0]
    # The controller either went on (its next log arrives) or was stopped with a report.
    assert result.crashes or any(r.msg == "still here" for r in result.logs)
    # one line at the end says how much was not shown
    [dropped] = [r.msg for r in result.logs if "of output dropped" in r.msg]
    assert str(path) in dropped
    if not result.crashes:
        assert "(199,500 lines over its budget" in dropped
    assert peak < 20 * 1024**2, f"the parent held {peak / 1024**2:.0f} MiB for 200k lines of output"
    assert_gone(read_pid(tmp_path))


def test_print_without_newlines_is_bounded(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            for i in range(20_000):
                print("x" * 1000, end="")
    """)
    result = go(path, output_lines=50)
    lines = stdout_lines(result)
    assert 0 < len(lines) <= 50
    assert all(len(line) <= 1000 + len(" [... cut]") for line in lines)
    assert all(line.endswith(" [... cut]") for line in lines)
    assert_gone(read_pid(tmp_path))


@pytest.mark.parametrize("cap", [1_000, None], ids=["small-cap", "default-cap"])
def test_log_flood_is_capped(tmp_path: Path, cap: int | None) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            log = node.get_logger()
            for i in range(100_000):
                log.info(f"log line {i}")
            print("still here")
    """)
    tracemalloc.start()
    try:
        result = go(path, log_lines=cap) if cap else go(path)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    cap = cap or Limits().log_lines
    own = [r for r in result.logs if r.node == "driver"]
    assert len(own) == cap
    assert own[0].msg == "log line 0" and own[-1].msg == f"log line {cap - 1}"
    notices = [r.msg for r in result.logs if "log over its budget" in r.msg and r.node == "turtletui"]
    assert len(notices) == 1 and str(path) in notices[0]
    [dropped] = [r.msg for r in result.logs if "log messages over its budget dropped" in r.msg]
    assert f"{100_000 - cap:,} log messages" in dropped or cap == Limits().log_lines
    assert len(result.logs) < cap + 100
    assert result.crashes == [] and "still here" in stdout_lines(result)
    assert peak < 40 * 1024**2, f"the parent held {peak / 1024**2:.0f} MiB for a log flood"
    assert_gone(read_pid(tmp_path))


def test_default_log_cap() -> None:
    assert 1_000 <= Limits().log_lines <= 100_000


# -- memory ------------------------------------------------------------------------------------


def test_unbounded_allocation_is_stopped(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            hoard = []
            while True:
                hoard.append(bytearray(10**7))  # <- here
    """)
    result = go(path, memory_bytes=512 * 1024**2)
    crash = only_crash(result, "memory", path)
    assert "memory" in crash.message.lower()
    assert crash.t == pytest.approx(CRASH_T)
    assert_frames(crash, path, line_of(path, "# <- here"))
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


# -- processes the controller starts ------------------------------------------------------------


@pytest.mark.parametrize(
    "body",
    [
        """
        def misbehave(node):
            pid = os.fork()
            if pid == 0:
                time.sleep(60)
                os._exit(0)
            note("grandchild_pid", pid)  # the parent: the child may be killed before it could
        """,
        """
        def misbehave(node):
            pid = os.fork()
            if pid == 0:
                os.setsid()  # leaves the controller's process group
                time.sleep(60)
                os._exit(0)
            note("grandchild_pid", pid)
            time.sleep(0.2)
        """,
        """
        def misbehave(node):
            node.proc = subprocess.Popen(["sleep", "60"])
            note("grandchild_pid", node.proc.pid)
        """,
        """
        def misbehave(node):
            node.proc = subprocess.Popen(["sleep", "60"], start_new_session=True)
            note("grandchild_pid", node.proc.pid)
        """,
        """
        def misbehave(node):
            # A daemon with a clean environment, orphaned while the child lives.
            subprocess.run(
                ["sh", "-c", "sleep 60 & echo $! > grandchild_pid"],
                cwd=os.path.dirname(os.path.abspath(__file__)),
                start_new_session=True,
                env={"PATH": os.environ.get("PATH", "/usr/bin:/bin")},
            )
        """,
    ],
    ids=["fork", "fork-setsid", "popen", "popen-new-session", "daemon-clean-env"],
)
def test_started_processes_are_killed(tmp_path: Path, body: str) -> None:
    path = write(tmp_path, body.replace("60", "600"))
    started = time.monotonic()
    result = go(path)
    assert time.monotonic() - started < 300, "the run waited for what the controller started"
    grandchild = read_pid(tmp_path, "grandchild_pid", timeout=30.0)
    assert grandchild != read_pid(tmp_path)
    assert_gone(read_pid(tmp_path))
    assert_gone(grandchild)
    assert not any("Traceback" in r.msg for r in result.logs)


def test_daemonised_grandchild_of_a_dead_controller_is_killed(tmp_path: Path) -> None:
    """Double fork with setsid (a daemon), then the controller dies: the orphan
    is in no group, session or tree of the child's any more."""
    path = write(tmp_path, """
        def misbehave(node):
            noted, written = os.pipe()
            if os.fork() == 0:
                os.setsid()
                if os.fork() == 0:
                    note("grandchild_pid", os.getpid())
                    os.write(written, b"x")
                    time.sleep(60)
                os._exit(0)
            # wait in wall time (a simulated wait could outlast the run on a busy
            # machine, and what it does after the run counts for nothing)
            os.read(noted, 1)
            os._exit(1)
    """)
    result = go(path, step_timeout=60.0)
    crash = only_crash(result, "exit", path)
    assert "status 1" in crash.message
    assert_gone(read_pid(tmp_path))
    assert_gone(read_pid(tmp_path, "grandchild_pid"))


def test_fork_then_exit_is_reported_promptly(tmp_path: Path) -> None:
    """A grandchild holding the reply pipe open does not hide the child's death."""
    path = write(tmp_path, """
        def misbehave(node):
            noted, written = os.pipe()
            if os.fork() == 0:
                note("grandchild_pid", os.getpid())
                os.write(written, b"x")
                time.sleep(60)
                os._exit(0)
            os.read(noted, 1)  # exit once the grandchild is noted, not before it ran
            os._exit(4)
    """)
    result = go(path, step_timeout=60.0)
    crash = only_crash(result, "exit", path)  # not a timeout: its death was noticed
    assert "status 4" in crash.message
    assert_gone(read_pid(tmp_path))
    assert_gone(read_pid(tmp_path, "grandchild_pid", timeout=30.0))


# -- tampering with turtletui from inside the sandbox -------------------------------------------

WALL_RUN = """
class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.tick)
        self.n = 0

    def tick(self):
        self.n += 1
        msg = Twist()
        msg.linear.x = 4.0
        self.pub.publish(msg)
"""


def assert_clamped_at_wall(result: RunResult) -> None:
    final = result.turtles["turtle1"]
    assert final.x == pytest.approx(ARENA)
    assert final.wall_hits >= 1
    assert all(0.0 <= x <= ARENA and 0.0 <= y <= ARENA for _, x, y, _ in result.poses["turtle1"])


def test_patching_the_arena_size_changes_nothing(tmp_path: Path) -> None:
    path = write(tmp_path, textwrap.dedent("""
        import turtletui.sim.constants as constants
        import turtletui.sim.world as world
        constants.ARENA_SIZE = 1000.0
        for name in dir(world):
            if isinstance(getattr(world, name), float) and getattr(world, name) > 11:
                setattr(world, name, 1000.0)
    """) + WALL_RUN)
    result = go(path, duration=3.0)
    assert result.crashes == []
    assert_clamped_at_wall(result)


def test_patching_child_publish_is_validated_by_the_parent(tmp_path: Path) -> None:
    path = write(tmp_path, """
        from turtletui.runtime import outbox, protocol

        def forged_published(self, topic, msg, publisher, young):
            self.publishes.append(protocol.Publish(topic.name, [["fast", 0.0, 0.0], [0.0, 0.0, 0.0]]))

        def misbehave(node):
            outbox.ParentOutbox.published = forged_published
            node.pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert "sent something turtlesim cannot accept" in crash.message
    assert crash.t == pytest.approx(CRASH_T + 0.1)
    assert_stopped(result, CRASH_T + 0.1)
    assert_gone(read_pid(tmp_path))


def test_publishing_on_an_undeclared_topic_is_refused(tmp_path: Path) -> None:
    path = write(tmp_path, """
        from turtletui.compat import context
        from turtletui.runtime import protocol

        def misbehave(node):
            context.current_host().outbox.publishes.append(protocol.Publish("/turtle1/teleport_anywhere", []))
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert "cannot accept" in crash.message and "/turtle1/teleport_anywhere" in crash.message
    assert_gone(read_pid(tmp_path))


def test_forged_poses_are_not_the_trajectory(tmp_path: Path) -> None:
    """Anyone may publish a Pose on /turtle1/pose (as in ROS), but the recorded
    trajectory is the simulated turtle's."""
    path = write(tmp_path, """
        class Driver(Node):
            def __init__(self):
                super().__init__("driver")
                self.pub = self.create_publisher(Pose, "/turtle1/pose", 10)
                self.create_timer(0.05, self.tick)

            def tick(self):
                self.pub.publish(Pose(x=100.0, y=-5.0))
    """)
    result = go(path, duration=1.0)
    assert result.crashes == []
    poses = result.poses["turtle1"]
    assert len(poses) > 50
    assert all(0.0 <= x <= ARENA and 0.0 <= y <= ARENA for _, x, y, _ in poses)
    assert len({t for t, *_ in poses}) == len(poses)


FORGE = """
from turtletui.compat import context


def misbehave(node):
    # Write a reply of one's own on the pipe to turtletui, then keep quiet:
    # the parent acts on the forged frame (not on a timeout).
    os.write(context.current_host().fd_out, FRAME)
    block(30)
"""


def frame(payload: object) -> bytes:
    data = payload if isinstance(payload, bytes) else json.dumps(payload).encode()
    return struct.pack(">I", len(data)) + data


REFUSED = "sent something turtlesim cannot accept"
MALFORMED = "sent a malformed reply"
FORGED = {
    # name: (frame, kind of the crash or None if harmless, what its message says)
    "not-json": (frame(b"{not json"), "exception", MALFORMED),
    "more-after-the-value": (frame(b'{"log": []} {"done": true}'), "exception", MALFORMED),
    "white-space-first": (frame(b' {"log": []}'), "exception", MALFORMED),
    "not-utf8": (frame(b'{"log": "\xff\xfe"}'), "exception", MALFORMED),
    "not-an-object": (frame([1, 2, 3]), "exception", MALFORMED),
    "deep-nesting": (frame(b"[" * 100_000 + b"]" * 100_000), "exception", MALFORMED),
    "too-big": (struct.pack(">I", 2**31) + b"{}", "flood", "bytes in one step"),
    "unknown-entry": (frame({"teleport": [[1, 2]]}), "exception", "unknown report entry 'teleport'"),
    "log-not-triples": (frame({"log": [1, 2]}), "exception", "a Log must be an array of its fields"),
    "log-bad-level": (frame({"log": [["loud", "n", "m", True, 0]]}), "exception", "log[0]: Log.level must be an integer"),
    "decl-empty": (frame({"decl": [[]]}), "exception", "decl[0]: a graph change must be an array"),
    "decl-unknown-kind": (frame({"decl": [["teleport", 1]]}), "exception", "unknown graph change str 'teleport'"),
    "decl-short": (frame({"decl": [["pub", 99, 1, "/x"]]}), "exception", "a DeclarePublisher has 6 fields"),
    "decl-unknown-node": (frame({"decl": [["pub", 99, 12345, "/x", "geometry_msgs/msg/Twist", 10, None]]}), "exception", "names no node of the controller: 12345"),
    "decl-unknown-type": (frame({"decl": [["sub", 98, 1, "/turtle1/pose", "no_pkg/msg/Nothing", 10, "", None]]}), "exception", REFUSED),
    "decl-wrong-type": (frame({"decl": [["pub", 97, 1, "/turtle1/cmd_vel", "turtlesim/msg/Pose", 10, None]]}), "exception", REFUSED),
    "decl-unknown-qos": (frame({"decl": [["pub", 99, 1, "/x", "geometry_msgs/msg/Twist", 1, [7, 7, 7]]]}), "exception", "DeclarePublisher.qos must be null or QoS policies"),
    "removal-short": (frame({"decl": [["rmrecord", "service", 1]]}), "exception", "a RemoveRecord has 3 fields"),
    "removal-unknown": (frame({"decl": [["rmrecord", "turtle", 1, "/turtle1"]]}), "exception", "RemoveRecord.kind must be one of service"),
    "param-garbage": (frame({"decl": [["param", 1, "p", {"nested": [1]}, False]]}), "exception", "SetParameter.value must be a value a ROS parameter can hold"),
    "pub-not-a-list": (frame({"pub": 5}), "exception", "pub: must be an array of Publish records"),
    "pub-fields-not-a-list": (frame({"pub": [["/turtle1/cmd_vel", {"linear": 1}, 0, False]]}), "exception", "Publish.values must be a list of field values"),
    "pub-short-fields": (frame({"pub": [["/turtle1/cmd_vel", [1, 2, 3], 0, False]]}), "exception", REFUSED),
    "pub-bad-field": (frame({"pub": [["/turtle1/cmd_vel", [["fast", 0, 0], [0, 0, 0]], 0, False]]}), "exception", REFUSED),
    "call-bad-request": (frame({"call": [[1, "/spawn", ["far", 1.0, 0.0, ""]]]}), "exception", REFUSED),
    "asrv-unknown-type": (frame({"decl": [["asrv", 1, "/spin", "no_pkg/action/Nothing"]]}), "exception", REFUSED),
    "served-not-arrays": (frame({"served": [5]}), "exception", "served[0]: a served-goal event must be an array"),
    "served-bad-status": (frame({"served": [["result", 1, "won", []]]}), "exception", "FinishServedGoal.status must be one of succeeded"),
    "served-bad-cancel-code": (frame({"served": [["cancel", 1, 9, True]]}), "exception", "AnswerServedCancel.code must be a CancelGoal return code"),
    "wake-infinite": (frame(b'{"wake": Infinity}'), "exception", "wake: must be an integer or null"),
    "wake-nan": (frame(b'{"wake": NaN}'), "exception", REFUSED),
    "wake-string": (frame({"wake": "soon"}), "exception", REFUSED),
    "logs-dropped-negative": (frame({"logs_dropped": -5}), "exception", "logs_dropped: must be a count"),
    "crash-not-an-array": (frame({"done": True, "crash": "oops"}), "exception", "a Crash must be an array"),
    "crash-bad-frames": (frame({"done": True, "crash": ["x", "m", 5]}), "exception", "Crash.frames must be a list of strings"),
    "crash-made-up": (frame({"done": True, "crash": ["banana", "a\nb", []]}), "exception", "a b"),
    # Harmless: an answer to nothing is ignored; a wake-up at the end of time means
    # "never" (the forger, still asleep when the run ends, does not answer "end").
    "resp-unknown": (frame({"resp": [[424242, [1]]]}), None, ""),
    "served-unknown-goal": (frame({"served": [["result", 424242, "succeeded", [1.0]]]}), None, ""),
    "wake-huge": (frame({"wake": 10**400}), None, ""),
}


@pytest.mark.parametrize("case", sorted(FORGED))
def test_forged_reply_on_the_pipe(tmp_path: Path, case: str) -> None:
    # lockstep's pipe: the fast path's forgeries are tests/runtime/test_fastpath.py's
    forged, kind, says = FORGED[case]
    path = write(tmp_path, FORGE.replace("FRAME", repr(forged)))
    result = go(path, lockstep=True)
    assert not any("Traceback" in r.msg for r in result.logs)
    assert_gone(read_pid(tmp_path))
    if kind is None:
        assert [c.kind for c in result.crashes] in ([], ["timeout"]), result.crashes
        assert all(c.t == pytest.approx(2.0) for c in result.crashes)
        return
    crash = only_crash(result, kind, path)
    assert says in crash.message
    assert crash.t == pytest.approx(CRASH_T)
    assert_stopped(result, CRASH_T)


def test_forged_reply_then_not_reading(tmp_path: Path) -> None:
    """The child answers with a forged frame and stops reading: the parent's next
    message (large: 3000 subscriptions to the pose) must not block it on a full pipe."""
    path = write(tmp_path, """
        import struct
        from turtletui.compat import context

        def forge_and_hang():
            os.write(context.current_host().fd_out, struct.pack(">I", 2) + b"{}")
            block(600)

        def misbehave(node):
            for _ in range(3000):
                node.create_subscription(Pose, "/turtle1/pose", lambda msg: None, 10)
            node.create_timer(0.1, forge_and_hang)
    """)
    started = time.monotonic()
    # The 3000 subscriptions cost the child 0.3-0.5 s of CPU in one step here, more on a
    # busy CI machine: the step's deadline must not run out before the child forges.
    result = go(path, step_timeout=4.0, lockstep=True)  # the fast path sends the child nothing
    assert time.monotonic() - started < 300, "the parent waited for the child to read"
    crash = only_crash(result, "timeout", path)
    assert CRASH_T + 0.1 <= crash.t < CRASH_T + 0.2
    assert_gone(read_pid(tmp_path))


def test_memory_limit_too_small_to_start(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            pass
    """)
    result = go(path, memory_bytes=16 * 1024**2)
    assert len(result.crashes) == 1
    crash = result.crashes[0]
    assert crash.kind in ("exit", "memory", "killed"), crash.details()
    assert str(path) in crash.summary()
    assert result.turtles["turtle1"].distance == 0.0


# -- wrong and absurd messages ------------------------------------------------------------------


def test_publishing_the_wrong_message_type(tmp_path: Path) -> None:
    path = write(tmp_path, """
        def misbehave(node):
            node.pub.publish(Pose(x=1.0))  # <- here
    """)
    result = go(path)
    crash = only_crash(result, "exception", path)
    assert crash.message.startswith("TypeError:")
    assert "Pose" in crash.message and "Twist" in crash.message
    assert_frames(crash, path, line_of(path, "# <- here"))
    assert_stopped(result, CRASH_T)
    assert_gone(read_pid(tmp_path))


@pytest.mark.parametrize("value", ["float('nan')", "float('inf')", "-float('inf')"])
def test_non_finite_velocities_are_ignored(tmp_path: Path, value: str) -> None:
    path = write(tmp_path, f"""
        class Driver(Node):
            def __init__(self):
                super().__init__("driver")
                self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
                self.create_timer(0.1, self.tick)

            def tick(self):
                msg = Twist()
                msg.linear.x = {value}
                msg.angular.z = {value}
                self.pub.publish(msg)
    """)
    result = go(path)
    assert result.crashes == []
    warnings = [r for r in result.logs if r.node == "turtlesim" and r.level_name == "WARN"]
    assert warnings and "non-finite" in warnings[0].msg
    assert all(0.0 <= x <= ARENA and 0.0 <= y <= ARENA for _, x, y, _ in result.poses["turtle1"])
    assert all(math.isfinite(th) for *_, th in result.poses["turtle1"])
    final = result.turtles["turtle1"]
    assert 0.0 <= final.x <= ARENA and 0.0 <= final.y <= ARENA


# -- determinism ----------------------------------------------------------------------------------


def test_sandboxed_runs_are_deterministic(tmp_path: Path) -> None:
    path = write(tmp_path, """
        import random

        class Driver(Node):
            def __init__(self):
                super().__init__("driver")
                self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
                self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
                self.create_timer(0.05, self.tick)
                self.x = 0.0

            def on_pose(self, pose):
                self.x = pose.x

            def tick(self):
                msg = Twist()
                msg.linear.x = random.uniform(0.5, 2.0) + 0.1 * self.x
                msg.angular.z = random.uniform(-2.0, 2.0)
                self.pub.publish(msg)
    """)
    first = run([path], duration=2.0, seed=7, keep_poses=True)
    second = run([path], duration=2.0, seed=7, keep_poses=True)
    other = run([path], duration=2.0, seed=8, keep_poses=True)
    assert first.crashes == second.crashes == []
    assert len(first.poses["turtle1"]) > 100
    assert first.poses == second.poses
    assert first.poses != other.poses


def test_limits_reach_the_child(tmp_path: Path) -> None:
    """api.run passes ``limits`` through: the child sees its memory limit."""
    path = write(tmp_path, """
        import json, resource
        note("limit", json.dumps(resource.getrlimit(resource.RLIMIT_AS)))

        def misbehave(node):
            pass
    """)
    go(path, memory_bytes=700 * 1024**2, duration=0.5)
    soft, hard = json.loads((tmp_path / "limit").read_text())
    assert soft == 700 * 1024**2


def test_the_graders_secrets_never_reach_student_code(tmp_path: Path, monkeypatch) -> None:
    """Student code sees the variables a program needs (PATH, locale, ROS's
    own) and none of the grader's: the results key, CI tokens, credentials."""
    monkeypatch.setenv("TURTLETUI_RESULTS_KEY", "0123456789abcdef")
    monkeypatch.setenv("GITHUB_TOKEN", "ghp_secret")
    monkeypatch.setenv("AWS_SECRET_ACCESS_KEY", "aws_secret")
    monkeypatch.setenv("ROS_DOMAIN_ID", "17")
    path = write(tmp_path, """
        import json
        note("environ", json.dumps(dict(os.environ)))

        def misbehave(node):
            pass
    """)
    go(path, duration=0.5)
    seen = json.loads((tmp_path / "environ").read_text())
    assert not {"TURTLETUI_RESULTS_KEY", "GITHUB_TOKEN", "AWS_SECRET_ACCESS_KEY"} & set(seen)
    assert not any("secret" in value or "0123456789abcdef" in value for value in seen.values())
    assert seen["ROS_DOMAIN_ID"] == "17"
    assert seen["PATH"] == os.environ["PATH"]


@pytest.mark.parametrize("host", HOSTS)
def test_a_service_destroyed_and_created_again_in_one_callback(tmp_path: Path, host: str) -> None:
    """Graph changes reach the parent in the order they were made: the removal
    before the new declaration, so the parent does not refuse a second server."""
    result = ControllerHost(host, tmp_path).run(
        """
import rclpy
from rclpy.node import Node
from std_srvs.srv import Empty

class Server(Node):
    def __init__(self):
        super().__init__("server")
        self.service = self.create_service(Empty, "/ping", self.ping)
        self.client = self.create_client(Empty, "/ping")
        self.create_timer(0.1, self.tick)
        self.ticks = 0

    def ping(self, request, response):
        self.get_logger().info(f"ping answered after {self.ticks} ticks")
        return response

    def tick(self):
        self.ticks += 1
        if self.ticks == 2:
            self.destroy_service(self.service)
            self.service = self.create_service(Empty, "/ping", self.ping)
            self.client.call_async(Empty.Request())
""",
        duration=0.5,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "server") == ["ping answered after 2 ticks"]
