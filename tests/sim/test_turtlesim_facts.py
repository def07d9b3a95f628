"""Every fact of shared/TURTLESIM.md, checked on the World and through the graph.

World-level tests drive ``turtletui.sim.World`` directly; tests about topics,
services, actions and log lines go through ``Simulation`` (graph + world +
/turtlesim node) in lockstep. One tick is 16 ms = 16_000_000 ns; tick n fires
at n * 16 ms, tick 1 only records the time.
"""

from __future__ import annotations

import math
import struct

import numpy as np
import pytest

from turtletui.graph.logs import ERROR, INFO, WARN
from turtletui.graph.turtlesim_node import QOS_DEPTH
from turtletui.interfaces.geometry_msgs import Twist, Vector3
from turtletui.interfaces.std_srvs import Empty
from turtletui.interfaces.turtlesim import (
    Color,
    Kill,
    Pose,
    RotateAbsolute,
    SetPen,
    Spawn,
    TeleportAbsolute,
    TeleportRelative,
)
from turtletui.runtime.simulation import Simulation
from turtletui.sim import (
    ARENA_SIZE,
    BACKGROUND,
    CENTER,
    COMMAND_TIMEOUT,
    DT,
    METER_PX,
    PEN_COLOR,
    PEN_WIDTH,
    PIXELS,
    RotationFeedback,
    RotationFinished,
    SimError,
    WallHit,
    Warning_,
    World,
    normalize_angle,
)
from turtletui.sim.canvas import UNPAINTED, to_pixel
from turtletui.sim.constants import ROTATE_SPEED, ROTATE_TOLERANCE

TICK_NS = 16_000_000
EXACT_CENTER = CENTER
# turtlesim's spawnTurtle takes float arguments, so turtle1 starts at the
# float32 value of the centre; every position below is relative to that.
CENTER = struct.unpack("f", struct.pack("f", EXACT_CENTER))[0]
NS = 1_000_000_000


# -- helpers ---------------------------------------------------------------------


def f32(value: float) -> float:
    """``value`` rounded to float32, as a Pose field carries it."""
    return struct.unpack("f", struct.pack("f", value))[0]


def make_sim(**kwargs) -> tuple[Simulation, list]:
    logs: list = []
    sim = Simulation(log_sinks=[logs.append], **kwargs)
    # The facts here are turtlesim's, tick by tick: the test's probe nodes
    # match turtlesim at once instead of after discovery (tests/compat/test_discovery.py).
    sim.graph.discovery_ns = 0
    return sim, logs


def run_ticks(sim: Simulation, n: int) -> None:
    """Run exactly ``n`` more 16 ms ticks (time must sit on a tick boundary)."""
    assert sim.graph.now_ns % TICK_NS == 0
    sim.run_until(sim.graph.now_ns + n * TICK_NS)


def observe(sim: Simulation, topic: str, msg_type: type) -> list[tuple[int, object]]:
    """Subscribe a test node to ``topic``; returns the (now_ns, msg) it receives."""
    node = sim.graph.add_node(f"observer_{len(sim.graph.nodes)}", owner="test")
    out: list[tuple[int, object]] = []
    sim.graph.add_subscription(node, topic, msg_type, 1000, lambda m: out.append((sim.graph.now_ns, m)))
    return out


def call(sim: Simulation, service: str, request):
    """Call a service through the graph and return its response."""
    box: list = []
    sim.graph.call(service, request, box.append, owner="test")
    sim.graph.run_ready()
    assert len(box) == 1, f"{service} did not answer"
    return box[0]


def command(sim: Simulation, vx: float = 0.0, wz: float = 0.0, vy: float = 0.0, turtle: str = "turtle1") -> None:
    msg = Twist(linear=Vector3(x=vx, y=vy), angular=Vector3(z=wz))
    sim.graph.publish(sim.graph.topics[f"/{turtle}/cmd_vel"], msg)
    sim.graph.run_ready()


def messages(logs: list, level: int | None = None, node: str = "turtlesim") -> list[str]:
    return [r.msg for r in logs if r.node == node and (level is None or r.level == level)]


def started_world(**kwargs) -> World:
    """A world past its first (recording-only) tick."""
    world = World(**kwargs)
    assert world.step() is False
    return world


def column_rows(world: World, col: int, color: tuple[int, int, int]) -> list[int]:
    """Rows of pixel column ``col`` painted in ``color``."""
    pixels = world.canvas.pixels
    return [int(r) for r in np.nonzero(np.all(pixels[:, col] == color, axis=1))[0]]


def send_goal(sim: Simulation, theta: float, turtle: str = "turtle1"):
    accepted: list = []
    feedback: list = []
    results: list = []
    sim.graph.send_goal(
        f"/{turtle}/rotate_absolute",
        RotateAbsolute.Goal(theta=theta),
        "test",
        accepted.append,
        feedback.append,
        lambda status, result: results.append((status, result)),
    )
    sim.graph.run_ready()
    assert len(accepted) == 1
    return accepted[0], feedback, results


# -- arena and start -------------------------------------------------------------------


def test_arena_is_499_over_45_metres_and_500_pixels():
    assert PIXELS == 500
    assert METER_PX == 45.0
    assert ARENA_SIZE == (500 - 1) / 45
    assert ARENA_SIZE == pytest.approx(11.088888, abs=1e-6)
    world = World()
    assert world.canvas.pixels.shape == (500, 500, 3)


def test_origin_is_bottom_left_with_y_up():
    # Pixel row 0 is the top of the image (y = 11.0889 m), row 499 the bottom.
    assert to_pixel(0.0, 0.0) == (0, 499)
    assert to_pixel(ARENA_SIZE, ARENA_SIZE) == (499, 0)
    world = started_world()
    turtle = world.turtles["turtle1"]
    turtle.theta = math.pi / 2
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    world.step()
    assert turtle.y > CENTER
    assert turtle.x == pytest.approx(CENTER, abs=1e-12)


@pytest.mark.parametrize(
    ("theta", "expected_x", "expected_y"),
    [(0.0, ARENA_SIZE, CENTER), (math.pi, 0.0, CENTER), (math.pi / 2, CENTER, ARENA_SIZE), (-math.pi / 2, CENTER, 0.0)],
)
def test_the_arena_walls_are_at_0_and_11_0889(theta, expected_x, expected_y):
    world = started_world()
    turtle = world.turtles["turtle1"]
    turtle.theta = theta
    for _ in range(400):  # 6.4 s at 2 m/s: far past the wall
        world.command_velocity("turtle1", 2.0, 0.0, 0.0)
        world.step()
    assert turtle.x == pytest.approx(expected_x, abs=1e-9)
    assert turtle.y == pytest.approx(expected_y, abs=1e-9)
    assert 0.0 <= turtle.x <= ARENA_SIZE and 0.0 <= turtle.y <= ARENA_SIZE


