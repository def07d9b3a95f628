"""What the arena draws over the pen image, as plain data: each turtle's
colour, the characters of pen colours in ASCII, and the fading marks where
turtles hit a wall or an obstacle. No Textual, no rendering."""

from __future__ import annotations

import colorsys
import re
import zlib
from collections import deque
from typing import NamedTuple

from turtletui.sim import Cleared, Event, ObstacleHit, WallHit
from turtletui.sim.constants import ARENA_SIZE, PEN_COLOR

TURTLE_COLORS = (
    (255, 214, 0),  # yellow
    (80, 230, 110),  # green
    (255, 120, 40),  # orange
    (255, 100, 210),  # pink
    (70, 225, 235),  # cyan
    (255, 255, 255),  # white
    (190, 140, 255),  # violet
    (255, 70, 70),  # red
)
"""One colour per turtle, bright on the blue floor, the lavender trail and one another."""

_NUMBERED = re.compile(r"turtle(\d+)\Z")


def turtle_color(name: str) -> tuple[int, int, int]:
    """The colour a turtle is drawn in: turtle1 yellow, turtle2 green ... (by
    its number), other names by a hash of the name; the same on every run."""
    match = _NUMBERED.match(name)
    index = int(match.group(1)) - 1 if match else zlib.crc32(name.encode())
    return TURTLE_COLORS[index % len(TURTLE_COLORS)]


OBSTACLE_CHAR = "X"
OVERLAY_CHAR = "."
DEFAULT_PEN_CHAR = "#"
"""turtlesim's own pen colour (lavender) in ASCII."""

_HUE_CHARS = "*$+~=%"
"""Pen colours in ASCII by hue: red, yellow, green, cyan, blue, magenta."""


def pen_char(rgb: tuple[int, int, int]) -> str:
    """The ASCII character of a trail drawn in ``rgb``: '#' for turtlesim's
    default pen, else one character per hue (red '*', yellow '$', green '+',
    cyan '~', blue '=', magenta '%'), 'o' for white-ish and ':' for dark or
    grey pens. Part 7's red and green halves read '*' and '+'."""
    if tuple(rgb) == PEN_COLOR:
        return DEFAULT_PEN_CHAR
    r, g, b = (c / 255 for c in rgb)
    hue, lightness, saturation = colorsys.rgb_to_hls(r, g, b)
    if saturation < 0.25 or lightness < 0.12 or lightness > 0.92:
        return "o" if lightness >= 0.5 else ":"
    return _HUE_CHARS[round(hue * 6) % 6]


class HitMark(NamedTuple):
    """Where a turtle ran into a wall or an obstacle, and when (simulated s)."""

    x: float
    y: float
    t: float


FADE_SECONDS = 3.0
"""Simulated seconds a hit mark stays on the arena, fading."""
FADE_LEVELS = 3
"""Steps of the fading (a frame changes only when a mark changes its step)."""
_SAME_PLACE = 0.3
"""Metres: a turtle pushing along a wall refreshes its mark rather than adding marks."""


class HitMarks:
    """The recent wall and obstacle hits of a simulation, fed with its events."""

    def __init__(self, capacity: int = 64) -> None:
        self._marks: deque[HitMark] = deque(maxlen=capacity)

    def record(self, event: Event, t: float) -> None:
        """Take one event of the world at simulated time ``t`` (others are ignored)."""
        if isinstance(event, Cleared):
            self._marks.clear()
            return
        if not isinstance(event, (WallHit, ObstacleHit)):
            return
        # A wall hit reports where the turtle would have gone; it is drawn where it hit.
        x = min(max(event.x, 0.0), ARENA_SIZE)
        y = min(max(event.y, 0.0), ARENA_SIZE)
        for i in range(len(self._marks) - 1, max(len(self._marks) - 8, -1), -1):
            mark = self._marks[i]
            if abs(mark.x - x) < _SAME_PLACE and abs(mark.y - y) < _SAME_PLACE:
                del self._marks[i]
                break
        self._marks.append(HitMark(x, y, t))

    def clear(self) -> None:
        """Forget every mark (the simulation starts again)."""
        self._marks.clear()

    def visible(self, now: float) -> tuple[tuple[float, float, int], ...]:
        """(x, y, level) of the marks still shown at ``now``; level 0 is the
        freshest, FADE_LEVELS - 1 the faintest."""
        shown = []
        for mark in self._marks:
            age = now - mark.t
            if 0.0 <= age < FADE_SECONDS:
                shown.append((mark.x, mark.y, int(age / FADE_SECONDS * FADE_LEVELS)))
        return tuple(shown)
