"""The pen image: a 500 x 500 raster, as turtlesim's ``path_image``.

Segments are queued as data and rasterised in vectorised batches when the
image is read, so a turtle drawing every 16 ms costs 48 bytes appended per step;
a run nobody watches (headless, grading) draws only to bound the queue.
A colour sensor read (every step while a run is recorded) tests the few
queued segments near its pixel instead of rasterising the queue.
Coordinates follow turtlesim: pixel = metres * 45 with the y axis flipped
(pixel row 0 is the top, y = 11.0889 m).

In ROS 2 turtlesim the pen image is a layer of its own, filled with
transparent white (``qRgba(255, 255, 255, 0)``); the background colour is
painted beneath it only on screen. So the colour sensor reads (255, 255, 255)
on ground no pen has touched, and a background change recolours the screen
without wiping the trails. The canvas keeps which pixels a pen painted
(``painted``) beside the picture as it is shown (``pixels``, ``packed``:
the trails over the background), so renderers stay a plain read.
"""

from __future__ import annotations

import math
import struct
from collections import deque

import numpy as np

from turtletui.sim.constants import BACKGROUND, METER_PX, PIXELS

_FLUSH_AT = 65536
_SEGMENT = struct.Struct("6d")
"""A queued segment as bytes: x0, y0, x1, y1 (m), packed colour, width, as
float64 (packing six numbers costs half what array("d").extend does)."""
_pack_segment = _SEGMENT.pack
_unpack_segment = _SEGMENT.unpack_from
_FLUSH_BYTES = _FLUSH_AT * _SEGMENT.size
"""Queued segments (3 MB) that are rasterised even if nobody reads the image."""
_RASTER_CHUNK = 512
"""Segments rasterised at once."""
_LAZY_READS_AT = 64
"""Queued segments up to which a colour read tests them one by one instead of flushing."""
_CHANGES_KEPT = 256
"""Recent changes remembered for changed_since (older asks get the whole image)."""
_LAST_PX = PIXELS - 1
_MARGIN_PX = 4096.0
"""How far (pixels) past the image a pen line is followed; beyond, it is cut."""
UNPAINTED = (255, 255, 255)
"""What the colour sensor reads where no pen has drawn: the pen layer's transparent white."""


def _pack(rgb: tuple[int, int, int]) -> int:
    return rgb[0] | rgb[1] << 8 | rgb[2] << 16


def to_pixel(x: float, y: float) -> tuple[int, int]:
    """Pixel (column, row) under world point (x, y) m, rounded like Qt's toPoint."""
    col = int(x * METER_PX + 0.5)
    row = int((_LAST_PX / METER_PX - y) * METER_PX + 0.5)
    return min(max(col, 0), _LAST_PX), min(max(row, 0), _LAST_PX)