def test_turtle1_starts_at_the_centre_facing_plus_x():
    world = World()
    assert list(world.turtles) == ["turtle1"]
    turtle = world.turtles["turtle1"]
    assert CENTER == pytest.approx(5.5444444, abs=1e-6)
    assert turtle.x == pytest.approx(CENTER, abs=1e-6)
    assert turtle.y == pytest.approx(CENTER, abs=1e-6)
    assert turtle.theta == 0.0
    assert (turtle.vx, turtle.vy, turtle.wz) == (0.0, 0.0, 0.0)


def test_turtle1_first_pose_is_the_centre():
    sim, _ = make_sim()
    poses = observe(sim, "/turtle1/pose", Pose)
    run_ticks(sim, 2)
    assert len(poses) == 1
    pose = poses[0][1]
    assert (pose.x, pose.y, pose.theta) == (f32(CENTER), f32(CENTER), 0.0)
    assert (pose.linear_velocity, pose.angular_velocity) == (0.0, 0.0)


def test_background_colour_is_69_86_255_everywhere_at_start():
    assert BACKGROUND == (69, 86, 255)
    world = World()
    assert world.background == (69, 86, 255)
    pixels = world.canvas.pixels
    assert np.all(pixels == np.array([69, 86, 255], dtype=np.uint8))


def test_default_pen_is_179_184_255_width_3_and_on():
    assert PEN_COLOR == (179, 184, 255)
    assert PEN_WIDTH == 3
    world = World()
    turtle = world.turtles["turtle1"]
    assert turtle.pen_on is True
    assert turtle.pen_color == (179, 184, 255)
    assert turtle.pen_width == 3


def test_default_pen_draws_a_3_pixel_line_in_its_colour():
    world = started_world()
    for _ in range(40):
        world.command_velocity("turtle1", 1.0, 0.0, 0.0)
        world.step()
    # The turtle drove along y = CENTER (float32: pixel row 249.49999 -> 249).
    col, row = to_pixel(CENTER + 0.3, CENTER)
    assert row == 249
    assert column_rows(world, col, PEN_COLOR) == [248, 249, 250]
    pixels = world.canvas.pixels
    assert tuple(pixels[247, col]) == BACKGROUND
    assert tuple(pixels[251, col]) == BACKGROUND


# -- the update step -------------------------------------------------------------------------


def test_dt_is_16_ms_and_the_timer_runs_at_62_5_hz():
    assert DT == 0.016
    sim, _ = make_sim()
    assert sim.turtlesim.timer.period_ns == 16_000_000
    run_ticks(sim, 2)
    poses = observe(sim, "/turtle1/pose", Pose)
    sim.run_until(2 * TICK_NS + NS)  # one simulated second
    assert len(poses) == 62  # ticks 3..64: 0.048 s .. 1.024 s
    stamps = [t for t, _ in poses]
    assert all(b - a == TICK_NS for a, b in zip(stamps, stamps[1:], strict=False))


def test_each_step_moves_by_speed_times_0_016():
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    xs = [turtle.x]
    for _ in range(5):
        world.step()
        xs.append(turtle.x)
    steps = [b - a for a, b in zip(xs, xs[1:], strict=False)]
    assert steps == pytest.approx([0.016] * 5, abs=1e-12)


def test_first_tick_only_records_time_on_the_world():
    world = World()
    turtle = world.turtles["turtle1"]
    world.command_velocity("turtle1", 1.0, 0.0, 1.0)
    assert world.step() is False
    assert world.ticks == 1
    assert (turtle.x, turtle.y, turtle.theta) == (pytest.approx(CENTER), pytest.approx(CENTER), 0.0)
    x_before = turtle.x
    assert world.step() is True
    assert turtle.x > x_before
    assert turtle.theta == pytest.approx(0.016, abs=1e-12)


def test_first_tick_publishes_no_pose():
    sim, _ = make_sim()
    topic = sim.graph.topics["/turtle1/pose"]
    sim.run_until(TICK_NS)  # tick 1
    assert sim.world.ticks == 1
    assert topic.count == 0
    assert sim.graph.topics["/turtle1/color_sensor"].count == 0
    sim.run_until(2 * TICK_NS)  # tick 2
    assert topic.count == 1
    sim.run_until(3 * TICK_NS)
    assert topic.count == 2


def test_a_command_before_start_moves_only_from_the_second_tick():
    sim, _ = make_sim()
    poses = observe(sim, "/turtle1/pose", Pose)
    command(sim, vx=1.0)
    sim.run_until(TICK_NS)
    assert sim.world.turtles["turtle1"].x == pytest.approx(CENTER, abs=1e-12)
    sim.run_until(2 * TICK_NS)
    assert poses[0][0] == 2 * TICK_NS
    assert poses[0][1].x == f32(CENTER + 0.016)


def test_teleport_is_applied_before_motion_in_the_same_step():
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.teleport_absolute("turtle1", 1.0, 2.0, 0.0)
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    assert (turtle.x, turtle.y) == (pytest.approx(CENTER), pytest.approx(CENTER))  # queued, not yet
    world.step()
    # Teleported to (1, 2) first, then moved 0.016 along theta 0.
    assert turtle.x == pytest.approx(1.016, abs=1e-12)
    assert turtle.y == pytest.approx(2.0, abs=1e-12)
    assert turtle.teleports == []


def test_queued_teleports_apply_in_order():
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.teleport_absolute("turtle1", 1.0, 1.0, 0.0)
    world.teleport_relative("turtle1", 2.0, 0.0)
    world.teleport_relative("turtle1", 1.0, math.pi / 2)
    world.step()
    assert turtle.x == pytest.approx(3.0, abs=1e-9)
    assert turtle.y == pytest.approx(2.0, abs=1e-9)
    assert turtle.theta == pytest.approx(math.pi / 2, abs=1e-9)


def _rotate_world(world: World, goal_theta: float, max_steps: int = 1000):
    goal = world.start_rotation("turtle1", goal_theta)
    turtle = world.turtles["turtle1"]
    thetas, feedback, finished = [turtle.theta], [], []
    for _ in range(max_steps):
        world.step()
        thetas.append(turtle.theta)
        for event in world.take_events():
            if isinstance(event, RotationFeedback):
                feedback.append(event.remaining)
            elif isinstance(event, RotationFinished):
                finished.append(event)
        if goal.status != "active":
            break
    return goal, thetas, feedback, finished


def test_rotate_absolute_turns_at_plus_1_rad_s_and_stops_within_0_02():
    assert ROTATE_SPEED == 1.0 and ROTATE_TOLERANCE == 0.02
    world = started_world()
    goal, thetas, feedback, finished = _rotate_world(world, 1.0)
    turns = [b - a for a, b in zip(thetas, thetas[1:], strict=False)]
    # 62 steps of +0.016 rad reach 0.992 (0.008 to go), the 63rd succeeds without turning.
    assert turns[:62] == pytest.approx([0.016] * 62, abs=1e-12)
    assert turns[62] == 0.0
    assert len(turns) == 63
    assert goal.status == "succeeded"
    assert world.turtles["turtle1"].theta == pytest.approx(0.992, abs=1e-9)
    assert world.turtles["turtle1"].wz == 0.0
    assert len(finished) == 1 and finished[0].status == "succeeded"
    # result delta = normalize(float(start - now)): turtle.cpp casts the difference to float
    assert finished[0].delta == normalize_angle(f32(0.0 - world.turtles["turtle1"].theta))
    assert finished[0].delta == pytest.approx(-0.992, abs=1e-7)
    # feedback `remaining` every step, the last one under the tolerance
    assert len(feedback) == 63
    assert feedback[0] == pytest.approx(1.0, abs=1e-12)
    assert feedback[1] == pytest.approx(0.984, abs=1e-9)
    assert abs(feedback[-1]) < 0.02 <= abs(feedback[-2])


