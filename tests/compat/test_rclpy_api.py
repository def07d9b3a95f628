"""Ordinary rclpy controllers, written to tmp_path, run in-process by turtletui.api.run."""

from __future__ import annotations

import math
import struct
import textwrap
from pathlib import Path

import pytest

from turtletui.api import RosArgsError, run
from turtletui.graph.core import LOCKSTEP_EPOCH_NS
from turtletui.plugins.bundled import reference_path


def f32(value: float) -> float:
    return struct.unpack("f", struct.pack("f", value))[0]


def write(tmp_path: Path, name: str, source: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip(), encoding="utf-8")
    return path


def node_logs(result, node: str) -> list[str]:
    return [r.msg for r in result.logs if r.node == node]


def line_of(path: Path, marker: str) -> int:
    """1-based line number of the line containing ``marker``."""
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        if marker in line:
            return number
    raise AssertionError(f"{marker!r} not in {path}")


# -- the course's Part 6 node -------------------------------------------------------------


def test_part6_reference_controller_drives_60_s_without_hitting_a_wall(controller_host):
    path = reference_path("turtle_controller.py")
    assert path.exists()
    result = run([path], duration=60.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    assert result.sim_time == 60.0
    logs = node_logs(result, "turtle_controller")
    assert logs[0] == "Turtle autonomous driving controller has started! (Collision Avoidance Mode)"
    assert "Warning: Approaching wall detected! Changing direction." in logs
    assert result.wall_hits == 0
    assert not any("I hit the wall" in r.msg for r in result.logs)
    assert result.turtles["turtle1"].distance > 100.0
    turtle = result.turtles["turtle1"]
    assert 0.0 < turtle.x < 11.0889 and 0.0 < turtle.y < 11.0889


def test_part4_reference_draw_circle_runs_open_loop_on_a_circle(controller_host):
    result = run([reference_path("draw_circle.py")], duration=10.0, sandbox=controller_host.sandboxed, keep_poses=True)
    assert result.crashes == []
    assert node_logs(result, "draw_circle") == ["Draw circle node has been started"]
    # linear 2 m/s, angular 1 rad/s from the centre facing +x: radius 2 around (c, c + 2)
    c = 499 / 90
    moving = [(x, y) for t, x, y, _ in result.poses["turtle1"] if t > 0.6]
    assert len(moving) > 500
    radii = [math.hypot(x - c, y - (c + 2.0)) for x, y in moving]
    assert min(radii) == pytest.approx(2.0, abs=0.02) and max(radii) == pytest.approx(2.0, abs=0.02)
    assert result.turtles["turtle1"].distance == pytest.approx(2.0 * (10.0 - 0.5), abs=0.1)
    assert result.wall_hits == 0


def test_part5_reference_pose_subscriber_logs_every_pose(controller_host):
    result = run([reference_path("pose_subscriber.py")], duration=1.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    logs = node_logs(result, "pose_subscriber")
    assert len(logs) == 59  # ticks 2..62 publish a pose; the first two come before discovery (50 ms)
    assert set(logs) == {"(5.544444561004639, 5.544444561004639)"}


# -- timers and logging --------------------------------------------------------------------


def test_timer_node_logs_once_per_simulated_second(tmp_path, controller_host):
    path = write(
        tmp_path,
        "counter_node.py",
        """
        import rclpy
        from rclpy.node import Node


        class Counter(Node):
            def __init__(self):
                super().__init__("counter")
                self.count = 0
                self.create_timer(1.0, self.tick)

            def tick(self):
                self.get_logger().info(f"count {self.count}")
                self.count += 1


        def main():
            rclpy.init()
            rclpy.spin(Counter())
            rclpy.shutdown()
        """,
    )
    result = run([path], duration=5.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    records = [r for r in result.logs if r.node == "counter"]
    assert [r.msg for r in records] == [f"count {i}" for i in range(5)]
    assert [r.t for r in records] == [1.0, 2.0, 3.0, 4.0, 5.0]
    assert all(r.level_name == "INFO" for r in records)


def test_node_subclass_without_main_is_run(tmp_path, controller_host):
    path = write(
        tmp_path,
        "no_main_node.py",
        """
        from rclpy.node import Node


        class Hello(Node):
            def __init__(self):
                super().__init__("hello")
                self.create_timer(0.5, lambda: self.get_logger().info("hi"))
        """,
    )
    result = run([path], duration=2.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    assert node_logs(result, "hello") == ["hi"] * 4


def test_logger_throttle_duration_and_once(tmp_path, controller_host):
    path = write(
        tmp_path,
        "throttle_node.py",
        """
        import rclpy
        from rclpy.node import Node


        class Chatty(Node):
            def __init__(self):
                super().__init__("chatty")
                self.create_timer(0.1, self.tick)

            def tick(self):
                self.get_logger().info("throttled", throttle_duration_sec=1.0)
                self.get_logger().warn("only once", once=True)
                self.get_logger().debug("hidden at INFO level")


        def main():
            rclpy.init()
            rclpy.spin(Chatty())
        """,
    )
    result = run([path], duration=3.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    records = [r for r in result.logs if r.node == "chatty"]
    throttled = [r.t for r in records if r.msg == "throttled"]
    assert throttled == pytest.approx([0.1, 1.1, 2.1])
    once = [r for r in records if r.msg == "only once"]
    assert len(once) == 1 and once[0].level_name == "WARN" and once[0].t == pytest.approx(0.1)
    assert not any(r.msg == "hidden at INFO level" for r in records)


def test_clock_now_follows_simulated_time(tmp_path, controller_host):
    path = write(
        tmp_path,
        "clock_node.py",
        """
        import rclpy
        from rclpy.node import Node


        class Clocky(Node):
            def __init__(self):
                super().__init__("clocky")
                self.get_logger().info(f"start {self.get_clock().now().nanoseconds}")
                self.create_timer(0.5, self.tick)

            def tick(self):
                self.get_logger().info(f"now {self.get_clock().now().nanoseconds}")


        def main():
            rclpy.init()
            rclpy.spin(Clocky())
        """,
    )
    result = run([path], duration=2.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    logs = node_logs(result, "clocky")
    assert logs[0] == f"start {LOCKSTEP_EPOCH_NS}"
    stamps = [int(m.split()[1]) for m in logs[1:]]
    assert stamps == [LOCKSTEP_EPOCH_NS + k * 500_000_000 for k in range(1, 5)]
    records = [r for r in result.logs if r.node == "clocky"]
    assert all(r.stamp_ns == int(r.msg.split()[1]) for r in records)


def test_duration_and_time_arithmetic():
    import turtletui.compat

    turtletui.compat.install()
    from rclpy.clock import ClockType
    from rclpy.duration import Duration
    from rclpy.time import Time

    t0 = Time(seconds=2, nanoseconds=500)
    t1 = Time(seconds=3.25)
    assert (t1 - t0) == Duration(nanoseconds=1_249_999_500)
    assert t0 + Duration(seconds=1) == Time(nanoseconds=3_000_000_500)
    assert t1 - Duration(seconds=0.25) == Time(seconds=3)
    assert Duration(seconds=1.5) > Duration(seconds=1)
    assert Duration(seconds=0.5) * 3 == Duration(seconds=1.5)
    assert Duration(seconds=2) - Duration(seconds=0.5) == Duration(nanoseconds=1_500_000_000)
    assert t0 < t1 and t1 >= t0
    assert t1.seconds_nanoseconds() == (3, 250_000_000)
    msg = t1.to_msg()
    assert (msg.sec, msg.nanosec) == (3, 250_000_000)
    assert Time.from_msg(msg).nanoseconds == 3_250_000_000
    d = Duration(seconds=1.75).to_msg()
    assert (d.sec, d.nanosec) == (1, 750_000_000)
    with pytest.raises(TypeError):
        Time(seconds=1, clock_type=ClockType.ROS_TIME) - Time(seconds=1, clock_type=ClockType.SYSTEM_TIME)
    with pytest.raises(ValueError):
        Time(seconds=-1)


def test_duration_plus_time_is_a_time_as_in_rclpy():
    # rclpy: Duration.__add__ returns NotImplemented for a Time, so Time.__radd__ answers.
    import turtletui.compat

    turtletui.compat.install()
    from rclpy.duration import Duration
    from rclpy.time import Time

    later = Duration(seconds=1) + Time(seconds=2)
    assert type(later) is Time
    assert later.nanoseconds == 3_000_000_000


def test_comparing_a_time_with_another_type_is_false_as_in_rclpy():
    # rclpy's Time.__eq__ returns NotImplemented for non-Time objects: == is False, not an error.
    import turtletui.compat

    turtletui.compat.install()
    from rclpy.duration import Duration
    from rclpy.time import Time

    assert (Time(seconds=1) == Duration(seconds=1)) is False
    assert (Time(seconds=1) != None) is True  # noqa: E711


# -- services -------------------------------------------------------------------------------------


def test_service_client_call_async_with_done_callback_changes_the_pen(tmp_path, controller_host):
    path = write(
        tmp_path,
        "pen_client.py",
        """
        import rclpy
        from rclpy.node import Node
        from turtlesim.srv import SetPen


        class PenNode(Node):
            def __init__(self):
                super().__init__("pen_node")
                self.client = self.create_client(SetPen, "/turtle1/set_pen")
                self.timer = self.create_timer(0.5, self.change)

            def change(self):
                self.timer.cancel()
                request = SetPen.Request()
                request.r = 255
                request.g = 0
                request.b = 0
                request.width = 5
                request.off = 0
                future = self.client.call_async(request)
                future.add_done_callback(self.done)

            def done(self, future):
                self.get_logger().info(f"pen changed: {type(future.result()).__name__}")


        def main():
            rclpy.init()
            rclpy.spin(PenNode())
        """,
    )
    sims = []
    result = run([path], duration=2.0, sandbox=controller_host.sandboxed, setup=sims.append)
    assert result.crashes == []
    calls = [c for c in result.service_calls if c[1] == "/turtle1/set_pen"]
    assert len(calls) == 1
    t, _, request, _ = calls[0]
    assert t == pytest.approx(0.5)
    assert (request.r, request.g, request.b, request.width, request.off) == (255, 0, 0, 5, 0)
    assert node_logs(result, "pen_node") == ["pen changed: SetPen_Response"]
    turtle = sims[0].world.turtles["turtle1"]
    assert turtle.pen_color == (255, 0, 0) and turtle.pen_width == 5


def test_part7_reference_pen_controller_switches_colours(tmp_path, controller_host):
    path = reference_path("turtle_controller_pen.py")
    result = run([path], duration=20.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    pens = [(c[2].r, c[2].g, c[2].b) for c in result.service_calls if c[1] == "/turtle1/set_pen"]
    assert pens[:2] == [(255, 0, 0), (0, 255, 0)]
    assert all(a != b for a, b in zip(pens, pens[1:], strict=False))  # only on a side change
    assert result.wall_hits == 0


def test_spin_until_future_complete_in_main_spawns_a_turtle(tmp_path, controller_host):
    path = write(
        tmp_path,
        "spawner.py",
        """
        import rclpy
        from turtlesim.srv import Spawn


        def main():
            rclpy.init()
            node = rclpy.create_node("spawner")
            client = node.create_client(Spawn, "/spawn")
            if not client.wait_for_service(timeout_sec=1.0):
                raise RuntimeError("no /spawn")
            future = client.call_async(Spawn.Request(x=2.0, y=3.0, theta=0.5, name=""))
            rclpy.spin_until_future_complete(node, future)
            node.get_logger().info(f"spawned {future.result().name} done={future.done()}")
            node.destroy_node()
            rclpy.shutdown()
        """,
    )
    result = run([path], duration=1.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    assert node_logs(result, "spawner") == ["spawned turtle2 done=True"]
    assert sorted(result.turtles) == ["turtle1", "turtle2"]
    turtle2 = result.turtles["turtle2"]
    assert (turtle2.x, turtle2.y, turtle2.theta) == (2.0, 3.0, 0.5)
    assert result.sim_time == 1.0
    spawn_calls = [c for c in result.service_calls if c[1] == "/spawn"]
    assert len(spawn_calls) == 1 and spawn_calls[0][3].name == "turtle2"


def test_spin_until_future_complete_inside_a_callback_is_a_crash_not_a_hang(tmp_path, controller_host):
    path = write(
        tmp_path,
        "deadlock_node.py",
        """
        import rclpy
        from rclpy.node import Node
        from turtlesim.srv import Spawn


        class Deadlock(Node):
            def __init__(self):
                super().__init__("deadlock")
                self.client = self.create_client(Spawn, "/spawn")
                self.create_timer(0.5, self.tick)

            def tick(self):
                future = self.client.call_async(Spawn.Request(x=1.0, y=1.0, theta=0.0))
                rclpy.spin_until_future_complete(self, future)  # WAITS HERE


        def main():
            rclpy.init()
            rclpy.spin(Deadlock())
        """,
    )
    result = run([path], duration=3.0, sandbox=controller_host.sandboxed)
    assert len(result.crashes) == 1
    crash = result.crashes[0]
    assert crash.kind == "exception"
    assert crash.t == pytest.approx(0.5)
    assert crash.message.startswith("RuntimeError: spin_until_future_complete() was called inside a callback")
    assert "deadlock" in crash.message
    assert "call_async() with add_done_callback()" in crash.message
    assert any(f'"{path.resolve()}", line {line_of(path, "WAITS HERE")}' in f for f in crash.frames)
    assert result.sim_time == 3.0  # the run went on to its end
    assert not result.ok


NESTED_WAIT = """
    import rclpy
    from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
    from rclpy.node import Node
    from std_srvs.srv import Empty


    class Clearer(Node):
        def __init__(self):
            super().__init__("clearer")
            group = MutuallyExclusiveCallbackGroup() if OWN_GROUP else None
            self.client = self.create_client(Empty, "/clear", callback_group=group)
            self.ticks = 0
            self.create_timer(0.5, self.tick)

        def tick(self):
            self.ticks += 1
            future = self.client.call_async(Empty.Request())
            rclpy.spin_until_future_complete(self, future, timeout_sec=TIMEOUT)
            self.get_logger().info(f"tick {self.ticks} done={future.done()}")


    def main():
        rclpy.init()
        rclpy.spin(Clearer())
    """


@pytest.mark.parametrize(
    ("own_group", "timeout", "done"),
    [
        # the client in a group of its own: the nested spin handles its response
        (True, None, "True"),
        (True, 1.0, "True"),
        # in the timer's (the node's default) group: its response waits until the
        # timer returns, so the nested spin waits out its timeout, and the timer goes on
        (False, 0.2, "False"),
    ],
)
def test_spin_until_future_complete_in_a_callback_spins_as_rclpy_does(
    tmp_path, controller_host, own_group, timeout, done
):
    # rclpy spins the executor again inside the callback: what other callback
    # groups have ready runs, and a timeout ends the wait (Kilted's rclpy, run;
    # https://github.com/ros2/rclpy/issues/1018, /issues/1313)
    source = NESTED_WAIT.replace("OWN_GROUP", str(own_group)).replace("TIMEOUT", str(timeout))
    path = write(tmp_path, "nested_wait.py", source)
    result = run([path], duration=2.9, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    assert node_logs(result, "clearer") == [f"tick {n} done={done}" for n in range(1, 6)]


def test_client_call_inside_a_callback_is_refused_with_an_explanation(tmp_path, controller_host):
    path = write(
        tmp_path,
        "sync_call_node.py",
        """
        import rclpy
        from rclpy.node import Node
        from std_srvs.srv import Empty


        class SyncCall(Node):
            def __init__(self):
                super().__init__("sync_call")
                self.client = self.create_client(Empty, "/clear")
                self.create_timer(0.25, self.tick)

            def tick(self):
                self.client.call(Empty.Request())


        def main():
            rclpy.init()
            rclpy.spin(SyncCall())
        """,
    )
    result = run([path], duration=1.0, sandbox=controller_host.sandboxed)
    assert len(result.crashes) == 1
    assert result.crashes[0].message.startswith("RuntimeError: /clear: Client.call() inside a callback would deadlock")


# -- actions ------------------------------------------------------------------------------------------


def test_action_client_rotate_absolute_with_feedback_and_result(tmp_path, controller_host):
    path = write(
        tmp_path,
        "rotator.py",
        """
        import rclpy
        from rclpy.action import ActionClient
        from rclpy.node import Node
        from turtlesim.action import RotateAbsolute


        class Rotator(Node):
            def __init__(self):
                super().__init__("rotator")
                self.feedback = []
                self.client = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
                self.client.wait_for_server()
                goal = RotateAbsolute.Goal()
                goal.theta = 1.0
                future = self.client.send_goal_async(goal, feedback_callback=self.on_feedback)
                future.add_done_callback(self.on_goal)

            def on_feedback(self, msg):
                self.feedback.append(msg.feedback.remaining)

            def on_goal(self, future):
                handle = future.result()
                self.get_logger().info(f"accepted {handle.accepted}")
                handle.get_result_async().add_done_callback(self.on_result)

            def on_result(self, future):
                response = future.result()
                self.get_logger().info(
                    f"status {response.status} delta {response.result.delta!r} "
                    f"feedback {len(self.feedback)} first {self.feedback[0]!r}"
                )


        def main():
            rclpy.init()
            rclpy.spin(Rotator())
        """,
    )
    result = run([path], duration=3.0, sandbox=controller_host.sandboxed)
    assert result.crashes == []
    logs = node_logs(result, "rotator")
    assert logs[0] == "accepted True"
    assert len(logs) == 2
    words = logs[1].split()
    assert words[0:2] == ["status", "4"]  # GoalStatus.STATUS_SUCCEEDED
    delta = float(words[3])
    assert delta == pytest.approx(-0.992, abs=1e-5)
    assert delta == f32(delta)
    assert int(words[5]) == 63
    assert float(words[7]) == 1.0
    assert result.turtles["turtle1"].theta == pytest.approx(0.992, abs=1e-6)


# -- parameters and --ros-args ---------------------------------------------------------------------------


PARAM_NODE = """
import rclpy
from rclpy.node import Node


class Speedy(Node):
    def __init__(self):
        super().__init__("speedy")
        self.declare_parameter("speed", 1.0)
        value = self.get_parameter("speed").value
        double = self.get_parameter("speed").get_parameter_value().double_value
        self.get_logger().info(f"speed {value!r} {type(value).__name__} double {double!r}")


def main():
    rclpy.init()
    rclpy.spin(Speedy())
"""


def test_parameter_from_the_command_line_overrides_the_default(tmp_path, controller_host):
    path = write(tmp_path, "speedy.py", PARAM_NODE)
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed, ros_args=["-p", "speed:=3.0"])
    assert result.crashes == []
    assert node_logs(result, "speedy") == ["speed 3.0 float double 3.0"]


def test_parameter_default_without_override(tmp_path, controller_host):
    path = write(tmp_path, "speedy_default.py", PARAM_NODE)
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    assert node_logs(result, "speedy") == ["speed 1.0 float double 1.0"]


def test_parameter_override_with_explicit_ros_args_marker(tmp_path, controller_host):
    path = write(tmp_path, "speedy_marker.py", PARAM_NODE)
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed, ros_args=["--ros-args", "-p", "speedy:speed:=2.5"])
    assert node_logs(result, "speedy") == ["speed 2.5 float double 2.5"]


def test_integer_override_of_a_double_parameter_is_refused_with_a_hint(tmp_path, controller_host):
    path = write(tmp_path, "speedy_int.py", PARAM_NODE)
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed, ros_args=["-p", "speed:=3"])
    assert len(result.crashes) == 1
    message = result.crashes[0].message
    assert message.startswith("InvalidParameterTypeException: ")
    assert "'speed'" in message
    assert "expecting type 'DOUBLE'" in message
    assert "3.0" in message
    assert node_logs(result, "speedy") == []


def test_malformed_ros_args_raise_ros_args_error(tmp_path):
    path = write(tmp_path, "speedy_bad.py", PARAM_NODE)
    with pytest.raises(RosArgsError, match=r"-p speed.*NAME:=VALUE"):
        run([path], duration=0.5, sandbox=False, ros_args=["-p", "speed"])
    with pytest.raises(RosArgsError, match="needs a value"):
        run([path], duration=0.5, sandbox=False, ros_args=["-p"])


def test_remap_sends_turtle1_commands_to_turtle2(tmp_path, controller_host):
    path = write(
        tmp_path,
        "remapped.py",
        """
        import rclpy
        from geometry_msgs.msg import Twist
        from turtlesim.srv import Spawn


        def main():
            rclpy.init()
            node = rclpy.create_node("remapped")
            client = node.create_client(Spawn, "/spawn")
            client.wait_for_service()
            future = client.call_async(Spawn.Request(x=2.0, y=2.0, theta=0.0, name="turtle2"))
            rclpy.spin_until_future_complete(node, future)
            pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
            node.get_logger().info(f"publishing on {pub.topic_name}")

            def tick():
                msg = Twist()
                msg.linear.x = 1.0
                pub.publish(msg)

            node.create_timer(0.1, tick)
            rclpy.spin(node)
        """,
    )
    result = run([path], duration=2.0, sandbox=controller_host.sandboxed, ros_args=["--remap", "/turtle1/cmd_vel:=/turtle2/cmd_vel"])
    assert result.crashes == []
    assert node_logs(result, "remapped") == ["publishing on /turtle2/cmd_vel"]
    assert result.turtles["turtle1"].distance == 0.0
    assert result.turtles["turtle2"].distance > 1.5
    assert result.turtles["turtle2"].x > 3.5


def test_remap_with_short_flag_and_relative_topic(tmp_path, controller_host):
    path = write(
        tmp_path,
        "remapped_rel.py",
        """
        import rclpy
        from geometry_msgs.msg import Twist


        def main():
            rclpy.init()
            node = rclpy.create_node("rel")
            pub = node.create_publisher(Twist, "cmd_vel", 10)
            node.get_logger().info(pub.topic_name)
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed, ros_args=["-r", "cmd_vel:=/turtle1/cmd_vel"])
    assert node_logs(result, "rel") == ["/turtle1/cmd_vel"]


# -- messages --------------------------------------------------------------------------------------------


def test_assigning_an_int_to_a_float_field_fails_mentioning_the_float(tmp_path, controller_host):
    path = write(
        tmp_path,
        "int_field.py",
        """
        import rclpy
        from geometry_msgs.msg import Twist


        def main():
            rclpy.init()
            node = rclpy.create_node("int_field")
            msg = Twist()
            try:
                msg.linear.x = 2
            except AssertionError as err:
                node.get_logger().error(f"AssertionError: {err}")
            node.get_logger().info(f"x stays {msg.linear.x!r}")
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    logs = node_logs(result, "int_field")
    assert len(logs) == 2
    assert logs[0].startswith("AssertionError: ")
    assert "2.0" in logs[0] and "'x'" in logs[0]
    assert logs[1] == "x stays 0.0"


def test_int_field_assertion_directly():
    from turtletui.interfaces.geometry_msgs import Twist

    msg = Twist()
    with pytest.raises(AssertionError, match=r"2\.0"):
        msg.linear.x = 2
    msg.linear.x = 2.0
    assert msg.linear.x == 2.0


def test_publishing_the_wrong_message_type_names_both_types(tmp_path, controller_host):
    path = write(
        tmp_path,
        "wrong_type.py",
        """
        import rclpy
        from geometry_msgs.msg import Twist
        from turtlesim.msg import Pose


        def main():
            rclpy.init()
            node = rclpy.create_node("wrong_type")
            pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
            try:
                pub.publish(Pose())
            except TypeError as err:
                node.get_logger().error(f"TypeError: {err}")
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    logs = node_logs(result, "wrong_type")
    assert len(logs) == 1
    assert logs[0].startswith("TypeError: ")
    assert "geometry_msgs/msg/Twist" in logs[0]
    assert "turtlesim/msg/Pose" in logs[0]


def test_uncaught_wrong_message_type_is_a_crash(tmp_path, controller_host):
    path = write(
        tmp_path,
        "wrong_type_crash.py",
        """
        import rclpy
        from geometry_msgs.msg import Twist
        from std_msgs.msg import String


        def main():
            rclpy.init()
            node = rclpy.create_node("wrong_type_crash")
            pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
            pub.publish(String(data="go"))  # BAD PUBLISH
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    assert len(result.crashes) == 1
    message = result.crashes[0].message
    assert message.startswith("TypeError: ")
    assert "geometry_msgs/msg/Twist" in message and "std_msgs/msg/String" in message
    assert any(f"line {line_of(path, 'BAD PUBLISH')}" in f for f in result.crashes[0].frames)


def test_a_turtlesim_msgs_subscriber_receives_turtlesims_poses(tmp_path, controller_host):
    path = write(
        tmp_path,
        "msgs_sub.py",
        """
        import rclpy
        from turtlesim_msgs.msg import Pose


        def main():
            rclpy.init()
            node = rclpy.create_node("msgs_sub")
            got = []
            node.create_subscription(Pose, "/turtle1/pose", got.append, 10)
            node.create_timer(1.0, lambda: node.get_logger().info(f"{len(got)} {got[0].x:.6f}"))
            rclpy.spin(node)
        """,
    )
    result = run([path], duration=1.0, sandbox=controller_host.sandboxed, distro="kilted")  # turtlesim_msgs from Kilted on
    assert result.crashes == []
    assert node_logs(result, "msgs_sub") == ["59 5.544445"]  # ticks 4..62: discovery takes 50 ms


# -- QoS -----------------------------------------------------------------------------------------------


def test_qos_profile_and_sensor_data_profile_are_accepted(tmp_path, controller_host):
    path = write(
        tmp_path,
        "qos_node.py",
        """
        import rclpy
        from geometry_msgs.msg import Twist
        from rclpy.node import Node
        from rclpy.qos import QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
        from turtlesim.msg import Pose


        class QosNode(Node):
            def __init__(self):
                super().__init__("qos_node")
                self.poses = 0
                self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", QoSProfile(depth=3))
                self.sub = self.create_subscription(Pose, "/turtle1/pose", self.on_pose, qos_profile_sensor_data)
                self.create_timer(0.5, self.tick)
                profile = QoSProfile(depth=4, reliability=ReliabilityPolicy.BEST_EFFORT)
                self.get_logger().info(f"ready {profile.depth} {qos_profile_sensor_data.depth}")

            def on_pose(self, pose):
                self.poses += 1

            def tick(self):
                msg = Twist()
                msg.linear.x = 1.0
                self.pub.publish(msg)
                self.get_logger().info(f"poses {self.poses}")


        def main():
            rclpy.init()
            rclpy.spin(QosNode())
        """,
    )
    sims = []
    depths = {}

    def on_log(record):
        if record.node == "qos_node" and record.msg.startswith("ready"):
            graph = sims[0].graph
            mine = [s for s in graph.topics["/turtle1/pose"].subscriptions if s.node.name == "qos_node"]
            pubs = [p for p in graph.topics["/turtle1/cmd_vel"].publishers if p.node.name == "qos_node"]
            depths["sub"] = [s.depth for s in mine]
            depths["pub"] = [p.depth for p in pubs]

    result = run([path], duration=2.0, sandbox=controller_host.sandboxed, setup=sims.append, on_log=on_log)
    assert result.crashes == []
    logs = node_logs(result, "qos_node")
    assert logs[0] == "ready 4 5"
    assert depths == {"sub": [5], "pub": [3]}
    # poses from ticks 2..31, ..62, ..93, ..124 (tick 125 at exactly 2.0 s is delivered after the timer)
    assert logs[1:] == ["poses 28", "poses 59", "poses 90", "poses 121"]  # none before discovery (50 ms)
    assert result.turtles["turtle1"].distance > 1.0


def test_qos_profile_without_depth_is_refused():
    import turtletui.compat

    turtletui.compat.install()
    from rclpy.qos import QoSProfile

    with pytest.raises(ValueError, match=r"^History and/or depth settings are required\.$"):  # rclpy's text
        QoSProfile()
    assert QoSProfile(depth=7).depth == 7


# -- crashes --------------------------------------------------------------------------------------------------


CRASHER = """
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Crasher(Node):
    def __init__(self):
        super().__init__("crasher")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.ticks = 0
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.ticks += 1
        msg = Twist()
        msg.linear.x = 1.0
        msg.angular.z = 0.2
        self.pub.publish(msg)
        if self.ticks == 10:
            self.explode()

    def explode(self):
        raise ValueError("boom")  # RAISES HERE


def main():
    rclpy.init()
    rclpy.spin(Crasher())
"""


def test_a_crash_in_a_callback_is_reported_with_frames_and_the_run_goes_on(tmp_path, controller_host):
    path = write(tmp_path, "crasher.py", CRASHER)
    result = run([path], duration=4.0, sandbox=controller_host.sandboxed)
    assert result.sim_time == 4.0
    assert len(result.crashes) == 1
    crash = result.crashes[0]
    assert crash.kind == "exception"
    assert crash.message == "ValueError: boom"
    assert crash.t == pytest.approx(1.0)
    frames = "\n".join(crash.frames)
    resolved = str(path.resolve())
    assert f'File "{resolved}", line {line_of(path, "RAISES HERE")}, in explode' in frames
    assert f'File "{resolved}", line {line_of(path, "self.explode()")}, in tick' in frames
    assert 'raise ValueError("boom")' in frames
    assert "site-packages" not in frames and "turtletui/" not in frames  # only the controller's own file
    crash_logs = [r for r in result.logs if r.node == "turtletui"]
    # The summary, then two lines per frame of the student's file.
    assert len(crash_logs) == 1 + 2 * len(crash.frames)
    assert {r.level_name for r in crash_logs} == {"ERROR"}
    assert crash_logs[0].msg.startswith("controller ")
    assert "crashed at t=1.000 s: ValueError: boom" in crash_logs[0].msg
    # turtlesim goes on publishing after the crash
    assert [r.t for r in result.logs if r.node == "crasher"] == []
    assert result.turtles["turtle1"].x > 5.544


def test_the_turtle_stops_at_once_when_its_controller_crashes(tmp_path, controller_host):
    # The crashing callback published a Twist just before raising; that command
    # must not keep the turtle driving for another second after the crash.
    path = write(tmp_path, "crasher_stop.py", CRASHER)
    result = run([path], duration=4.0, sandbox=controller_host.sandboxed, keep_poses=True)
    crash = result.crashes[0]
    poses = result.poses["turtle1"]
    before = [x for t, x, _, _ in poses if t < crash.t]
    assert before[-1] > before[0]  # it was moving
    after = [(x, y, theta) for t, x, y, theta in poses if t > crash.t]
    assert len(after) > 150
    assert len(set(after)) == 1, f"still moving until t={max(t for t, x, y, th in poses if (x, y, th) != after[-1]):.3f}"
    turtle = result.turtles["turtle1"]
    assert (f32(turtle.x), f32(turtle.y), f32(turtle.theta)) == after[-1]
    assert turtle.distance == pytest.approx(0.9, abs=0.05)


DRIVE_THEN_CRASH = """
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Crasher(Node):
    def __init__(self):
        super().__init__("crasher")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.drive)
        self.create_timer(1.05, self.explode)

    def drive(self):
        msg = Twist()
        msg.linear.x = 1.0
        self.pub.publish(msg)

    def explode(self):
        raise KeyError("gone")
"""

# The course's Part 6 main() destroys the node in `finally:`, before the
# runtime learns of the crash; the turtle must stop all the same.
MAIN_WITH_FINALLY = """

def main():
    rclpy.init()
    node = Crasher()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()
"""


@pytest.mark.parametrize("main", ["", MAIN_WITH_FINALLY], ids=["node-class-only", "main-with-finally"])
def test_the_turtle_stops_when_the_controller_crashes_in_another_callback(tmp_path, main, controller_host):
    path = tmp_path / "crasher.py"
    path.write_text(DRIVE_THEN_CRASH + main)
    result = run([path], duration=3.0, sandbox=controller_host.sandboxed, keep_poses=True)
    assert [c.message for c in result.crashes] == ["KeyError: 'gone'"]
    after = {(x, y, theta) for t, x, y, theta in result.poses["turtle1"] if t > 1.05}
    assert len(after) == 1
    assert result.turtles["turtle1"].distance == pytest.approx(0.944, abs=0.02)


def test_a_crash_at_import_time_reports_the_line(tmp_path, controller_host):
    path = write(
        tmp_path,
        "bad_import.py",
        """
        import rclpy

        value = 1 / 0  # ZERO


        def main():
            rclpy.init()
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    assert len(result.crashes) == 1
    assert result.crashes[0].message == "ZeroDivisionError: division by zero"
    assert any(f"line {line_of(path, 'ZERO')}" in f for f in result.crashes[0].frames)
    assert result.sim_time == 0.5


def test_sys_exit_with_an_error_status_is_reported(tmp_path, controller_host):
    path = write(
        tmp_path,
        "exits.py",
        """
        import sys


        def main():
            sys.exit(3)
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    assert [(c.kind, c.message) for c in result.crashes] == [("exit", "exited with status 3")]


@pytest.mark.parametrize(
    ("code", "message"),
    [("1", "exited with status 1"), ('"bye"', "exited with status 1: bye"), ('"bye\\n  now"', "exited with status 1: bye now")],
)
def test_sys_exit_in_a_callback_says_where_and_the_status_python_exits_with(tmp_path, controller_host, code, message):
    # sys.exit("bye") prints bye and exits with status 1, as python3 FILE does;
    # the report named neither the status nor the line that exited
    path = write(
        tmp_path,
        "exits.py",
        f"""
        import sys
        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("quitter")
            node.create_timer(0.25, lambda: sys.exit({code}))  # EXIT
            rclpy.spin(node)
        """,
    )
    result = run([path], duration=0.5, sandbox=controller_host.sandboxed)
    assert [(c.kind, c.message) for c in result.crashes] == [("exit", message)]
    summary = result.crashes[0].summary()
    assert summary.endswith(f'(File "{path}", line {line_of(path, "EXIT")}, in <lambda>)'), summary


def test_run_refuses_a_bad_duration(tmp_path):
    path = write(tmp_path, "speedy_dur.py", PARAM_NODE)
    for bad in (0.0, -1.0, math.nan):
        with pytest.raises(ValueError, match="duration"):
            run([path], duration=bad, sandbox=False)
