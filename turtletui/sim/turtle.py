"""One turtle: its state and turtlesim's ``Turtle::update`` step."""

from __future__ import annotations

import math
import struct
from collections.abc import Sequence
from dataclasses import dataclass, field

from turtletui.sim.constants import (
    ARENA_SIZE,
    COMMAND_TIMEOUT,
    PEN_COLOR,
    PEN_WIDTH,
    ROTATE_SPEED,
    ROTATE_TOLERANCE,
    normalize_angle,
)
from turtletui.sim.events import Event, ObstacleHit, RotationFeedback, RotationFinished, WallHit
from turtletui.sim.obstacles import Obstacle, first_entry

_cos = math.cos
_PI = math.pi
_sin = math.sin
_F32 = struct.Struct("f")


@dataclass(eq=False)
class RotationGoal:
    """An accepted rotate_absolute goal: turn ``turtle`` to heading ``theta``.

    ``status`` is "active" until the goal succeeds, is canceled or aborted.
    """

    turtle: str
    theta: float
    start_theta: float
    status: str = "active"
    cancel_requested: bool = False
    delta: float = 0.0


@dataclass(eq=False, slots=True)
class Turtle:
    """State of one turtle, in metres, radians and seconds (world frame, y up)."""

    name: str
    x: float
    y: float
    theta: float
    vx: float = 0.0
    """Commanded forward speed, m/s."""
    vy: float = 0.0
    """Commanded sideways speed, m/s (used only when the world is holonomic)."""
    wz: float = 0.0
    """Commanded turn rate, rad/s."""
    last_command_time: float = 0.0
    pen_on: bool = True
    pen_color: tuple[int, int, int] = PEN_COLOR
    pen_width: int = PEN_WIDTH
    teleports: list[tuple[bool, float, float, float]] = field(default_factory=list)
    """Queued (relative, a, b, c) requests: absolute (x, y, theta), relative (linear, angular, -)."""
    rotation: RotationGoal | None = None
    distance: float = 0.0
    """Metres driven so far (teleports excluded)."""
    wall_hits: int = 0
    """Times the turtle ran into a wall (a stay against the wall counts once)."""
    touching_wall: bool = False
    obstacle_hits: int = 0
    """Times the turtle ran into an obstacle (pushing against one counts once)."""
    touching_obstacle: bool = False
    color: tuple[int, int, int] = (0, 0, 0)
    """Last colour sensed under the turtle (set by World.step when asked)."""

    def update(
        self, now: float, dt: float, events: list[Event], obstacles: Sequence[Obstacle] = ()
    ) -> None:
        """Advance this turtle by ``dt`` seconds at simulated time ``now``.

        Follows turtlesim's order after the queued teleports (``apply_teleports``,
        called first by World.step): rotate_absolute goal, command timeout,
        semi-implicit heading update, move, clamp. With ``obstacles`` (not in
        turtlesim) a move that would enter one stops where it meets the
        surface, before the clamp at the walls. Pose publishing and the
        step's pen segment happen in the caller, as in turtlesim: the colour
        sensor reads the image before this step's line is drawn.
        """
        if self.rotation is not None:
            self._advance_rotation(now, events)
        if now - self.last_command_time > COMMAND_TIMEOUT:
            self.vx = self.vy = self.wz = 0.0
        theta = self.theta + self.wz * dt
        if not -_PI <= theta < _PI:
            theta = normalize_angle(theta)
        self.theta = theta
        vx = self.vx
        vy = self.vy
        c = _cos(theta)
        s = _sin(theta)
        x = self.x + (c * vx - s * vy) * dt
        y = self.y + (s * vx + c * vy) * dt
        if obstacles:
            x, y = self._block(x, y, obstacles, events)
        if x < 0.0 or x > ARENA_SIZE or y < 0.0 or y > ARENA_SIZE:
            events.append(WallHit(self.name, x, y))
            if not self.touching_wall:
                self.touching_wall = True
                self.wall_hits += 1
            x = min(max(x, 0.0), ARENA_SIZE)
            y = min(max(y, 0.0), ARENA_SIZE)
        elif self.touching_wall:
            self.touching_wall = False
        self.x = x
        self.y = y

    def _block(
        self, x: float, y: float, obstacles: Sequence[Obstacle], events: list[Event]
    ) -> tuple[float, float]:
        stop = first_entry(obstacles, self.x, self.y, x - self.x, y - self.y)
        if stop is None:
            self.touching_obstacle = False
            return x, y
        events.append(ObstacleHit(self.name, stop[0], stop[1]))
        if not self.touching_obstacle:
            self.touching_obstacle = True
            self.obstacle_hits += 1
        return stop

    def apply_teleports(self, draw) -> None:
        """Apply queued teleports in order, drawing each jump when the pen is on."""
        for relative, a, b, c in self.teleports:
            old_x, old_y = self.x, self.y
            if relative:
                self.theta = normalize_angle(self.theta + b)
                self.x += _cos(self.theta) * a
                self.y += _sin(self.theta) * a
            else:
                # turtlesim stores y flipped and clamps it at the top edge:
                # pos.y = max(0, height - y)
                self.x = a
                self.y = min(b, ARENA_SIZE)
                self.theta = normalize_angle(c)
            if self.pen_on:
                draw(old_x, old_y, self.x, self.y, self.pen_color, self.pen_width)
        self.teleports.clear()

    def _advance_rotation(self, now: float, events: list[Event]) -> None:
        # turtle.cpp: a cancel ends the goal with the result of the previous
        # tick (delta not recomputed); otherwise the heading is compared as a
        # float, and delta is normalize(float(start - heading)).
        goal = self.rotation
        assert goal is not None
        if goal.cancel_requested:
            goal.status = "canceled"
            self.rotation = None
            self.vx = self.vy = self.wz = 0.0
            events.append(RotationFinished(goal, "canceled", goal.delta))
            return
        target = normalize_angle(goal.theta)
        heading = _float32(self.theta)
        remaining = normalize_angle(target - heading)
        goal.delta = normalize_angle(_float32(goal.start_theta - self.theta))
        events.append(RotationFeedback(goal, remaining))
        if abs(normalize_angle(heading - target)) < ROTATE_TOLERANCE:
            goal.status = "succeeded"
            self.rotation = None
            self.vx = self.vy = self.wz = 0.0
            events.append(RotationFinished(goal, "succeeded", goal.delta))
        else:
            self.wz = -ROTATE_SPEED if remaining < 0.0 else ROTATE_SPEED
            self.vx = self.vy = 0.0
            self.last_command_time = now


def _float32(value: float) -> float:
    """``static_cast<float>(value)`` back as a Python float."""
    try:
        return _F32.unpack(_F32.pack(value))[0]
    except OverflowError:
        return math.copysign(math.inf, value)