def test_rotate_absolute_turns_at_minus_1_rad_s_toward_a_smaller_heading():
    world = started_world()
    goal, thetas, feedback, finished = _rotate_world(world, -0.5)
    turns = [b - a for a, b in zip(thetas, thetas[1:], strict=False)]
    assert turns[0] == pytest.approx(-0.016, abs=1e-12)
    assert all(t <= 0.0 for t in turns)
    assert goal.status == "succeeded"
    assert abs(normalize_angle(world.turtles["turtle1"].theta + 0.5)) < 0.02
    assert finished[0].delta == f32(-world.turtles["turtle1"].theta)
    assert feedback[0] == pytest.approx(-0.5, abs=1e-12)


def test_rotate_absolute_takes_the_short_way_across_pi():
    world = started_world()
    world.turtles["turtle1"].theta = 3.0
    goal, thetas, _, finished = _rotate_world(world, -3.0)
    # normalize(-3 - 3) = 2*pi - 6 = +0.283: turn positive, wrapping through pi.
    assert thetas[1] - thetas[0] == pytest.approx(0.016, abs=1e-12)
    assert any(t < 0 for t in thetas)
    assert goal.status == "succeeded"
    assert len(thetas) - 1 < 25  # 0.283 rad at 1 rad/s is ~18 steps, not ~375
    assert finished[0].delta == normalize_angle(f32(3.0 - world.turtles["turtle1"].theta))


def test_rotate_absolute_counts_as_a_fresh_command_so_long_turns_do_not_time_out():
    world = started_world()
    goal, thetas, _, _ = _rotate_world(world, 3.0)  # 3 s of turning, timeout is 1 s
    assert goal.status == "succeeded"
    assert abs(world.turtles["turtle1"].theta - 3.0) < 0.02
    assert len(thetas) - 1 > int(1.0 / DT) * 2


def test_rotate_absolute_sets_linear_speed_to_zero():
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    world.step()
    x = turtle.x
    world.take_events()
    world.start_rotation("turtle1", 1.0)
    world.step()
    assert turtle.vx == 0.0 and turtle.wz == 1.0
    assert turtle.x == x


def test_rotate_absolute_cancel_stops_the_turtle_and_reports_canceled():
    world = started_world()
    turtle = world.turtles["turtle1"]
    goal = world.start_rotation("turtle1", 2.0)
    for _ in range(10):
        world.step()
    theta = turtle.theta
    assert theta == pytest.approx(0.16, abs=1e-9)
    world.take_events()
    world.cancel_rotation(goal)
    world.step()
    events = world.take_events()
    finished = [e for e in events if isinstance(e, RotationFinished)]
    assert [e.status for e in finished] == ["canceled"]
    assert goal.status == "canceled"
    assert turtle.rotation is None
    assert turtle.wz == 0.0
    assert turtle.theta == theta  # stopped before turning this step
    # the result is the one computed on the previous tick (heading 0.144), not recomputed
    assert finished[0].delta == goal.delta == normalize_angle(f32(0.0 - 0.144))
    for _ in range(5):
        world.step()
    assert turtle.theta == theta


def test_a_goal_canceled_before_its_first_tick_reports_delta_0():
    world = started_world()
    goal = world.start_rotation("turtle1", 2.0)
    world.cancel_rotation(goal)
    world.step()
    (finished,) = [e for e in world.take_events() if isinstance(e, RotationFinished)]
    assert (finished.status, finished.delta) == ("canceled", 0.0)


def test_a_rotation_goal_logs_how_it_ended_as_turtlesim_does():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    sim.world.start_rotation("turtle1", 0.1)
    run_ticks(sim, 10)
    assert messages(logs, INFO)[-1] == "Rotation goal completed successfully"
    goal = sim.world.start_rotation("turtle1", 2.0)
    run_ticks(sim, 3)
    sim.world.cancel_rotation(goal)
    run_ticks(sim, 1)
    assert messages(logs, INFO)[-1] == "Rotation goal canceled"
    assert messages(logs, INFO).count("Rotation goal completed successfully") == 1


def test_velocity_command_aborts_rotate_absolute_with_a_warning():
    world = started_world()
    turtle = world.turtles["turtle1"]
    goal = world.start_rotation("turtle1", 2.0)
    for _ in range(5):
        world.step()
    world.take_events()
    world.command_velocity("turtle1", 0.5, 0.0, 0.0)
    events = world.take_events()
    warnings = [e for e in events if isinstance(e, Warning_)]
    assert [(w.turtle, w.text) for w in warnings] == [
        ("turtle1", "Velocity command received during rotation goal. Aborting goal")
    ]
    assert [e.status for e in events if isinstance(e, RotationFinished)] == ["aborted"]
    assert goal.status == "aborted"
    theta = turtle.theta
    world.step()
    assert turtle.theta == theta  # the command (wz = 0) now rules
    assert turtle.vx == 0.5


def test_rotate_absolute_through_the_action_succeeds_with_delta_and_feedback():
    sim, _ = make_sim()
    run_ticks(sim, 1)
    handle, feedback, results = send_goal(sim, 1.0)
    sim.run_until(2 * NS)
    assert len(results) == 1
    status, result = results[0]
    assert status == "succeeded"
    assert result.delta == f32(normalize_angle(0.0 - sim.world.turtles["turtle1"].theta))
    assert result.delta == pytest.approx(-0.992, abs=1e-6)
    assert len(feedback) == 63
    assert feedback[0].remaining == 1.0
    assert feedback[1].remaining == pytest.approx(0.984, abs=1e-6)
    assert all(isinstance(f, RotateAbsolute.Feedback) for f in feedback)
    assert handle.status == "succeeded"


def test_rotate_absolute_cancel_through_the_action():
    sim, _ = make_sim()
    run_ticks(sim, 1)
    handle, feedback, results = send_goal(sim, 2.0)
    run_ticks(sim, 10)
    assert results == []
    theta = sim.world.turtles["turtle1"].theta
    assert theta == pytest.approx(0.16, abs=1e-9)
    sim.graph.cancel_goal(handle)
    sim.graph.run_ready()
    run_ticks(sim, 1)
    assert [s for s, _ in results] == ["canceled"]
    run_ticks(sim, 20)
    assert sim.world.turtles["turtle1"].theta == theta
    assert len(feedback) == 10


