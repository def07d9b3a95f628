"""The arena as markers for Foxglove's 3D panel and RViz: background, walls,
obstacles, the turtles and their pen trails (visualization_msgs/MarkerArray).

turtlesim draws into an image; here the trail is rebuilt from what a
recording already holds: turtlesim's poses and the set_pen, spawn, kill,
clear and reset calls. Each message is the whole scene (a DELETEALL marker
first), so a viewer that seeks shows it complete; trails are thinned to half
a pixel of turtlesim's image, and whole scenes are sent at most once a second
(every five seconds once they are large).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from turtletui.interfaces.builtin_interfaces import Duration, Time
from turtletui.interfaces.geometry_msgs import Point, Pose, Quaternion, Vector3
from turtletui.interfaces.std_msgs import ColorRGBA, Header
from turtletui.interfaces.visualization_msgs import Marker, MarkerArray
from turtletui.sim.constants import ARENA_SIZE, METER_PX, PEN_COLOR, PEN_WIDTH
from turtletui.sim.obstacles import Circle

FRAME = "world"
"""The fixed frame: turtlesim's arena, x right, y up, metres (REP 103)."""

TOLERANCE = 0.5 / METER_PX
"""How far (m) a thinned trail may stray from the path: half a pixel."""

_MAX_DROPPED = 16
_SMALL_SCENE_POINTS = 2000
_TURTLE_GREEN = (0.27, 0.63, 0.28)
_NS_PER_S = 1_000_000_000


@dataclass
class _Pen:
    on: bool = True
    color: tuple[int, int, int] = PEN_COLOR
    width: int = PEN_WIDTH


@dataclass
class _Stroke:
    """A line drawn with one pen without lifting it."""

    color: tuple[int, int, int]
    width: int
    points: list[tuple[float, float]]
    dropped: list[tuple[float, float]] = field(default_factory=list)
    """Points left out since the last one kept: the next thinning checks them too."""

    def add(self, q: tuple[float, float]) -> bool:
        """Append a point; False when it only replaced the last (a straight run)."""
        points = self.points
        if len(points) >= 2:
            candidates = [*self.dropped, points[-1]]
            a = points[-2]
            if len(candidates) <= _MAX_DROPPED and all(_off_line(p, a, q) <= TOLERANCE for p in candidates):
                self.dropped = candidates
                points[-1] = q
                return False
        self.dropped = []
        points.append(q)
        return True


