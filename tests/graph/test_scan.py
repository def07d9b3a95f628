"""The simulated LiDAR: sensor_msgs/LaserScan on /<turtle>/scan from the turtlesim node."""

from __future__ import annotations

import math
import struct

import numpy as np
import pytest

from turtletui.graph.core import LOCKSTEP_EPOCH_NS, NS_PER_S, Graph
from turtletui.graph.logs import WARN
from turtletui.graph.qos import DEFAULT, SENSOR_DATA
from turtletui.graph.turtlesim_node import TurtlesimNode
from turtletui.interfaces import interface_name
from turtletui.interfaces.geometry_msgs import Twist, Vector3
from turtletui.interfaces.sensor_msgs import LaserScan
from turtletui.interfaces.turtlesim import Kill, Spawn
from turtletui.sim import ARENA_SIZE, DT, Box, Circle, Lidar, World

TICK_NS = round(DT * NS_PER_S)
AHEAD = Box(8.0, 0.0, 9.0, 11.0)
"""A box across the arena, 8 m from the left wall: in front of turtle1."""


def f32(value: float) -> float:
    return struct.unpack("f", struct.pack("f", value))[0]


class Rig:
    """A graph with the turtlesim node over ``world`` and a test node."""

    def __init__(self, world: World) -> None:
        self.graph = Graph(type_name=interface_name)
        self.logs: list = []
        self.graph.log_sinks.append(self.logs.append)
        self.turtlesim = TurtlesimNode(self.graph, world)
        self.world = world
        self.node = self.graph.add_node("tester", owner="test")

    def observe(self, topic: str, qos=SENSOR_DATA) -> list[tuple[int, LaserScan]]:
        out: list[tuple[int, LaserScan]] = []
        self.graph.add_subscription(
            self.node, topic, LaserScan, 1000, lambda m: out.append((self.graph.now_ns, m)), qos=qos
        )
        return out

    def ticks(self, n: int) -> None:
        for _ in range(n):
            self.graph.advance(self.graph.now_ns + TICK_NS)
            self.graph.run_ready()

    def drive(self, vx: float, turtle: str = "turtle1") -> None:
        msg = Twist(linear=Vector3(x=vx))
        self.graph.publish(self.graph.topics[f"/{turtle}/cmd_vel"], msg)
        self.graph.run_ready()

    def call(self, service: str, request) -> None:
        self.graph.call(service, request, lambda response: None, owner="test")
        self.graph.run_ready()


def rig(lidar: Lidar | None = None, obstacles=(AHEAD,), seed: int = 0) -> Rig:
    return Rig(World(obstacles=obstacles, lidar=lidar, seed=seed))


def test_ranges_follow_the_geometry_relative_to_the_heading():
    r = rig(Lidar(samples=4, range_max=6.0))
    scans = r.observe("/turtle1/scan")
    r.ticks(2)
    turtle = r.world.turtles["turtle1"]
    ranges = list(scans[-1][1].ranges)
    # ahead (+x): the box; left (+y), behind, right: the walls
    expected = [8.0 - turtle.x, ARENA_SIZE - turtle.y, turtle.x, turtle.y]
    assert ranges == pytest.approx([f32(v) for v in expected], abs=1e-6)
    # Facing +y, the first beam looks up and the second (counter-clockwise) left.
    r.call("/spawn", Spawn.Request(x=3.0, y=2.0, theta=math.pi / 2, name="up"))
    scans_up = r.observe("/up/scan")
    r.ticks(1)
    up = list(scans_up[-1][1].ranges)
    assert up[:2] == [math.inf, 3.0]  # the top wall is 9.1 m up, past range_max


def test_readings_follow_rep_117_inf_beyond_range_minus_inf_too_close():
    r = rig(Lidar(samples=4, range_min=0.1, range_max=3.0))
    scans = r.observe("/turtle1/scan")
    r.ticks(2)
    ahead, left = scans[-1][1].ranges[:2]
    assert ahead == pytest.approx(f32(8.0 - r.world.turtles["turtle1"].x))
    assert left == math.inf  # the top wall is 5.5 m away, past range_max
    for _ in range(100):
        r.drive(2.0)
        r.ticks(1)
    assert r.world.turtles["turtle1"].x == 8.0  # blocked at the box
    assert scans[-1][1].ranges[0] == -math.inf


def test_message_fields_frame_and_stamp():
    lidar = Lidar(samples=72, range_min=0.12, range_max=3.5, rate=10.0)
    r = rig(lidar)
    scans = r.observe("/turtle1/scan")
    r.ticks(12)
    now_ns, msg = scans[0]
    assert msg.header.frame_id == "turtle1"
    stamp = msg.header.stamp.sec * NS_PER_S + msg.header.stamp.nanosec
    assert stamp == LOCKSTEP_EPOCH_NS + now_ns
    assert len(msg.ranges) == 72 and msg.ranges.typecode == "f"
    assert msg.intensities.tolist() == []
    assert msg.angle_min == 0.0
    assert msg.angle_increment == f32(2 * math.pi / 72)
    assert msg.angle_max == f32(71 * 2 * math.pi / 72)
    assert (msg.range_min, msg.range_max) == (f32(0.12), f32(3.5))
    assert msg.scan_time == f32(6 * DT)
    assert msg.time_increment == 0.0


def test_a_configured_rate_is_rounded_to_whole_ticks():
    r = rig(Lidar(samples=8, rate=10.0))  # 62.5 / 10 = 6.25: every 6th tick
    scans = r.observe("/turtle1/scan")
    r.ticks(60)
    times = [t for t, _ in scans]
    assert len(times) == 10
    assert set(np.diff(times)) == {6 * TICK_NS}