def test_velocity_command_aborts_the_action_and_logs_the_exact_warning():
    sim, logs = make_sim()
    run_ticks(sim, 1)
    _, _, results = send_goal(sim, 2.0)
    run_ticks(sim, 5)
    command(sim, vx=1.0)
    assert [s for s, _ in results] == ["aborted"]
    assert "Velocity command received during rotation goal. Aborting goal" in messages(logs, WARN)


def test_a_new_goal_aborts_the_previous_one():
    sim, logs = make_sim()
    run_ticks(sim, 1)
    _, _, first = send_goal(sim, 2.0)
    run_ticks(sim, 3)
    _, _, second = send_goal(sim, -1.0)
    assert [s for s, _ in first] == ["aborted"]
    assert "Rotation goal received before a previous goal finished. Aborting previous goal" in messages(logs, WARN)
    sim.run_until(4 * NS)
    assert [s for s, _ in second] == ["succeeded"]


# -- command timeout -----------------------------------------------------------------------------


def test_command_timeout_is_exactly_62_ticks_on_the_world():
    assert COMMAND_TIMEOUT == 1.0
    world = started_world()
    world.step()  # tick 2, t = 0.032
    turtle = world.turtles["turtle1"]
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    assert turtle.last_command_time == pytest.approx(0.032)
    x0 = turtle.x
    for _ in range(62):  # up to 0.992 s after the command: still moving
        world.step()
    assert turtle.vx == 1.0
    assert turtle.x == pytest.approx(x0 + 62 * 0.016, abs=1e-9)
    x1 = turtle.x
    world.step()  # 1.008 s after the command: more than 1.0 s, stops
    assert (turtle.vx, turtle.vy, turtle.wz) == (0.0, 0.0, 0.0)
    assert turtle.x == x1


def test_command_timeout_through_the_pose_topic():
    sim, _ = make_sim()
    run_ticks(sim, 2)
    poses = observe(sim, "/turtle1/pose", Pose)
    command(sim, vx=1.0, wz=0.5)  # at t = 0.032 s
    sim.run_until(2 * NS)
    by_time = {t: p for t, p in poses}
    moving = by_time[2 * TICK_NS + 62 * TICK_NS]  # t = 1.024 s: 0.992 s after the command
    stopped = by_time[2 * TICK_NS + 63 * TICK_NS]  # t = 1.040 s: 1.008 s after
    assert (moving.linear_velocity, moving.angular_velocity) == (1.0, 0.5)
    assert (stopped.linear_velocity, stopped.angular_velocity) == (0.0, 0.0)
    assert stopped.x == moving.x and stopped.theta == moving.theta
    last = poses[-1][1]
    assert (last.x, last.y, last.theta) == (moving.x, moving.y, moving.theta)


def test_a_controller_that_keeps_publishing_keeps_moving():
    sim, _ = make_sim()
    run_ticks(sim, 2)
    for _ in range(4):  # a command every 0.5 s for 2 s
        command(sim, vx=1.0)
        sim.run_until(sim.graph.now_ns + 500_000_000)
    assert sim.world.turtles["turtle1"].vx == 1.0


# -- the motion equations ------------------------------------------------------------------------


def test_heading_update_is_semi_implicit():
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.command_velocity("turtle1", 1.0, 0.0, 1.0)
    world.step()
    assert turtle.theta == pytest.approx(0.016, abs=1e-15)
    # position uses the NEW theta (0.016), not the old one (0)
    assert turtle.x == pytest.approx(CENTER + math.cos(0.016) * 0.016, abs=1e-13)
    assert turtle.y == pytest.approx(CENTER + math.sin(0.016) * 0.016, abs=1e-13)
    assert turtle.y != pytest.approx(CENTER, abs=1e-6)


@pytest.mark.parametrize(
    ("angle", "expected"),
    [
        (0.0, 0.0),
        (math.pi, -math.pi),
        (-math.pi, -math.pi),
        (1.5 * math.pi, -0.5 * math.pi),
        (-1.5 * math.pi, 0.5 * math.pi),
        (2 * math.pi + 0.5, 0.5),
        (-7.0, -7.0 + 2 * math.pi),
        (3.0, 3.0),
    ],
)
def test_normalize_angle_maps_to_minus_pi_inclusive_pi_exclusive(angle, expected):
    result = normalize_angle(angle)
    assert result == pytest.approx(expected, abs=1e-12)
    assert -math.pi <= result < math.pi


def test_heading_wraps_from_plus_pi_to_minus_pi():
    world = started_world()
    turtle = world.turtles["turtle1"]
    turtle.theta = math.pi - 0.008
    world.command_velocity("turtle1", 0.0, 0.0, 1.0)
    world.step()
    assert turtle.theta == pytest.approx(-math.pi + 0.008, abs=1e-12)
    turtle.theta = -math.pi + 0.008
    world.command_velocity("turtle1", 0.0, 0.0, -1.0)
    world.step()
    assert turtle.theta == pytest.approx(math.pi - 0.008, abs=1e-12)
    turtle.theta = math.pi - 0.016
    world.command_velocity("turtle1", 0.0, 0.0, 1.0)
    world.step()
    assert -math.pi <= turtle.theta < math.pi


# -- walls --------------------------------------------------------------------------------


def test_leaving_the_arena_reports_the_unclamped_position_and_clamps():
    world = started_world()
    turtle = world.turtles["turtle1"]
    turtle.x = 11.08
    world.command_velocity("turtle1", 2.0, 0.0, 0.0)
    world.step()
    hits = [e for e in world.take_events() if isinstance(e, WallHit)]
    assert len(hits) == 1
    assert hits[0].turtle == "turtle1"
    assert hits[0].x == pytest.approx(11.112, abs=1e-9)
    assert hits[0].y == pytest.approx(CENTER, abs=1e-12)
    assert turtle.x == ARENA_SIZE
    assert turtle.wall_hits == 1


def test_clamping_at_the_bottom_left_corner_clamps_both():
    world = started_world()
    turtle = world.turtles["turtle1"]
    turtle.x, turtle.y, turtle.theta = 0.01, 0.005, -3 * math.pi / 4
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    world.step()
    hits = [e for e in world.take_events() if isinstance(e, WallHit)]
    assert len(hits) == 1
    assert hits[0].x < 0 and hits[0].y < 0
    assert (turtle.x, turtle.y) == (0.0, 0.0)


def test_wall_warning_text_is_turtlesims_with_percent_f():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    sim.world.turtles["turtle1"].x = 11.08
    command(sim, vx=2.0)
    run_ticks(sim, 1)
    warnings = [r for r in logs if r.level == WARN and r.node == "turtlesim"]
    # turtle.cpp prints its canvas y (y axis down): 11.088889 - 5.544445 = 5.544444
    assert [r.msg for r in warnings] == ["Oh no! I hit the wall! (Clamping from [x=11.112000, y=5.544444])"]
    run_ticks(sim, 2)  # still pushing into the wall: warned every step, as turtlesim does
    warnings = [r.msg for r in logs if r.level == WARN and r.node == "turtlesim"]
    assert warnings[1:] == ["Oh no! I hit the wall! (Clamping from [x=11.120889, y=5.544444])"] * 2
    assert sim.world.turtles["turtle1"].x == ARENA_SIZE
    assert sim.world.turtles["turtle1"].wall_hits == 1


