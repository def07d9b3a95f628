"""Both hosts end a run alike: what is due at the last instant runs (a timer's
callback, a sleep that ends then, the code after it) until the controller waits
for a later moment; and each log line says whether a callback logged it."""

from __future__ import annotations

from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.sandbox import Limits

LOOPS = {
    "sleep": """
import time
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("looper")
    n = 0
    while rclpy.ok():
        node.get_logger().info(f"line {n}")
        n += 1
        time.sleep(1.0)
""",
    "spin_once": """
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("looper")
    n = 0
    while rclpy.ok():
        rclpy.spin_once(node, timeout_sec=1.0)
        node.get_logger().info(f"line {n}")
        n += 1
""",
    "timer": """
import rclpy
from rclpy.node import Node


class Looper(Node):
    def __init__(self):
        super().__init__("looper")
        self.get_logger().info("started")
        self.n = 0
        self.create_timer(1.0, self.tick)

    def tick(self):
        self.get_logger().info(f"line {self.n}")
        self.n += 1


def main():
    rclpy.init()
    rclpy.spin(Looper())
""",
}


def lines(path: Path, *, trusted: bool) -> list[tuple[float, str, bool]]:
    result = run([ControllerSpec("looper", path, trusted=trusted)], duration=3.0)
    assert result.ok, result.crashes
    return [(r.t, r.msg, r.in_callback) for r in result.logs if r.node == "looper"]


@pytest.mark.parametrize("kind", sorted(LOOPS))
def test_a_run_ends_alike_in_both_hosts_and_says_where_each_line_came_from(tmp_path: Path, kind: str) -> None:
    path = tmp_path / f"{kind}.py"
    path.write_text(LOOPS[kind])
    in_process = lines(path, trusted=True)
    assert lines(path, trusted=False) == in_process
    expected = {
        # the sleep that ends at t=3 s returns, its line is logged, the next sleep ends the run
        "sleep": [(0.0, "line 0", False), (1.0, "line 1", False), (2.0, "line 2", False), (3.0, "line 3", False)],
        # the last spin_once waits past the end: it returns at once and the loop logs once more
        "spin_once": [(1.0, "line 0", False), (2.0, "line 1", False), (3.0, "line 2", False), (3.0, "line 3", False)],
        "timer": [(0.0, "started", False), (1.0, "line 0", True), (2.0, "line 1", True), (3.0, "line 2", True)],
    }[kind]
    assert in_process == expected


SLEEPS_IN_A_CALLBACK = """
import time
import rclpy
from rclpy.node import Node


class Looper(Node):
    def __init__(self):
        super().__init__("looper")
        self.create_timer(0.5, self.loop)

    def loop(self):
        n = 0
        while True:  # never returns: on a robot it runs until the node is stopped
            self.get_logger().info(f"line {n}")
            n += 1
            time.sleep(1.0)


def main():
    rclpy.init()
    node = Looper()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        node.get_logger().info("stopped")
"""


@pytest.mark.parametrize("host", ["in-process", "fast", "lockstep"])
@pytest.mark.parametrize("caught", [True, False], ids=["caught", "uncaught"])
def test_a_callback_still_sleeping_at_the_end_is_stopped_as_ctrl_c_stops_a_node(
    tmp_path: Path, host: str, caught: bool
) -> None:
    # Its sleeps return at once once the run is over: the loop would never end.
    source = SLEEPS_IN_A_CALLBACK
    if not caught:
        source = source.replace("    try:\n        rclpy.spin(node)\n    except KeyboardInterrupt:\n", "    rclpy.spin(node)\n    if 0:\n")
    path = tmp_path / "looper.py"
    path.write_text(source)
    spec = ControllerSpec("looper", path, trusted=host == "in-process")
    result = run([spec], duration=3.0, limits=None if host == "in-process" else Limits(lockstep=host == "lockstep"))
    assert result.ok, result.crashes
    logged = [(r.t, r.msg) for r in result.logs if r.node == "looper"]
    expected = [(0.5, "line 0"), (1.5, "line 1"), (2.5, "line 2")]
    assert logged == expected + ([(3.0, "stopped")] if caught else [])
    assert not [r.msg for r in result.logs if "still busy" in r.msg]