def test_without_a_rate_every_pose_tick_scans():
    r = rig(Lidar(samples=8))
    scans = r.observe("/turtle1/scan")
    poses: list = []
    r.graph.add_subscription(r.node, "/turtle1/pose", r.graph.topics["/turtle1/pose"].msg_type, 1000, poses.append)
    r.ticks(10)
    assert len(scans) == len(poses) == 9  # the first tick only records the time


def noisy_ranges(seed: int, subscribe_late: bool = False) -> np.ndarray:
    r = rig(Lidar(samples=90, range_max=20.0, noise_std=0.05), seed=seed)
    if subscribe_late:
        r.ticks(5)
    scans = r.observe("/turtle1/scan")
    r.ticks(5 if subscribe_late else 10)
    return np.array([list(m.ranges) for _, m in scans[-3:]])


def test_noise_is_deterministic_for_a_seed_and_differs_between_seeds():
    first = noisy_ranges(seed=7)
    assert np.array_equal(first, noisy_ranges(seed=7))
    assert not np.array_equal(first, noisy_ranges(seed=8))
    # A subscriber that joins late sees the same values as one there from the start.
    assert np.array_equal(first, noisy_ranges(seed=7, subscribe_late=True))


def test_noise_has_the_standard_deviation_of_the_world():
    r = rig(Lidar(samples=360, range_max=20.0, noise_std=0.05), obstacles=())
    scans = r.observe("/turtle1/scan")
    r.ticks(3)
    turtle = r.world.turtles["turtle1"]
    clean = Lidar(samples=360, range_max=20.0).scan((), turtle.x, turtle.y, turtle.theta)
    errors = np.concatenate([np.asarray(m.ranges) - clean for _, m in scans])
    assert abs(errors.mean()) < 0.01
    assert 0.045 < errors.std() < 0.055


def test_the_scan_is_best_effort_so_a_reliable_subscription_hears_nothing_and_is_told():
    r = rig(Lidar(samples=8))
    reliable = r.observe("/turtle1/scan", qos=DEFAULT)
    best_effort = r.observe("/turtle1/scan")
    r.ticks(5)
    assert reliable == [] and len(best_effort) == 4
    assert [rec.msg for rec in r.logs if rec.level == WARN] == [
        "New subscription discovered on topic '/turtle1/scan', requesting incompatible QoS. "
        "No messages will be sent to it. Last incompatible policy: RELIABILITY_QOS_POLICY"
    ]


def dropped(seed: int, dropout: float = 0.05, scans: int = 40) -> np.ndarray:
    """Which readings of ``scans`` scans came back nan."""
    r = rig(Lidar(samples=90, range_max=20.0, noise_std=0.01, dropout=dropout), seed=seed)
    seen = r.observe("/turtle1/scan")
    r.ticks(scans + 1)
    return np.isnan(np.array([list(m.ranges) for _, m in seen]))


def test_dropped_readings_are_nan_at_the_configured_share_and_repeat_with_the_seed():
    failed = dropped(seed=3)
    assert failed.shape == (40, 90)
    assert 0.035 < failed.mean() < 0.065  # 3,600 readings at 5 %
    assert failed.any(axis=1).sum() > 30  # spread over the scans, not bunched
    assert np.array_equal(failed, dropped(seed=3))
    assert not np.array_equal(failed, dropped(seed=4))
    assert not dropped(seed=3, dropout=0.0).any()


def test_a_dropped_reading_is_nan_whatever_the_beam_would_have_measured():
    lidar = Lidar(samples=4, range_min=0.1, range_max=3.0)
    # from (7.5, 2.0) facing +x: the box 0.5 m ahead, past range_max left and behind, the wall 2 m right
    assert lidar.scan([AHEAD], 7.5, 2.0, 0.0).tolist() == [0.5, math.inf, math.inf, 2.0]
    ranges = lidar.scan([AHEAD], 7.5, 2.0, 0.0, failed=np.array([True, False, True, False]))
    assert math.isnan(ranges[0]) and math.isnan(ranges[2])
    assert ranges.tolist()[1::2] == [math.inf, 2.0]


def test_no_lidar_no_scan_topic():
    r = rig(None)
    r.ticks(3)
    assert "/turtle1/scan" not in r.graph.topics


def test_rays_are_cast_only_when_someone_listens(monkeypatch):
    casts: list = []
    original = Lidar.scan

    def counting(self, *args, **kwargs):
        casts.append(1)
        return original(self, *args, **kwargs)

    monkeypatch.setattr(Lidar, "scan", counting)
    r = rig(Lidar(samples=8))
    r.ticks(5)
    assert casts == []
    seen: list = []
    r.graph.taps.append(lambda kind, payload: seen.append(payload[0].name) if kind == "topic" else None)
    r.ticks(2)
    assert len(casts) == 2 and "/turtle1/scan" in seen


def test_every_turtle_scans_in_its_own_frame_until_killed():
    r = rig(Lidar(samples=8))
    r.call("/spawn", Spawn.Request(x=2.0, y=2.0, theta=0.0, name="t2"))
    scans = r.observe("/t2/scan")
    r.ticks(3)
    assert scans and {m.header.frame_id for _, m in scans} == {"t2"}
    r.call("/kill", Kill.Request(name="t2"))
    assert not r.graph.topics["/t2/scan"].publishers


def test_hitting_an_obstacle_logs_a_warning_like_the_wall_one():
    r = rig(None, obstacles=(Circle(7.0, 5.544445, 0.5),))
    for _ in range(60):
        r.drive(2.0)
        r.ticks(1)
    warnings = [rec.msg for rec in r.logs if rec.level == WARN]
    assert warnings[0] == f"Oh no! I hit an obstacle! (Blocked at [x={6.5:f}, y={r.world.turtles['turtle1'].y:f}])"
