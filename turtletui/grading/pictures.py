"""Pictures of a run seen from above, for feedback: the arena's walls, the
world's obstacles, the turtle's path, where it hit a wall or an obstacle, and
where (and which way) it started.

Two renderings of the same drawing: SVG (text, scales in a browser) and PNG
(what Gradescope's HTML feedback and PrairieLearn's ``images`` show). The PNG
is a small numpy raster written with zlib: lines, discs and rectangles are all
it needs (no text), so an imaging library would add a dependency for nothing.
"""

from __future__ import annotations

import base64
import struct
import zlib
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from turtletui.grading.results import Picture
from turtletui.sim.constants import ARENA_SIZE

PIXELS = 360
"""Width and height of the PNG."""
BACKGROUND = (69, 86, 255)  # turtlesim's default background colour
WALL = (20, 24, 60)
OBSTACLE = (150, 150, 160)
PATH = (255, 255, 255)
HIT = (230, 40, 40)
START = (40, 200, 90)
HIT_DISTANCE = 0.02
"""Metres from an obstacle that count as touching it."""


@dataclass(frozen=True)
class Drawing:
    """What a picture shows, in metres in the arena's frame (y up)."""

    path: np.ndarray
    """(n, 2) x, y of the turtle, in order."""
    start: tuple[float, float, float]
    hits: np.ndarray
    """(k, 2) where it hit a wall or an obstacle."""
    obstacles: tuple[Any, ...] = ()
    arena: float = ARENA_SIZE


def drawing_of(xy: np.ndarray, start: Sequence[float], obstacles: Sequence[Any] = (), arena: float = ARENA_SIZE) -> Drawing:
    """A drawing from the turtle's positions: a hit is the first position of
    each stretch spent against a wall (turtlesim clamps it onto the wall) or
    touching an obstacle."""
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    touching = (xy[:, 0] <= 0.0) | (xy[:, 0] >= arena) | (xy[:, 1] <= 0.0) | (xy[:, 1] >= arena)
    if obstacles and len(xy):
        from turtletui.sim.obstacles import nearest_distance

        near = np.array([nearest_distance(obstacles, x, y) <= HIT_DISTANCE for x, y in xy])
        touching |= near
    begins = touching & ~np.concatenate(([False], touching[:-1]))
    x, y, theta = (float(v) for v in start)
    return Drawing(xy, (x, y, theta), xy[begins], tuple(obstacles), arena)


def picture_of_trace(trace: Any, scenario: str) -> Picture:
    """The picture of turtle1's run in a grading trace."""
    poses = trace.pose_array("turtle1")
    drawing = drawing_of(poses[:, 1:3], trace.start, trace.obstacles, trace.arena_size)
    return Picture(scenario, base64.b64encode(render_png(drawing)).decode("ascii"), render_svg(drawing))


# -- svg ----------------------------------------------------------------------------


def _hex(colour: tuple[int, int, int]) -> str:
    return "#{:02x}{:02x}{:02x}".format(*colour)


def _thin(xy: np.ndarray, step: float) -> np.ndarray:
    """Positions at least ``step`` metres apart (and the last one): a 60 s run
    has 3,750 poses, most of them closer than a pixel."""
    if len(xy) < 3:
        return xy
    kept = [0]
    last = xy[0]
    for i in range(1, len(xy) - 1):
        if abs(xy[i, 0] - last[0]) + abs(xy[i, 1] - last[1]) >= step:
            kept.append(i)
            last = xy[i]
    kept.append(len(xy) - 1)
    return xy[kept]


def render_svg(drawing: Drawing) -> str:
    """The drawing as a standalone SVG document, 1 unit = 1 cm."""
    size = drawing.arena

    def px(x: float, y: float) -> str:
        return f"{x * 100:.1f},{(size - y) * 100:.1f}"

    extent = f"{size * 100:.1f}"
    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {extent} {extent}" width="{PIXELS}" height="{PIXELS}">',
        f'<rect x="0" y="0" width="{extent}" height="{extent}" fill="{_hex(BACKGROUND)}" '
        f'stroke="{_hex(WALL)}" stroke-width="12"/>',
    ]
    for shape in drawing.obstacles:
        if hasattr(shape, "r"):
            cx, cy = px(shape.cx, shape.cy).split(",")
            parts.append(f'<circle cx="{cx}" cy="{cy}" r="{shape.r * 100:.1f}" fill="{_hex(OBSTACLE)}"/>')
        else:
            x0, y0, x1, y1 = shape.bounds
            parts.append(
                f'<rect x="{x0 * 100:.1f}" y="{(size - y1) * 100:.1f}" width="{(x1 - x0) * 100:.1f}" '
                f'height="{(y1 - y0) * 100:.1f}" fill="{_hex(OBSTACLE)}"/>'
            )
    points = " ".join(px(x, y) for x, y in _thin(drawing.path, 0.02))
    if points:
        parts.append(f'<polyline points="{points}" fill="none" stroke="{_hex(PATH)}" stroke-width="5"/>')
    x, y, theta = drawing.start
    tip = px(x + 0.6 * np.cos(theta), y + 0.6 * np.sin(theta))
    parts.append(f'<line x1="{px(x, y).split(",")[0]}" y1="{px(x, y).split(",")[1]}" '
                 f'x2="{tip.split(",")[0]}" y2="{tip.split(",")[1]}" stroke="{_hex(START)}" stroke-width="8"/>')
    cx, cy = px(x, y).split(",")
    parts.append(f'<circle cx="{cx}" cy="{cy}" r="14" fill="{_hex(START)}"><title>start</title></circle>')
    for hx, hy in drawing.hits:
        cx, cy = px(hx, hy).split(",")
        parts.append(f'<circle cx="{cx}" cy="{cy}" r="16" fill="none" stroke="{_hex(HIT)}" stroke-width="6">'
                     f"<title>hit at x={hx:.2f}, y={hy:.2f}</title></circle>")
    parts.append("</svg>")
    return "\n".join(parts) + "\n"


