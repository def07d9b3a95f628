"""The arena and its turtles: turtlesim's ``TurtleFrame`` without the window."""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Iterable

import numpy as np

from turtletui.errors import TurtletuiError
from turtletui.sim.canvas import PenCanvas
from turtletui.sim.constants import BACKGROUND, CENTER, DT, QT_DEFAULT_PEN_WIDTH
from turtletui.sim.events import (
    Cleared,
    Event,
    Killed,
    RotationFinished,
    Spawned,
    Warning_,
)
from turtletui.sim.obstacles import Box, Circle, Lidar, Obstacle
from turtletui.sim.turtle import RotationGoal, Turtle

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_isfinite = math.isfinite
_hypot = math.hypot
_F32 = struct.Struct("3f")


class SimError(TurtletuiError, ValueError):
    """A request turtlesim refuses; the message is the line turtlesim logs."""


class World:
    """Deterministic turtlesim: turtles, pen image and the requests that change them.

    ``step()`` advances time by ``DT``; every other method is a request that
    takes effect as turtlesim's service callbacks do. Whatever turtlesim would
    log is appended to ``events``, which the owner drains with ``take_events``.

    Beyond turtlesim, a world may hold ``obstacles`` (circles and boxes that
    block turtles as the walls do, see turtletui.sim.obstacles) and a
    ``lidar`` every turtle carries; ``seed`` seeds the LiDAR's noise.
    Without them the world is exactly turtlesim's.
    """

    def __init__(
        self,
        *,
        holonomic: bool = False,
        background: tuple[int, int, int] = BACKGROUND,
        spawn_turtle1: bool = True,
        obstacles: Iterable[Obstacle] = (),
        lidar: Lidar | None = None,
        seed: int = 0,
    ) -> None:
        self.holonomic = holonomic
        """Whether linear.y of a velocity command moves the turtle sideways."""
        self.obstacles: tuple[Obstacle, ...] = tuple(obstacles)
        """Circles and boxes turtles cannot enter (fixed for the world's life)."""
        for obstacle in self.obstacles:
            if not isinstance(obstacle, (Circle, Box)):
                raise TypeError(f"an obstacle must be a Circle or a Box, got {type(obstacle).__name__}")
        self.lidar = lidar
        """The LiDAR on every turtle, or None for none (turtlesim)."""
        self.seed = seed
        self._rng: np.random.Generator | None = None
        self.canvas = PenCanvas(background)
        self.turtles: dict[str, Turtle] = {}
        self.ticks = 0
        """Timer ticks so far; the first only records the time, as in turtlesim."""
        self.events: list[Event] = []
        self._id_counter = 0
        self.turtles_in_order: list[Turtle] = []
        """The turtles in the order they update (by name, as turtlesim's
        std::map); read-only: the world replaces the list when it changes."""
        if spawn_turtle1:
            self.spawn(CENTER, CENTER, 0.0)

    @property
    def time(self) -> float:
        """Simulated seconds since start (ticks * DT)."""
        return self.ticks * DT

    @property
    def background(self) -> tuple[int, int, int]:
        return self.canvas.background
    @property
    def rng(self) -> np.random.Generator:
        """The world's random generator (the LiDAR's noise), seeded with ``seed``."""
        if self._rng is None:
            self._rng = np.random.default_rng(self.seed)
        return self._rng

    def take_events(self) -> list[Event]:
        """Return and forget the events reported since the last call."""
        events = self.events
        self.events = []
        return events

    # -- time ---------------------------------------------------------------
    def step(self, sense_color: bool = False) -> bool:
        """Advance one 16 ms tick. Returns False for the first tick, which only
        records the time (turtles start moving on the second).

        With ``sense_color`` each turtle's ``color`` is set to the pixel under
        it after moving and before drawing this step's segment, which is what
        turtlesim's color_sensor publishes.
        """
        self.ticks += 1
        if self.ticks == 1:
            return False
        now = self.ticks * DT
        events = self.events
        canvas = self.canvas
        draw = canvas.draw_segment
        obstacles = self.obstacles
        for turtle in self.turtles_in_order:
            if turtle.teleports:
                # turtlesim takes old_pos for the step's segment after teleports.
                turtle.apply_teleports(draw)
            old_x = turtle.x
            old_y = turtle.y
            turtle.update(now, DT, events, obstacles)
            x = turtle.x
            y = turtle.y
            moved = x != old_x or y != old_y
            if moved:
                turtle.distance += _hypot(x - old_x, y - old_y)
            if sense_color:
                turtle.color = canvas.color_at(x, y)
            if moved and turtle.pen_on:
                draw(old_x, old_y, x, y, turtle.pen_color, turtle.pen_width)
        return True

    # -- requests -----------------------------------------------------------
    def turtle(self, name: str) -> Turtle:
        """The turtle called ``name``; SimError if there is none."""
        try:
            return self.turtles[name]
        except KeyError:
            raise SimError(f"There is no turtle named [{name}]") from None

    def spawn(self, x: float, y: float, theta: float, name: str = "") -> str:
        """Add a turtle; an empty name picks turtleN with the next free N."""
        if not name:
            while True:
                self._id_counter += 1
                name = f"turtle{self._id_counter}"
                if name not in self.turtles:
                    break
        elif name in self.turtles:
            raise SimError(f"A turtle named [{name}] already exists")
        elif not _NAME.match(name) or "__" in name:
            raise SimError(
                f"Invalid turtle name [{name}]: use letters, digits and single underscores,"
                " starting with a letter"
            )
        for field, value in (("x", x), ("y", y), ("theta", theta)):
            if not _isfinite(value):
                raise SimError(f"Refused to spawn turtle [{name}]: {field}={value} is not finite")
        # turtlesim's spawnTurtle takes floats: the pose starts float32-rounded.
        x, y, theta = _F32.unpack(_F32.pack(x, y, theta))
        turtle = Turtle(name, x, y, theta, last_command_time=self.time)
        self.turtles[name] = turtle
        self._reorder()
        self.events.append(Spawned(name, turtle.x, turtle.y, turtle.theta))
        return name

    def place(self, name: str, x: float, y: float, theta: float) -> None:
        """Put a turtle somewhere before time runs (a scenario's start): no line
        is drawn; float32-rounded as a spawn is."""
        turtle = self.turtle(name)
        turtle.x, turtle.y, turtle.theta = _F32.unpack(_F32.pack(x, y, theta))

    def kill(self, name: str) -> None:
        """Remove a turtle."""
        turtle = self.turtles.pop(name, None)
        if turtle is None:
            raise SimError(f"Tried to kill turtle [{name}], which does not exist")
        self._abort_rotation(turtle)
        self._reorder()
        self.events.append(Killed(name))

    def clear(self) -> None:
        """Wipe the drawing with the background colour (the /clear service)."""
        self.canvas.clear()
        self.events.append(Cleared())

    def set_background(self, rgb: tuple[int, int, int]) -> None:
        """Change the background colour. As in turtlesim, only the screen is
        repainted: the trails drawn so far stay (and /clear keeps the new colour)."""
        self.canvas.set_background(tuple(rgb))

    def reset(self) -> None:
        """Remove every turtle, restart the name counter, spawn turtle1, clear."""
        for turtle in list(self.turtles.values()):
            self._abort_rotation(turtle)
            self.events.append(Killed(turtle.name))
        self.turtles.clear()
        self.turtles_in_order = []
        self._id_counter = 0
        self.spawn(CENTER, CENTER, 0.0)
        self.clear()

    def command_velocity(self, name: str, vx: float, vy: float, wz: float) -> None:
        """A Twist on /<name>/cmd_vel: set the velocities and the command time."""
        turtle = self.turtles.get(name) or self.turtle(name)
        if vx - vx + vy - vy + wz - wz != 0.0:  # one is inf or nan (x - x is 0 for any finite x)
            self.events.append(
                Warning_(
                    name,
                    f"Ignored a non-finite velocity command (linear.x={vx}, linear.y={vy},"
                    f" angular.z={wz}): the turtle stops",
                )
            )
            vx = vy = wz = 0.0
        turtle.last_command_time = self.ticks * DT  # self.time, on every command
        turtle.vx = vx
        turtle.vy = vy if self.holonomic else 0.0
        turtle.wz = wz
        if turtle.rotation is not None:
            self.events.append(
                Warning_(name, "Velocity command received during rotation goal. Aborting goal")
            )
            self._abort_rotation(turtle)

    def set_pen(self, name: str, r: int, g: int, b: int, width: int, off: int) -> None:
        """Change the pen: off lifts it (colour and width unchanged). Otherwise
        turtlesim makes a new Qt pen, so width 0 gives Qt's default, 1 pixel."""
        turtle = self.turtle(name)
        turtle.pen_on = not off
        if off:
            return
        turtle.pen_color = (r, g, b)
        turtle.pen_width = width or QT_DEFAULT_PEN_WIDTH

    def teleport_absolute(self, name: str, x: float, y: float, theta: float) -> None:
        """Queue a jump to (x, y, theta); it happens at the start of the next step."""
        turtle = self.turtle(name)
        _require_finite("teleport_absolute", name, x=x, y=y, theta=theta)
        turtle.teleports.append((False, float(x), float(y), float(theta)))

    def teleport_relative(self, name: str, linear: float, angular: float) -> None:
        """Queue a turn by ``angular`` then a move of ``linear`` metres ahead."""
        turtle = self.turtle(name)
        _require_finite("teleport_relative", name, linear=linear, angular=angular)
        turtle.teleports.append((True, float(linear), float(angular), 0.0))

    def start_rotation(self, name: str, theta: float) -> RotationGoal:
        """Accept a rotate_absolute goal, aborting the turtle's previous one."""
        turtle = self.turtle(name)
        _require_finite("rotate_absolute", name, theta=theta)
        if turtle.rotation is not None:
            self.events.append(
                Warning_(
                    name,
                    "Rotation goal received before a previous goal finished. Aborting previous goal",
                )
            )
            self._abort_rotation(turtle)
        goal = RotationGoal(name, float(theta), turtle.theta)
        turtle.rotation = goal
        return goal

    def cancel_rotation(self, goal: RotationGoal) -> None:
        """Ask for a goal to stop; it ends as canceled at the next step."""
        if goal.status == "active":
            goal.cancel_requested = True

    def _abort_rotation(self, turtle: Turtle) -> None:
        goal = turtle.rotation
        if goal is not None:
            goal.status = "aborted"
            turtle.rotation = None
            self.events.append(RotationFinished(goal, "aborted", goal.delta))

    def _reorder(self) -> None:
        # turtlesim keeps its turtles in a std::map, so they update by name order.
        self.turtles_in_order = [self.turtles[key] for key in sorted(self.turtles)]


def _require_finite(service: str, name: str, **values: float) -> None:
    for field, value in values.items():
        if not _isfinite(value):
            raise SimError(f"Refused {service} for turtle [{name}]: {field}={value} is not finite")