def test_wall_warning_prints_negative_coordinates_with_percent_f():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    turtle = sim.world.turtles["turtle1"]
    turtle.x, turtle.theta = 0.01, math.pi
    command(sim, vx=1.0)
    run_ticks(sim, 1)
    assert messages(logs, WARN) == ["Oh no! I hit the wall! (Clamping from [x=-0.006000, y=5.544444])"]
    assert turtle.x == 0.0


def test_wall_warning_prints_turtlesims_canvas_y_at_the_top_and_bottom_walls():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    turtle = sim.world.turtles["turtle1"]
    turtle.y, turtle.theta = ARENA_SIZE - 0.019, math.pi / 2
    command(sim, vx=2.0)
    run_ticks(sim, 1)
    # 11.069889 + 0.032 = 11.101889 m up is canvas y 11.088889 - 11.101889 = -0.013000
    assert messages(logs, WARN) == ["Oh no! I hit the wall! (Clamping from [x=5.544445, y=-0.013000])"]
    assert turtle.y == ARENA_SIZE
    del logs[:]
    turtle.y, turtle.theta = 0.01, -math.pi / 2
    command(sim, vx=1.0)
    run_ticks(sim, 1)
    assert messages(logs, WARN) == ["Oh no! I hit the wall! (Clamping from [x=5.544445, y=11.094889])"]


# -- holonomic ----------------------------------------------------------------------------------


def test_linear_y_is_ignored_unless_holonomic():
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.command_velocity("turtle1", 0.0, 1.0, 0.0)
    world.step()
    assert turtle.vy == 0.0
    assert (turtle.x, turtle.y) == (pytest.approx(CENTER, abs=1e-12), pytest.approx(CENTER, abs=1e-12))


def test_linear_y_moves_sideways_when_holonomic():
    world = started_world(holonomic=True)
    turtle = world.turtles["turtle1"]
    turtle.theta = math.pi / 2  # facing +y: sideways (+vy) is -x
    world.command_velocity("turtle1", 0.0, 1.0, 0.0)
    world.step()
    assert turtle.vy == 1.0
    assert turtle.x == pytest.approx(CENTER - 0.016, abs=1e-12)
    assert turtle.y == pytest.approx(CENTER, abs=1e-12)


def test_holonomic_parameter_of_the_turtlesim_node():
    sim, _ = make_sim()
    assert sim.turtlesim.node.parameters["holonomic"] is False
    run_ticks(sim, 2)
    command(sim, vy=1.0)
    run_ticks(sim, 1)
    assert sim.world.turtles["turtle1"].y == pytest.approx(CENTER, abs=1e-12)
    assert sim.turtlesim.set_parameter("holonomic", True) is None
    assert sim.turtlesim.node.parameters["holonomic"] is True
    assert sim.world.holonomic is True
    command(sim, vy=1.0)
    run_ticks(sim, 1)
    assert sim.world.turtles["turtle1"].y == pytest.approx(CENTER + 0.016, abs=1e-12)
    assert sim.turtlesim.set_parameter("holonomic", 1) is not None  # not a bool: refused
    assert sim.world.holonomic is True


# -- pose -------------------------------------------------------------------------------------


def test_pose_fields_are_float32_with_speed_magnitude_and_turn_rate():
    sim, _ = make_sim()
    assert sim.turtlesim.set_parameter("holonomic", True) is None
    poses = observe(sim, "/turtle1/pose", Pose)
    run_ticks(sim, 2)
    command(sim, vx=3.0, vy=4.0, wz=0.7)
    run_ticks(sim, 3)
    turtle = sim.world.turtles["turtle1"]
    pose = poses[-1][1]
    assert pose.x == f32(turtle.x)
    assert pose.y == f32(turtle.y)
    assert pose.theta == f32(turtle.theta)
    assert pose.x != turtle.x  # the double was really rounded
    assert pose.linear_velocity == 5.0  # |(3, 4)|
    assert pose.angular_velocity == f32(0.7)


def test_pose_linear_velocity_is_a_magnitude_for_reverse_driving():
    sim, _ = make_sim()
    poses = observe(sim, "/turtle1/pose", Pose)
    run_ticks(sim, 2)
    command(sim, vx=-2.0, wz=-1.0)
    run_ticks(sim, 1)
    pose = poses[-1][1]
    assert pose.linear_velocity == 2.0
    assert pose.angular_velocity == -1.0
    assert pose.x == f32(CENTER - 2.0 * 0.016 * math.cos(-0.016))


# -- color sensor -------------------------------------------------------------------------------


def test_color_sensor_reads_transparent_white_on_unpainted_ground():
    # turtlesim's pen image is filled with qRgba(255, 255, 255, 0); the
    # background is painted beneath it on screen only.
    sim, _ = make_sim()
    colors = observe(sim, "/turtle1/color_sensor", Color)
    run_ticks(sim, 3)
    assert len(colors) == 2
    assert all((c.r, c.g, c.b) == (255, 255, 255) for _, c in colors)
    assert tuple(sim.world.canvas.pixels[0, 0]) == BACKGROUND  # what the screen shows


def test_color_sensor_reads_the_turtles_own_trail_when_moving_slowly():
    sim, _ = make_sim()
    colors = observe(sim, "/turtle1/color_sensor", Color)
    run_ticks(sim, 2)
    call(sim, "/turtle1/set_pen", SetPen.Request(r=255, g=0, b=0, width=3, off=0))
    command(sim, vx=0.1)
    run_ticks(sim, 30)
    readings = [(c.r, c.g, c.b) for _, c in colors]
    # The sensor reads the image before this step's segment is drawn, so the
    # first moving step still sees unpainted ground; after that, the trail.
    assert readings[0] == UNPAINTED
    assert readings[1] == UNPAINTED
    assert readings[2] == (255, 0, 0)
    assert readings[-10:] == [(255, 0, 0)] * 10


def test_color_sensor_reads_unpainted_ground_again_after_clear():
    sim, _ = make_sim()
    colors = observe(sim, "/turtle1/color_sensor", Color)
    run_ticks(sim, 2)
    command(sim, vx=0.1)
    run_ticks(sim, 20)
    assert (colors[-1][1].r, colors[-1][1].g, colors[-1][1].b) == PEN_COLOR
    call(sim, "/turtle1/set_pen", SetPen.Request(off=1))
    call(sim, "/clear", Empty.Request())
    del colors[:]
    command(sim, vx=0.1)
    run_ticks(sim, 20)
    assert len(colors) == 20
    assert all((c.r, c.g, c.b) == UNPAINTED for _, c in colors)


# -- spawn / kill / reset / clear ------------------------------------------------------------------


