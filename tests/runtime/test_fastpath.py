"""The fast path of a sandboxed run (turtletui.runtime.fastpath): the child
runs the controller against its own copy of the simulation and the parent
replays what it did. It must give exactly what lockstep gives (and what the
in-process host gives), and a controller that tampers with its copy must
gain nothing: its run is reported as tampered.
"""

from __future__ import annotations

import textwrap
from dataclasses import replace
from pathlib import Path

import pytest

from turtletui.api import RunResult, run
from turtletui.graph.logs import PRINTED_SUFFIXES
from turtletui.runtime import fastpath
from turtletui.runtime.sandbox import Limits

FAST = Limits(lockstep=False)
"""The fast path even for runs too short for it to pay."""

REFERENCE = Path(__file__).resolve().parents[2] / "plugins" / "reference"


@pytest.fixture
def fast_runs(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The labels of the controllers that took the fast path in this test."""
    taken: list[str] = []
    start = fastpath.FastHost.start.__func__  # type: ignore[attr-defined]

    def counted(cls, sim, spec, **kwargs):  # noqa: ANN001, ANN202
        taken.append(spec.label)
        return start(cls, sim, spec, **kwargs)

    monkeypatch.setattr(fastpath.FastHost, "start", classmethod(counted))
    return taken


def write(tmp_path: Path, source: str, name: str = "controller.py") -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip(), encoding="utf-8")
    return path


def both_paths(path: Path, fast_runs: list[str], **options) -> tuple[RunResult, RunResult]:
    """The run on the fast path and in lockstep (asserting which is which)."""
    fast_limits = replace(options.get("limits") or Limits(), lockstep=False)
    fast = run([path], keep_poses=True, **{**options, "limits": fast_limits})
    assert fast_runs, "the run did not take the fast path"
    taken = len(fast_runs)
    limits = replace(options.pop("limits", None) or Limits(), lockstep=True)
    lockstep = run([path], keep_poses=True, limits=limits, **options)
    assert len(fast_runs) == taken, "Limits(lockstep=True) took the fast path"
    return fast, lockstep


def logs(result: RunResult, *, printed: bool = True) -> list[tuple]:
    return [(r.t, r.node, r.level, r.msg) for r in result.logs if printed or not r.node.endswith(PRINTED_SUFFIXES)]


def assert_same(fast: RunResult, other: RunResult, *, printed: bool = True) -> None:
    assert fast.poses == other.poses
    assert fast.service_calls == other.service_calls
    assert [c.details() for c in fast.crashes] == [c.details() for c in other.crashes]
    assert logs(fast, printed=printed) == logs(other, printed=printed)
    assert fast.sim_time == other.sim_time


# -- the same run, whichever path ------------------------------------------------------------------
@pytest.mark.parametrize("reference", sorted(p.name for p in REFERENCE.glob("*.py") if p.name != "__init__.py"))
def test_reference_controllers_run_the_same_on_both_paths_and_in_process(reference, fast_runs):
    path = REFERENCE / reference
    fast, lockstep = both_paths(path, fast_runs, duration=12.0)
    assert_same(fast, lockstep)
    in_process = run([path], duration=12.0, keep_poses=True, sandbox=False)
    assert fast.poses == in_process.poses
    assert fast.service_calls == in_process.service_calls


EVERYTHING = """
import math
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import Spawn, SetPen, TeleportAbsolute
from turtlesim.action import RotateAbsolute


class Everything(Node):
    def __init__(self):
        super().__init__("everything")
        self.declare_parameter("speed", 1.0)
        self.speed = self.get_parameter("speed").value
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        # published before anyone has discovered it: lost, as in ROS
        first = Twist()
        first.linear.x = 9.0
        self.cmd.publish(first)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.spawn = self.create_client(Spawn, "/spawn")
        self.pen = self.create_client(SetPen, "/turtle1/set_pen")
        self.teleport = self.create_client(TeleportAbsolute, "/turtle1/teleport_absolute")
        self.rotate = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.ticks = 0
        self.create_timer(0.05, self.tick)

    def on_pose(self, pose):
        self.pose = pose

    def tick(self):
        self.ticks += 1
        if self.ticks == 5:
            self.spawn.call_async(Spawn.Request(x=2.0, y=3.0, theta=0.5, name="second"))
            self.pen.call_async(SetPen.Request(r=255, g=0, b=0, width=4, off=0))
        if self.ticks == 20:
            future = self.teleport.call_async(TeleportAbsolute.Request(x=3.0, y=8.0, theta=1.0))
            future.add_done_callback(lambda f: self.get_logger().info("teleported"))
        if self.ticks == 30:
            self.rotate.wait_for_server(timeout_sec=1.0)
            goal = self.rotate.send_goal_async(RotateAbsolute.Goal(theta=-math.pi / 2), feedback_callback=self.feedback)
            goal.add_done_callback(self.accepted)
        if 30 <= self.ticks < 60:
            return
        cmd = Twist()
        cmd.linear.x = self.speed
        cmd.angular.z = 0.4
        self.cmd.publish(cmd)
        if self.ticks % 10 == 0:
            print(f"tick {self.ticks} x={getattr(self, 'pose', Pose()).x:.4f}", flush=True)

    def feedback(self, msg):
        self.remaining = msg.feedback.remaining

    def accepted(self, future):
        self.get_logger().info(f"goal accepted: {future.result().accepted}")
        future.result().get_result_async().add_done_callback(
            lambda f: self.get_logger().info(f"rotated, delta {f.result().result.delta:.5f}")
        )


def main():
    rclpy.init()
    rclpy.spin(Everything())
"""


def test_timers_services_actions_parameters_and_discovery_are_the_same(tmp_path, fast_runs):
    path = write(tmp_path, EVERYTHING)
    options = {"duration": 6.0, "ros_args": ["-p", "speed:=1.5"]}
    fast, lockstep = both_paths(path, fast_runs, **options)
    assert fast.ok, fast.crashes
    assert {"/spawn", "/turtle1/set_pen", "/turtle1/teleport_absolute"} <= {c[1] for c in fast.service_calls}
    assert any("rotated, delta" in r.msg for r in fast.logs)
    assert sum("tick" in r.msg for r in fast.logs) >= 5
    assert_same(fast, lockstep)
    in_process = run([path], keep_poses=True, sandbox=False, **options)
    assert_same(fast, in_process, printed=False)


QOS = """
import rclpy
from geometry_msgs.msg import Twist, Vector3
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("driver")
    cmd = node.create_publisher(Twist, "/turtle1/cmd_vel", qos_profile_sensor_data)
    kept = QoSProfile(depth=2, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    latched = node.create_publisher(String, "/latched", kept)
    for i in range(3):
        latched.publish(String(data=f"latched {i}"))
    other = Node("late")
    heard = []
    node.create_timer(0.1, lambda: cmd.publish(Twist(linear=Vector3(x=1.0))))

    def join():
        timer.cancel()
        latched_qos = QoSProfile(depth=5, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        other.create_subscription(String, "/latched", lambda m: heard.append(m.data), latched_qos)

    timer = node.create_timer(0.3, join)
    node.create_timer(1.0, lambda: node.get_logger().info(f"heard {heard} matched {cmd.get_subscription_count()}"))
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(other)
    executor.spin()
"""


def test_qos_mismatches_and_late_joiners_are_the_same_on_both_paths_and_in_process(tmp_path, fast_runs):
    path = write(tmp_path, QOS)
    fast, lockstep = both_paths(path, fast_runs, duration=1.5)
    assert fast.ok, fast.crashes
    assert any("offering incompatible QoS" in r.msg for r in fast.logs if r.node == "turtlesim")
    assert any(r.msg.startswith("heard ['latched 1', 'latched 2'") for r in fast.logs if r.node == "driver")
    assert_same(fast, lockstep)
    assert_same(fast, run([path], keep_poses=True, sandbox=False, duration=1.5), printed=False)


ON_CLOCK = """
import rclpy
from builtin_interfaces.msg import Time
from geometry_msgs.msg import Twist, Vector3
from rclpy.clock import Clock as SteadyClock, ClockType
from rclpy.node import Node
from rclpy.parameter import Parameter
from rosgraph_msgs.msg import Clock


class Driver(Node):
    \"\"\"Drives on /clock time, which its own steady timer publishes at 3/4 of the run's pace.\"\"\"

    def __init__(self):
        super().__init__("driver", parameter_overrides=[Parameter("use_sim_time", value=True)])
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.clock_pub = self.create_publisher(Clock, "/clock", 10)
        self.ns = 0
        self.create_timer(0.04, self.publish_clock, clock=SteadyClock(clock_type=ClockType.STEADY_TIME))
        self.create_timer(0.1, self.drive)
        self.turns = 0

    def publish_clock(self):
        self.ns += 30_000_000
        self.clock_pub.publish(Clock(clock=Time(sec=self.ns // 10**9, nanosec=self.ns % 10**9)))

    def drive(self):
        self.turns += 1
        self.cmd.publish(Twist(linear=Vector3(x=1.0), angular=Vector3(z=0.3 * (self.turns % 4))))
        self.get_logger().info(f"drive {self.turns} at {self.get_clock().now().nanoseconds}")
"""


def test_timers_on_clock_time_are_the_same_on_both_paths_and_in_process(tmp_path, fast_runs):
    path = write(tmp_path, ON_CLOCK)
    fast, lockstep = both_paths(path, fast_runs, duration=2.0)
    assert fast.ok, fast.crashes
    drives = [r.msg for r in fast.logs if r.node == "driver"]
    assert drives[:3] == ["drive 1 at 120000000", "drive 2 at 210000000", "drive 3 at 300000000"]
    assert fast.turtles["turtle1"].x > 6.0
    assert_same(fast, lockstep)
    assert_same(fast, run([path], keep_poses=True, sandbox=False, duration=2.0), printed=False)

def test_the_same_seed_gives_the_same_run_twice(tmp_path, fast_runs):
    path = write(tmp_path, EVERYTHING.replace("self.speed = self.get_parameter", "import random\n        self.speed = random.random() + 0 * self.get_parameter"))
    first = run([path], duration=4.0, keep_poses=True, seed=3, limits=FAST)
    again = run([path], duration=4.0, keep_poses=True, seed=3, limits=FAST)
    other = run([path], duration=4.0, keep_poses=True, seed=4, limits=FAST)
    assert len(fast_runs) == 3
    assert_same(first, again)
    assert first.poses != other.poses


MULTI_THREADED = """
import threading
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.srv import Spawn


class Threads(Node):
    def __init__(self):
        super().__init__("threads")
        group = ReentrantCallbackGroup()
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.spawn = self.create_client(Spawn, "/spawn", callback_group=group)
        self.create_timer(0.1, self.drive, callback_group=group)
        self.create_timer(0.5, self.call, callback_group=group)
        self.n = 0

    def drive(self):
        cmd = Twist()
        cmd.linear.x = 1.0
        cmd.angular.z = 0.5 if self.n % 2 else -0.5
        self.cmd.publish(cmd)

    def call(self):
        self.n += 1
        response = self.spawn.call(Spawn.Request(x=1.0 + self.n, y=2.0, theta=0.0, name=""))
        self.get_logger().info(f"spawned {response.name} on {threading.current_thread().name != ''}")


def main():
    rclpy.init()
    executor = MultiThreadedExecutor(num_threads=3)
    executor.add_node(Threads())
    executor.spin()
"""


def test_a_multi_threaded_executor_is_the_same_on_both_paths(tmp_path, fast_runs):
    fast, lockstep = both_paths(write(tmp_path, MULTI_THREADED), fast_runs, duration=3.0)
    assert fast.ok, fast.crashes
    assert sum("spawned" in r.msg for r in fast.logs) >= 4
    assert_same(fast, lockstep)


@pytest.mark.parametrize(
    "misbehaviour, kind",
    [
        ("raise ValueError('boom')", "exception"),
        ("os._exit(3)", "exit"),
        ("sys.exit(2)", "exit"),
        ("while True: pass", "timeout"),
        ("print('x' * 200, flush=True)", None),
    ],
)
def test_a_failing_controller_fails_at_the_same_instant_on_both_paths(tmp_path, fast_runs, misbehaviour, kind):
    path = write(
        tmp_path,
        """
        import os, sys
        import rclpy
        from rclpy.node import Node
        from geometry_msgs.msg import Twist


        class Failing(Node):
            def __init__(self):
                super().__init__("failing")
                self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
                self.create_timer(0.016, self.tick)
                self.n = 0

            def tick(self):
                self.n += 1
                cmd = Twist()
                cmd.linear.x = 1.0
                self.cmd.publish(cmd)
                if self.n % 7 == 0:
                    print("tick", self.n)
                if self.n == 40:
                    MISBEHAVE


        def main():
            rclpy.init()
            rclpy.spin(Failing())
        """.replace("MISBEHAVE", misbehaviour),
    )
    # the start may take a minute; a stuck callback after it is stopped at the step's timeout
    limits = Limits(step_timeout=0.5, start_timeout=60.0)
    fast, lockstep = both_paths(path, fast_runs, duration=1.5, limits=limits)
    assert [c.kind for c in fast.crashes] == ([kind] if kind else [])
    assert_same(fast, lockstep)
    assert fast.wall_time < 30  # about 1 s: the child's first answers came late, at the start's timeout


# -- tampering --------------------------------------------------------------------------------------
TAMPER = """
import gc
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Tamper(Node):
    def __init__(self):
        super().__init__("tamper")
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.05, self.tick)
        self.n = 0

    def tick(self):
        self.n += 1
        cmd = Twist()
        cmd.linear.x = 2.0
        self.cmd.publish(cmd)
        if self.n == 10:
            TAMPER


def main():
    rclpy.init()
    rclpy.spin(Tamper())
"""

TAMPERINGS = {
    # its copy's turtle teleported through the world object
    "world": """[w for w in gc.get_objects() if type(w).__name__ == "World"][0].place("turtle1", 1.0, 1.0, 0.0)""",
    # turtlesim's physics patched in the child: its copy's turtle stops
    "physics": """__import__("turtletui.sim.world").sim.world.World.step = lambda self, *a, **k: False""",
    # a made-up batch on the pipe
    "pipe": """__import__("os").write(__import__("turtletui.compat.context").compat.context.current_host().fd_out, b"\\0\\0\\0\\x04junk")""",
}


@pytest.mark.parametrize("how", sorted(TAMPERINGS))
def test_tampering_with_the_childs_copy_is_reported_and_changes_nothing_measured(tmp_path, fast_runs, how):
    path = write(tmp_path, TAMPER.replace("TAMPER\n", TAMPERINGS[how] + "\n").replace("            TAMPER", "            " + TAMPERINGS[how]))
    result = run([path], duration=3.0, keep_poses=True, limits=FAST)
    assert fast_runs
    assert [c.kind for c in result.crashes] == ["tampered"], result.crashes
    crash = result.crashes[0]
    assert "tampered with the simulator" in crash.message
    assert crash.t <= 2.0  # a made-up batch may come before the answers it overtook
    # the trusted simulation never saw the teleport: the turtle only drove east
    poses = result.poses["turtle1"]
    assert all(abs(y - poses[0][2]) < 1e-9 for _, _, y, _ in poses)
    assert not any(x == 1.0 for _, x, _, _ in poses)


GRADED = """+++
id = "fast-drive"
title = "Drive a metre while a scripted drive turns the turtle"

[[scenarios]]
name = "centre"
start = {x = 3.0, y = 5.5, theta = 0.0}
duration = 3.0
drive = {linear = 0.0, angular = 0.2}

[[checks]]
name = "distance"
weight = 1.0
thresholds = {min = 1.0}

[[checks]]
name = "no_crash"
weight = 1.0
+++
# Drive
"""


def test_a_submission_that_tampers_with_its_copy_scores_nothing_and_an_honest_one_is_unchanged(tmp_path, fast_runs):
    from support.grading import make_class

    from turtletui.grading.batch import grade_submissions
    from turtletui.grading.engine import prepare
    from turtletui.grading.submissions import find_submissions
    from turtletui.lessons.loader import load_lesson

    lesson = tmp_path / "drive.md"
    lesson.write_text(GRADED)
    plan = prepare(load_lesson(lesson))
    honest = TAMPER.replace("            TAMPER\n", "            pass\n")
    cheat = TAMPER.replace("TAMPER", TAMPERINGS["world"])
    klass = make_class(tmp_path / "class", {"honest": honest, "cheat": cheat})
    fast = {s.student: s for s in grade_submissions(plan, find_submissions([klass]), jobs=1).submissions}
    assert fast_runs
    taken = len(fast_runs)
    lockstep = grade_submissions(plan, find_submissions([klass / "honest"]), jobs=1, limits=Limits(lockstep=True))
    assert len(fast_runs) == taken
    assert fast["honest"].score == lockstep.submissions[0].score == 2.0
    assert [(t.name, t.status, t.output) for t in fast["honest"].tests] == [
        (t.name, t.status, t.output) for t in lockstep.submissions[0].tests
    ]
    assert fast["cheat"].score == 0.0
    assert "tampered" in "\n".join(t.output for t in fast["cheat"].tests)


def test_a_set_up_the_child_cannot_redo_keeps_the_lockstep_path(tmp_path, fast_runs):
    from turtletui.runtime.replica import ReplicableSetup

    path = write(tmp_path, TAMPER.replace("            TAMPER\n", "            pass\n"))

    def spawn_a_turtle(sim):  # noqa: ANN001, ANN202 - a plain set-up: opaque to the child
        sim.world.place("turtle1", 2.0, 2.0, 0.0)

    def add_a_node(sim):  # noqa: ANN001, ANN202 - an observer that changes the graph
        sim.graph.add_node("watcher", owner="test")

    for setup in (spawn_a_turtle, ReplicableSetup((), add_a_node)):
        result = run([path], duration=1.0, keep_poses=True, setup=setup, limits=FAST)
        assert result.ok, result.crashes
    assert fast_runs == []
    run([path], duration=1.0, setup=ReplicableSetup((), lambda sim: None), limits=FAST)
    assert len(fast_runs) == 1


IDLE = """
import rclpy
from rclpy.node import Node

rclpy.init()
rclpy.spin(Node("idle"))
"""


def test_without_a_fork_server_only_a_run_long_enough_to_repay_the_copy_takes_the_fast_path(tmp_path, fast_runs):
    from turtletui.runtime.replica import FAST_PATH_MIN_NS

    path = write(tmp_path, IDLE)
    short = run([path], duration=FAST_PATH_MIN_NS / 1e9 - 1)
    assert short.ok, short.crashes
    assert fast_runs == []
    long = run([path], duration=FAST_PATH_MIN_NS / 1e9)
    assert long.ok, long.crashes
    assert len(fast_runs) == 1


REPEATS = """
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64MultiArray, MultiArrayDimension
from turtlesim.msg import Pose

rclpy.init()
node = Node("repeats")
publisher = node.create_publisher(Float64MultiArray, "numbers", 10)

def send(pose):
    msg = Float64MultiArray(data=[1.0, 2.0])
    msg.layout.dim.append(MultiArrayDimension(label="x", size=2, stride=2))
    publisher.publish(msg)

node.create_subscription(Pose, "/turtle1/pose", send, 10)
rclpy.spin(node)
"""


def test_a_message_changed_by_whoever_received_it_leaves_the_next_identical_one_alone(tmp_path, fast_runs):
    # The same Report, tick after tick, is decoded once: each message built
    # from it must still be a message of its own.
    from turtletui.runtime.replica import ReplicableSetup

    path = write(tmp_path, REPEATS)
    for limits in (FAST, Limits(lockstep=True)):
        seen: list[tuple] = []

        def spoil(kind, payload, seen=seen):  # noqa: ANN001, ANN202
            if kind == "topic" and payload[0].name == "/numbers":
                msg = payload[1]
                seen.append((list(msg.data), [(d.label, d.size) for d in msg.layout.dim]))
                msg.data[0] = 99.0
                msg.layout.dim[0].label = "spoiled"
                msg.layout.dim.append(msg.layout.dim[0])

        result = run([path], duration=1.0, setup=ReplicableSetup((), lambda sim: sim.graph.taps.append(spoil)), limits=limits)
        assert result.ok, result.crashes
        assert len(seen) >= 40
        assert set(map(repr, seen)) == {repr(([1.0, 2.0], [("x", 2)]))}
    assert len(fast_runs) == 1
