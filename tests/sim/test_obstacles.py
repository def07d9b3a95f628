"""Obstacles: geometry, blocking turtles the way walls do, and ray casting."""

from __future__ import annotations

import math

import numpy as np
import pytest

from turtletui.sim import ARENA_SIZE, CENTER, Box, Circle, ObstacleHit, WallHit, World
from turtletui.sim.obstacles import (
    cast_rays,
    collides,
    first_entry,
    nearest_distance,
    push_out,
    surface_distance,
)

RING = Circle(8.0, CENTER, 1.0)
BLOCK = Box(1.0, 1.0, 2.0, 3.0)


# -- geometry -----------------------------------------------------------------------


@pytest.mark.parametrize(
    "make",
    [
        lambda: Circle(1.0, 1.0, 0.0),
        lambda: Circle(1.0, math.nan, 1.0),
        lambda: Box(2.0, 1.0, 1.0, 3.0),
        lambda: Box(1.0, 1.0, 2.0, 1.0),
        lambda: Box(0.0, 0.0, math.inf, 1.0),
    ],
)
def test_degenerate_obstacles_are_refused(make):
    with pytest.raises(ValueError):
        make()


def test_the_surface_is_outside_and_the_interior_collides():
    assert collides([RING], 8.0, CENTER)
    assert collides([RING], 7.5, CENTER)
    assert not collides([RING], 7.0, CENTER)  # on the surface
    assert collides([BLOCK], 1.5, 2.0)
    assert not collides([BLOCK], 1.0, 2.0)  # on the left side
    assert not collides([BLOCK], 5.0, 5.0)
    assert not collides([], 1.5, 2.0)


def test_surface_distance_is_signed():
    assert surface_distance(RING, 5.0, CENTER) == pytest.approx(2.0)
    assert surface_distance(RING, 8.0, CENTER) == pytest.approx(-1.0)
    assert surface_distance(BLOCK, 0.0, 2.0) == pytest.approx(1.0)
    assert surface_distance(BLOCK, 5.0, 7.0) == pytest.approx(5.0)  # to the corner (2, 3)
    assert surface_distance(BLOCK, 1.25, 2.0) == pytest.approx(-0.25)
    assert nearest_distance([RING, BLOCK], 0.0, 2.0) == pytest.approx(1.0)
    assert nearest_distance([], 0.0, 2.0) == math.inf


def test_push_out_moves_to_the_nearest_surface_point():
    x, y = push_out(RING, 7.5, CENTER)
    assert (x, y) == pytest.approx((7.0, CENTER))
    assert not collides([RING], x, y)
    assert push_out(BLOCK, 1.1, 2.0) == (1.0, 2.0)
    assert push_out(BLOCK, 1.5, 2.9) == (1.5, 3.0)
    assert push_out(BLOCK, 5.0, 5.0) == (5.0, 5.0)  # outside: unchanged


# -- a step ------------------------------------------------------------------------------


def test_a_step_into_a_circle_stops_on_its_surface():
    stop = first_entry([RING], 6.5, CENTER, 1.0, 0.0)
    assert stop == pytest.approx((7.0, CENTER))
    assert not collides([RING], *stop)
    assert first_entry([RING], 6.5, CENTER, 0.4, 0.0) is None  # short of it
    assert first_entry([RING], 6.5, CENTER, -1.0, 0.0) is None  # away from it


def test_a_step_into_a_box_stops_exactly_on_the_face():
    assert first_entry([BLOCK], 0.5, 2.0, 1.0, 0.0) == (1.0, 2.0)
    stop = first_entry([BLOCK], 1.5, 3.5, 0.2, -1.0)
    assert stop[1] == 3.0 and stop[0] == pytest.approx(1.6)
    # From the face, pushing on stays there; sliding along it is free.
    assert first_entry([BLOCK], 1.0, 2.0, 0.1, 0.0) == (1.0, 2.0)
    assert first_entry([BLOCK], 1.0, 2.0, 0.0, 0.5) is None


def test_a_fast_step_cannot_tunnel_through_a_thin_obstacle():
    wall = Box(5.0, 0.0, 5.05, 11.0)
    assert first_entry([wall], 4.0, 2.0, 3.0, 0.0) == (5.0, 2.0)


def test_a_step_from_inside_is_not_blocked_so_the_turtle_can_leave():
    assert first_entry([RING], 8.0, CENTER, 2.0, 0.0) is None
    assert first_entry([BLOCK], 1.5, 2.0, 0.0, -3.0) is None


def test_the_first_obstacle_on_the_way_blocks():
    near = Circle(4.0, 2.0, 0.5)
    far = Box(6.0, 0.0, 7.0, 4.0)
    assert first_entry([far, near], 2.0, 2.0, 6.0, 0.0) == pytest.approx((3.5, 2.0))


# -- rays --------------------------------------------------------------------------------


def test_rays_stop_at_the_walls_without_obstacles():
    angles = np.array([0.0, math.pi / 2, math.pi, -math.pi / 2, math.pi / 4])
    ranges = cast_rays([], 2.0, 3.0, angles, 100.0)
    # The diagonal ray leaves through the top wall, the nearer one along it.
    expected = [ARENA_SIZE - 2.0, ARENA_SIZE - 3.0, 2.0, 3.0, (ARENA_SIZE - 3.0) * math.sqrt(2)]
    assert ranges == pytest.approx(expected)
    assert cast_rays([], 2.0, 3.0, angles, 2.5) == pytest.approx([2.5, 2.5, 2.0, 2.5, 2.5])