def test_spawn_with_a_name_creates_the_turtle_and_logs():
    sim, logs = make_sim()
    response = call(sim, "/spawn", Spawn.Request(x=1.0, y=2.0, theta=0.5, name="t2"))
    assert response.name == "t2"
    turtle = sim.world.turtles["t2"]
    assert (turtle.x, turtle.y, turtle.theta) == (1.0, 2.0, 0.5)
    assert "Spawning turtle [t2] at x=[1.000000], y=[2.000000], theta=[0.500000]" in messages(logs, INFO)


def test_spawn_without_a_name_picks_the_next_free_turtleN():
    sim, _ = make_sim()
    assert call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0)).name == "turtle2"
    assert call(sim, "/spawn", Spawn.Request(x=2.0, y=1.0, theta=0.0, name="turtle4")).name == "turtle4"
    assert call(sim, "/spawn", Spawn.Request(x=3.0, y=1.0, theta=0.0)).name == "turtle3"
    assert call(sim, "/spawn", Spawn.Request(x=4.0, y=1.0, theta=0.0)).name == "turtle5"
    assert sorted(sim.world.turtles) == ["turtle1", "turtle2", "turtle3", "turtle4", "turtle5"]


def test_spawn_of_an_existing_name_fails_and_logs_an_error():
    sim, logs = make_sim()
    call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0, name="t2"))
    response = call(sim, "/spawn", Spawn.Request(x=3.0, y=3.0, theta=0.0, name="t2"))
    assert response.name == ""
    assert messages(logs, ERROR) == ["A turtle named [t2] already exists"]
    assert sim.world.turtles["t2"].x == 1.0
    assert call(sim, "/spawn", Spawn.Request(name="turtle1")).name == ""
    assert messages(logs, ERROR)[-1] == "A turtle named [turtle1] already exists"


def test_world_spawn_of_an_existing_name_raises_the_log_line():
    world = World()
    with pytest.raises(SimError, match=r"^A turtle named \[turtle1\] already exists$"):
        world.spawn(1.0, 1.0, 0.0, "turtle1")


def test_kill_removes_the_turtle_and_all_its_endpoints():
    sim, _ = make_sim()
    call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0, name="t2"))
    graph = sim.graph
    assert graph.topics["/t2/pose"].publishers
    assert graph.topics["/t2/color_sensor"].publishers
    assert graph.topics["/t2/cmd_vel"].subscriptions
    for service in ("/t2/set_pen", "/t2/teleport_absolute", "/t2/teleport_relative"):
        assert service in graph.services
    assert "/t2/rotate_absolute" in graph.action_servers
    call(sim, "/kill", Kill.Request(name="t2"))
    assert "t2" not in sim.world.turtles
    for topic in ("/t2/pose", "/t2/color_sensor", "/t2/cmd_vel"):
        assert topic not in graph.topics or not (graph.topics[topic].publishers or graph.topics[topic].subscriptions)
    for service in ("/t2/set_pen", "/t2/teleport_absolute", "/t2/teleport_relative"):
        assert service not in graph.services
    assert "/t2/rotate_absolute" not in graph.action_servers
    # turtle1 is untouched
    assert "/turtle1/set_pen" in graph.services and graph.topics["/turtle1/pose"].publishers
    run_ticks(sim, 3)
    assert graph.topics["/turtle1/pose"].count == 2


def test_kill_of_an_unknown_turtle_fails_and_logs_an_error():
    sim, logs = make_sim()
    call(sim, "/kill", Kill.Request(name="nobody"))
    assert messages(logs, ERROR) == ["Tried to kill turtle [nobody], which does not exist"]
    assert list(sim.world.turtles) == ["turtle1"]
    with pytest.raises(SimError, match=r"^Tried to kill turtle \[ghost\], which does not exist$"):
        sim.world.kill("ghost")


def test_reset_removes_all_turtles_respawns_turtle1_resets_counter_and_clears():
    sim, logs = make_sim()
    call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0))  # turtle2
    call(sim, "/spawn", Spawn.Request(x=2.0, y=2.0, theta=0.0, name="t9"))
    run_ticks(sim, 2)
    command(sim, vx=1.0, wz=0.5)
    run_ticks(sim, 20)
    assert not np.all(sim.world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))
    logs.clear()
    call(sim, "/reset", Empty.Request())
    assert list(sim.world.turtles) == ["turtle1"]
    turtle = sim.world.turtles["turtle1"]
    assert turtle.x == pytest.approx(CENTER, abs=1e-6) and turtle.theta == 0.0
    assert (turtle.vx, turtle.wz) == (0.0, 0.0)
    assert np.all(sim.world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))
    assert messages(logs, INFO)[0] == "Resetting turtlesim."
    assert any(m.startswith("Spawning turtle [turtle1] at") for m in messages(logs, INFO))
    assert "/t9/set_pen" not in sim.graph.services and "/turtle2/set_pen" not in sim.graph.services
    assert "/turtle1/set_pen" in sim.graph.services
    # the name counter restarted
    assert call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0)).name == "turtle2"
    run_ticks(sim, 2)
    assert sim.world.turtles["turtle1"].x == pytest.approx(CENTER, abs=1e-6)  # new turtle1 is still


def test_clear_wipes_the_drawing_and_logs():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    command(sim, vx=1.0)
    run_ticks(sim, 20)
    assert not np.all(sim.world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))
    call(sim, "/clear", Empty.Request())
    assert np.all(sim.world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))
    assert "Clearing turtlesim." in messages(logs, INFO)
    assert sim.world.turtles["turtle1"].vx == 1.0  # clear does not stop anything


# -- set_pen --------------------------------------------------------------------------------------


def _drive_right(world: World, steps: int = 40) -> int:
    for _ in range(steps):
        world.command_velocity("turtle1", 1.0, 0.0, 0.0)
        world.step()
    return to_pixel(CENTER + 0.3, CENTER)[0]


def test_set_pen_colour_and_width():
    world = started_world()
    world.set_pen("turtle1", 255, 0, 0, 5, 0)
    col = _drive_right(world)
    assert column_rows(world, col, (255, 0, 0)) == [247, 248, 249, 250, 251]
    assert column_rows(world, col, PEN_COLOR) == []


def test_set_pen_width_0_gives_qts_default_width_of_1_pixel():
    # turtle.cpp makes a new QPen and sets the width only when it is not 0
    world = started_world()
    world.set_pen("turtle1", 255, 0, 0, 7, 0)
    world.set_pen("turtle1", 0, 255, 0, 0, 0)
    turtle = world.turtles["turtle1"]
    assert turtle.pen_width == 1 and turtle.pen_color == (0, 255, 0)
    col = _drive_right(world)
    assert column_rows(world, col, (0, 255, 0)) == [249]


def test_set_pen_off_lifts_the_pen_so_nothing_is_drawn():
    world = started_world()
    world.set_pen("turtle1", 255, 0, 0, 5, 1)
    turtle = world.turtles["turtle1"]
    assert turtle.pen_on is False
    assert turtle.pen_color == PEN_COLOR  # off: colour and width untouched
    _drive_right(world)
    assert turtle.x > CENTER + 0.5
    assert np.all(world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))
    world.set_pen("turtle1", 0, 0, 255, 0, 0)  # pen down again, a new pen of width 1
    assert turtle.pen_on is True and turtle.pen_width == 1


