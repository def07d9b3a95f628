"""Where ROS 2 would wait for ever, turtletui says why and what to do, in both
hosts, and the run goes on to its end; what ROS 2 allows (a synchronous call in
a callback of its own group under a MultiThreadedExecutor) works. The programs
that ROS 2 runs to the end are in tests/fidelity (compared with the real rclpy)."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

import pytest

from turtletui.api import run

HOSTS = [
    pytest.param(False, id="in-process"),
    pytest.param(
        True, id="sandboxed", marks=pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX")
    ),
]

SERVICE_NODE = """
import threading
import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool


class Caller(Node):
    def __init__(self, client_group):
        super().__init__("caller")
        self.create_service(SetBool, "toggle", self.on_toggle, callback_group=ReentrantCallbackGroup())
        self.client = self.create_client(SetBool, "toggle", callback_group=client_group)
        self.create_timer(0.5, self.tick)

    def on_toggle(self, request, response):
        response.success = request.data
        return response

    def tick(self):
        response = self.client.call(SetBool.Request(data=True))  # CALLS HERE
        self.get_logger().info(f"answer {response.success}")
"""


def write(tmp_path: Path, name: str, source: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip(), encoding="utf-8")
    return path


def only_crash(result):
    assert len(result.crashes) == 1, result.crashes
    return result.crashes[0]


@pytest.mark.parametrize("sandbox", HOSTS)
def test_a_synchronous_call_in_a_single_threaded_callback_explains_the_deadlock(tmp_path, sandbox):
    path = write(tmp_path, "single.py", SERVICE_NODE + """
def main():
    rclpy.init()
    node = Caller(None)
    rclpy.spin(node)
""")
    result = run([path], duration=2.0, sandbox=sandbox)
    crash = only_crash(result)
    assert crash.t == pytest.approx(0.5)
    assert crash.message.startswith("RuntimeError: /toggle: Client.call() inside a callback would deadlock in ROS 2")
    assert "one thread" in crash.message
    assert "call_async()" in crash.message and "MultiThreadedExecutor" in crash.message
    assert any("CALLS HERE" in frame or "single.py" in frame for frame in crash.frames)
    assert result.sim_time == 2.0  # the run went on to its end


@pytest.mark.parametrize("sandbox", HOSTS)
def test_a_client_in_the_callbacks_own_exclusive_group_is_a_deadlock_even_multithreaded(tmp_path, sandbox):
    path = write(tmp_path, "same_group.py", SERVICE_NODE + """
def main():
    rclpy.init()
    node = Caller(None)  # the client in the node's default group, as the timer
    executor = MultiThreadedExecutor()
    executor.add_node(node)
    executor.spin()
""")
    crash = only_crash(run([path], duration=2.0, sandbox=sandbox))
    assert "same mutually exclusive callback group as the callback that waits" in crash.message


@pytest.mark.parametrize("sandbox", HOSTS)
def test_a_client_in_a_group_of_its_own_answers_under_a_multithreaded_executor(tmp_path, sandbox):
    path = write(tmp_path, "own_group.py", SERVICE_NODE + """
def main():
    rclpy.init()
    node = Caller(MutuallyExclusiveCallbackGroup())
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(node)
    executor.spin()
""")
    result = run([path], duration=1.6, sandbox=sandbox)
    assert result.ok, result.crashes
    assert [r.msg for r in result.logs if r.node == "caller"] == ["answer True"] * 3


@pytest.mark.parametrize("sandbox", HOSTS)
def test_a_call_from_main_with_nothing_spinning_explains_the_hang(tmp_path, sandbox):
    path = write(tmp_path, "main_call.py", """
import rclpy
from rclpy.node import Node
from std_srvs.srv import Empty


def main():
    rclpy.init()
    node = Node("main_caller")
    client = node.create_client(Empty, "/clear")
    client.wait_for_service()
    client.call(Empty.Request())
""")
    crash = only_crash(run([path], duration=1.0, sandbox=sandbox))
    assert crash.message.startswith("RuntimeError: /clear: Client.call() with nothing spinning the node")
    assert "threading.Thread(target=rclpy.spin" in crash.message


@pytest.mark.parametrize("sandbox", HOSTS)
def test_a_rate_with_nothing_spinning_explains_the_hang(tmp_path, sandbox):
    path = write(tmp_path, "rate.py", """
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("looper")
    rate = node.create_rate(10)
    rate.sleep()
""")
    crash = only_crash(run([path], duration=1.0, sandbox=sandbox))
    assert crash.message.startswith("RuntimeError: Rate.sleep() with nothing spinning the node")
    assert "create_timer" in crash.message


def test_a_call_that_times_out_raises_timeout_error(tmp_path):
    path = write(tmp_path, "timeout.py", """
