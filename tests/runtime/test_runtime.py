"""How controllers are hosted: lockstep timing, simulated sleeps, determinism."""

import textwrap
from pathlib import Path

import pytest

from turtletui.api import run

PUBLISH_AND_SLEEP = """
import time
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = Node("sleeper")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    for i in range(4):
        msg = Twist()
        msg.linear.x = 1.0
        pub.publish(msg)
        node.get_logger().info(f"published {i}")
        time.sleep(0.5)
    rclpy.shutdown()
"""


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_time_sleep_in_main_lets_simulated_time_pass(tmp_path: Path, sandbox: bool) -> None:
    path = write(tmp_path, "sleeper.py", PUBLISH_AND_SLEEP)
    result = run([path], duration=4.0, sandbox=sandbox)
    assert result.crashes == []
    stamps = [r.t for r in result.logs if r.node == "sleeper"]
    assert stamps == [0.0, 0.5, 1.0, 1.5]
    # The command of t=0 goes before turtlesim has discovered the publisher
    # (lost, as in ROS 2); driven at 1 m/s from t=0.512 (the first update
    # after the command of t=0.5) until 1 s after the last command at t=1.5.
    assert result.turtles["turtle1"].distance == pytest.approx(1.98, abs=0.02)


def test_two_sandboxed_controllers_share_one_world(tmp_path: Path) -> None:
    sleeper = write(tmp_path, "sleeper.py", PUBLISH_AND_SLEEP)
    watcher = write(
        tmp_path,
        "watcher.py",
        """
        import rclpy
        from rclpy.node import Node
        from turtlesim.msg import Pose


        class Watcher(Node):
            def __init__(self):
                super().__init__("watcher")
                self.moving = False
                self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

            def on_pose(self, pose):
                if pose.linear_velocity > 0 and not self.moving:
                    self.moving = True
                    self.get_logger().info(f"moving at x={pose.x:.3f}")
        """,
    )
    result = run([sleeper, watcher], duration=2.0)
    assert result.crashes == []
    moving = [r for r in result.logs if r.node == "watcher"]
    assert [(r.t, r.msg) for r in moving] == [(0.512, "moving at x=5.560")]


def test_a_sandboxed_run_is_repeatable_including_hash_order(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "hashy.py",
        """
        import random
        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("hashy")
            words = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta"}
            node.get_logger().info(" ".join(words) + f" {random.random()}")
            rclpy.spin(node)
        """,
    )
    first, second = (
        [r.msg for r in run([path], duration=0.1).logs if r.node == "hashy"] for _ in range(2)
    )
    assert first == second and len(first) == 1


def test_spin_returns_when_a_callback_shuts_down(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "quitter.py",
        """
        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("quitter")
            node.create_timer(0.5, lambda: rclpy.shutdown())
            rclpy.spin(node)
            node.get_logger().info("spin returned")
        """,
    )
    for sandbox in (True, False):
        result = run([path], duration=2.0, sandbox=sandbox)
        assert result.crashes == []
        assert [r.t for r in result.logs if r.msg == "spin returned"] == [0.5]


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_a_crash_is_logged_as_one_line_records_with_the_students_frames(tmp_path: Path, sandbox: bool) -> None:
    path = write(
        tmp_path,
        "crasher.py",
        """
        import rclpy
        from rclpy.node import Node


        def boom():
            return 1 / 0


        def main():
            rclpy.init()
            node = Node("crasher")
            node.create_timer(0.25, boom)
            rclpy.spin(node)
        """,
    )
    result = run([path], duration=1.0, sandbox=sandbox)
    lines = [r.msg for r in result.logs if r.node == "turtletui"]
    assert all("\n" not in line for line in lines)
    assert lines[0].startswith(f"controller {path} crashed at t=0.250 s: ZeroDivisionError")
    # The student's frames only, outermost first, as Python prints them.
    assert f'File "{path}", line 14, in main' in lines[1]
    assert f'File "{path}", line 7, in boom' in lines[-2]
    assert lines[-1].strip() == "return 1 / 0"
    assert not any("turtletui" in line for line in lines[1:])


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_a_loop_of_calls_cannot_stop_simulated_time(tmp_path: Path, sandbox: bool) -> None:
    path = write(
        tmp_path,
        "looper.py",
        """
        import rclpy
        from rclpy.node import Node
        from turtlesim.srv import SetPen


        def main():
            rclpy.init()
            node = Node("looper")
            client = node.create_client(SetPen, "/turtle1/set_pen")
            client.wait_for_service()
            calls = 0
            while rclpy.ok():
                future = client.call_async(SetPen.Request(r=calls % 256))
                rclpy.spin_until_future_complete(node, future)
                calls += 1
            node.get_logger().info(f"calls: {calls}")
        """,
    )
    result = run([path], duration=0.5, sandbox=sandbox, keep_calls=False)
    assert result.sim_time == pytest.approx(0.5)
    [line] = [r.msg for r in result.logs if r.node == "looper"]
    calls = int(line.split()[1])
    ticks = (0.5 - 0.05) / 0.016  # from the discovery of the service (50 ms)
    # At most 64 at each instant: t=0.05, every 16 ms tick, and the end.
    assert ticks * 32 < calls <= (ticks + 2) * 64


