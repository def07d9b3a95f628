"""What a sandboxed controller may spend: a controller too slow for a robot is
stopped within seconds with a verdict that says why, a run can be given a
wall-clock limit, CPU kills are reported as CPU, and output is capped."""

from __future__ import annotations

import re
import sys
import textwrap
from pathlib import Path

import pytest
from support.controllers import WALL_TIME
from typer.testing import CliRunner

from turtletui.api import run
from turtletui.cli import app
from turtletui.runtime.budget import CALLS, WAKE, OutputBudget, Pace
from turtletui.runtime.sandbox import Limits

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX processes")

POSE_NODE = WALL_TIME + """
import signal
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class Avoider(Node):
    def __init__(self):
        super().__init__("avoider")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose):
        SLOW
        cmd = Twist()
        cmd.linear.x = 1.0
        self.pub.publish(cmd)


def main():
    BEFORE
    rclpy.init()
    rclpy.spin(Avoider())
"""


def write(folder: Path, text: str, name: str = "node.py") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    path.write_text(textwrap.dedent(text))
    return path


def pose_node(tmp_path: Path, slow: str, before: str = "pass") -> Path:
    return write(tmp_path, POSE_NODE.replace("SLOW", slow).replace("BEFORE", before))


# -- too slow for real time ------------------------------------------------------------


@pytest.mark.parametrize(
    "slow, takes",
    [("work(0.03)", (25, 60)), ("block(0.2)", (180, 260))],
    ids=["30 ms of CPU", "a 200 ms blocking call"],
)
def test_a_controller_that_cannot_keep_up_is_stopped_with_the_reason(
    tmp_path: Path, slow: str, takes: tuple[int, int]
) -> None:
    """30 ms of work for a pose every 16 ms: a robot would leave this node
    behind. It is stopped once too far behind real time (3 s by default; 1 s
    here to keep the test short. A run took 1013 s and was reported as out of
    memory before)."""
    path = pose_node(tmp_path, slow)
    result = run([path], duration=600.0, limits=Limits(realtime_lag=1.0))
    [crash] = result.crashes
    assert crash.kind == "slow"
    assert "could not keep up with real time" in crash.message
    found = re.search(r"your pose_callback takes (\d+) ms on average", crash.message)
    assert found and takes[0] <= int(found[1]) <= takes[1], crash.message
    assert "a message on /turtle1/pose arrives every 16 ms: on a real robot this node falls behind" in crash.message
    # 1 s behind: 1 / (30 - 16) * 16 ms = 1.1 s of simulated time for the first
    assert crash.t < 5.0
    assert result.sim_time == pytest.approx(600.0)  # the world went on without it
    assert "was stopped at" in crash.summary()


def test_a_slow_timer_is_named(tmp_path: Path) -> None:
    path = write(tmp_path, POSE_NODE.replace("BEFORE", "pass").replace("SLOW", "pass").replace(
        'self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)',
        "self.create_timer(0.01, self.control_step)\n\n    def control_step(self):\n        work(0.03)",
    ))
    [crash] = run([path], duration=600.0, limits=Limits(realtime_lag=1.0)).crashes
    assert crash.kind == "slow"
    # 30 ms of CPU a call, measured as wall time less what the machine kept the
    # child waiting for a CPU: on a busy machine that estimate can land a little under
    taken = re.search(r"your control_step \(a timer\) and loops between sleeps take (\d+) ms", crash.message)
    assert taken is not None, crash.message
    assert 25 <= int(taken.group(1)) <= 45
    assert "are due every 10 ms" in crash.message


def test_a_controller_a_little_faster_than_real_time_is_not_stopped(tmp_path: Path) -> None:
    result = run([pose_node(tmp_path, "block(0.005)")], duration=3.0)
    assert result.crashes == []


def test_the_pace_is_not_judged_in_real_time_or_when_switched_off(tmp_path: Path) -> None:
    path = pose_node(tmp_path, "work(0.03)")
    # 50 poses of 30 ms each: 0.7 s behind real time at the end
    [crash] = run([path], duration=0.8, limits=Limits(realtime_lag=0.3)).crashes
    assert crash.kind == "slow"
    assert run([path], duration=0.8, limits=Limits(realtime_lag=None)).crashes == []
    assert run([path], duration=0.8, realtime=True, limits=Limits(realtime_lag=0.3)).crashes == []


