"""Obstacles in the arena, and the simulated LiDAR that sees them.

Geometry in metres, world frame (x right, y up), pure and deterministic:
circles and axis-aligned boxes. A turtle is a point, as in turtlesim: it
collides when it is strictly inside an obstacle; a point on the surface is
outside. The turtle is *blocked* where its step enters an obstacle
(:func:`first_entry`); the scan casts every beam at once with numpy
(:func:`cast_rays`), the arena walls counting as obstacles.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from turtletui.sim.constants import ARENA_SIZE

_INF = math.inf
_sqrt = math.sqrt


@dataclass(frozen=True, slots=True)
class Circle:
    """A round obstacle: centre (cx, cy) and radius r, metres."""

    cx: float
    cy: float
    r: float
    bounds: tuple[float, float, float, float] = field(init=False, repr=False, compare=False)
    """(x0, y0, x1, y1): the bounding box."""

    def __post_init__(self) -> None:
        _require_finite(self, cx=self.cx, cy=self.cy, r=self.r)
        if not self.r > 0.0:
            raise ValueError(f"a circle's radius must be positive, got {self.r}")
        r = self.r
        object.__setattr__(self, "bounds", (self.cx - r, self.cy - r, self.cx + r, self.cy + r))


@dataclass(frozen=True, slots=True)
class Box:
    """An axis-aligned rectangular obstacle from (x0, y0) to (x1, y1), metres."""

    x0: float
    y0: float
    x1: float
    y1: float
    bounds: tuple[float, float, float, float] = field(init=False, repr=False, compare=False)
    """(x0, y0, x1, y1): the bounding box, the box itself."""

    def __post_init__(self) -> None:
        _require_finite(self, x0=self.x0, y0=self.y0, x1=self.x1, y1=self.y1)
        if not (self.x0 < self.x1 and self.y0 < self.y1):
            raise ValueError(
                f"a box needs x0 < x1 and y0 < y1, got ({self.x0}, {self.y0}) to ({self.x1}, {self.y1})"
            )
        object.__setattr__(self, "bounds", (self.x0, self.y0, self.x1, self.y1))


Obstacle = Circle | Box


def _require_finite(obstacle: object, **values: float) -> None:
    for name, value in values.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise ValueError(f"{type(obstacle).__name__}.{name} must be a finite number, got {value!r}")


# -- points ---------------------------------------------------------------------


def inside(obstacle: Obstacle, x: float, y: float) -> bool:
    """Whether (x, y) is strictly inside ``obstacle`` (the surface is outside)."""
    if type(obstacle) is Circle:
        dx = x - obstacle.cx
        dy = y - obstacle.cy
        return dx * dx + dy * dy < obstacle.r * obstacle.r
    return obstacle.x0 < x < obstacle.x1 and obstacle.y0 < y < obstacle.y1


def collides(obstacles: Sequence[Obstacle], x: float, y: float) -> bool:
    """Whether (x, y) is strictly inside any of ``obstacles``."""
    return any(inside(obstacle, x, y) for obstacle in obstacles)


def surface_distance(obstacle: Obstacle, x: float, y: float) -> float:
    """Signed distance from (x, y) to the surface: positive outside, negative inside."""
    if type(obstacle) is Circle:
        return math.hypot(x - obstacle.cx, y - obstacle.cy) - obstacle.r
    dx = max(obstacle.x0 - x, x - obstacle.x1)
    dy = max(obstacle.y0 - y, y - obstacle.y1)
    if dx <= 0.0 and dy <= 0.0:
        return max(dx, dy)
    return math.hypot(max(dx, 0.0), max(dy, 0.0))


def nearest_distance(obstacles: Sequence[Obstacle], x: float, y: float) -> float:
    """Distance from (x, y) to the nearest obstacle surface (negative inside one;
    inf without obstacles). The arena walls are not included."""
    return min((surface_distance(o, x, y) for o in obstacles), default=_INF)


def push_out(obstacle: Obstacle, x: float, y: float) -> tuple[float, float]:
    """The point of ``obstacle``'s surface nearest to (x, y), if (x, y) is inside
    it; (x, y) unchanged otherwise. The result is never strictly inside."""
    if not inside(obstacle, x, y):
        return x, y
    if type(obstacle) is Circle:
        dx = x - obstacle.cx
        dy = y - obstacle.cy
        length = math.hypot(dx, dy)
        if length == 0.0:
            dx, dy, length = 1.0, 0.0, 1.0  # the centre: out along +x, a fixed choice
        # A hair beyond r so rounding cannot leave the point inside.
        scale = obstacle.r * (1.0 + 1e-12) / length
        return obstacle.cx + dx * scale, obstacle.cy + dy * scale
    exits = (
        (x - obstacle.x0, obstacle.x0, y),
        (obstacle.x1 - x, obstacle.x1, y),
        (y - obstacle.y0, x, obstacle.y0),
        (obstacle.y1 - y, x, obstacle.y1),
    )
    _, px, py = min(exits, key=lambda exit_: exit_[0])
    return px, py


# -- a step -------------------------------------------------------------------------


def first_entry(
    obstacles: Sequence[Obstacle], x: float, y: float, dx: float, dy: float
) -> tuple[float, float] | None:
    """Where the step from (x, y) by (dx, dy) first enters an obstacle, or None.

    The point returned is on the surface, never strictly inside. A step that
    starts inside an obstacle (a turtle spawned or teleported there) is not
    blocked by it, so the turtle can drive out. Grazing a surface (moving
    along a box's side, touching a circle) is not entering.
    """
    length = _sqrt(dx * dx + dy * dy)
    if length == 0.0:
        return None
    ux = dx / length
    uy = dy / length
    best = length
    hit: Obstacle | None = None
    face = -1
    # The step's bounding box: most obstacles are nowhere near a 16 ms step.
    lo_x, hi_x = (x, x + dx) if dx >= 0.0 else (x + dx, x)
    lo_y, hi_y = (y, y + dy) if dy >= 0.0 else (y + dy, y)
    for obstacle in obstacles:
        b0, b1, b2, b3 = obstacle.bounds
        if b0 > hi_x or b2 < lo_x or b1 > hi_y or b3 < lo_y:
            continue
        if type(obstacle) is Circle:
            t, axis = _circle_entry(obstacle, x, y, ux, uy), -1
        else:
            t, axis = _box_entry(obstacle, x, y, ux, uy)
        if t < best:
            best, hit, face = t, obstacle, axis
    if hit is None:
        return None
    px = x + ux * best
    py = y + uy * best
    if type(hit) is Circle:
        return push_out(hit, px, py)
    # Snap onto the face entered: exact coordinates keep the point on the
    # surface despite rounding, so the next step starts outside.
    if face == 0:
        px = hit.x0 if ux > 0.0 else hit.x1
    elif face == 1:
        py = hit.y0 if uy > 0.0 else hit.y1
    return px, py


def _circle_entry(c: Circle, x: float, y: float, ux: float, uy: float) -> float:
    fx = x - c.cx
    fy = y - c.cy
    outside = fx * fx + fy * fy - c.r * c.r
    b = fx * ux + fy * uy
    if outside < 0.0 or b >= 0.0:
        return _INF  # starts inside, or heads away
    disc = b * b - outside
    if disc <= 0.0:
        return _INF
    return max(-b - _sqrt(disc), 0.0)


def _box_entry(box: Box, x: float, y: float, ux: float, uy: float) -> tuple[float, int]:
    """(distance to the entry point, 0 if entering through a side x = const,
    1 through y = const); (inf, -1) if the ray does not enter."""
    if box.x0 < x < box.x1 and box.y0 < y < box.y1:
        return _INF, -1  # starts inside
    enter, leave, face = -_INF, _INF, -1
    for axis, p, u, lo, hi in ((0, x, ux, box.x0, box.x1), (1, y, uy, box.y0, box.y1)):
        if u == 0.0:
            if not lo < p < hi:
                return _INF, -1
            continue
        t0 = (lo - p) / u
        t1 = (hi - p) / u
        if t0 > t1:
            t0, t1 = t1, t0
        if t0 > enter:
            enter, face = t0, axis
        leave = min(leave, t1)
    if enter >= leave or leave <= 0.0:
        return _INF, -1
    return max(enter, 0.0), face


# -- rays -----------------------------------------------------------------------------


def cast_rays(
    obstacles: Sequence[Obstacle],
    x: float,
    y: float,
    angles: np.ndarray,
    range_max: float,
    arena: float = ARENA_SIZE,
) -> np.ndarray:
    """Distance along each ray from (x, y) at world ``angles`` (radians) to the
    first obstacle or arena wall, capped at ``range_max``; float64, one per ray.

    Rays from inside an obstacle all measure 0; so does a ray from a wall outwards.
    """
    return RayCaster(obstacles, arena).cast(x, y, angles, range_max)


class RayCaster:
    """:func:`cast_rays` for a fixed set of obstacles, their arrays made once."""

    def __init__(self, obstacles: Sequence[Obstacle], arena: float = ARENA_SIZE) -> None:
        self.obstacles = tuple(obstacles)
        self.arena = arena
        circles = [o for o in self.obstacles if type(o) is Circle]
        boxes = [o for o in self.obstacles if type(o) is Box]
        c = np.array([(o.cx, o.cy, o.r) for o in circles], dtype=float).reshape(-1, 3)
        self._cx, self._cy, self._r2 = c[:, 0], c[:, 1], c[:, 2] ** 2
        k = np.array([(o.x0, o.y0, o.x1, o.y1) for o in boxes], dtype=float).reshape(-1, 4)
        self._x0, self._y0, self._x1, self._y1 = k.T.copy()

    def cast(self, x: float, y: float, angles: np.ndarray, range_max: float) -> np.ndarray:
        """Distances along the rays from (x, y) at world ``angles``, as cast_rays."""
        if collides(self.obstacles, x, y):
            return np.zeros(len(angles))
        ux = np.cos(angles)
        uy = np.sin(angles)
        arena = self.arena
        with np.errstate(divide="ignore", invalid="ignore"):
            # Walls: where the ray leaves [0, arena]^2; fmin drops the NaN of
            # a ray along a wall it stands on.
            tx = np.where(ux > 0.0, arena - x, x) / np.abs(ux)
            ty = np.where(uy > 0.0, arena - y, y) / np.abs(uy)
            best = np.maximum(np.fmin(np.fmin(tx, ty), range_max), 0.0)
            if self._cx.size:
                fx = x - self._cx
                fy = y - self._cy
                b = np.multiply.outer(ux, fx) + np.multiply.outer(uy, fy)
                # From outside (checked above), t >= 0 exactly when the ray
                # heads in and meets the circle; NaN (a miss) fails the test too.
                t = -b - np.sqrt(b * b - (fx * fx + fy * fy - self._r2))
                best = np.minimum(best, np.where(t >= 0.0, t, np.inf).min(axis=1))
            if self._x0.size:
                inv_x = (1.0 / ux)[:, None]
                inv_y = (1.0 / uy)[:, None]
                t0 = (self._x0 - x) * inv_x
                t1 = (self._x1 - x) * inv_x
                t2 = (self._y0 - y) * inv_y
                t3 = (self._y1 - y) * inv_y
                enter = np.maximum(np.minimum(t0, t1), np.minimum(t2, t3))
                leave = np.minimum(np.maximum(t0, t1), np.maximum(t2, t3))
                # A ray along a side (0 * inf = NaN) fails the test: grazing is no hit.
                hit = (leave > enter) & (leave > 0.0)
                best = np.minimum(best, np.where(hit, enter, np.inf).min(axis=1))
        return best


# -- the LiDAR ------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Lidar:
    """A planar LiDAR on every turtle, published as sensor_msgs/LaserScan.

    Angles are radians relative to the turtle's heading, counter-clockwise
    (REP 103). By default the beams cover a full turn starting straight ahead
    (``ranges[0]`` is in front, a quarter of the way round is to the left), as
    the TurtleBot3's LDS-01 does. Readings follow REP 117: ``inf`` when nothing
    is within ``range_max``, ``-inf`` for a surface closer than ``range_min``,
    ``nan`` for a beam that measured nothing usable (``dropout``).
    """

    samples: int = 360
    """Beams per scan."""
    angle_min: float = 0.0
    angle_max: float | None = None
    """Angle of the last beam; None: a full turn without repeating the first beam."""
    range_min: float = 0.0
    range_max: float = 3.5
    """Metres."""
    noise_std: float = 0.0
    """Standard deviation of the Gaussian noise added to each reading, metres."""
    rate: float | None = None
    """Scans per second (rounded to whole 16 ms ticks); None: every tick, with the poses."""
    dropout: float = 0.0
    """Share of readings that come back empty (``nan``), each beam drawn on its own."""

    def __post_init__(self) -> None:
        if isinstance(self.samples, bool) or not isinstance(self.samples, int) or self.samples < 1:
            raise ValueError(f"samples must be a positive integer, got {self.samples!r}")
        fields = {"angle_min": self.angle_min, "range_min": self.range_min, "range_max": self.range_max}
        fields["noise_std"] = self.noise_std
        fields["dropout"] = self.dropout
        if self.angle_max is not None:
            fields["angle_max"] = self.angle_max
        if self.rate is not None:
            fields["rate"] = self.rate
        _require_finite(self, **fields)
        if not 0.0 <= self.range_min < self.range_max:
            raise ValueError(
                f"need 0 <= range_min < range_max, got range_min={self.range_min}, range_max={self.range_max}"
            )
        if self.noise_std < 0.0:
            raise ValueError(f"noise_std must not be negative, got {self.noise_std}")
        if not 0.0 <= self.dropout < 1.0:
            raise ValueError(f"dropout must be a share of readings from 0 up to (not including) 1, got {self.dropout}")
        if self.rate is not None and not self.rate > 0.0:
            raise ValueError(f"rate must be a positive number of Hz, got {self.rate}")
        if self.angle_max is not None and self.angle_max < self.angle_min:
            raise ValueError(f"angle_max ({self.angle_max}) is below angle_min ({self.angle_min})")

    @property
    def angle_increment(self) -> float:
        """Radians between neighbouring beams."""
        if self.angle_max is None:
            return 2.0 * math.pi / self.samples
        return (self.angle_max - self.angle_min) / (self.samples - 1) if self.samples > 1 else 0.0

    @property
    def last_angle(self) -> float:
        """The angle of the last beam (LaserScan's angle_max)."""
        if self.angle_max is None:
            return self.angle_min + self.angle_increment * (self.samples - 1)
        return self.angle_max

    def angles(self) -> np.ndarray:
        """Beam angles relative to the heading, radians."""
        return self.angle_min + self.angle_increment * np.arange(self.samples)

    def period_ticks(self, dt: float) -> int:
        """Ticks between scans: ``rate`` rounded to whole ticks of ``dt`` seconds."""
        if self.rate is None:
            return 1
        return max(1, round(1.0 / (self.rate * dt)))

    def scan(
        self,
        obstacles: Sequence[Obstacle] | RayCaster,
        x: float,
        y: float,
        theta: float,
        noise: np.ndarray | None = None,
        angles: np.ndarray | None = None,
        failed: np.ndarray | None = None,
    ) -> np.ndarray:
        """float32 ranges from (x, y) facing ``theta``: true distances plus
        ``noise`` (metres, one per beam), kept within [range_min, range_max];
        inf past range_max, -inf below range_min and nan where ``failed``
        (booleans, one per beam) holds (REP 117). ``obstacles`` may be a
        RayCaster made once for them (faster); ``angles`` self.angles()."""
        if angles is None:
            angles = self.angles()
        caster = obstacles if isinstance(obstacles, RayCaster) else RayCaster(obstacles)
        true = caster.cast(x, y, angles + theta, self.range_max)
        measured = true if noise is None else np.clip(true + noise, self.range_min, self.range_max)
        ranges = np.where(true >= self.range_max, np.inf, measured)
        ranges = np.where(true < self.range_min, -np.inf, ranges)
        if failed is not None:
            ranges = np.where(failed, np.nan, ranges)
        return ranges.astype(np.float32)
