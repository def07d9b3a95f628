"""The arena as terminal lines: pen image, turtles, hit marks, a metre scale.

Pure rendering with numpy and Rich segments, no Textual: ``ArenaRenderer``
turns a ``turtletui.sim.World`` into one list of Rich segments per terminal
line, and says which lines differ from the previous frame so the Textual
widget (``widgets/arena.py``) repaints only those.

Geometry: a terminal cell is about twice as tall as it is wide. In ``half``
mode a cell shows two square pixels stacked, in ``braille`` mode 2 x 4
(turtletui.tui.cells). The arena is ``N`` cells wide and ``N / 2`` lines
tall, the largest even ``N`` that fits beside the scale:

    11┤▀▀▀▀▀▀▀▀│     line ``top``: the first arena row (y = 11.09 m)
      │        │
     0┤        │     the last arena row (y = 0 m)
      └┬───┬───┘     bottom border, a tick per metre
       0   1   2     x labels (as many as fit: every 1, 2, 5 or 10 m)

Zoomed in (``Camera``), the arena shows a square window of the 500 x 500
pen image that follows a turtle, and the scale shows that window's metres.

Turtlesim's pen image is shrunk block by block; each block shows its pixel
that differs most from the background, so a 3 pixel trail stays visible in
a 42 pixel arena (an area average would fade it away).

Each turtle is two cells in its own colour (turtletui.tui.marks): a body
(the cell filled with the colour) and a head, "▶ ◥ ▲ ◤ ◀ ◣ ▼ ◢" on a dark
cell, on the side it faces, with its name on the line above or below; a wall or obstacle hit leaves a red "×"
that fades in three steps over three simulated seconds.
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
from turtletui.sim.constants import ARENA_SIZE, METER_PX, PIXELS
from turtletui.sim.obstacles import Circle
from turtletui.tui import cells as cell_modes
from turtletui.tui.marks import OBSTACLE_CHAR, OVERLAY_CHAR, pen_char, turtle_color

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
TILE_COLOR = (16, 18, 28)
"""Background of a turtle's cells and its name: dark, so the turtle's colour
stands out on the floor, on any trail and on white."""
HIT_COLORS = ((255, 40, 40), (215, 50, 50), (170, 60, 60))
"""A hit mark's colour, freshest first, as it fades."""

HEADS = "▶◥▲◤◀◣▼◢"
"""A turtle's head by heading, counter-clockwise from +x in steps of 45 degrees."""
ASCII_HEADS = ">/^\\</v\\"
"""The same eight headings in ASCII."""
BODY = " "
"""A turtle's body: a cell filled with its colour."""
ASCII_BODY = "@"
HIT = "×"
ASCII_HIT = "!"

# Where the head sits, (line, column) from the body, for each of the 8 headings.
_HEAD_OFFSETS = ((0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0), (1, 1))

_LABEL_WIDTH = 2  # "11"
_GUTTER = _LABEL_WIDTH + 2  # labels, left border, right border

ZOOMS = (1.0, 1.5, 2.0, 3.0, 4.0, 6.0)
"""Zoom factors the camera offers (1: the whole arena)."""

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


class Window(NamedTuple):
    """The square of the 500 x 500 pen image the arena shows (pixels)."""

    col: int
    row: int
    span: int


WHOLE = Window(0, 0, PIXELS)


class Layout(NamedTuple):
    """Where the arena sits in a ``width`` x ``height`` cell area."""

    width: int
    height: int
    size: int
    """N: arena cells across (N / 2 lines down)."""
    left: int
    """Column of the first arena cell."""
    top: int
    """Line of the first arena row."""
    across: int = 1
    """Pixels a cell shows across (1 in half-block mode, 2 in braille)."""
    window: Window = WHOLE

    @property
    def rows(self) -> int:
        """Lines of the arena."""
        return self.size // 2

    @property
    def pixels(self) -> int:
        """Arena pixels a side (square)."""
        return self.size * self.across

    @property
    def down(self) -> int:
        """Pixels a cell shows down (twice ``across``: square pixels)."""
        return 2 * self.across

    def block_of(self, pixel: int, axis: int = 0) -> int:
        """The arena pixel covering pen-image pixel ``pixel`` (a column for
        axis 0, a row for axis 1); outside 0 .. pixels - 1 when the window
        does not show it."""
        start = self.window.col if axis == 0 else self.window.row
        span = self.window.span
        return ((pixel - start + 1) * self.pixels + span - 1) // span - 1

    def pixel_of(self, x: float, y: float) -> tuple[int, int]:
        """Arena (pixel column, pixel row) under world point (x, y) metres."""
        col, row = to_pixel(x, y)
        return self.block_of(col, 0), self.block_of(row, 1)

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        """Arena (cell column, line) under world point (x, y) metres."""
        col, row = self.pixel_of(x, y)
        return col // self.across, row // self.down

    def edges(self) -> np.ndarray:
        """Pen-image offsets (within the window) where each arena pixel's block starts."""
        return np.arange(self.pixels) * self.window.span // self.pixels