def test_a_run_over_its_wall_clock_limit_is_stopped(tmp_path: Path) -> None:
    path = pose_node(tmp_path, "block(0.01)")
    result = run([path], duration=60.0, limits=Limits(run_seconds=1.0, run_seconds_reason="as a test says"))
    [crash] = result.crashes
    assert crash.kind == "time"
    assert "ran out of time after 1." in crash.message
    assert crash.message.endswith(" s of wall time: as a test says")
    assert crash.t < 5.0


def test_a_run_stopped_by_its_limit_while_behind_real_time_is_told_why(tmp_path: Path) -> None:
    """On a busy machine the run's limit may come first: the verdict still
    says the controller could not keep up, and what took the time."""
    path = pose_node(tmp_path, "work(0.03)")
    limits = Limits(realtime_lag=None, run_seconds=3.0, run_seconds_reason="as a test says")
    [crash] = run([path], duration=60.0, limits=limits).crashes
    assert crash.kind == "time"
    assert "s of wall time: as a test says; it could not keep up with real time (" in crash.message
    assert "your pose_callback takes" in crash.message
    assert crash.message.endswith("on a real robot this node falls behind")


def test_the_report_names_the_busiest_cause() -> None:
    pace = Pace(start_ns=0, subscriptions={1: ("pose_callback", "/turtle1/pose"), 2: ("", "/turtle1/scan")})
    for i in range(10):
        assert pace.charge(1, 0.030, 16_000_000 * (i + 1)) < 3.0
        pace.charge(WAKE, 0.001, 16_000_000 * (i + 1))
    report = pace.report(160_000_000)
    assert report.startswith("could not keep up with real time (0.3 s of wall time for 0.2 s of simulated time)")
    assert "your pose_callback takes 30 ms on average; a message on /turtle1/pose arrives every 16 ms" in report
    for i in range(40):
        pace.charge((1, 2), 0.050, 16_000_000 * (i + 11))
    assert "your callbacks for /turtle1/pose, /turtle1/scan take 50 ms" in pace.report(800_000_000)
    pace.charge(CALLS, 10.0, 800_000_000)
    assert "your callbacks for service and action answers take 10000 ms" in pace.report(800_000_000)


def test_time_a_busy_machine_kept_the_controller_waiting_is_not_its_own() -> None:
    pace = Pace(start_ns=0, subscriptions={1: ("on_pose", "/turtle1/pose")})
    behind = 0.0
    for i in range(100):
        behind = pace.charge(1, 0.040, 16_000_000 * (i + 1))
    assert behind == pytest.approx(4.0 - 1.6)
    assert pace.excuse(3.0, 1_600_000_000) == pytest.approx(4.0 - 3.0 - 1.6)
    report = pace.report(1_600_000_000)
    assert "(1.0 s of wall time for 1.6 s of simulated time, not counting 3.0 s" in report
    assert "your on_pose takes 10 ms on average" in report


# -- CPU ---------------------------------------------------------------------------------


@pytest.mark.parametrize("before", ["pass", "signal.signal(signal.SIGXCPU, signal.SIG_IGN)"], ids=["", "ignores SIGXCPU"])
def test_a_cpu_kill_is_reported_as_cpu(tmp_path: Path, before: str) -> None:
    """The soft CPU limit sends SIGXCPU; a controller that ignores it is killed
    at the hard one a few seconds later (SIGKILL): CPU either way, never
    "out of memory"."""
    path = pose_node(tmp_path, "work(30)", before)
    result = run([path], duration=5.0, limits=Limits(cpu_seconds=1, step_timeout=60.0, realtime_lag=None))
    [crash] = result.crashes
    assert crash.kind == "cpu", crash.details()
    assert crash.message == "used more than its CPU limit of 1 s"


# -- output ------------------------------------------------------------------------------