def test_a_thread_still_looping_at_the_end_is_stopped_without_failing_the_run(tmp_path: Path) -> None:
    path = tmp_path / "driver.py"
    path.write_text("""
import threading, time
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = Node("driver")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)

    def drive():
        while True:  # not a daemon: the program never ends by itself
            msg = Twist()
            msg.linear.x = 1.0
            pub.publish(msg)
            time.sleep(0.1)

    threading.Thread(target=drive).start()
    rclpy.spin(node)
""")
    result = run([path], duration=3.0)
    assert result.ok, result.crashes
    assert result.turtles["turtle1"].distance > 2.0
    assert [r.msg for r in result.logs if r.node == "turtletui" and "still busy" in r.msg] == [
        f"{path}: still busy 1 s after the run ended (a loop in a thread that never returns?): stopped"
    ]


WAITS_IN_A_CALLBACK = {
    # each way a callback can wait in simulated time
    "rclpy clock": "self.get_clock().sleep_for(Duration(seconds=1.0))",
    "clock polling": "start = time.time()\n            while time.time() - start < 1.0:\n                pass",
}


@pytest.mark.parametrize("host", ["in-process", "fast", "lockstep"])
@pytest.mark.parametrize("wait", sorted(WAITS_IN_A_CALLBACK))
def test_a_callback_waiting_any_way_at_the_end_is_stopped_alike(tmp_path: Path, host: str, wait: str) -> None:
    source = SLEEPS_IN_A_CALLBACK.replace("time.sleep(1.0)", WAITS_IN_A_CALLBACK[wait]).replace(
        "import rclpy\n", "import rclpy\nfrom rclpy.duration import Duration\n", 1
    )
    path = tmp_path / "looper.py"
    path.write_text(source)
    spec = ControllerSpec("looper", path, trusted=host == "in-process")
    result = run([spec], duration=3.0, limits=None if host == "in-process" else Limits(lockstep=host == "lockstep"))
    assert result.ok, result.crashes
    logged = [r.msg for r in result.logs if r.node == "looper"]
    assert logged[-1] == "stopped" and len(logged) >= 3, logged
    assert not [r.msg for r in result.logs if "still busy" in r.msg]


@pytest.mark.parametrize("host", ["in-process", "sandboxed"])
def test_a_multithreaded_executors_callback_is_stopped_as_the_main_threads(tmp_path: Path, host: str) -> None:
    path = tmp_path / "looper.py"
    path.write_text(SLEEPS_IN_A_CALLBACK.replace(
        "        rclpy.spin(node)\n",
        "        from rclpy.executors import MultiThreadedExecutor\n        rclpy.spin(node, executor=MultiThreadedExecutor())\n",
    ))
    result = run([ControllerSpec("looper", path, trusted=host == "in-process")], duration=3.0)
    assert result.ok, result.crashes
    assert [r.msg for r in result.logs if r.node == "looper"][-1] == "stopped"
    assert not [r.msg for r in result.logs if "still busy" in r.msg]


@pytest.mark.parametrize("host", ["in-process", "fast", "lockstep"])
def test_a_loop_in_main_that_never_looks_at_rclpy_ok_ends_after_the_run(tmp_path: Path, host: str) -> None:
    path = tmp_path / "driver.py"
    path.write_text("""
import time
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = Node("driver")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    msg = Twist()
    msg.linear.x = 1.0
    try:
        while True:
            pub.publish(msg)
            time.sleep(0.1)
    finally:
        node.get_logger().info("stopped")
""")
    spec = ControllerSpec("driver", path, trusted=host == "in-process")
    result = run([spec], duration=3.0, limits=None if host == "in-process" else Limits(lockstep=host == "lockstep"))
    assert result.ok, result.crashes
    assert [(r.t, r.msg) for r in result.logs if r.node == "driver"] == [(3.0, "stopped")]
    assert not [r.msg for r in result.logs if "still busy" in r.msg]