def test_set_pen_service_per_turtle():
    sim, _ = make_sim()
    call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0, name="t2"))
    call(sim, "/t2/set_pen", SetPen.Request(r=1, g=2, b=3, width=9, off=0))
    assert sim.world.turtles["t2"].pen_color == (1, 2, 3)
    assert sim.world.turtles["t2"].pen_width == 9
    assert sim.world.turtles["turtle1"].pen_color == PEN_COLOR


# -- teleport --------------------------------------------------------------------------------------


def test_teleport_absolute_draws_a_line_when_the_pen_is_on():
    sim, _ = make_sim()
    run_ticks(sim, 1)
    call(sim, "/turtle1/teleport_absolute", TeleportAbsolute.Request(x=2.0, y=CENTER, theta=1.0))
    turtle = sim.world.turtles["turtle1"]
    assert turtle.x == pytest.approx(CENTER, abs=1e-6)  # queued until the next step
    run_ticks(sim, 1)
    assert turtle.x == pytest.approx(2.0, abs=1e-6)
    assert turtle.theta == pytest.approx(1.0, abs=1e-6)
    assert sim.world.canvas.color_at(3.5, CENTER) == PEN_COLOR
    assert sim.world.canvas.color_at(1.0, CENTER) == UNPAINTED


def test_teleport_absolute_draws_nothing_when_the_pen_is_off():
    sim, _ = make_sim()
    run_ticks(sim, 1)
    call(sim, "/turtle1/set_pen", SetPen.Request(off=1))
    call(sim, "/turtle1/teleport_absolute", TeleportAbsolute.Request(x=2.0, y=CENTER, theta=0.0))
    run_ticks(sim, 1)
    assert sim.world.turtles["turtle1"].x == pytest.approx(2.0, abs=1e-6)
    assert np.all(sim.world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))


def test_teleport_relative_turns_then_moves_along_the_new_heading():
    sim, _ = make_sim()
    run_ticks(sim, 1)
    call(sim, "/turtle1/teleport_relative", TeleportRelative.Request(linear=2.0, angular=math.pi / 2))
    run_ticks(sim, 1)
    turtle = sim.world.turtles["turtle1"]
    assert turtle.theta == pytest.approx(math.pi / 2, abs=1e-6)
    assert turtle.x == pytest.approx(CENTER, abs=1e-6)
    assert turtle.y == pytest.approx(CENTER + 2.0, abs=1e-6)
    assert sim.world.canvas.color_at(CENTER, CENTER + 1.0) == PEN_COLOR


def test_teleport_relative_draws_nothing_when_the_pen_is_off():
    world = started_world()
    world.set_pen("turtle1", 0, 0, 0, 0, 1)
    world.teleport_relative("turtle1", 2.0, 0.0)
    world.step()
    assert world.turtles["turtle1"].x == pytest.approx(CENTER + 2.0, abs=1e-9)
    assert np.all(world.canvas.pixels == np.array(BACKGROUND, dtype=np.uint8))


def test_teleport_does_not_count_as_distance_driven():
    # Turtle.distance: "Metres driven so far (teleports excluded)".
    world = started_world()
    turtle = world.turtles["turtle1"]
    world.teleport_absolute("turtle1", 1.0, 1.0, 0.0)
    world.step()
    assert (turtle.x, turtle.y) == (1.0, 1.0)
    assert turtle.distance == 0.0
    world.command_velocity("turtle1", 1.0, 0.0, 0.0)
    world.teleport_relative("turtle1", 3.0, 0.0)
    world.step()
    assert turtle.x == pytest.approx(4.016, abs=1e-12)
    assert turtle.distance == pytest.approx(0.016, abs=1e-12)


# -- start log lines, QoS, names ------------------------------------------------------------------------


def test_start_log_line_names_the_node():
    _, logs = make_sim()
    assert logs[0].node == "turtlesim"
    assert logs[0].level == INFO
    assert logs[0].msg == "Starting turtlesim with node name /turtlesim"


def test_start_log_line_of_turtle1_uses_turtlesims_float32_centre():
    # turtlesim passes the centre as float (width_in_meters_ / 2), so %f prints 5.544445.
    _, logs = make_sim()
    assert [r.msg for r in logs] == [
        "Starting turtlesim with node name /turtlesim",
        "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]",
    ]
    assert all(r.level == INFO and r.node == "turtlesim" for r in logs)


def test_turtlesims_topics_keep_the_last_7():
    assert QOS_DEPTH == 7
    sim, _ = make_sim()
    topics = sim.graph.topics
    assert [p.depth for p in topics["/turtle1/pose"].publishers] == [7]
    assert [p.depth for p in topics["/turtle1/color_sensor"].publishers] == [7]
    assert [s.depth for s in topics["/turtle1/cmd_vel"].subscriptions] == [7]
    call(sim, "/spawn", Spawn.Request(x=1.0, y=1.0, theta=0.0, name="t2"))
    assert [p.depth for p in topics["/t2/pose"].publishers] == [7]