def test_output_over_the_budget_is_counted_and_one_line_says_how_much(tmp_path: Path) -> None:
    """20 MB printed: about 1 MB reaches ``run --headless``'s terminal (60 MB
    printed let 3.8 MB through before), then one line says what was dropped."""
    path = write(tmp_path, """
        import rclpy
        from rclpy.node import Node

        def main():
            rclpy.init()
            node = Node("printer")
            line = "x" * 99
            for _ in range(200_000):
                print(line)
            print("y" * 5000)
            node.get_logger().info("printed")
            rclpy.spin(node)
    """)
    result = CliRunner().invoke(app, ["run", str(path), "--headless", "--duration", "1"])
    assert result.exit_code == 0, result.output
    # 10,000 printed lines of 100 bytes on stdout; the node's log and turtletui's notices on stderr
    assert 900_000 < len(result.stdout) < 1_600_000
    assert "printed" in result.stderr
    [notice] = [line for line in result.stderr.splitlines() if "output over its budget" in line]
    assert "of 1.0 MB or 10,000 lines per run: the rest is dropped" in notice
    [dropped] = [line for line in result.stderr.splitlines() if "of output dropped" in line]
    assert f"{path}: 19.0 MB of output dropped (190,001 lines over its budget" in dropped


def test_long_lines_are_cut() -> None:
    shown: list[str] = []
    budget = OutputBudget(shown.append, max_bytes=10_000, max_lines=100, line_chars=10)
    budget.feed(b"short\n" + b"a" * 25 + b"\nnext")
    budget.feed(b" line\n" + b"b" * 100)  # a line without end yet: its start is shown
    budget.feed(b"b" * 100 + b"\nafter\n", final=True)
    assert shown == ["short", "aaaaaaaaaa [... cut]", "next line", "bbbbbbbbbb [... cut]", "after"]
    assert budget.dropped() == "205 bytes of output dropped (2 long lines cut at 10 characters)"


def test_output_past_the_budget_is_dropped_whole_lines_first() -> None:
    shown: list[str] = []
    budget = OutputBudget(shown.append, max_bytes=20, max_lines=100, line_chars=100)
    assert budget.feed(b"0123456789\n0123456789\nabc\n") is True
    assert shown == ["0123456789"]
    assert budget.feed(b"more\n" * 3) is False
    assert budget.dropped() == "30 bytes of output dropped (5 lines over its budget of 20 bytes or 100 lines per run)"


def test_the_default_budgets() -> None:
    limits = Limits()
    assert limits.output_bytes == 1_000_000 and limits.output_line_chars == 1000
    assert limits.realtime_lag == 3.0 and limits.run_seconds is None


def test_a_rate_cap_shows_so_many_lines_a_second_and_notes_the_rest() -> None:
    # the app's cap: no budget per run, at most 3 lines a second (a clock the test moves)
    shown: list[str] = []
    notes: list[int] = []
    now = [100.0]
    budget = OutputBudget(
        shown.append, max_bytes=1 << 40, max_lines=1 << 40, line_chars=100,
        lines_per_second=3, clock=lambda: now[0], note=notes.append,
    )
    budget.feed(b"a\nb\n")
    budget.feed(b"c\nd\ne\n")  # d and e: over this second's 3
    assert shown == ["a", "b", "c"] and notes == []
    now[0] = 100.5
    budget.feed(b"f\n")  # the same second
    now[0] = 101.2
    budget.feed(b"g\nh\n")  # a new second: the 3 not shown are told first
    assert shown == ["a", "b", "c", "g", "h"] and notes == [3]
    assert budget.over is False  # the run's budget is not spent: nothing is dropped for good
    assert budget.dropped() == "6 bytes of output dropped (3 lines over 3 a second)"


def test_the_child_sends_so_many_log_records_a_second_and_logs_a_note_of_the_rest() -> None:
    # the app's cap on a log flood, in the child: what is refused is neither sent nor
    # counted as over the run's budget; a [turtletui] note says how many, once a second
    from turtletui.graph.core import Graph
    from turtletui.graph.logs import INFO, WARN
    from turtletui.interfaces import interface_name
    from turtletui.runtime.budget import RateCap
    from turtletui.runtime.outbox import ParentOutbox

    graph = Graph(type_name=interface_name)
    now = [5.0]

    def note(count: int) -> None:
        graph.log("turtletui", WARN, f"{count} not shown")

    outbox = ParentOutbox(graph, log_rate=RateCap(2, lambda: now[0], note))
    outbox.install()
    for i in range(5):
        graph.log("flood", INFO, f"line {i}")
    now[0] = 6.5
    graph.log("flood", INFO, "line 5")
    report = outbox.report(None)
    assert [(log.node, log.text) for log in report.logs] == [
        ("flood", "line 0"), ("flood", "line 1"), ("turtletui", "3 not shown"), ("flood", "line 5"),
    ]
    assert report.logs_dropped == 0
