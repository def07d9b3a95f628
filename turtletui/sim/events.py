"""What a simulation step or request did that someone should hear about.

The physics returns these as data; the turtlesim node turns them into the log
lines and action messages the real turtlesim would produce.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from turtletui.sim.turtle import RotationGoal


@dataclass(frozen=True, slots=True)
class Event:
    """Base class of everything the world reports."""


@dataclass(frozen=True, slots=True)
class WallHit(Event):
    """A turtle left the arena and was clamped back; x, y are before the clamp."""

    turtle: str
    x: float
    y: float


@dataclass(frozen=True, slots=True)
class ObstacleHit(Event):
    """A turtle's step ran into an obstacle; x, y is where it was stopped (the surface)."""

    turtle: str
    x: float
    y: float


@dataclass(frozen=True, slots=True)
class Spawned(Event):
    """A turtle appeared (spawn service, or turtle1 at start and reset)."""

    turtle: str
    x: float
    y: float
    theta: float


@dataclass(frozen=True, slots=True)
class Killed(Event):
    """A turtle was removed (kill service or reset)."""

    turtle: str


@dataclass(frozen=True, slots=True)
class Cleared(Event):
    """The pen drawing was wiped (clear, reset or a background change)."""


@dataclass(frozen=True, slots=True)
class Warning_(Event):
    """A warning turtlesim logs about a turtle, e.g. an aborted rotation goal."""

    turtle: str
    text: str


@dataclass(frozen=True, slots=True)
class RotationFeedback(Event):
    """A rotate_absolute goal is in progress: ``remaining`` radians to go."""

    goal: RotationGoal
    remaining: float


@dataclass(frozen=True, slots=True)
class RotationFinished(Event):
    """A rotate_absolute goal ended: status is succeeded, canceled or aborted."""

    goal: RotationGoal
    status: str
    delta: float