def test_cmd_vel_subscription_keeps_only_the_last_7_messages():
    sim, _ = make_sim()
    seen: list[float] = []
    world = sim.world
    original = world.command_velocity
    world.command_velocity = lambda name, vx, vy, wz: (seen.append(vx), original(name, vx, vy, wz))
    topic = sim.graph.topics["/turtle1/cmd_vel"]
    for i in range(10):
        sim.graph.publish(topic, Twist(linear=Vector3(x=float(i))))
    sim.graph.run_ready()
    assert seen == [3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
    assert sim.world.turtles["turtle1"].vx == 9.0


def test_interface_names_and_types_per_turtle():
    sim, _ = make_sim()
    graph = sim.graph
    assert {n: t.type_name for n, t in graph.topics.items()} == {
        "/turtle1/cmd_vel": "geometry_msgs/msg/Twist",
        "/turtle1/pose": "turtlesim/msg/Pose",
        "/turtle1/color_sensor": "turtlesim/msg/Color",
        # what rclcpp gives every node
        "/rosout": "rcl_interfaces/msg/Log",
        "/parameter_events": "rcl_interfaces/msg/ParameterEvent",
    }
    assert {n: s.type_name for n, s in graph.services.items()} == {
        "/clear": "std_srvs/srv/Empty",
        "/reset": "std_srvs/srv/Empty",
        "/spawn": "turtlesim/srv/Spawn",
        "/kill": "turtlesim/srv/Kill",
        "/turtle1/set_pen": "turtlesim/srv/SetPen",
        "/turtle1/teleport_absolute": "turtlesim/srv/TeleportAbsolute",
        "/turtle1/teleport_relative": "turtlesim/srv/TeleportRelative",
        # the parameter services rclcpp gives the node
        "/turtlesim/describe_parameters": "rcl_interfaces/srv/DescribeParameters",
        "/turtlesim/get_parameters": "rcl_interfaces/srv/GetParameters",
        "/turtlesim/get_parameter_types": "rcl_interfaces/srv/GetParameterTypes",
        "/turtlesim/list_parameters": "rcl_interfaces/srv/ListParameters",
        "/turtlesim/set_parameters": "rcl_interfaces/srv/SetParameters",
        "/turtlesim/set_parameters_atomically": "rcl_interfaces/srv/SetParametersAtomically",
        # Iron on: rcl's type description service (start_type_description_service)
        "/turtlesim/get_type_description": "type_description_interfaces/srv/GetTypeDescription",
    }
    assert {n: a.type_name for n, a in graph.action_servers.items()} == {
        "/turtle1/rotate_absolute": "turtlesim/action/RotateAbsolute"
    }
    assert [n.fqn for n in graph.nodes] == ["/turtlesim"]


# -- parameters --------------------------------------------------------------------------------------------


def test_turtlesim_parameters_are_declared_with_defaults():
    sim, _ = make_sim()
    own = {name: value for name, value in sim.turtlesim.node.parameters.items()
           if name not in ("use_sim_time", "start_type_description_service")
           and not name.startswith("qos_overrides.")}  # what every rclcpp node declares (tests/graph)
    assert own == {
        "background_r": 69,
        "background_g": 86,
        "background_b": 255,
        "holonomic": False,
    }


def test_background_parameter_repaints_the_screen_and_keeps_the_trails():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    command(sim, vx=1.0)
    run_ticks(sim, 20)
    canvas = sim.world.canvas
    trail = canvas.painted.copy()
    assert canvas.color_at(CENTER + 0.1, CENTER) == PEN_COLOR
    assert sim.turtlesim.set_parameter("background_r", 0) is None
    assert sim.turtlesim.node.parameters["background_r"] == 0
    assert sim.world.background == (0, 86, 255)
    assert np.all(canvas.pixels[~trail] == np.array([0, 86, 255], dtype=np.uint8))
    assert sim.turtlesim.set_parameter("background_g", 10) is None
    assert sim.turtlesim.set_parameter("background_b", 20) is None
    assert np.all(canvas.pixels[~trail] == np.array([0, 10, 20], dtype=np.uint8))
    assert np.all(canvas.pixels[trail] == np.array(PEN_COLOR, dtype=np.uint8))  # the trail stays
    assert canvas.color_at(CENTER + 0.1, CENTER) == PEN_COLOR
    assert canvas.color_at(1.0, 1.0) == UNPAINTED  # the sensor never reads the background
    assert "Clearing turtlesim." not in messages(logs, INFO)
    call(sim, "/clear", Empty.Request())  # clear now shows the new background
    assert np.all(canvas.pixels == np.array([0, 10, 20], dtype=np.uint8))


@pytest.mark.parametrize(("name", "value"), [("background_r", 256), ("background_g", -1), ("background_b", 1.5), ("background_r", True), ("nonsense", 1)])
def test_background_parameter_refuses_bad_values(name, value):
    sim, _ = make_sim()
    reason = sim.turtlesim.set_parameter(name, value)
    assert isinstance(reason, str) and reason
    assert sim.world.background == BACKGROUND
    assert sim.turtlesim.node.parameters["background_r"] == 69


# -- robustness: non-finite input ---------------------------------------------------------------------------


def test_non_finite_velocity_is_refused_with_a_warning_and_the_turtle_stops():
    sim, logs = make_sim()
    run_ticks(sim, 2)
    command(sim, vx=1.0, wz=0.5)
    run_ticks(sim, 5)
    command(sim, vx=float("nan"), wz=0.5)
    turtle = sim.world.turtles["turtle1"]
    assert (turtle.vx, turtle.vy, turtle.wz) == (0.0, 0.0, 0.0)
    pose = (turtle.x, turtle.y, turtle.theta)
    run_ticks(sim, 5)
    assert (turtle.x, turtle.y, turtle.theta) == pose
    assert all(math.isfinite(v) for v in pose)
    warnings = messages(logs, WARN)
    assert len(warnings) == 1
    assert warnings[0].startswith("Ignored a non-finite velocity command (linear.x=nan")
    assert warnings[0].endswith("the turtle stops")


@pytest.mark.parametrize("bad", [float("inf"), float("-inf"), float("nan")])
def test_non_finite_turn_rate_is_refused_on_the_world(bad):
    world = started_world()
    world.command_velocity("turtle1", 1.0, 0.0, bad)
    turtle = world.turtles["turtle1"]
    world.step()
    assert math.isfinite(turtle.theta) and turtle.theta == 0.0
    assert turtle.x == pytest.approx(CENTER, abs=1e-12)
    assert any(isinstance(e, Warning_) for e in world.take_events())


def test_teleport_to_non_finite_is_refused():
    sim, logs = make_sim()
    run_ticks(sim, 1)
    call(sim, "/turtle1/teleport_absolute", TeleportAbsolute.Request(x=float("inf"), y=1.0, theta=0.0))
    call(sim, "/turtle1/teleport_relative", TeleportRelative.Request(linear=float("nan"), angular=0.0))
    run_ticks(sim, 1)
    turtle = sim.world.turtles["turtle1"]
    assert turtle.x == pytest.approx(CENTER, abs=1e-6) and turtle.y == pytest.approx(CENTER, abs=1e-6)
    errors = messages(logs, ERROR)
    assert errors == [
        "Refused teleport_absolute for turtle [turtle1]: x=inf is not finite",
        "Refused teleport_relative for turtle [turtle1]: linear=nan is not finite",
    ]
    with pytest.raises(SimError):
        sim.world.teleport_absolute("turtle1", 1.0, float("nan"), 0.0)
    assert sim.world.turtles["turtle1"].teleports == []


# -- determinism ---------------------------------------------------------------------------------------------


def _scripted_run() -> list[tuple[str, str, str, str, str, str]]:
    sim, _ = make_sim()
    out: list = []
    for name in ("turtle1", "t2"):
        if name == "t2":
            call(sim, "/spawn", Spawn.Request(x=2.0, y=3.0, theta=0.3, name="t2"))
        node = sim.graph.add_node(f"rec_{name}", owner="test")
        sim.graph.add_subscription(
            node,
            f"/{name}/pose",
            Pose,
            1000,
            lambda p, name=name: out.append(
                (name, str(sim.graph.now_ns), p.x.hex(), p.y.hex(), p.theta.hex(), p.linear_velocity.hex())
            ),
        )
    run_ticks(sim, 2)
    for i in range(40):
        command(sim, vx=1.5 + 0.01 * i, wz=math.sin(i))
        command(sim, vx=2.0, wz=-0.3, turtle="t2")
        run_ticks(sim, 3)
    send_goal(sim, -2.0)
    sim.run_until(sim.graph.now_ns + 2 * NS)
    return out


def test_two_identical_runs_give_identical_pose_sequences_bit_for_bit():
    first = _scripted_run()
    second = _scripted_run()
    assert len(first) > 300
    assert first == second