SERVER = """
import rclpy
from rclpy.node import Node
from std_srvs.srv import SetBool


class Switch(Node):
    def __init__(self):
        super().__init__("switch")
        self.create_service(SetBool, "/switch", self.on_request)

    def on_request(self, request, response):
        response.success = True
        response.message = "on" if request.data else "off"
        return response
"""

CLIENT = """
import rclpy
from rclpy.node import Node
from std_srvs.srv import SetBool


def main():
    rclpy.init()
    node = Node("caller")
    client = node.create_client(SetBool, "/switch")
    if not client.wait_for_service(timeout_sec=1.0):
        node.get_logger().error("no /switch")
        return
    for data in (True, False):
        future = client.call_async(SetBool.Request(data=data))
        rclpy.spin_until_future_complete(node, future)
        node.get_logger().info(f"{future.result().success} {future.result().message}")
    rclpy.spin(node)
"""


@pytest.mark.parametrize("server_in_process", [False, True], ids=["both-sandboxed", "server-in-process"])
def test_a_controllers_service_answers_another_controller(tmp_path: Path, server_in_process: bool) -> None:
    from turtletui.runtime.loader import ControllerSpec

    server = write(tmp_path, "switch.py", SERVER)
    client = write(tmp_path, "caller.py", CLIENT)
    server_spec = ControllerSpec("switch", path=server, trusted=server_in_process)
    result = run([server_spec, client], duration=1.0)
    assert result.crashes == []
    assert [r.msg for r in result.logs if r.node == "caller"] == ["True on", "True off"]
    assert [(name, req.data, resp.message) for _, name, req, resp in result.service_calls] == [
        ("/switch", True, "on"),
        ("/switch", False, "off"),
    ]


def test_a_plugin_node_factory_runs_sandboxed_and_in_process(tmp_path: Path, monkeypatch) -> None:
    from turtletui.runtime.loader import ControllerSpec

    package = tmp_path / "site" / "square_plugin"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text(textwrap.dedent("""
        def nodes():
            from square_plugin.driver import Driver
            return [Driver]
    """))
    (package / "driver.py").write_text(textwrap.dedent("""
        from geometry_msgs.msg import Twist
        from rclpy.node import Node


        class Driver(Node):
            def __init__(self):
                super().__init__("driver")
                self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
                self.create_timer(0.1, self.drive)

            def drive(self):
                msg = Twist()
                msg.linear.x = 1.0
                self.pub.publish(msg)
    """))
    monkeypatch.syspath_prepend(str(tmp_path / "site"))
    import square_plugin

    distances = []
    for trusted in (False, True):
        spec = ControllerSpec("square", factory=square_plugin.nodes, trusted=trusted)
        result = run([spec], duration=1.0)
        assert result.crashes == []
        distances.append(result.turtles["turtle1"].distance)
    assert distances[0] == distances[1] == pytest.approx(0.9, abs=0.05)