def test_rays_meet_the_nearest_obstacle():
    angles = np.array([0.0, math.pi, math.pi / 2])
    ranges = cast_rays([RING, BLOCK], 4.0, 2.0, angles, 20.0)
    assert ranges[1] == pytest.approx(2.0)  # the box's right face at x = 2
    assert ranges[2] == pytest.approx(ARENA_SIZE - 2.0)
    ranges = cast_rays([RING], 5.0, CENTER, np.array([0.0, 0.1]), 20.0)
    assert ranges[0] == pytest.approx(2.0)
    # The second ray meets the circle where |p + t u - c| = r.
    t = ranges[1]
    hit = np.array([5.0 + t * math.cos(0.1), CENTER + t * math.sin(0.1)])
    assert np.hypot(*(hit - [8.0, CENTER])) == pytest.approx(1.0)


def test_rays_from_inside_an_obstacle_measure_zero():
    ranges = cast_rays([RING, BLOCK], 1.5, 2.0, np.linspace(0, 6, 7), 5.0)
    assert np.all(ranges == 0.0)


def test_rays_along_a_box_side_pass():
    ranges = cast_rays([BLOCK], 0.0, 1.0, np.array([0.0]), 20.0)
    assert ranges[0] == pytest.approx(ARENA_SIZE)


# -- in the world ------------------------------------------------------------------------


def drive(world: World, vx: float, wz: float = 0.0, steps: int = 60) -> list:
    events = []
    for _ in range(steps):
        world.command_velocity("turtle1", vx, 0.0, wz)
        world.step()
        events += world.take_events()
    return events


def test_a_turtle_is_blocked_at_the_surface_and_counts_one_hit_per_contact():
    world = World(obstacles=[RING])
    start_y = world.turtles["turtle1"].y
    events = drive(world, 2.0, steps=80)  # 2.5 m ahead: it would pass x = 7
    turtle = world.turtles["turtle1"]
    assert turtle.x == pytest.approx(7.0) and turtle.y == start_y
    assert not collides(world.obstacles, turtle.x, turtle.y)
    hits = [e for e in events if isinstance(e, ObstacleHit)]
    assert hits and all(e.turtle == "turtle1" for e in hits)
    assert hits[0].x == pytest.approx(7.0)
    assert turtle.obstacle_hits == 1 and turtle.touching_obstacle
    assert not any(isinstance(e, WallHit) for e in events)
    drive(world, 0.0, wz=math.pi / 0.016 / 50, steps=50)  # turn round on the spot
    drive(world, 2.0, steps=10)  # and drive away
    assert not turtle.touching_obstacle and turtle.x < 7.0
    drive(world, 0.0, wz=math.pi / 0.016 / 50, steps=50)
    drive(world, 2.0, steps=40)
    assert turtle.obstacle_hits == 2


def test_the_pen_trail_stops_at_the_obstacle():
    world = World(obstacles=[RING])
    drive(world, 2.0, steps=80)
    before = world.turtles["turtle1"].distance
    drive(world, 2.0, steps=20)
    assert world.turtles["turtle1"].distance == before == pytest.approx(7.0 - CENTER, abs=1e-6)


def test_an_obstacle_in_front_of_a_wall_blocks_before_the_wall():
    world = World(obstacles=[Box(10.8, 0.0, 11.0, 11.0)])
    events = drive(world, 5.0, steps=120)
    assert world.turtles["turtle1"].x == 10.8
    assert world.turtles["turtle1"].wall_hits == 0
    assert not any(isinstance(e, WallHit) for e in events)


def test_far_obstacles_leave_the_trajectory_bit_for_bit_unchanged():
    plain = World()
    with_far = World(obstacles=[Circle(1.0, 10.0, 0.3)])
    for world in (plain, with_far):
        drive(world, 2.0, wz=0.7, steps=300)
    a, b = plain.turtles["turtle1"], with_far.turtles["turtle1"]
    assert (a.x, a.y, a.theta, a.wall_hits) == (b.x, b.y, b.theta, b.wall_hits)


def test_world_refuses_what_is_not_an_obstacle():
    with pytest.raises(TypeError):
        World(obstacles=[(1.0, 2.0, 3.0)])


def test_vectorised_rays_agree_with_the_step_blocking_geometry():
    """cast_rays (numpy, every beam at once) and first_entry (one step, scalar)
    are two implementations of the same geometry: they must agree."""
    rng = np.random.default_rng(1)
    obstacles = [Circle(3.0, 3.0, 1.0), Circle(8.0, 7.0, 0.5), Box(5.0, 1.0, 6.0, 9.0), BLOCK]
    angles = np.linspace(-math.pi, math.pi, 37)
    checked = 0
    for x, y in rng.uniform(0.0, ARENA_SIZE, (40, 2)):
        if collides(obstacles, x, y):
            assert np.all(cast_rays(obstacles, x, y, angles, 20.0) == 0.0)
            continue
        ranges = cast_rays(obstacles, x, y, angles, 20.0)
        for angle, measured in zip(angles, ranges, strict=True):
            dx, dy = 30.0 * math.cos(angle), 30.0 * math.sin(angle)
            stop = first_entry(obstacles, x, y, dx, dy)
            to_obstacle = math.inf if stop is None else math.hypot(stop[0] - x, stop[1] - y)
            wall = cast_rays([], x, y, np.array([angle]), 20.0)[0]
            assert measured == pytest.approx(min(to_obstacle, wall), abs=1e-9)
            checked += 1
    assert checked > 500