# -- png ----------------------------------------------------------------------------


class _Raster:
    def __init__(self, size: int, arena: float) -> None:
        self.size = size
        self.scale = (size - 1) / arena
        self.arena = arena
        self.rgb = np.empty((size, size, 3), dtype=np.uint8)
        self.rgb[:] = BACKGROUND
        rows, cols = np.mgrid[0:size, 0:size]
        self._cols, self._rows = cols, rows

    def to_px(self, x: float, y: float) -> tuple[float, float]:
        return x * self.scale, (self.arena - y) * self.scale

    def disc(self, x: float, y: float, radius: float, colour: tuple[int, int, int], ring: float = 0.0) -> None:
        cx, cy = self.to_px(x, y)
        d2 = (self._cols - cx) ** 2 + (self._rows - cy) ** 2
        mask = d2 <= radius**2
        if ring:
            mask &= d2 >= (radius - ring) ** 2
        self.rgb[mask] = colour

    def box(self, x0: float, y0: float, x1: float, y1: float, colour: tuple[int, int, int]) -> None:
        c0, r1 = self.to_px(x0, y0)
        c1, r0 = self.to_px(x1, y1)
        mask = (self._cols >= c0) & (self._cols <= c1) & (self._rows >= r0) & (self._rows <= r1)
        self.rgb[mask] = colour

    def polyline(self, xy: np.ndarray, colour: tuple[int, int, int], width: int = 2) -> None:
        if len(xy) == 0:
            return
        cols = xy[:, 0] * self.scale
        rows = (self.arena - xy[:, 1]) * self.scale
        # points every half pixel along each segment
        length = np.hypot(np.diff(cols), np.diff(rows))
        steps = np.maximum(1, np.ceil(length * 2)).astype(int)
        pc = [cols[:1]]
        pr = [rows[:1]]
        for i, n in enumerate(steps):
            t = np.arange(1, n + 1) / n
            pc.append(cols[i] + (cols[i + 1] - cols[i]) * t)
            pr.append(rows[i] + (rows[i + 1] - rows[i]) * t)
        c = np.rint(np.concatenate(pc)).astype(int)
        r = np.rint(np.concatenate(pr)).astype(int)
        for dc in range(width):
            for dr in range(width):
                cc = np.clip(c + dc - width // 2, 0, self.size - 1)
                rr = np.clip(r + dr - width // 2, 0, self.size - 1)
                self.rgb[rr, cc] = colour


def render_png(drawing: Drawing, size: int = PIXELS) -> bytes:
    """The drawing as a PNG of ``size`` x ``size`` pixels."""
    raster = _Raster(size, drawing.arena)
    for shape in drawing.obstacles:
        if hasattr(shape, "r"):
            raster.disc(shape.cx, shape.cy, shape.r * raster.scale, OBSTACLE)
        else:
            raster.box(*shape.bounds, OBSTACLE)
    raster.polyline(_thin(drawing.path, 0.5 / raster.scale), PATH)
    x, y, theta = drawing.start
    raster.polyline(np.array([[x, y], [x + 0.6 * np.cos(theta), y + 0.6 * np.sin(theta)]]), START, width=3)
    raster.disc(x, y, 5, START)
    for hx, hy in drawing.hits:
        raster.disc(hx, hy, 7, HIT, ring=3)
    raster.rgb[:3, :] = WALL
    raster.rgb[-3:, :] = WALL
    raster.rgb[:, :3] = WALL
    raster.rgb[:, -3:] = WALL
    return encode_png(raster.rgb)


def encode_png(rgb: np.ndarray) -> bytes:
    """An (h, w, 3) uint8 array as PNG bytes (8-bit RGB, no interlace)."""
    height, width, _ = rgb.shape
    rows = np.concatenate([np.zeros((height, 1), dtype=np.uint8), rgb.reshape(height, width * 3)], axis=1)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(rows.tobytes(), 9))
        + chunk(b"IEND", b"")
    )