@pytest.mark.parametrize("caught", [True, False], ids=["caught", "uncaught"])
def test_threads_still_run_to_their_end_after_the_run_ended_the_main_thread(tmp_path: Path, caught: bool) -> None:
    # as Python joins non-daemon threads after a KeyboardInterrupt too
    source = SLEEPS_IN_A_CALLBACK.replace(
        "    node = Looper()\n",
        "    node = Looper()\n"
        "    import threading\n"
        "    def last_words():\n"
        "        while rclpy.ok():\n"
        "            time.sleep(0.5)\n"
        "        node.get_logger().info('thread done')\n"
        "    threading.Thread(target=last_words).start()\n",
    )
    if not caught:
        source = source.replace("    try:\n        rclpy.spin(node)\n    except KeyboardInterrupt:\n", "    rclpy.spin(node)\n    if 0:\n")
    path = tmp_path / "looper.py"
    path.write_text(source)
    result = run([path], duration=3.0)
    assert result.ok, result.crashes
    assert "thread done" in [r.msg for r in result.logs if r.node == "looper"]


def test_a_timeout_the_child_reports_itself_at_the_end_stays_its_crash(tmp_path: Path) -> None:
    # only the parent's own wait for the last report may end a run quietly
    path = tmp_path / "forger.py"
    path.write_text("""
import rclpy
from rclpy.node import Node
from turtletui.runtime import outbox, protocol


def main():
    rclpy.init()
    rclpy.spin(Node("forger"))
    real = outbox.ParentOutbox.report

    def report(self, wake_ns, *, done=False, crash=None):
        if done:
            crash = protocol.Crash("timeout", "made up", ())
        return real(self, wake_ns, done=done, crash=crash)

    outbox.ParentOutbox.report = report
""")
    result = run([path], duration=1.0)
    assert [(c.kind, c.message) for c in result.crashes] == [("timeout", "made up")]
    assert not [r.msg for r in result.logs if "still busy" in r.msg]


@pytest.mark.parametrize("host", ["fast", "lockstep"])
def test_a_child_that_dies_on_its_way_out_after_the_run_is_no_crash(tmp_path: Path, host: str) -> None:
    # its last report never comes; what it does once the run is over counts for nothing
    path = tmp_path / "quitter.py"
    path.write_text(SLEEPS_IN_A_CALLBACK.replace(
        '        node.get_logger().info("stopped")\n', '        import os\n        os._exit(3)\n'
    ))
    result = run([path], duration=3.0, limits=Limits(lockstep=host == "lockstep"))
    assert result.ok, result.crashes
    assert [r.msg for r in result.logs if r.node == "looper"] == ["line 0", "line 1", "line 2"]


WAITS_FOR_A_MISSPELT_SERVICE = """
import rclpy
from rclpy.node import Node
from turtlesim.srv import SetPen


class PenNode(Node):
    def __init__(self):
        super().__init__("pen")
        self.create_timer(0.5, self.change_pen)

    def change_pen(self):
        client = self.create_client(SetPen, "/turtle1/setpen")  # the course's loop, a typo in the name
        for _ in range(10_000):  # bounded, so that a host that never stops it still ends the test
            if client.wait_for_service(1.0):
                return
            self.get_logger().warning("Waiting for service...")
        self.get_logger().info("never stopped")


def main():
    rclpy.init()
    node = PenNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        node.get_logger().info("stopped")
"""


@pytest.mark.parametrize("host", ["in-process", "fast", "lockstep"])
def test_a_callback_waiting_for_a_service_that_never_comes_is_stopped_at_the_end(tmp_path: Path, host: str) -> None:
    # Part 7's `while not client.wait_for_service(1.0)` with a misspelt name: once
    # the run is over each wait returned at once, so the loop went on for ever
    # (in-process: endless warnings; sandboxed: killed a second later as "still busy").
    path = tmp_path / "pen.py"
    path.write_text(WAITS_FOR_A_MISSPELT_SERVICE)
    spec = ControllerSpec("pen", path, trusted=host == "in-process")
    result = run([spec], duration=3.0, limits=None if host == "in-process" else Limits(lockstep=host == "lockstep"))
    assert result.ok, result.crashes
    logged = [(r.t, r.msg) for r in result.logs if r.node == "pen"]
    assert logged == [(1.5, "Waiting for service..."), (2.5, "Waiting for service..."), (3.0, "stopped")]
    assert not [r.msg for r in result.logs if "still busy" in r.msg]
