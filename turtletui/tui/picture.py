"""The arena as turtlesim's window shows it: a 500 x 500 RGB picture of the
background and pen image, obstacles, lesson overlays, hit marks and a turtle
sprite per turtle, for terminals with a graphics protocol. numpy only (PNG
through Pillow on request); no Textual.
"""

from __future__ import annotations

import io
import math
from collections.abc import Sequence
from functools import lru_cache
from typing import TYPE_CHECKING

import numpy as np

from turtletui.sim.canvas import to_pixel
from turtletui.sim.constants import METER_PX, PIXELS
from turtletui.tui.marks import turtle_color
from turtletui.tui.render import (
    HIT_COLORS,
    OBSTACLE_COLOR,
    WHOLE,
    Overlay,
    Window,
    normalise_overlays,
    obstacle_pixels,
)

if TYPE_CHECKING:
    from turtletui.sim import World

SPRITE = 45
"""A turtle sprite's size in pixels: one metre, as turtlesim's turtle images."""


def arena_picture(
    world: World,
    *,
    overlays: Sequence[Overlay | Sequence] = (),
    hits: Sequence[tuple[float, float, int]] = (),
    window: Window = WHOLE,
) -> np.ndarray:
    """(span, span, 3) uint8 RGB: the pen image with everything drawn over it,
    cropped to ``window`` (the whole 500 x 500 image by default)."""
    picture = np.array(world.canvas.pixels, dtype=np.uint8)  # a copy: the canvas stays as it is
    if world.obstacles:
        picture[obstacle_pixels(tuple(world.obstacles))] = OBSTACLE_COLOR
    for overlay in normalise_overlays(overlays):
        _dotted_rectangle(picture, overlay)
    for x, y, level in hits:
        _ring(picture, x, y, HIT_COLORS[min(level, len(HIT_COLORS) - 1)])
    for name, turtle in sorted(world.turtles.items()):
        _sprite(picture, turtle.x, turtle.y, turtle.theta, turtle_color(name))
    col, row, span = window
    return picture[row : row + span, col : col + span]


def png_bytes(picture: np.ndarray, size: tuple[int, int] | None = None) -> bytes:
    """The picture as PNG, scaled to ``size`` (width, height) pixels if given."""
    from PIL import Image

    image = Image.fromarray(np.ascontiguousarray(picture), "RGB")
    if size is not None and size != image.size:
        image = image.resize(size, Image.Resampling.NEAREST)
    buffer = io.BytesIO()
    image.save(buffer, "PNG", compress_level=1)
    return buffer.getvalue()


def _dotted_rectangle(picture: np.ndarray, overlay: Overlay) -> None:
    c0, r0 = to_pixel(overlay.x0, overlay.y0)
    c1, r1 = to_pixel(overlay.x1, overlay.y1)
    c0, c1 = sorted((c0, c1))
    r0, r1 = sorted((r0, r1))
    dash = (np.arange(PIXELS) // 6) % 2 == 0  # 6 px on, 6 px off
    for r in (r0, r1):
        cols = np.arange(c0, c1 + 1)
        cols = cols[dash[cols]]
        picture[max(r - 1, 0) : r + 1, cols] = overlay.color
    for c in (c0, c1):
        rows = np.arange(r0, r1 + 1)
        rows = rows[dash[rows]]
        picture[rows, max(c - 1, 0) : c + 1] = overlay.color


def _ring(picture: np.ndarray, x: float, y: float, color) -> None:
    cx, cy = to_pixel(x, y)
    r = 10
    rows = np.arange(max(cy - r - 2, 0), min(cy + r + 3, PIXELS))
    cols = np.arange(max(cx - r - 2, 0), min(cx + r + 3, PIXELS))
    d = np.hypot(rows[:, None] - cy, cols[None, :] - cx)
    ring = (d >= r - 2) & (d <= r + 1)
    cross = (np.abs(np.abs(rows[:, None] - cy) - np.abs(cols[None, :] - cx)) <= 1) & (d <= r - 3)
    block = picture[rows[0] : rows[-1] + 1, cols[0] : cols[-1] + 1]
    block[ring | cross] = color


@lru_cache(maxsize=64)
def sprite_masks(theta_step: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(shell, skin, outline) masks of a turtle sprite facing ``theta_step`` x 5
    degrees, SPRITE x SPRITE pixels centred on the turtle. Read only."""
    theta = math.radians(theta_step * 5)
    half = SPRITE // 2
    ys, xs = np.mgrid[-half : half + 1, -half : half + 1].astype(float)
    # Picture rows grow downwards: world y is -row. Turn into the turtle's frame.
    u = xs * math.cos(theta) - ys * math.sin(theta)  # forward
    v = -xs * math.sin(theta) - ys * math.cos(theta)  # to the left
    scale = METER_PX / 45.0
    shell = (u / (13 * scale)) ** 2 + (v / (10 * scale)) ** 2 <= 1.0
    head = (u - 17 * scale) ** 2 + v**2 <= (5.5 * scale) ** 2
    legs = np.zeros_like(shell)
    for lu, lv in ((8, 10), (8, -10), (-8, 10), (-8, -10)):
        legs |= (u - lu * scale) ** 2 + (v - lv * scale) ** 2 <= (3.5 * scale) ** 2
    tail = (u < -12 * scale) & (u > -18 * scale) & (np.abs(v) <= 1.5 * scale)
    skin = (head | legs | tail) & ~shell
    body = shell | skin
    grown = body.copy()
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        grown |= np.roll(body, (dy, dx), axis=(0, 1))
    outline = grown & ~body
    for mask in (shell, skin, outline):
        mask.flags.writeable = False
    return shell, skin, outline


def _sprite(picture: np.ndarray, x: float, y: float, theta: float, color) -> None:
    shell, skin, outline = sprite_masks(round(math.degrees(theta) / 5) % 72)
    cx, cy = to_pixel(x, y)
    half = SPRITE // 2
    r0, c0 = cy - half, cx - half
    rs, cs = max(r0, 0), max(c0, 0)
    re, ce = min(r0 + SPRITE, PIXELS), min(c0 + SPRITE, PIXELS)
    block = picture[rs:re, cs:ce]
    crop = (slice(rs - r0, re - r0), slice(cs - c0, ce - c0))
    dark = tuple(c // 3 for c in color)
    block[outline[crop]] = (16, 18, 28)
    block[skin[crop]] = dark
    block[shell[crop]] = color