class PenCanvas:
    """Trails drawn by the turtles' pens, shown over the background colour.

    Pixels are stored packed, one little-endian uint32 (r, g, b, 0) each, so a
    batch of stamps is one fancy assignment; ``pixels`` is an RGB view of it.
    A boolean mask beside them says which pixels a pen painted.
    """

    def __init__(self, background: tuple[int, int, int] = BACKGROUND) -> None:
        self._packed = np.zeros((PIXELS, PIXELS), dtype="<u4")
        self._flat = memoryview(self._packed).cast("B").cast("I")
        self._rgb = self._packed.view(np.uint8).reshape(PIXELS, PIXELS, 4)[:, :, :3]
        self._rgb.flags.writeable = False
        self._painted = np.zeros((PIXELS, PIXELS), dtype=bool)
        self._pending = bytearray()
        """Queued segments (_SEGMENT each): x0, y0, x1, y1 (m), packed colour, width."""
        self._reach: list[tuple[float, ...]] = []
        """For the first queued segments, the pixels (c0, c1, r0, r1) beyond which
        each paints nothing, and the same for it and all before it together:
        worked out once each, when the colour sensor reads."""
        self._pen: tuple[int, int, int] | None = None
        self._pen_packed = 0
        """The last pen colour drawn with, and it packed (a turtle keeps its colour)."""
        self.background = background
        self.version = 0
        """Increases whenever the image changes; renderers cache on it."""
        self._changes: deque[tuple[int, tuple[int, int, int, int]]] = deque(maxlen=_CHANGES_KEPT)
        self.clear(background)

    def __getstate__(self) -> dict:
        # the views share the packed array's memory: rebuilt, not copied
        state = self.__dict__.copy()
        del state["_flat"], state["_rgb"]
        return state

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._flat = memoryview(self._packed).cast("B").cast("I")
        self._rgb = self._packed.view(np.uint8).reshape(PIXELS, PIXELS, 4)[:, :, :3]
        self._rgb.flags.writeable = False

    @property
    def packed(self) -> np.ndarray:
        """The image as (500, 500) little-endian uint32 (r | g << 8 | b << 16). Read only."""
        if self._pending:
            self._flush()
        view = self._packed.view()
        view.flags.writeable = False
        return view

    def changed_since(self, version: int) -> tuple[int, int, int, int] | None:
        """The pixel rows and columns (r0, r1, c0, c1, inclusive) that changed
        after ``version``, so a renderer can redo just that part; the whole
        image if that is too long ago; None if nothing changed."""
        if self._pending:
            self._flush()
        if version >= self.version:
            return None
        if not self._changes or self._changes[0][0] > version + 1:
            return (0, _LAST_PX, 0, _LAST_PX)
        boxes = [box for v, box in self._changes if v > version]
        if not boxes:
            return None
        return (
            min(b[0] for b in boxes),
            max(b[1] for b in boxes),
            min(b[2] for b in boxes),
            max(b[3] for b in boxes),
        )

    @property
    def pixels(self) -> np.ndarray:
        """The image as a (500, 500, 3) uint8 array, row 0 at the top. Read only."""
        if self._pending:
            self._flush()
        return self._rgb

    @property
    def painted(self) -> np.ndarray:
        """(500, 500) bool: True where a pen has drawn since the last clear. Read only."""
        if self._pending:
            self._flush()
        view = self._painted.view()
        view.flags.writeable = False
        return view

    def clear(self, background: tuple[int, int, int] | None = None) -> None:
        """Drop every trail (the /clear service), showing the background colour."""
        if background is not None:
            self.background = background
        del self._pending[:]
        del self._reach[:]
        self._painted[:, :] = False
        self._packed[:, :] = _pack(self.background)
        self._changed_everything()

    def set_background(self, background: tuple[int, int, int]) -> None:
        """Show another background colour beneath the trails, which stay."""
        if self._pending:
            self._flush()
        self.background = background
        self._packed[~self._painted] = _pack(background)
        self._changed_everything()

    def _changed_everything(self) -> None:
        self.version += 1
        self._changes.append((self.version, (0, _LAST_PX, 0, _LAST_PX)))

    def draw_segment(
        self,
        x0: float,
        y0: float,
        x1: float,
        y1: float,
        color: tuple[int, int, int],
        width: int,
    ) -> None:
        """Queue a pen line from (x0, y0) to (x1, y1) metres, ``width`` pixels wide."""
        if color is self._pen:
            packed = self._pen_packed
        else:
            packed = self._pen_packed = color[0] | color[1] << 8 | color[2] << 16
            self._pen = color
        pending = self._pending
        pending += _pack_segment(x0, y0, x1, y1, packed, width)
        if len(pending) >= _FLUSH_BYTES:
            self._flush()

    def color_at(self, x: float, y: float) -> tuple[int, int, int]:
        """RGB of the pen image under world point (x, y), as turtlesim's
        color_sensor: UNPAINTED (255, 255, 255) where no pen has drawn."""
        col, row = to_pixel(x, y)
        value = self._pending_color(col, row) if self._pending else None
        if value is None:
            if not self._painted[row, col]:
                return UNPAINTED
            value = self._flat[row * PIXELS + col]
        return value & 0xFF, value >> 8 & 0xFF, value >> 16 & 0xFF

    def _pending_color(self, col: int, row: int) -> int | None:
        """The packed colour the newest queued segment over pixel (col, row)
        gives it, or None when no queued segment covers it (the queue may then
        have been flushed). A sensor read every tick so costs a few float
        operations, where rasterising each tick's one segment costs a batch."""
        pending = self._pending
        end = len(pending)
        if end > _LAZY_READS_AT * _SEGMENT.size:
            self._flush()
            return None
        # Segments beyond the arena land on its edge pixels too (clipped).
        x_edge = col == 0 or col == _LAST_PX
        y_edge = row == 0 or row == _LAST_PX
        reach = self._reach
        size = _SEGMENT.size
        for at in range(len(reach) * size, end, size):
            c0, c1, r0, r1 = _reach(*_unpack_segment(pending, at))
            if reach:
                _, _, _, _, u0, u1, v0, v1 = reach[-1]
                reach.append((c0, c1, r0, r1, min(u0, c0), max(u1, c1), min(v0, r0), max(v1, r1)))
            else:
                reach.append((c0, c1, r0, r1, c0, c1, r0, r1))
        for i in range(len(reach) - 1, -1, -1):
            c0, c1, r0, r1, u0, u1, v0, v1 = reach[i]
            if not (x_edge or u0 <= col <= u1) or not (y_edge or v0 <= row <= v1):
                break  # beyond every segment up to this one
            if not (x_edge or c0 <= col <= c1) or not (y_edge or r0 <= row <= r1):
                continue
            x0, y0, x1, y1, packed, width = _unpack_segment(pending, i * size)
            covered = _covers(x0, y0, x1, y1, width, col, row)
            if covered is None or (covered and not 0 <= packed < 1 << 24):
                self._flush()  # beyond the exact test: the raster decides
                return None
            if covered:
                return int(packed)
        return None

    def _flush(self) -> None:
        if not self._pending:
            return
        queued = np.frombuffer(self._pending, dtype=np.float64).reshape(-1, 6).copy()
        del self._pending[:]
        del self._reach[:]
        self.version += 1
        # In chunks: their scratch arrays stay small enough to be reused rather
        # than mapped afresh (page faults cost more than the arithmetic).
        boxes = [self._rasterise(queued[i : i + _RASTER_CHUNK]) for i in range(0, len(queued), _RASTER_CHUNK)]
        boxes = [box for box in boxes if box is not None]
        if boxes:
            rows0, rows1, cols0, cols1 = zip(*boxes, strict=True)
            self._changes.append((self.version, (min(rows0), max(rows1), min(cols0), max(cols1))))

    @np.errstate(over="ignore", invalid="ignore")  # lines to absurd teleports are cut below
    def _rasterise(self, segments: np.ndarray) -> tuple[int, int, int, int] | None:
        """Paint queued segments (rows of x0, y0, x1, y1, packed colour,
        width) in order; the box (r0, r1, c0, c1) they touched, None if none."""
        top = _LAST_PX / METER_PX
        x0 = segments[:, 0] * METER_PX
        y0 = (top - segments[:, 1]) * METER_PX
        dx = segments[:, 2] * METER_PX - x0
        dy = (top - segments[:, 3]) * METER_PX - y0
        colors = segments[:, 4].astype("<u4")
        widths = np.maximum(segments[:, 5], 1.0)
        far = _far(x0, y0, x0 + dx, y0 + dy)
        if far.any():
            # A line to a teleport far outside (x = 1e7 m) would have millions
            # of samples: it is cut where it leaves the margin, or dropped.
            keep, x0, y0, dx, dy = _cut(x0, y0, dx, dy, far)
            x0, y0, dx, dy, colors, widths = x0[keep], y0[keep], dx[keep], dy[keep], colors[keep], widths[keep]
        # Qt's default square cap extends a wide line by half its width at
        # both ends (a zero-length line becomes a width x width square).
        length = np.hypot(dx, dy)
        moving = length > 1e-9
        ux = np.where(moving, dx / np.where(moving, length, 1.0), 1.0)
        uy = np.where(moving, dy / np.where(moving, length, 1.0), 0.0)
        cap = widths / 2.0
        x0 = x0 - ux * cap
        y0 = y0 - uy * cap
        dx = dx + 2.0 * ux * cap
        dy = dy + 2.0 * uy * cap
        # Scan-convert each (capped) segment as a polygon of the pen's width:
        # for every pixel centre along the major axis the line covers, paint
        # the centres across the minor axis within half the width over the
        # cosine of the line's angle. Pixel centres sit on integer coordinates,
        # matching turtlesim's rounding of positions to pixels.
        x_major = np.abs(dx) >= np.abs(dy)
        start = np.where(x_major, x0, y0)
        delta = np.where(x_major, dx, dy)
        minor0 = np.where(x_major, y0, x0)
        slope = np.where(x_major, dy, dx) / delta
        half = widths * np.hypot(dx, dy) / np.abs(delta) / 2.0
        lo = np.ceil(np.minimum(start, start + delta))
        samples = np.maximum(np.ceil(np.maximum(start, start + delta)) - lo, 0).astype(np.int64)
        seg = np.repeat(np.arange(len(x0)), samples)
        first = np.cumsum(samples) - samples
        along = lo[seg] + (np.arange(seg.size) - first[seg])
        across = minor0[seg] + (along - start[seg]) * slope[seg]
        low = np.ceil(across - half[seg])
        count = (np.ceil(across + half[seg]) - low).astype(np.int64)
        if not count.size:
            return None
        # A fixed-width grid per sample; steps past a sample's count repeat its
        # last pixel, which paints nothing new and avoids a masked copy. Pixel
        # indices fit int32 (the grid is the bulk of the work: half the bytes).
        width = int(count.max())
        steps = np.minimum(np.arange(width, dtype=np.int32), (count - 1).astype(np.int32)[:, None])
        # Past the arena a pixel clips to its edge; moving ``low`` to just past
        # it first keeps the sum in int32 and clips the same.
        low_px = np.clip(low, -width, PIXELS).astype(np.int32)[:, None]
        across_px = np.clip(low_px + steps, 0, _LAST_PX)
        along_px = np.clip(along, 0, _LAST_PX).astype(np.int32)
        major = x_major[seg]
        along_stride = np.where(major, 1, PIXELS).astype(np.int32)
        across_stride = np.where(major, PIXELS, 1).astype(np.int32)
        index = across_px * across_stride[:, None]
        index += (along_px * along_stride)[:, None]
        # Row-major order of the (sample, step) grid keeps later segments over
        # earlier ones: numpy assigns repeated indices in order.
        flat = index.ravel()
        self._packed.ravel()[flat] = np.repeat(colors[seg], width)
        self._painted.ravel()[flat] = True
        # The changed box: a sample's pixels across grow along its grid row.
        first, last, minor = across_px[:, 0], across_px[:, -1], ~major
        rows = _bounds(first, last, major, along_px, along_px, minor)
        cols = _bounds(along_px, along_px, major, first, last, minor)
        return (*rows, *cols)


