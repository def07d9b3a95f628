"""What rcl and rclpy give every node besides what the student makes: /rosout and
/parameter_events publishers, parameter events, use_sim_time and /clock.

Checked against the real rclpy (Kilted) by tests/fidelity/programs/
plumbing_endpoints.py, parameter_events.py and use_sim_time.py; here the same
behaviour between two controller files (two processes when sandboxed), under
both hosts.
"""

from __future__ import annotations

from support.hosts import node_logs, write_controller

from turtletui.api import run
from turtletui.graph.logs import WARN

WATCHER = """
import rclpy
from rclpy.node import Node
from rcl_interfaces.msg import ParameterEvent


class Watcher(Node):
    def __init__(self):
        super().__init__("watcher")
        self.create_subscription(ParameterEvent, "/parameter_events", self.seen, 100)

    def seen(self, event):
        new = [p.name for p in event.new_parameters]
        changed = [(p.name, p.value.double_value) for p in event.changed_parameters]
        deleted = [p.name for p in event.deleted_parameters]
        self.get_logger().info(f"{event.node} {event.stamp.sec} {new} {changed} {deleted}")
"""

TUNER = """
import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter


class Tuner(Node):
    def __init__(self):
        super().__init__("tuner", allow_undeclared_parameters=True)
        self.timer = self.create_timer(0.5, self.tune)

    def tune(self):
        self.timer.cancel()
        self.declare_parameter("speed", 1.0)
        self.set_parameters([Parameter("speed", value=2.5)])
        self.set_parameters([Parameter("speed", value="fast")])  # refused: no event
        self.set_parameters([Parameter("gain", value=0.5)])
        self.set_parameters([Parameter("gain", Parameter.Type.NOT_SET)])
        self.undeclare_parameter("speed")  # rclpy publishes nothing for this
"""


def test_a_nodes_parameter_events_reach_a_node_in_another_file(tmp_path):
    # two files run sandboxed only (in-process runs one): parameter_events.py
    # in tests/fidelity has two nodes of one program under both hosts
    watcher = write_controller(tmp_path, WATCHER, "watcher.py")
    tuner = write_controller(tmp_path, TUNER, "tuner.py")
    result = run([watcher, tuner], duration=1.0)
    assert result.ok, result.crashes
    # The tuner's own declarations at start (use_sim_time ...) were published
    # before the watcher had discovered it: lost, as between two ROS 2 processes.
    assert node_logs(result, "watcher") == [
        "/tuner 1700000000 ['speed'] [] []",
        "/tuner 1700000000 [] [('speed', 2.5)] []",
        "/tuner 1700000000 ['gain'] [] []",
        "/tuner 1700000000 [] [] ['gain']",
    ]


def test_turtlesims_parameter_changes_are_parameter_events(controller_host):
    watcher = controller_host.write(WATCHER, "watcher.py")

    def set_background_later(sim):
        node = sim.turtlesim.node
        sim.graph.call_later(node, 500_000_000, lambda: node.parameter_setter("background_r", 10))

    result = run([watcher], duration=1.0, sandbox=controller_host.sandboxed, setup=set_background_later)
    assert result.ok, result.crashes
    assert node_logs(result, "watcher") == ["/turtlesim 1700000000 [] [('background_r', 0.0)] []"]


SIM_TIME = """
import rclpy
from rclpy.clock import Clock, ClockType
from rclpy.node import Node


class Timed(Node):
    def __init__(self):
        super().__init__("timed")
        # on a steady clock: a timer on the node's clock would follow /clock (tests/compat/test_sim_time.py)
        self.create_timer(0.25, self.tick, clock=Clock(clock_type=ClockType.STEADY_TIME))

    def tick(self):
        clock = self.get_clock()
        self.get_logger().info(f"{self.get_parameter('use_sim_time').value} {clock.ros_time_is_active} "
                               f"{clock.now().nanoseconds}")
"""

CLOCK = """
import rclpy
from rclpy.clock import Clock as WallClock, ClockType
from rclpy.node import Node
from rosgraph_msgs.msg import Clock


class Simulator(Node):
    def __init__(self):
        super().__init__("simulator")
        self.pub = self.create_publisher(Clock, "/clock", 10)
        self.seconds = 100
        self.create_timer(0.2, self.tick, clock=WallClock(clock_type=ClockType.STEADY_TIME))

    def tick(self):
        self.seconds += 1
        msg = Clock()
        msg.clock.sec = self.seconds
        self.pub.publish(msg)
"""


def test_use_sim_time_without_clock_stands_still_and_says_why_once(controller_host):
    program = controller_host.write(SIM_TIME, "timed.py")
    result = run([program], duration=0.6, sandbox=controller_host.sandboxed, ros_args=["-p", "use_sim_time:=true"])
    assert result.ok, result.crashes
    assert node_logs(result, "timed") == ["True True 0", "True True 0"]
    notes = [r.msg for r in result.logs if r.node == "turtletui" and "use_sim_time" in r.msg]
    assert len(notes) == 1
    assert notes[0].startswith("/timed uses simulated time (use_sim_time is true) but nothing publishes /clock")


def test_use_sim_time_follows_a_clock_published_by_another_file(tmp_path):
    timed = write_controller(tmp_path, SIM_TIME, "timed.py")
    clock = write_controller(tmp_path, CLOCK, "clock.py")
    result = run([timed, clock], duration=1.1, ros_args=["-p", "use_sim_time:=true"])
    assert result.ok, result.crashes
    # ticks at 0.25 s, 0.5 s ...; /clock says 101 s at 0.2 s, 102 s at 0.4 s ...
    assert node_logs(result, "timed") == [
        "True True 101000000000", "True True 102000000000", "True True 103000000000", "True True 104000000000",
    ]


def test_the_plumbing_topics_raise_no_typo_warning(controller_host):
    result = controller_host.run(SIM_TIME, duration=2.0)
    assert result.ok, result.crashes
    warnings = [r.msg for r in result.logs if r.level >= WARN]
    assert warnings == []