import threading
import rclpy
from rclpy.node import Node
from std_srvs.srv import Empty


def main():
    rclpy.init()
    node = Node("impatient")
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    client = node.create_client(Empty, "/nobody_serves_this")
    try:
        client.call(Empty.Request(), timeout_sec=0.5)
    except TimeoutError:
        node.get_logger().info("timed out")
""")
    result = run([path], duration=2.0, sandbox=True)
    assert result.ok, result.crashes
    assert [(r.t, r.msg) for r in result.logs if r.node == "impatient"] == [(0.5, "timed out")]


@pytest.mark.parametrize("sandbox", [False, True], ids=["in-process", "sandboxed"])
def test_a_best_effort_cmd_vel_does_not_drive_turtlesim(tmp_path, sandbox):
    """Both sides warn, in rclpy's and rclcpp's words, whether turtlesim and
    the controller share a process or not."""
    path = write(tmp_path, "sensor_qos.py", """
import rclpy
from geometry_msgs.msg import Twist, Vector3
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", qos_profile_sensor_data)
        self.create_timer(0.1, lambda: self.pub.publish(Twist(linear=Vector3(x=1.0))))
        self.create_timer(0.55, lambda: self.get_logger().info(f"matched {self.pub.get_subscription_count()}"))


def main():
    rclpy.init()
    rclpy.spin(Driver())
""")
    result = run([path], duration=1.0, sandbox=sandbox, keep_poses=True)
    assert result.ok, result.crashes
    assert [r.msg for r in result.logs if r.node == "driver"] == [
        "New subscription discovered on topic '/turtle1/cmd_vel', requesting incompatible QoS. "
        "No messages will be sent to it. Last incompatible policy: RELIABILITY",
        "matched 0",
    ]
    assert (
        "New publisher discovered on topic '/turtle1/cmd_vel', offering incompatible QoS. "
        "No messages will be sent to it. Last incompatible policy: RELIABILITY_QOS_POLICY"
    ) in [r.msg for r in result.logs if r.node == "turtlesim"]
    assert {(x, y) for _, x, y, _ in result.poses["turtle1"]} == {(result.poses["turtle1"][0][1], result.poses["turtle1"][0][2])}



@pytest.mark.parametrize("sandbox", HOSTS)
def test_subscriptions_honour_their_groups_and_get_copies_of_their_own(tmp_path, sandbox):
    """A message for a busy MutuallyExclusive group waits for it (in order),
    a Reentrant group's runs at once, an async callback holds its group until
    it ends, and each subscription has its own copy of what was published."""
    path = write(tmp_path, "groups.py", """
import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import SetBool


class Groups(Node):
    def __init__(self):
        super().__init__("groups")
        group = MutuallyExclusiveCallbackGroup()
        self.pub = self.create_publisher(String, "chat", 10)
        self.create_subscription(String, "chat", self.in_group, 10, callback_group=group)
        self.create_subscription(String, "chat", self.reentrant, 10, callback_group=ReentrantCallbackGroup())
        self.create_subscription(String, "chat", self.awaits, 10)
        self.create_service(SetBool, "wait", self.on_wait, callback_group=ReentrantCallbackGroup())
        self.client = self.create_client(SetBool, "wait", callback_group=ReentrantCallbackGroup())
        self.create_timer(0.5, self.tick, callback_group=group)
        self.ticks = 0

    def say(self, text):
        self.get_logger().info(text)

    def tick(self):
        self.ticks += 1
        if self.ticks > 1:
            return
        for data in ("a", "b"):
            msg = String(data=data)
            self.pub.publish(msg)
            msg.data = "changed after publish"
        self.say("tick waits")
        self.client.call(SetBool.Request(data=True))
        self.say("tick done")

    def on_wait(self, request, response):
        response.success = request.data
        return response

    def in_group(self, msg):
        self.say(f"in_group {msg.data}")

    def reentrant(self, msg):
        self.say(f"reentrant {msg.data}")
        msg.data = "changed by reentrant"

    async def awaits(self, msg):
        self.say(f"awaits {msg.data} starts")
        await self.client.call_async(SetBool.Request(data=True))
        self.say(f"awaits {msg.data} ends")


def main():
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(Groups())
    executor.spin()


if __name__ == "__main__":
    main()
