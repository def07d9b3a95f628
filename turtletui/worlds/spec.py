"""What a world is, as data: obstacles, LiDAR and background."""

from __future__ import annotations

from dataclasses import dataclass

from turtletui.errors import TurtletuiError
from turtletui.sim import BACKGROUND, Lidar, Obstacle, World


class WorldError(TurtletuiError, ValueError):
    """A world that cannot be found or used; the message is one line."""


@dataclass(frozen=True)
class WorldSpec:
    """A world's description; ``build`` makes a fresh simulation World of it."""

    name: str
    description: str = ""
    obstacles: tuple[Obstacle, ...] = ()
    """Circles and boxes (turtletui.sim.Circle, turtletui.sim.Box), metres."""
    lidar: Lidar | None = None
    """The LiDAR every turtle carries (published on /<turtle>/scan); None for none."""
    background: tuple[int, int, int] | None = None
    """Background colour (r, g, b); None for turtlesim's own."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "obstacles", tuple(self.obstacles))

    def build(self, seed: int = 0) -> World:
        """A new World with turtle1 at the centre; ``seed`` seeds the LiDAR's noise."""
        return World(
            obstacles=self.obstacles,
            lidar=self.lidar,
            background=self.background or BACKGROUND,
            seed=seed,
        )
