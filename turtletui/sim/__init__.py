"""Deterministic turtlesim physics: no I/O, no clocks, no front ends.

``World.step()`` is the only way simulated time passes; everything the ROS 2
turtlesim does to its turtles (shared/TURTLESIM.md) happens here, and what it
would log is returned as events for the turtlesim node to turn into log lines.
"""

from turtletui.sim.canvas import PenCanvas
from turtletui.sim.constants import (
    ARENA_SIZE,
    BACKGROUND,
    CENTER,
    COMMAND_TIMEOUT,
    DT,
    METER_PX,
    PEN_COLOR,
    PEN_WIDTH,
    PIXELS,
    normalize_angle,
)
from turtletui.sim.events import (
    Cleared,
    Event,
    Killed,
    ObstacleHit,
    RotationFeedback,
    RotationFinished,
    Spawned,
    WallHit,
    Warning_,
)
from turtletui.sim.obstacles import Box, Circle, Lidar, Obstacle
from turtletui.sim.turtle import RotationGoal, Turtle
from turtletui.sim.world import SimError, World

__all__ = [
    "ARENA_SIZE",
    "BACKGROUND",
    "CENTER",
    "COMMAND_TIMEOUT",
    "DT",
    "METER_PX",
    "PEN_COLOR",
    "PEN_WIDTH",
    "PIXELS",
    "Box",
    "Circle",
    "Cleared",
    "Event",
    "Killed",
    "Lidar",
    "Obstacle",
    "ObstacleHit",
    "PenCanvas",
    "RotationFeedback",
    "RotationFinished",
    "RotationGoal",
    "SimError",
    "Spawned",
    "Turtle",
    "WallHit",
    "Warning_",
    "World",
    "normalize_angle",
]
