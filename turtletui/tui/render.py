"""The arena as terminal lines: half-block pixels, turtles, a metre scale.

Pure rendering with numpy and Rich segments, no Textual: ``ArenaRenderer``
turns a ``turtletui.sim.World`` into one list of Rich segments per terminal
line, and says which lines differ from the previous frame so the Textual
widget (``widgets/arena.py``) repaints only those.

Geometry: a terminal cell is about twice as tall as it is wide, so one cell
shows two square pixels stacked ("▀" with the upper pixel as foreground and
the lower as background). The arena is ``N`` pixels a side: ``N`` cells wide,
``N / 2`` cells tall, the largest even ``N`` that fits beside the scale.

    11┤▀▀▀▀▀▀▀▀│     line ``top``: the first arena row (y = 11.09 m)
      │        │
     0┤        │     the last arena row (y = 0 m)
      └┬───┬───┘     bottom border, a tick per metre
       0   1   2     x labels (as many as fit: every 1, 2, 5 or 10 m)

Turtlesim's pen image (500 x 500 pixels) is shrunk block by block; each block
shows its pixel that differs most from the background, so a 3 pixel trail
stays visible in a 42 pixel arena (an area average would fade it away).
"""

from __future__ import annotations

import math
import textwrap
from collections import OrderedDict
from collections.abc import Hashable, Iterable, Sequence
from functools import lru_cache
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from rich.color import Color
from rich.segment import Segment
from rich.style import Style

from turtletui.sim.canvas import to_pixel
from turtletui.sim.constants import METER_PX, PIXELS
from turtletui.sim.obstacles import Circle

if TYPE_CHECKING:
    from turtletui.sim import Obstacle, World

MIN_WIDTH = 24
"""Fewest cells across that show the arena with its scale."""
MIN_HEIGHT = 12
"""Fewest lines that show the arena with its scale."""
TOO_SMALL = f"Terminal too small: need at least {MIN_WIDTH}x{MIN_HEIGHT} for the arena"
"""Shown instead of the arena below MIN_WIDTH x MIN_HEIGHT."""

METRES = 11
"""Whole metres on the scale: 0 .. 11 (the arena is 11.09 m a side)."""

OBSTACLE_COLOR = (52, 52, 68)
"""Fill colour of obstacles (dark slate: apart from the blue floor and the trails)."""
OVERLAY_COLOR = (255, 140, 0)
"""Default colour of an overlay rectangle's dotted outline (orange)."""
BORDER_COLOR = (150, 150, 160)
TURTLE_ON_DARK = (255, 235, 0)
"""Turtle glyph colour over a dark pixel (the default blue background)."""
TURTLE_ON_LIGHT = (0, 0, 0)
"""Turtle glyph colour over a light pixel (the default lavender trail)."""

ARROWS = "→↗↑↖←↙↓↘"
"""Turtle glyphs by heading, counter-clockwise from +x in steps of 45 degrees."""
ASCII_ARROWS = ">/^\\</v\\"
"""The same eight headings in ASCII."""

_LABEL_WIDTH = 2  # "11"
_GUTTER = _LABEL_WIDTH + 2  # labels, left border, right border
_UPPER_HALF = "▀"
_TURTLE = 1 << 62  # above any packed (upper << 32 | lower) cell value
_LOW32 = 0xFFFFFFFF

BOX = {"h": "─", "v": "│", "tl": "┌", "tr": "┐", "bl": "└", "br": "┘", "xtick": "┬", "ytick": "┤"}
ASCII_BOX = {
    "h": "-",
    "v": "|",
    "tl": "+",
    "tr": "+",
    "bl": "+",
    "br": "+",
    "xtick": "+",
    "ytick": "+",
}


class Overlay(NamedTuple):
    """A rectangle in metres drawn as a dotted outline (e.g. Part 6's safe box)."""

    x0: float
    y0: float
    x1: float
    y1: float
    color: tuple[int, int, int] = OVERLAY_COLOR


