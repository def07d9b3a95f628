"""The app's live session: its controllers live as long as the app (no CPU
cap, no cap per run on what they log, only so many lines a second; memory
still limited), they can be stopped and started, and the log rate of each
node is measured."""

from __future__ import annotations

import textwrap
import time
from pathlib import Path

from turtletui.graph.core import DISCOVERY_NS
from turtletui.runtime.loader import ControllerSpec
from turtletui.tui.session import LINES_PER_SECOND, LiveSession

NODE = textwrap.dedent("""
    import resource
    import rclpy
    from rclpy.node import Node


    def main():
        rclpy.init()
        node = Node("chatty")
        log = node.get_logger()

        def once():
            timer.cancel()
            for i in range(5_000):
                log.info(f"line {i}")

        def later():
            again.cancel()
            cpu = resource.getrlimit(resource.RLIMIT_CPU)[0]
            memory = resource.getrlimit(resource.RLIMIT_AS)[0]
            log.info(f"limits: cpu {'none' if cpu == resource.RLIM_INFINITY else cpu} memory {memory}")

        timer = node.create_timer(0.05, once)
        again = node.create_timer(1.5, later)
        rclpy.spin(node)
""")


def run_until(session: LiveSession, condition, timeout: float = 20.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        session.advance(time.monotonic())
        time.sleep(0.01)


def discovered(session: LiveSession) -> None:
    """Run until turtlesim has discovered teleop: a key pressed before is lost,
    as it is for turtle_teleop_key on a robot."""
    run_until(session, lambda: session.sim.graph.now_ns >= DISCOVERY_NS)


def test_controllers_in_the_app_have_no_cpu_cap_and_a_log_flood_is_told_not_shown(tmp_path: Path) -> None:
    path = tmp_path / "chatty.py"
    path.write_text(NODE)
    session = LiveSession([ControllerSpec("chatty", path=path)])
    try:
        run_until(session, lambda: any(r.msg.startswith("limits:") for r in session.logs))
        limits = next(r.msg for r in session.logs if r.msg.startswith("limits:"))
        assert limits.startswith("limits: cpu none memory ") and not limits.endswith(" -1")
        # no cap per run, but at most LINES_PER_SECOND a second (wall time): the 5,000 lines
        # logged at once are shown up to that, and the rest is told, not lost without a word
        shown = session.node_log_counts["chatty"]
        notes = [r.msg for r in session.logs if "log messages not shown" in r.msg]
        told = sum(int(note.split(" log messages")[0].replace(",", "")) for note in notes)
        assert LINES_PER_SECOND < shown < 5_001 and shown + told == 5_001, (shown, notes)
        assert all(note.endswith(f"the app shows at most {LINES_PER_SECOND:,} a second of each controller") for note in notes)
        assert session.slots[0].status == "running"
    finally:
        session.close()


def test_stop_and_start_the_controllers(tmp_path: Path) -> None:
    path = tmp_path / "chatty.py"
    path.write_text(NODE)
    session = LiveSession([ControllerSpec("chatty", path=path)])
    try:
        assert not session.controllers_held
        assert session.toggle_controllers() is False
        slot = session.slots[0]
        assert session.controllers_held and slot.host is None and (slot.status, slot.detail) == ("stopped", "by you")
        assert "/chatty" not in [n.fqn for n in session.sim.graph.nodes]
        path.write_text(NODE + "\n")  # a change to the file does not start a stopped node
        time.sleep(0.01)
        session.check_for_changes()
        assert slot.host is None
        assert session.toggle_controllers() is True
        assert slot.status == "running" and slot.host is not None and not session.controllers_held
    finally:
        session.close()


def test_log_rates_are_lines_per_wall_second_per_node() -> None:
    session = LiveSession()
    try:
        assert session.log_rates(100.0) == {}
        for _ in range(30):
            session.sim.graph.log("chatty", 20, "x")
        session.sim.graph.log("quiet", 20, "x")
        assert session.log_rates(100.5) == {}  # measured once a second
        assert session.log_rates(101.5) == {"chatty": 20.0, "quiet": 1 / 1.5}
        assert session.log_rates(103.0) == {}  # nothing since
    finally:
        session.close()


def test_a_new_world_starts_the_simulation_again_with_the_controllers_as_they_were(tmp_path: Path) -> None:
    from turtletui.runtime.turtlesim_args import parse_turtlesim_args
    from turtletui.worlds import resolve_world

    path = tmp_path / "quiet.py"
    path.write_text("import rclpy\nfrom rclpy.node import Node\n\n\ndef main():\n"
                    "    rclpy.init()\n    rclpy.spin(Node('quiet'))\n")
    args = parse_turtlesim_args(["-p", "background_r:=0", "-r", "__node:=my_sim"])
    session = LiveSession([ControllerSpec("one", path=path), ControllerSpec("two", path=path)], turtlesim=args)
    try:
        discovered(session)
        session.teleop.drive(1.0)
        run_until(session, lambda: session.sim.world.turtles["turtle1"].distance > 0.5)
        first, second = session.slots
        session.toggle_controllers()
        session.toggle_controllers()
        first.held = True  # stopped with s: it stays stopped in the new world
        session.change_world(resolve_world("lidar-course"))
        sim = session.sim
        assert session.t == 0.0 and sim.world.obstacles and sim.world.turtles["turtle1"].distance == 0.0
        assert sim.world.background[0] == 0 and any(n.fqn == "/my_sim" for n in sim.graph.nodes)  # its --ros-args
        assert first.host is None and second.host is not None and second.status == "running"
        discovered(session)
        session.teleop.drive(1.0)  # teleop drives the new turtle
        run_until(session, lambda: sim.world.turtles["turtle1"].distance > 0.5)
        assert any("starts again in the world lidar-course" in r.msg for r in session.logs)
    finally:
        session.close()


def test_a_recording_keeps_the_world(tmp_path: Path) -> None:
    import pytest

    from turtletui.worlds import resolve_world

    session = LiveSession(record=str(tmp_path / "run.jsonl"))
    try:
        assert session.world_fixed_by() == f"the recording to {tmp_path / 'run.jsonl'} (--record)"
        with pytest.raises(ValueError, match="keeps this session in its world"):
            session.change_world(resolve_world("lidar-course"))
        assert not session.sim.world.obstacles
    finally:
        session.close()


def test_the_teleop_keys_publish_from_teleop_turtles_cmd_vel_publisher() -> None:
    """As turtle_teleop_key: an rclcpp node whose publisher (reliable,
    volatile) others count and discover; a key pressed before
    turtlesim discovered it moves nothing, as on ROS 2."""
    from turtletui.graph.qos import Policies
    from turtletui.interfaces.geometry_msgs import Twist
    from turtletui.runtime.simulation import Simulation
    from turtletui.tui.session import Teleop

    logs: list = []
    sim = Simulation(log_sinks=[logs.append])
    teleop = Teleop(sim)
    [publisher] = sim.graph.publishers_of("/turtle1/cmd_vel")
    # keep last 7 from Jazzy on (turtlesim's topic_qos), 1 in Humble
    assert publisher.node.name == "teleop_turtle" and publisher.depth == 7 and publisher.qos == Policies()
    humble = Simulation(distro="humble")
    Teleop(humble)
    assert [p.depth for p in humble.graph.publishers_of("/turtle1/cmd_vel")] == [1]
    teleop.drive(linear=1.0)
    sim.run_until(DISCOVERY_NS)
    turtle = sim.world.turtles["turtle1"]
    assert turtle.distance == 0
    teleop.drive(linear=1.0)
    sim.run_until(DISCOVERY_NS + 200_000_000)
    assert turtle.distance > 0.3
    listener = sim.graph.add_node("listener")
    sim.graph.add_subscription(listener, "/turtle1/cmd_vel", Twist, 1, lambda m: None, qos=Policies(durability=1))
    assert [r.msg for r in logs if r.node == "teleop_turtle"] == [
        "New subscription discovered on topic '/turtle1/cmd_vel', requesting incompatible QoS. "
        "No messages will be sent to it. Last incompatible policy: DURABILITY_QOS_POLICY"
    ]


def test_on_a_real_graph_the_session_runs_as_its_distro(monkeypatch) -> None:
    """With --ros the simulated turtlesim names its types as the real graph's
    turtlesim does (turtlesim_msgs/... from Kilted on), whatever the default."""
    import turtletui.bridge.run as bridge_run

    attached = []
    monkeypatch.setattr(bridge_run, "attach", lambda sim, ros, **_: attached.append(sim) or None)
    for info, distro in (({"distro": "kilted", "turtlesim_package": "turtlesim_msgs"}, "kilted"),
                         ({"distro": "humble", "turtlesim_package": "turtlesim"}, "humble")):
        ros = bridge_run.RosConnection(twin=None, info=info)
        session = LiveSession([], ros=ros, start=False)
        try:
            assert session.sim.distro == distro
            assert attached[-1] is session.sim
        finally:
            session.close()