""")
    result = run([path], duration=1.0, sandbox=sandbox)
    assert result.ok, result.crashes
    said = [r.msg for r in result.logs if r.node == "groups"]
    assert sorted(said) == sorted([
        "tick waits", "tick done", "reentrant a", "reentrant b", "in_group a", "in_group b",
        "awaits a starts", "awaits a ends", "awaits b starts", "awaits b ends",
    ])
    assert said.index("reentrant b") < said.index("tick done") < said.index("in_group a") < said.index("in_group b")
    assert said.index("awaits a starts") < said.index("awaits a ends") < said.index("awaits b starts")


WORKER_RAISES = """
import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool


class Fragile(Node):
    def __init__(self):
        super().__init__("fragile")
        self.create_service(SetBool, "check", self.on_check, callback_group=ReentrantCallbackGroup())
        self.client = self.create_client(SetBool, "check", callback_group=MutuallyExclusiveCallbackGroup())
        self.asking = self.create_timer(0.1, self.ask, callback_group=MutuallyExclusiveCallbackGroup())
        self.create_timer(0.05, lambda: None, callback_group=MutuallyExclusiveCallbackGroup())

    def on_check(self, request, response):
        raise ValueError("cannot check")  # RAISES HERE

    def ask(self):
        self.asking.cancel()
        try:
            self.client.call(SetBool.Request(data=True), timeout_sec=0.5)
        except TimeoutError:
            self.get_logger().info("no answer in time")


def main():
    rclpy.init()
    node = Fragile()
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
"""


@pytest.mark.parametrize("sandbox", HOSTS)
def test_an_error_in_a_callback_beside_the_spinning_thread_leaves_spin_and_kills_the_node(tmp_path, sandbox):
    # As rclpy's MultiThreadedExecutor: not the end of one worker thread while the
    # node spins on, but spin() raising it in main(), so the program dies of it.
    path = write(tmp_path, "uncaught.py", WORKER_RAISES + """
    executor.spin()  # SPINS HERE
""")
    result = run([path], duration=3.0, sandbox=sandbox)
    crash = only_crash(result)
    assert crash.kind == "exception"
    assert crash.message.startswith("ValueError: cannot check")
    frames = "\n".join(crash.frames)
    assert "SPINS HERE" in frames and "RAISES HERE" in frames
    if sandbox:
        assert crash.t == pytest.approx(0.1)  # as soon as the main thread gets its turn
    else:
        # in-process the handler ran inside ask()'s wait, which it did not end
        assert [r.msg for r in result.logs if r.node == "fragile"] == ["no answer in time"]
        assert crash.t == pytest.approx(0.6)


@pytest.mark.parametrize("sandbox", HOSTS)
def test_after_a_callbacks_error_left_spin_the_executor_spins_on_and_shutdown_waits(tmp_path, sandbox):
    path = write(tmp_path, "caught.py", WORKER_RAISES + """
    try:
        executor.spin()
    except ValueError as err:
        node.get_logger().info(f"spin raised {err}")
    executor.spin_once(timeout_sec=0.1)
    node.get_logger().info(f"shut down: {executor.shutdown()}")
""")
    result = run([path], duration=3.0, sandbox=sandbox)
    assert result.ok, result.crashes
    said = [(r.t, r.msg) for r in result.logs if r.node == "fragile"]
    if sandbox:
        # spin_once runs the 0.15 s timer, shutdown() waits for ask() to time out
        assert said == [(0.1, "spin raised cannot check"), (0.6, "no answer in time"), (0.6, "shut down: True")]
    else:
        # in-process the handler ran inside ask()'s wait, so spin() raises after it
        assert said == [(0.6, "no answer in time"), (0.6, "spin raised cannot check"), (0.65, "shut down: True")]


@pytest.mark.parametrize("sandbox", HOSTS)
def test_a_custom_executor_that_spins_for_ever_stops_with_the_run(tmp_path, sandbox):
    # ROS 2 would spin until Ctrl-C; here the run's end stops it, without a crash,
    # and its spin_once took every tick through wait_for_ready_callbacks.
    path = write(tmp_path, "custom.py", """
import rclpy
from rclpy.executors import Executor
from rclpy.node import Node


class HandExecutor(Executor):
    def spin_once(self, timeout_sec=None):
        handler, entity, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)
        node.get_logger().info(f"{type(entity).__name__} of {node.get_name()}")
        handler()


def main():
    rclpy.init()
    node = Node("ticker")
    node.create_timer(0.5, lambda: None)
    executor = HandExecutor()
    executor.add_node(node)
    executor.spin()
""")
    result = run([path], duration=2.0, sandbox=sandbox)
    assert result.ok, result.crashes
    assert result.sim_time == 2.0
    assert [r.msg for r in result.logs if r.node == "ticker"] == ["Timer of ticker"] * 4