def normalise_overlays(overlays: Iterable[Overlay | Sequence]) -> tuple[Overlay, ...]:
    """Overlays as a hashable tuple; each item is an Overlay or (x0, y0, x1, y1[, rgb])."""
    result = []
    for item in overlays:
        x0, y0, x1, y1, *rest = item
        color = tuple(int(c) for c in rest[0]) if rest else OVERLAY_COLOR
        result.append(Overlay(float(x0), float(y0), float(x1), float(y1), color))
    return tuple(result)


class Layout(NamedTuple):
    """Where the arena sits in a ``width`` x ``height`` cell area."""

    width: int
    height: int
    size: int
    """N: arena pixels a side (N columns, N / 2 lines)."""
    left: int
    """Column of the first arena cell."""
    top: int
    """Line of the first arena row."""

    @property
    def rows(self) -> int:
        return self.size // 2

    def block_of(self, pixel: int) -> int:
        """The arena pixel (column or row) covering pen-image pixel ``pixel``."""
        return ((pixel + 1) * self.size + PIXELS - 1) // PIXELS - 1

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        """Arena (pixel column, pixel row) under world point (x, y) metres."""
        col, row = to_pixel(x, y)
        return self.block_of(col), self.block_of(row)


def layout_for(width: int, height: int) -> Layout | None:
    """The largest square arena that fits, centred; None below the minimum size."""
    if width < MIN_WIDTH or height < MIN_HEIGHT:
        return None
    size = min(width - _GUTTER, 2 * (height - 3), PIXELS)
    size -= size % 2
    left = (width - size - _GUTTER) // 2 + _LABEL_WIDTH + 1
    top = (height - size // 2 - 3) // 2 + 1
    return Layout(width, height, size, left, top)


def downsample(pixels: np.ndarray, background: tuple[int, int, int], size: int) -> np.ndarray:
    """Shrink the (500, 500, 3) pen image to (size, size) packed 0xBBGGRR pixels.

    Each output pixel is the pixel of its block whose bits differ most from
    the background's (largest ``packed ^ background``): a trail pixel whenever
    the block holds one, so thin trails survive any shrink, and a fixed
    choice where two pen colours share a block.
    """
    rgba = np.zeros((*pixels.shape[:2], 4), dtype=np.uint8)
    rgba[:, :, :3] = pixels
    background_bits = np.uint32(_pack(background))
    key = rgba.view("<u4")[:, :, 0] ^ background_bits
    edges = np.arange(size) * PIXELS // size
    key = np.maximum.reduceat(key, edges, axis=0)
    key = np.maximum.reduceat(key, edges, axis=1)
    return key ^ background_bits


def downsample_packed(
    packed: np.ndarray,
    background: tuple[int, int, int],
    size: int,
    image: np.ndarray | None = None,
    box: tuple[int, int, int, int] | None = None,
) -> np.ndarray:
    """downsample() from the canvas's packed uint32 image. Given the previous
    ``image`` and the ``box`` of pixels changed since (canvas.changed_since),
    only the blocks over that box are computed again."""
    background_bits = np.uint32(_pack(background))
    edges = np.arange(size) * PIXELS // size
    if image is None or box is None:
        key = packed ^ background_bits
        key = np.maximum.reduceat(key, edges, axis=0)
        return np.maximum.reduceat(key, edges, axis=1) ^ background_bits
    r0, r1, c0, c1 = box
    b_r0, b_r1 = np.searchsorted(edges, [r0, r1], side="right") - 1
    b_c0, b_c1 = np.searchsorted(edges, [c0, c1], side="right") - 1
    rows_end = edges[b_r1 + 1] if b_r1 + 1 < size else PIXELS
    cols_end = edges[b_c1 + 1] if b_c1 + 1 < size else PIXELS
    key = packed[edges[b_r0] : rows_end, edges[b_c0] : cols_end] ^ background_bits
    key = np.maximum.reduceat(key, edges[b_r0 : b_r1 + 1] - edges[b_r0], axis=0)
    key = np.maximum.reduceat(key, edges[b_c0 : b_c1 + 1] - edges[b_c0], axis=1)
    image = image.copy()
    image[b_r0 : b_r1 + 1, b_c0 : b_c1 + 1] = key ^ background_bits
    return image


def _pack(rgb: tuple[int, int, int]) -> int:
    return rgb[0] | rgb[1] << 8 | rgb[2] << 16


def _rgb(packed: int) -> Color:
    return Color.from_rgb(packed & 0xFF, packed >> 8 & 0xFF, packed >> 16 & 0xFF)


@lru_cache(maxsize=4096)
def _cell_style(upper: int, lower: int) -> Style:
    if upper == lower:
        return Style(bgcolor=_rgb(lower))
    return Style(color=_rgb(upper), bgcolor=_rgb(lower))


@lru_cache(maxsize=1024)
def _turtle_style(under: int) -> Style:
    r, g, b = under & 0xFF, under >> 8 & 0xFF, under >> 16 & 0xFF
    light = 0.2126 * r + 0.7152 * g + 0.0722 * b > 140
    return Style(
        color=Color.from_rgb(*(TURTLE_ON_LIGHT if light else TURTLE_ON_DARK)),
        bgcolor=_rgb(under),
        bold=True,
    )


BORDER_STYLE = Style(color=Color.from_rgb(*BORDER_COLOR))


def heading_index(theta: float) -> int:
    """0..7: the nearest of eight headings, counter-clockwise from +x."""
    return round(theta / (math.pi / 4)) % 8


class _Scene(NamedTuple):
    """The arena picture for one canvas version, size and overlay set."""

    image: np.ndarray
    """(N, N) packed pixels with overlays painted in."""
    cells: np.ndarray
    """(N / 2, N) uint64 cell values: upper << 32 | lower (colour mode)."""
    chars: np.ndarray
    """(N / 2, N) uint8 ASCII codes: ' ', '#' trail or obstacle, '.' overlay (ASCII mode)."""


class _Bounded(OrderedDict):
    """A small LRU mapping: the oldest entries go past ``maxsize``."""

    def __init__(self, maxsize: int) -> None:
        super().__init__()
        self.maxsize = maxsize

    def get(self, key, default=None):
        if key in self:
            self.move_to_end(key)
            return self[key]
        return default

    def put(self, key, value) -> None:
        self[key] = value
        if len(self) > self.maxsize:
            self.popitem(last=False)


class ArenaRenderer:
    """Renders a World into terminal lines, remembering the last frame.

    After ``frame()``: ``lines`` holds the segments of every line,
    ``line_keys`` a hashable key per line (equal keys mean equal lines, so a
    widget can cache strips on them) and ``changed_lines`` the indices of lines
    whose key differs from the frame before.
    """

    def __init__(self) -> None:
        self.lines: list[list[Segment]] = []
        self.line_keys: list[Hashable] = []
        self.changed_lines: list[int] = []
        self.layout: Layout | None = None
        """Where the arena was drawn in the last frame; None when it did not fit."""
        self.size: tuple[int, int] = (0, 0)
        """(width, height) in cells of the last frame."""
        self._frame_key: Hashable = None
        self._image_key: Hashable = None
        self._image: np.ndarray | None = None
        self._scene_key: Hashable = None
        self._scene: _Scene | None = None
        self._segments: _Bounded = _Bounded(2048)

    def frame(
        self,
        world: World,
        width: int,
        height: int,
        *,
        ascii: bool = False,
        overlays: Iterable[Overlay | Sequence] = (),
    ) -> list[list[Segment]]:
        """Render ``world`` into ``height`` lines of ``width`` cells.

        Returns one list of segments per line (colour mode: true-colour half
        blocks; ``ascii``: unstyled ASCII text). Sets ``changed_lines``.
        """
        width = max(int(width), 0)
        height = max(int(height), 0)
        self.size = (width, height)
        overlays = normalise_overlays(overlays)
        layout = layout_for(width, height)
        self.layout = layout
        if layout is None:
            return self._publish(("small", width, height), *_too_small(width, height))
        canvas = world.canvas
        packed = canvas.packed  # flushes queued segments, which bumps the version
        # The canvas itself, not its id: a new World's canvas could reuse a freed id.
        image_key = (canvas, canvas.version, canvas.background, layout.size)
        turtles = self._place_turtles(world, layout)
        frame_key = (layout, ascii, overlays, world.obstacles, image_key, turtles)
        if frame_key == self._frame_key:
            self.changed_lines = []
            return self.lines
        if image_key != self._image_key:
            previous = self._image_key
            if previous is not None and previous[0] is canvas and previous[2:] == image_key[2:]:
                # Same canvas, size and background: redo only what changed.
                box = canvas.changed_since(previous[1])
                self._image = downsample_packed(packed, canvas.background, layout.size, self._image, box)
            else:
                self._image = downsample_packed(packed, canvas.background, layout.size)
            self._image_key = image_key
        obstacles = world.obstacles
        scene_key = (image_key, overlays, obstacles)
        if scene_key != self._scene_key:
            self._scene = _scene(self._image, canvas.background, layout, overlays, obstacles)
            self._scene_key = scene_key
        lines, keys = self._compose(layout, ascii, turtles)
        self._frame_key = frame_key
        return self._publish(frame_key, lines, keys)

    def _publish(self, frame_key, lines, keys) -> list[list[Segment]]:
        old = self.line_keys
        if len(old) != len(keys):
            self.changed_lines = list(range(len(keys)))
        else:
            self.changed_lines = [
                i for i, (a, b) in enumerate(zip(old, keys, strict=True)) if a != b
            ]
        self.lines = lines
        self.line_keys = keys
        self._frame_key = frame_key
        return lines

    @staticmethod
    def _place_turtles(world: World, layout: Layout) -> tuple[tuple[int, int, int], ...]:
        """(arena pixel row, column, heading) per turtle, in turtlesim's draw order (by name)."""
        placed = []
        for name in sorted(world.turtles):
            turtle = world.turtles[name]
            col, row = layout.cell_of(turtle.x, turtle.y)
            placed.append((row, col, heading_index(turtle.theta)))
        return tuple(placed)

    def _compose(self, layout: Layout, ascii: bool, turtles) -> tuple[list, list]:
        scene = self._scene
        box = ASCII_BOX if ascii else BOX
        style = None if ascii else BORDER_STYLE
        width, height, size, left, top = layout
        rows = layout.rows
        # Turtles by line; a later turtle in the same cell is drawn over an earlier one.
        by_line: dict[int, dict[int, tuple[int, int]]] = {}
        for row, col, heading in turtles:
            by_line.setdefault(row // 2, {})[col] = (heading, int(scene.image[row, col]))
        x_ticks, x_labels = _x_scale(layout)
        y_ticks, y_labels = _y_scale(layout)
        pad_left = " " * (left - _LABEL_WIDTH - 1)
        pad_right = " " * (width - left - size - 1)
        lines: list[list[Segment]] = []
        keys: list[Hashable] = []
        segments = self._segments
        for line in range(height):
            arena_row = line - top
            if 0 <= arena_row < rows:
                here = tuple(sorted(by_line.get(arena_row, {}).items()))
                if ascii:
                    text = _ascii_row(scene.chars[arena_row], here)
                    key: Hashable = ("ascii", layout, line, text)
                else:
                    cells = scene.cells[arena_row]
                    key = ("rgb", layout, line, cells.tobytes(), here)
                cached = segments.get(key)
                if cached is None:
                    label = y_labels.get(arena_row, "").rjust(_LABEL_WIDTH)
                    tick = box["ytick"] if arena_row in y_ticks else box["v"]
                    head = Segment(pad_left + label + tick, style)
                    tail = Segment(box["v"] + pad_right, style)
                    if ascii:
                        cached = [Segment(head.text + text + tail.text)]
                    else:
                        cached = [head, *_rgb_row(cells, here), tail]
                    segments.put(key, cached)
            else:
                key = ("frame", ascii, layout, line)
                cached = segments.get(key)
                if cached is None:
                    text = _frame_line(layout, line, box, x_ticks, x_labels)
                    cached = [Segment(text, None if not text.strip() else style)]
                    segments.put(key, cached)
            lines.append(cached)
            keys.append(key)
        return lines, keys


@lru_cache(maxsize=8)
def obstacle_mask(size: int, obstacles: tuple[Obstacle, ...]) -> np.ndarray:
    """(size, size) bool: the arena pixels showing an obstacle. Like a trail,
    a block shows an obstacle if any pen-image pixel in it lies inside one (and
    the pixel under an obstacle's centre always does, so none vanishes). Read only."""
    pen = np.zeros((PIXELS, PIXELS), dtype=bool)
    # World coordinates of the pen-image pixels' centres (row 0 at the top).
    xs = (np.arange(PIXELS) / METER_PX)[None, :]
    ys = ((PIXELS - 1 - np.arange(PIXELS)) / METER_PX)[:, None]
    for obstacle in obstacles:
        if isinstance(obstacle, Circle):
            pen |= (xs - obstacle.cx) ** 2 + (ys - obstacle.cy) ** 2 <= obstacle.r**2
            centre = (obstacle.cx, obstacle.cy)
        else:
            pen |= (obstacle.x0 <= xs) & (xs <= obstacle.x1) & (obstacle.y0 <= ys) & (ys <= obstacle.y1)
            centre = ((obstacle.x0 + obstacle.x1) / 2, (obstacle.y0 + obstacle.y1) / 2)
        col, row = to_pixel(*centre)
        pen[row, col] = True
    edges = np.arange(size) * PIXELS // size
    mask = np.maximum.reduceat(pen.view(np.uint8), edges, axis=0)
    mask = np.maximum.reduceat(mask, edges, axis=1).astype(bool)
    mask.flags.writeable = False
    return mask


def _scene(image: np.ndarray, background, layout: Layout, overlays, obstacles=()) -> _Scene:
    size = layout.size
    trail = image != _pack(background)
    solid = obstacle_mask(size, tuple(obstacles))
    if obstacles:
        image = image.copy()
        image[solid] = _pack(OBSTACLE_COLOR)
    if overlays:
        image = image.copy() if not obstacles else image
        outline = np.zeros(image.shape, dtype=bool)
        for overlay in overlays:
            c0, r0 = layout.cell_of(overlay.x0, overlay.y0)
            c1, r1 = layout.cell_of(overlay.x1, overlay.y1)
            c0, c1 = sorted((c0, c1))
            r0, r1 = sorted((r0, r1))
            mask = np.zeros(image.shape, dtype=bool)
            # Dotted: the even pixels of each edge (a grid fixed to the arena,
            # so the dots do not crawl when a rectangle moves), and the corners.
            mask[r0, c0 + c0 % 2 : c1 + 1 : 2] = True
            mask[r1, c0 + c0 % 2 : c1 + 1 : 2] = True
            mask[r0 + r0 % 2 : r1 + 1 : 2, c0] = True
            mask[r0 + r0 % 2 : r1 + 1 : 2, c1] = True
            mask[[r0, r0, r1, r1], [c0, c1, c0, c1]] = True
            image[mask] = _pack(overlay.color)
            outline |= mask
    else:
        outline = np.zeros(image.shape, dtype=bool)
    upper = image[0::2].astype(np.uint64)
    lower = image[1::2].astype(np.uint64)
    cells = upper << np.uint64(32) | lower
    chars = np.full((size // 2, size), ord(" "), dtype=np.uint8)
    # In ASCII a cell holds one character: the trail wins over the outline.
    chars[outline[0::2] | outline[1::2]] = ord(".")
    chars[trail[0::2] | trail[1::2] | solid[0::2] | solid[1::2]] = ord("#")
    return _Scene(image, cells, chars)


def _rgb_row(cells: np.ndarray, turtles: tuple) -> list[Segment]:
    """Segments for one arena row: runs of equal cells share one segment."""
    if turtles:
        cells = cells.copy()
        for col, _ in turtles:
            cells[col] = _TURTLE + col
    starts = [0, *(np.flatnonzero(cells[1:] != cells[:-1]) + 1).tolist()]
    ends = [*starts[1:], len(cells)]
    values = cells[starts].tolist()
    glyphs = dict(turtles)
    result = []
    for start, end, value in zip(starts, ends, values, strict=True):
        if value >= _TURTLE:
            heading, under = glyphs[start]
            result.append(Segment(ARROWS[heading], _turtle_style(under)))
            continue
        upper, lower = value >> 32, value & _LOW32
        text = (" " if upper == lower else _UPPER_HALF) * (end - start)
        result.append(Segment(text, _cell_style(upper, lower)))
    return result


def _ascii_row(chars: np.ndarray, turtles: tuple) -> str:
    if turtles:
        chars = chars.copy()
        for col, (heading, _) in turtles:
            chars[col] = ord(ASCII_ARROWS[heading])
    return chars.tobytes().decode("ascii")


def _metre_step(positions: dict[int, int], fits) -> int:
    """The smallest of 1, 2, 5, 10 m whose labels ``fits`` accepts."""
    for step in (1, 2, 5, 10):
        if fits([(m, positions[m]) for m in range(0, METRES + 1, step)]):
            return step
    return METRES


def _x_scale(layout: Layout) -> tuple[set[int], dict[int, str]]:
    """Bottom scale: arena columns with a tick, and label text by column."""
    cols = {m: layout.block_of(round(m * METER_PX)) for m in range(METRES + 1)}

    def fits(marks) -> bool:
        end = -2
        for m, col in marks:
            if col <= end + 1:  # keep a blank between labels
                return False
            end = col + len(str(m)) - 1
        return layout.left + end < layout.width

    step = _metre_step(cols, fits)
    return set(cols.values()), {cols[m]: str(m) for m in range(0, METRES + 1, step)}


def _y_scale(layout: Layout) -> tuple[set[int], dict[int, str]]:
    """Left scale: arena rows (lines) with a tick, and label text by row."""
    last = PIXELS - 1
    rows = {m: layout.block_of(round(last - m * METER_PX)) // 2 for m in range(METRES + 1)}

    def fits(marks) -> bool:
        used = [row for _, row in marks]
        return len(set(used)) == len(used)

    step = _metre_step(rows, fits)
    return set(rows.values()), {rows[m]: str(m) for m in range(0, METRES + 1, step)}


def _frame_line(layout: Layout, line: int, box, x_ticks, x_labels) -> str:
    """A line outside the arena rows: top border, bottom border, x labels or blank."""
    width, _, size, left, top = layout
    chars = [" "] * width
    if line == top - 1:
        chars[left - 1 : left + size + 1] = box["tl"] + box["h"] * size + box["tr"]
    elif line == top + layout.rows:
        chars[left - 1 : left + size + 1] = box["bl"] + box["h"] * size + box["br"]
        for col in x_ticks:
            chars[left + col] = box["xtick"]
    elif line == top + layout.rows + 1:
        for col, label in x_labels.items():
            chars[left + col : left + col + len(label)] = label
    return "".join(chars)


def _too_small(width: int, height: int) -> tuple[list[list[Segment]], list[Hashable]]:
    """The TOO_SMALL message, wrapped and centred, cropped to the area."""
    wrapped = textwrap.wrap(TOO_SMALL, width) if width else []
    wrapped = wrapped[:height]
    first = (height - len(wrapped)) // 2
    lines, keys = [], []
    for line in range(height):
        index = line - first
        text = wrapped[index].center(width) if 0 <= index < len(wrapped) else " " * width
        lines.append([Segment(text)])
        keys.append(("small", text))
    return lines, keys