def _bounds(
    lo_a: np.ndarray, hi_a: np.ndarray, in_a: np.ndarray, lo_b: np.ndarray, hi_b: np.ndarray, in_b: np.ndarray
) -> tuple[int, int]:
    """The lowest of lo_a where in_a and lo_b where in_b, and the highest of hi_a, hi_b likewise."""
    low = min(int(lo_a.min(initial=_LAST_PX, where=in_a)), int(lo_b.min(initial=_LAST_PX, where=in_b)))
    high = max(int(hi_a.max(initial=0, where=in_a)), int(hi_b.max(initial=0, where=in_b)))
    return low, high


def _far(x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray) -> np.ndarray:
    """Which segments (pixel coordinates) reach past the margin around the image (or are not finite)."""
    near = (np.minimum(x0, x1) >= -_MARGIN_PX) & (np.maximum(x0, x1) <= _LAST_PX + _MARGIN_PX)
    near &= (np.minimum(y0, y1) >= -_MARGIN_PX) & (np.maximum(y0, y1) <= _LAST_PX + _MARGIN_PX)
    return ~near


def _cut(
    x0: np.ndarray, y0: np.ndarray, dx: np.ndarray, dy: np.ndarray, far: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The ``far`` segments cut to the margin around the image (Liang-Barsky);
    the others as they are. Returns which to keep (none of a far one may be
    inside, or it is not finite) and the segments."""
    lo, hi = -_MARGIN_PX, _LAST_PX + _MARGIN_PX
    t0 = np.zeros_like(x0)
    t1 = np.ones_like(x0)
    keep = np.ones(len(x0), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for p, q in ((-dx, x0 - lo), (dx, hi - x0), (-dy, y0 - lo), (dy, hi - y0)):
            r = q / p
            keep &= ~((p == 0) & (q < 0))
            t0 = np.where(p < 0, np.maximum(t0, r), t0)
            t1 = np.where(p > 0, np.minimum(t1, r), t1)
        keep &= ~far | (np.isfinite(t0) & np.isfinite(t1) & (t0 <= t1))
        cut_x0 = np.where(far, x0 + t0 * dx, x0)
        cut_y0 = np.where(far, y0 + t0 * dy, y0)
        cut_dx = np.where(far, (t1 - t0) * dx, dx)
        cut_dy = np.where(far, (t1 - t0) * dy, dy)
    keep &= np.isfinite(cut_x0) & np.isfinite(cut_y0) & np.isfinite(cut_dx) & np.isfinite(cut_dy)
    return keep, cut_x0, cut_y0, cut_dx, cut_dy


_EVERYWHERE = (-math.inf, math.inf, -math.inf, math.inf)


def _reach(x0: float, y0: float, x1: float, y1: float, packed: float, width: float) -> tuple[float, float, float, float]:
    """The pixel columns and rows (c0, c1, r0, r1) outside which ``_flush``
    paints nothing for this one segment (half a pixel generous, for rounding);
    everywhere when that is not plain (non-finite values). Along a line its
    square caps reach half the width; across it, the raster paints half the
    width over the cosine (``half`` in ``_covers``)."""
    top = _LAST_PX / METER_PX
    ax, bx = x0 * METER_PX, x1 * METER_PX
    ay, by = (top - y0) * METER_PX, (top - y1) * METER_PX
    width = max(width, 1.0)
    if not (math.isfinite(ax + bx + ay + by) and math.isfinite(width)):
        return _EVERYWHERE
    dx, dy = abs(bx - ax), abs(by - ay)
    length = math.hypot(dx, dy)
    ux, uy = (dx / length, dy / length) if length > 1e-9 else (1.0, 0.0)
    cap = width / 2.0
    across = cap / max(ux, uy)
    reach_x = cap * ux + (across if ux <= uy + 1e-9 else 0.0) + 0.5
    reach_y = cap * uy + (across if uy <= ux + 1e-9 else 0.0) + 0.5
    return min(ax, bx) - reach_x, max(ax, bx) + reach_x, min(ay, by) - reach_y, max(ay, by) + reach_y


def _covers(x0: float, y0: float, x1: float, y1: float, width: float, col: int, row: int) -> bool | None:
    """Whether ``_flush`` paints pixel (col, row) for this one segment: its
    arithmetic for one sample, in the same order on the same doubles (hypot
    is numpy's, as there). None when that is not a plain yes or no
    (non-finite values, many samples clipped onto an edge pixel)."""
    top = _LAST_PX / METER_PX
    ax, bx = x0 * METER_PX, x1 * METER_PX
    ay, by = (top - y0) * METER_PX, (top - y1) * METER_PX
    if not (-_MARGIN_PX <= min(ax, bx) and max(ax, bx) <= _LAST_PX + _MARGIN_PX):
        return None  # cut by the raster (see _cut), or not finite
    if not (-_MARGIN_PX <= min(ay, by) and max(ay, by) <= _LAST_PX + _MARGIN_PX):
        return None
    dx = bx - ax
    dy = by - ay
    width = max(width, 1.0)
    length = float(np.hypot(dx, dy))
    ux, uy = (dx / length, dy / length) if length > 1e-9 else (1.0, 0.0)
    cap = width / 2.0
    ax = ax - ux * cap
    ay = ay - uy * cap
    dx = dx + 2.0 * ux * cap
    dy = dy + 2.0 * uy * cap
    if abs(dx) >= abs(dy):
        start, delta, minor0, slope, along_px, across_px = ax, dx, ay, dy / dx, col, row
    else:
        start, delta, minor0, slope, along_px, across_px = ay, dy, ax, dx / dy, row, col
    half = width * float(np.hypot(dx, dy)) / abs(delta) / 2.0
    if not (math.isfinite(start + delta) and math.isfinite(slope) and math.isfinite(half) and math.isfinite(minor0)):
        return None
    lo = math.ceil(min(start, start + delta))
    hi = math.ceil(max(start, start + delta)) - 1
    # the samples whose along coordinate clips to along_px (all past an edge)
    first = lo if along_px == 0 else max(lo, along_px)
    last = hi if along_px == _LAST_PX else min(hi, along_px)
    if last - first > 8:
        return None
    for along in range(first, last + 1):
        across = minor0 + (float(along) - start) * slope
        low = math.ceil(across - half)
        count = math.ceil(across + half) - low
        reach_lo = min(max(low + min(0, count - 1), 0), _LAST_PX)
        reach_hi = min(max(low + count - 1, 0), _LAST_PX)
        if reach_lo <= across_px <= reach_hi:
            return True
    return False