def _off_line(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    """Distance from p to the segment a-b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    if length2 == 0.0:
        return math.hypot(p[0] - a[0], p[1] - a[1])
    u = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2))
    return math.hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy)


class Scene:
    """Follows a run's turtles and pens; ``due(t_ns)`` says when to send ``snapshot``."""

    def __init__(
        self,
        obstacles: tuple[Any, ...],
        background: tuple[int, int, int],
        turtles: list[str],
    ) -> None:
        self._obstacles = obstacles
        self.background = background
        self._pens: dict[str, _Pen] = {name: _Pen() for name in turtles}
        self._last: dict[str, tuple[float, float] | None] = dict.fromkeys(turtles)
        self._open: dict[str, _Stroke] = {}
        self._strokes: list[_Stroke] = []
        self._points = 0
        self._dirty = True
        self._urgent = True
        self._sent_ns: int | None = None

    # -- what happened ---------------------------------------------------------
    def pose(self, turtle: str, x: float, y: float) -> None:
        """turtlesim published this turtle's pose (it moved, drawing if its pen is down)."""
        if turtle not in self._pens:
            self._add_turtle(turtle)
        q = (x, y)
        last = self._last.get(turtle)
        self._last[turtle] = q
        if last is None or last == q:
            return
        pen = self._pens[turtle]
        if not pen.on:
            return
        stroke = self._open.get(turtle)
        if stroke is None:
            stroke = self._open[turtle] = _Stroke(pen.color, pen.width, [last])
            self._strokes.append(stroke)
            self._points += 1
        if stroke.add(q):
            self._points += 1
        self._dirty = True

    def set_pen(self, turtle: str, r: int, g: int, b: int, width: int, off: int) -> None:
        self._pens[turtle] = _Pen(not off, (r, g, b), width)
        self._open.pop(turtle, None)

    def spawned(self, turtle: str) -> None:
        self._add_turtle(turtle)

    def killed(self, turtle: str) -> None:
        self._pens.pop(turtle, None)
        self._last.pop(turtle, None)
        self._open.pop(turtle, None)
        self._dirty = self._urgent = True

    def cleared(self) -> None:
        self._strokes.clear()
        self._open.clear()
        self._points = 0
        self._dirty = self._urgent = True

    def reset(self) -> None:
        """turtlesim's /reset: every turtle gone (turtle1 comes back), the image cleared."""
        self.cleared()
        self._pens.clear()
        self._last.clear()

    def set_background(self, rgb: tuple[int, int, int]) -> None:
        if rgb != self.background:
            self.background = rgb
            self._dirty = self._urgent = True

    def _add_turtle(self, turtle: str) -> None:
        self._pens[turtle] = _Pen()
        self._last[turtle] = None
        self._open.pop(turtle, None)
        self._dirty = self._urgent = True

    # -- what to send ------------------------------------------------------------
    def due(self, t_ns: int) -> bool:
        """Whether a new snapshot should be sent at ``t_ns``."""
        if not self._dirty:
            return False
        if self._urgent or self._sent_ns is None:
            return True
        interval = 1 if self._points < _SMALL_SCENE_POINTS else 5
        return t_ns - self._sent_ns >= interval * _NS_PER_S

    def snapshot(self, t_ns: int, stamp_ns: int) -> MarkerArray:
        """The whole scene now; ``stamp_ns`` is ROS time for the headers."""
        self._sent_ns = t_ns
        self._dirty = self._urgent = False
        sec, nanosec = divmod(stamp_ns, _NS_PER_S)
        stamp = Time(sec=sec, nanosec=nanosec)
        markers = [Marker(header=Header(stamp=stamp, frame_id=FRAME), action=Marker.DELETEALL)]

        def add(ns: str, marker_id: int, kind: int, **fields: Any) -> None:
            fields.setdefault("header", Header(stamp=stamp, frame_id=FRAME))
            fields.setdefault("pose", Pose(orientation=Quaternion(w=1.0)))
            markers.append(Marker(ns=ns, id=marker_id, type=kind, action=Marker.ADD, lifetime=Duration(), **fields))

        half = ARENA_SIZE / 2
        add(
            "arena",
            0,
            Marker.CUBE,
            pose=Pose(position=Point(x=half, y=half, z=-0.005), orientation=Quaternion(w=1.0)),
            scale=Vector3(x=ARENA_SIZE, y=ARENA_SIZE, z=0.01),
            color=_color(self.background),
        )
        corners = [(0.0, 0.0), (ARENA_SIZE, 0.0), (ARENA_SIZE, ARENA_SIZE), (0.0, ARENA_SIZE), (0.0, 0.0)]
        add(
            "walls",
            0,
            Marker.LINE_STRIP,
            scale=Vector3(x=0.04),
            color=_color((255, 255, 255)),
            points=[Point(x=x, y=y) for x, y in corners],
        )
        for i, obstacle in enumerate(self._obstacles):
            if isinstance(obstacle, Circle):
                kind, (cx, cy), size = Marker.CYLINDER, (obstacle.cx, obstacle.cy), (2 * obstacle.r, 2 * obstacle.r)
            else:
                x0, y0, x1, y1 = obstacle.bounds
                kind, (cx, cy), size = Marker.CUBE, ((x0 + x1) / 2, (y0 + y1) / 2), (x1 - x0, y1 - y0)
            add(
                "obstacles",
                i,
                kind,
                pose=Pose(position=Point(x=cx, y=cy, z=0.15), orientation=Quaternion(w=1.0)),
                scale=Vector3(x=size[0], y=size[1], z=0.3),
                color=_color((128, 128, 128)),
            )
        for i, stroke in enumerate(self._strokes):
            add(
                "pen",
                i,
                Marker.LINE_STRIP,
                pose=Pose(position=Point(z=0.001), orientation=Quaternion(w=1.0)),
                scale=Vector3(x=max(stroke.width, 1) / METER_PX),
                color=_color(stroke.color),
                points=[Point(x=x, y=y) for x, y in stroke.points],
            )
        for i, turtle in enumerate(sorted(self._pens)):
            # drawn in the turtle's own frame: /tf moves it
            add(
                "turtles",
                i,
                Marker.ARROW,
                header=Header(stamp=stamp, frame_id=turtle),
                frame_locked=True,
                scale=Vector3(x=0.45, y=0.12, z=0.12),
                color=ColorRGBA(r=_TURTLE_GREEN[0], g=_TURTLE_GREEN[1], b=_TURTLE_GREEN[2], a=1.0),
            )
        return MarkerArray(markers=markers)


def _color(rgb: tuple[int, int, int]) -> ColorRGBA:
    return ColorRGBA(r=rgb[0] / 255, g=rgb[1] / 255, b=rgb[2] / 255, a=1.0)