def layout_for(width: int, height: int, mode: str = "half", window: Window = WHOLE) -> Layout | None:
    """The largest square arena that fits, centred; None below the minimum size."""
    if width < MIN_WIDTH or height < MIN_HEIGHT:
        return None
    across = cell_modes.CELL_PIXELS[mode][0]
    size = min(width - _GUTTER, 2 * (height - 3), PIXELS // across)
    size -= size % 2
    left = (width - size - _GUTTER) // 2 + _LABEL_WIDTH + 1
    top = (height - size // 2 - 3) // 2 + 1
    return Layout(width, height, size, left, top, across, window)


class Camera:
    """Zoom and follow: which square of the arena the view shows.

    At zoom 1 the whole arena. Zoomed in, the window follows a turtle (``follow``,
    or the first one alive): it moves only when the turtle leaves its middle
    half, by whole arena pixels, so the picture does not shimmer and most
    frames repaint only the lines the turtle is on.
    """

    def __init__(self) -> None:
        self.level = 0
        """Index into ZOOMS."""
        self.follow: str | None = None
        """Name of the turtle to follow; None: turtle1, else the first turtle."""
        self._origin: tuple[int, int] | None = None

    @property
    def zoom(self) -> float:
        return ZOOMS[self.level]

    def zoom_in(self) -> float:
        self.level = min(self.level + 1, len(ZOOMS) - 1)
        self._origin = None
        return self.zoom

    def zoom_out(self) -> float:
        self.level = max(self.level - 1, 0)
        self._origin = None
        return self.zoom

    def followed(self, world: World) -> str | None:
        """The turtle the view follows, if any is alive."""
        if self.follow in world.turtles:
            return self.follow
        if "turtle1" in world.turtles:
            return "turtle1"
        return next(iter(world.turtles), None)

    def follow_next(self, world: World) -> str | None:
        """Follow the next turtle (in spawn order); returns its name."""
        names = list(world.turtles)
        if not names:
            return None
        current = self.followed(world)
        index = names.index(current) + 1 if current in names else 0
        self.follow = names[index % len(names)]
        self._origin = None
        return self.follow

    def window(self, world: World, pixels: int) -> Window:
        """The window for an arena of ``pixels`` a side, following the turtle."""
        if self.level == 0:
            self._origin = None
            return WHOLE
        span = max(round(PIXELS / self.zoom), pixels // 2, 8)
        span = min(span, PIXELS)
        step = max(span / pixels, 1.0)  # pen-image pixels per arena pixel
        name = self.followed(world)
        if name is None:
            target = (PIXELS // 2, PIXELS // 2)
        else:
            turtle = world.turtles[name]
            target = to_pixel(turtle.x, turtle.y)
        if self._origin is None:
            origin = [t - span // 2 for t in target]
        else:
            origin = list(self._origin)
            for axis in (0, 1):
                low = origin[axis] + span // 4
                high = origin[axis] + span - span // 4
                if target[axis] < low:
                    origin[axis] -= math.ceil((low - target[axis]) / step) * step
                elif target[axis] > high:
                    origin[axis] += math.ceil((target[axis] - high) / step) * step
        origin = [int(min(max(round(o), 0), PIXELS - span)) for o in origin]
        self._origin = (origin[0], origin[1])
        return Window(origin[0], origin[1], span)


def downsample(pixels: np.ndarray, background: tuple[int, int, int], size: int) -> np.ndarray:
    """Shrink the (500, 500, 3) pen image to (size, size) packed 0xBBGGRR pixels.

    Each output pixel is the pixel of its block whose bits differ most from
    the background's (largest ``packed ^ background``): a trail pixel whenever
    the block holds one, so thin trails survive any shrink, and a fixed
    choice where two pen colours share a block.
    """
    rgba = np.zeros((*pixels.shape[:2], 4), dtype=np.uint8)
    rgba[:, :, :3] = pixels
    return downsample_packed(rgba.view("<u4")[:, :, 0], background, size)


def downsample_packed(
    packed: np.ndarray,
    background: tuple[int, int, int],
    size: int,
    image: np.ndarray | None = None,
    box: tuple[int, int, int, int] | None = None,
    window: Window = WHOLE,
) -> np.ndarray:
    """downsample() from the canvas's packed uint32 image, of the ``window``
    only. Given the previous ``image`` and the ``box`` of pixels changed since
    (canvas.changed_since), only the blocks over that box are computed again."""
    background_bits = np.uint32(_pack(background))
    col, row, span = window
    edges = np.arange(size) * span // size
    if image is None or box is None:
        key = packed[row : row + span, col : col + span] ^ background_bits
        key = np.maximum.reduceat(key, edges, axis=0)
        return np.maximum.reduceat(key, edges, axis=1) ^ background_bits
    r0, r1, c0, c1 = box
    r0, r1 = max(r0 - row, 0), min(r1 - row, span - 1)
    c0, c1 = max(c0 - col, 0), min(c1 - col, span - 1)
    if r0 > r1 or c0 > c1:
        return image  # the change is outside the window
    b_r0, b_r1 = np.searchsorted(edges, [r0, r1], side="right") - 1
    b_c0, b_c1 = np.searchsorted(edges, [c0, c1], side="right") - 1
    rows_end = edges[b_r1 + 1] if b_r1 + 1 < size else span
    cols_end = edges[b_c1 + 1] if b_c1 + 1 < size else span
    key = packed[row + edges[b_r0] : row + rows_end, col + edges[b_c0] : col + cols_end] ^ background_bits
    key = np.maximum.reduceat(key, edges[b_r0 : b_r1 + 1] - edges[b_r0], axis=0)
    key = np.maximum.reduceat(key, edges[b_c0 : b_c1 + 1] - edges[b_c0], axis=1)
    image = image.copy()
    image[b_r0 : b_r1 + 1, b_c0 : b_c1 + 1] = key ^ background_bits
    return image


def _pack(rgb: tuple[int, int, int]) -> int:
    return rgb[0] | rgb[1] << 8 | rgb[2] << 16


def _unpack(packed: int) -> tuple[int, int, int]:
    return packed & 0xFF, packed >> 8 & 0xFF, packed >> 16 & 0xFF


@lru_cache(maxsize=4096)
def _style(fg: int | None, bg: int, bold: bool = False) -> Style:
    return Style(
        color=None if fg is None else Color.from_rgb(*_unpack(fg)),
        bgcolor=Color.from_rgb(*_unpack(bg)),
        bold=bold or None,
    )


BORDER_STYLE = Style(color=Color.from_rgb(*BORDER_COLOR))


def heading_index(theta: float) -> int:
    """0..7: the nearest of eight headings, counter-clockwise from +x."""
    return round(theta / (math.pi / 4)) % 8


class Mark(NamedTuple):
    """A character drawn over one arena cell: part of a turtle, a name, a hit."""

    char: str
    fg: int
    """Packed colour of the character."""
    bg: int | None
    """Packed background; None keeps the cell's own."""
    bold: bool = False


class _Scene(NamedTuple):
    """The arena picture for one canvas version, layout and overlay set."""

    image: np.ndarray
    """(P, P) packed pixels with obstacles and overlays painted in."""
    cells: np.ndarray
    """(N / 2, N) uint64 cell values of the pixel mode (turtletui.tui.cells)."""
    chars: np.ndarray
    """(N / 2, N) uint8 ASCII codes: pen characters, obstacles, overlay dots."""


ROWS_KEPT = 256
"""Rendered rows kept for reuse (by the renderer, and as strips by the arena
widget): a few frames' worth. Unchanged rows come back frame after frame; a
row that changed almost never does, and every kept row is dozens of objects
each full garbage collection walks (2,048 made its pauses 4x longer)."""


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
        self.marks: dict[tuple[int, int], Mark] = {}
        """The last frame's turtles, names and hit marks by (line, column) of the arena."""
        self._frame_key: Hashable = None
        self._image_key: Hashable = None
        self._image: np.ndarray | None = None
        self._scene_key: Hashable = None
        self._scene: _Scene | None = None
        self._segments: _Bounded = _Bounded(ROWS_KEPT)

    def frame(
        self,
        world: World,
        width: int,
        height: int,
        *,
        ascii: bool = False,
        overlays: Iterable[Overlay | Sequence] = (),
        mode: str = "half",
        camera: Camera | None = None,
        hits: Sequence[tuple[float, float, int]] = (),
    ) -> list[list[Segment]]:
        """Render ``world`` into ``height`` lines of ``width`` cells.

        Returns one list of segments per line (colour mode: true-colour cells
        of pixel ``mode``, "half" or "braille"; ``ascii``: unstyled ASCII
        text). ``camera`` zooms; ``hits`` are (x, y, fade level) hit marks
        (turtletui.tui.marks.HitMarks.visible). Sets ``changed_lines``.
        """
        width = max(int(width), 0)
        height = max(int(height), 0)
        self.size = (width, height)
        overlays = normalise_overlays(overlays)
        mode = "half" if ascii else mode
        layout = layout_for(width, height, mode)
        if layout is not None and camera is not None:
            layout = layout._replace(window=camera.window(world, layout.pixels))
        self.layout = layout
        if layout is None:
            self.marks = {}
            return self._publish(("small", width, height), *_too_small(width, height))
        canvas = world.canvas
        packed = canvas.packed  # flushes queued segments, which bumps the version
        # The canvas itself, not its id: a new World's canvas could reuse a freed id.
        image_key = (canvas, canvas.version, canvas.background, layout.pixels, layout.window)
        marks = _marks(world, layout, hits, ascii)
        frame_key = (layout, ascii, mode, overlays, world.obstacles, image_key, tuple(marks.items()))
        if frame_key == self._frame_key:
            self.changed_lines = []
            return self.lines
        if image_key != self._image_key:
            previous = self._image_key
            if previous is not None and previous[0] is canvas and previous[2:] == image_key[2:]:
                # Same canvas, size, window and background: redo only what changed.
                box = canvas.changed_since(previous[1])
                self._image = downsample_packed(
                    packed, canvas.background, layout.pixels, self._image, box, layout.window
                )
            else:
                self._image = downsample_packed(packed, canvas.background, layout.pixels, window=layout.window)
            self._image_key = image_key
        scene_key = (image_key, overlays, world.obstacles, mode)
        if scene_key != self._scene_key:
            self._scene = _scene(self._image, canvas.background, layout, overlays, world.obstacles, mode)
            self._scene_key = scene_key
        self.marks = marks
        lines, keys = self._compose(layout, ascii, mode, marks, _wall_marks(layout, hits))
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

    def _compose(self, layout: Layout, ascii: bool, mode: str, marks: dict, walls: dict) -> tuple[list, list]:
        scene = self._scene
        box = ASCII_BOX if ascii else BOX
        style = None if ascii else BORDER_STYLE
        width, height, size, left, top = layout[:5]
        rows = layout.rows
        by_line: dict[int, list[tuple[int, Mark]]] = {}
        for (line, col), mark in sorted(marks.items()):
            by_line.setdefault(line, []).append((col, mark))
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
                here = tuple(by_line.get(arena_row, ()))
                label = y_labels.get(arena_row, "").rjust(_LABEL_WIDTH)
                tick = box["ytick"] if arena_row in y_ticks else box["v"]
                hit = (walls.get(("left", arena_row)), walls.get(("right", arena_row)))
                if ascii:
                    text = _ascii_row(scene.chars[arena_row], here)
                    key: Hashable = ("ascii", layout, line, label, tick, text, hit)
                else:
                    row_cells = scene.cells[arena_row]
                    key = (mode, layout, line, label, tick, row_cells.tobytes(), here, hit)
                cached = segments.get(key)
                if cached is None:
                    head = [Segment(pad_left + label, style), _wall_segment(tick, hit[0], style, ascii)]
                    tail = [_wall_segment(box["v"], hit[1], style, ascii), Segment(pad_right, style)]
                    if ascii:
                        cached = [Segment("".join(segment.text for segment in [*head, Segment(text), *tail]))]
                    else:
                        cached = [*head, *_rgb_row(row_cells, mode, here), *tail]
                    segments.put(key, cached)
            else:
                edge = "top" if line == top - 1 else "bottom" if line == top + rows else None
                hit_cols = tuple(sorted((c, lv) for (side, c), lv in walls.items() if side == edge))
                key = ("frame", ascii, layout, line, tuple(sorted(x_labels.items())), hit_cols)
                cached = segments.get(key)
                if cached is None:
                    text = _frame_line(layout, line, box, x_ticks, x_labels)
                    cached = _frame_segments(text, left, dict(hit_cols), None if not text.strip() else style, ascii)
                    segments.put(key, cached)
            lines.append(cached)
            keys.append(key)
        return lines, keys


def _wall_marks(layout: Layout, hits) -> dict[tuple[str, int], int]:
    """Border cells next to wall hits, so a hit shows even under the turtle
    that made it: ("left" | "right", arena line) or ("top" | "bottom", arena
    column) -> the freshest fade level there."""
    walls: dict[tuple[str, int], int] = {}
    edge = 0.5 / METER_PX  # within half a pen-image pixel of the wall
    for x, y, level in hits:
        col, line = layout.cell_of(x, y)
        sides = []
        if x <= edge:
            sides.append(("left", line))
        elif x >= ARENA_SIZE - edge:
            sides.append(("right", line))
        if y <= edge:
            sides.append(("bottom", col))
        elif y >= ARENA_SIZE - edge:
            sides.append(("top", col))
        for side, where in sides:
            limit = layout.rows if side in ("left", "right") else layout.size
            if 0 <= where < limit:
                walls[side, where] = min(level, walls.get((side, where), level))
    return walls


def _wall_segment(char: str, level: int | None, style: Style | None, ascii: bool) -> Segment:
    if level is None:
        return Segment(char, style)
    if ascii:
        return Segment(ASCII_HIT)
    color = HIT_COLORS[min(level, len(HIT_COLORS) - 1)]
    return Segment(char, Style(color=Color.from_rgb(*color), bold=True))


def _frame_segments(text: str, left: int, hit_cols: dict[int, int], style, ascii: bool) -> list[Segment]:
    """A border line with the columns of wall hits in their colour."""
    if not hit_cols:
        return [Segment(text, style)]
    result, start = [], 0
    for col in sorted(hit_cols):
        at = left + col
        if at > start:
            result.append(Segment(text[start:at], style))
        result.append(_wall_segment(text[at], hit_cols[col], style, ascii))
        start = at + 1
    if start < len(text):
        result.append(Segment(text[start:], style))
    return result


def _marks(world: World, layout: Layout, hits, ascii: bool) -> dict[tuple[int, int], Mark]:
    """Characters over the arena by (line, column): hit marks, then names,
    then turtles (later turtles over earlier ones, turtles over any name)."""
    rows, cols = layout.rows, layout.size
    marks: dict[tuple[int, int], Mark] = {}
    for x, y, level in hits:
        col, line = layout.cell_of(x, y)
        if 0 <= line < rows and 0 <= col < cols:
            color = _pack(HIT_COLORS[min(level, len(HIT_COLORS) - 1)])
            marks[line, col] = Mark(ASCII_HIT if ascii else HIT, color, None, level == 0)
    tiles = []
    tile = _pack(TILE_COLOR)
    for name, turtle in sorted(world.turtles.items()):  # turtlesim's draw order
        col, line = layout.cell_of(turtle.x, turtle.y)
        if not (0 <= line < rows and 0 <= col < cols):
            continue  # outside the zoomed window
        heading = heading_index(turtle.theta)
        d_line, d_col = _HEAD_OFFSETS[heading]
        head = (line + d_line, col + d_col)
        if not (0 <= head[0] < rows and 0 <= head[1] < cols):
            # At a wall: the head stays on the turtle's cell, the body steps back.
            head, (line, col) = (line, col), (line - d_line, col - d_col)
        color = _pack(turtle_color(name))
        tiles.append(((line, col), head, heading, color))
        # The name above the turtle, or below when the head or the border is above.
        label_line = line - 1
        if head[0] < line or label_line < 0:
            label_line = line + 1 if line + 1 < rows and head[0] <= line else line - 1
        if 0 <= label_line < rows:
            start = min(max(col - len(name) // 2, 0), max(cols - len(name), 0))
            for i, char in enumerate(name[: cols]):
                marks[label_line, start + i] = Mark(char, color, tile)
    for body, head, heading, color in tiles:
        marks[body] = Mark(ASCII_BODY, color, None, True) if ascii else Mark(BODY, color, color, True)
        marks[head] = Mark((ASCII_HEADS if ascii else HEADS)[heading], color, tile, True)
    return marks


@lru_cache(maxsize=4)
def obstacle_pixels(obstacles: tuple[Obstacle, ...]) -> np.ndarray:
    """(500, 500) bool: the pen-image pixels whose centre lies inside an
    obstacle, and the pixel under each obstacle's centre (so none vanishes
    when shrunk). Read only."""
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
    pen.flags.writeable = False
    return pen


@lru_cache(maxsize=8)
def obstacle_mask(pixels: int, obstacles: tuple[Obstacle, ...], window: Window = WHOLE) -> np.ndarray:
    """(pixels, pixels) bool: the arena pixels showing an obstacle. Like a trail,
    a block shows an obstacle if any pen-image pixel in it lies inside one. Read only."""
    col, row, span = window
    pen = obstacle_pixels(obstacles)[row : row + span, col : col + span]
    edges = np.arange(pixels) * span // pixels
    mask = np.maximum.reduceat(pen.view(np.uint8), edges, axis=0)
    mask = np.maximum.reduceat(mask, edges, axis=1).astype(bool)
    mask.flags.writeable = False
    return mask


def _outline(layout: Layout, overlays: tuple[Overlay, ...], shape) -> list[tuple[np.ndarray, Overlay]]:
    """Each overlay's dotted outline as a mask over the arena pixels."""
    result = []
    for overlay in overlays:
        c0, r0 = layout.pixel_of(overlay.x0, overlay.y0)
        c1, r1 = layout.pixel_of(overlay.x1, overlay.y1)
        c0, c1 = sorted((c0, c1))
        r0, r1 = sorted((r0, r1))
        mask = np.zeros(shape, dtype=bool)
        last = shape[0] - 1
        # Dotted: the even pixels of each edge (a grid fixed to the arena,
        # so the dots do not crawl when a rectangle moves), and the corners.
        # Edges outside a zoomed window are left out.
        cs, ce = max(c0, 0), min(c1, last)
        rs, re = max(r0, 0), min(r1, last)
        for r in (r0, r1):
            if 0 <= r <= last and cs <= ce:
                mask[r, cs + cs % 2 : ce + 1 : 2] = True
        for c in (c0, c1):
            if 0 <= c <= last and rs <= re:
                mask[rs + rs % 2 : re + 1 : 2, c] = True
        for r, c in ((r0, c0), (r0, c1), (r1, c0), (r1, c1)):
            if 0 <= r <= last and 0 <= c <= last:
                mask[r, c] = True
        result.append((mask, overlay))
    return result


def _scene(image: np.ndarray, background, layout: Layout, overlays, obstacles, mode: str) -> _Scene:
    floor = _pack(background)
    trail = image != floor
    solid = obstacle_mask(layout.pixels, tuple(obstacles), layout.window)
    painted = image
    if obstacles or overlays:
        painted = image.copy()
        painted[solid] = _pack(OBSTACLE_COLOR)
    outline = np.zeros(image.shape, dtype=bool)
    for mask, overlay in _outline(layout, overlays, image.shape):
        painted[mask] = _pack(overlay.color)
        outline |= mask
    cells = cell_modes.encode(painted, mode, floor)
    return _Scene(painted, cells, _ascii_chars(image, trail, solid, outline, floor))


def _ascii_chars(image, trail, solid, outline, floor: int) -> np.ndarray:
    """One ASCII character per half-block cell: a trail (its pen colour's
    character, the colour farthest from the floor where two meet) over an
    obstacle over an overlay dot over blank."""
    rank = np.zeros(image.shape, dtype=np.int64)
    rank[outline] = 1
    rank[solid] = 2
    key = (image ^ np.uint32(floor)).astype(np.int64)
    rank = np.where(trail, 3 + key, rank)
    upper, lower = rank[0::2], rank[1::2]
    best = np.maximum(upper, lower)
    values = np.where(upper >= lower, image[0::2], image[1::2])
    chars = np.full(best.shape, ord(" "), dtype=np.uint8)
    chars[best == 1] = ord(OVERLAY_CHAR)
    chars[best == 2] = ord(OBSTACLE_CHAR)
    drawn = best >= 3
    for value in np.unique(values[drawn]).tolist():
        chars[drawn & (values == value)] = ord(pen_char(_unpack(int(value))))
    return chars


def _rgb_row(row_cells: np.ndarray, mode: str, marks: tuple) -> list[Segment]:
    """Segments for one arena row: runs of equal cells share one segment."""
    columns = dict(marks)
    starts = [0, *(np.flatnonzero(row_cells[1:] != row_cells[:-1]) + 1).tolist()]
    for col in columns:
        starts.extend((col, col + 1))
    starts = sorted({s for s in starts if s < len(row_cells)})
    ends = [*starts[1:], len(row_cells)]
    values = row_cells[starts].tolist()
    result = []
    for start, end, value in zip(starts, ends, values, strict=True):
        mark = columns.get(start)
        if mark is not None:
            bg = mark.bg if mark.bg is not None else cell_modes.background_of(mode, value)
            result.append(Segment(mark.char, _style(mark.fg, bg, mark.bold)))
            continue
        char, fg, bg = cell_modes.glyph(mode, value)
        result.append(Segment(char * (end - start), _style(fg, bg)))
    return result


def _ascii_row(chars: np.ndarray, marks: tuple) -> str:
    if marks:
        chars = chars.copy()
        for col, mark in marks:
            chars[col] = ord(mark.char)
    return chars.tobytes().decode("ascii")


def _metre_step(positions: dict[int, int], fits) -> int:
    """The smallest of 1, 2, 5, 10 m whose labels ``fits`` accepts."""
    for step in (1, 2, 5, 10):
        if fits([(m, positions[m]) for m in positions if m % step == 0]):
            return step
    return METRES


def _x_scale(layout: Layout) -> tuple[set[int], dict[int, str]]:
    """Bottom scale: arena columns with a tick, and label text by column."""
    cols = {m: layout.block_of(round(m * METER_PX), 0) // layout.across for m in range(METRES + 1)}
    cols = {m: c for m, c in cols.items() if 0 <= c < layout.size}

    def fits(marks) -> bool:
        end = -2
        for m, col in marks:
            if col <= end + 1:  # keep a blank between labels
                return False
            end = col + len(str(m)) - 1
        return layout.left + end < layout.width

    step = _metre_step(cols, fits)
    return set(cols.values()), {c: str(m) for m, c in cols.items() if m % step == 0}


def _y_scale(layout: Layout) -> tuple[set[int], dict[int, str]]:
    """Left scale: arena rows (lines) with a tick, and label text by row."""
    last = PIXELS - 1
    rows = {m: layout.block_of(round(last - m * METER_PX), 1) // layout.down for m in range(METRES + 1)}
    rows = {m: r for m, r in rows.items() if 0 <= r < layout.rows}

    def fits(marks) -> bool:
        used = [row for _, row in marks]
        return len(set(used)) == len(used)

    step = _metre_step(rows, fits)
    return set(rows.values()), {r: str(m) for m, r in rows.items() if m % step == 0}


def _frame_line(layout: Layout, line: int, box, x_ticks, x_labels) -> str:
    """A line outside the arena rows: top border, bottom border, x labels or blank."""
    width, _, size, left, top = layout[:5]
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
        del chars[width:]
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
