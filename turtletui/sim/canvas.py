"""The pen image: a 500 x 500 RGB raster, as turtlesim's ``path_image``.

Segments are queued as data and rasterised in vectorised batches when the
image is read, so a turtle drawing every 16 ms costs a list append per step.
Coordinates follow turtlesim: pixel = metres * 45 with the y axis flipped
(pixel row 0 is the top, y = 11.0889 m).
"""

from __future__ import annotations

import numpy as np

from turtletui.sim.constants import BACKGROUND, METER_PX, PIXELS

_FLUSH_AT = 4096
_SAMPLE_STEP_PX = 0.5
_LAST_PX = PIXELS - 1


def to_pixel(x: float, y: float) -> tuple[int, int]:
    """Pixel (column, row) under world point (x, y) m, rounded like Qt's toPoint."""
    col = int(x * METER_PX + 0.5)
    row = int((_LAST_PX / METER_PX - y) * METER_PX + 0.5)
    return min(max(col, 0), _LAST_PX), min(max(row, 0), _LAST_PX)


class PenCanvas:
    """Trails drawn by the turtles' pens over the background colour."""

    def __init__(self, background: tuple[int, int, int] = BACKGROUND) -> None:
        self._pixels = np.empty((PIXELS, PIXELS, 3), dtype=np.uint8)
        self._flat = memoryview(self._pixels).cast("B")
        self._pending: list[tuple[float, float, float, float, int, int, int, int]] = []
        self.background = background
        self.version = 0
        """Increases whenever the image changes; renderers cache on it."""
        self.clear(background)

    @property
    def pixels(self) -> np.ndarray:
        """The image as a (500, 500, 3) uint8 array, row 0 at the top. Read only."""
        if self._pending:
            self._flush()
        view = self._pixels.view()
        view.flags.writeable = False
        return view

    def clear(self, background: tuple[int, int, int] | None = None) -> None:
        """Fill the image with the background colour, dropping every trail."""
        if background is not None:
            self.background = background
        self._pending.clear()
        self._pixels[:, :] = self.background
        self.version += 1

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
        pending = self._pending
        pending.append((x0, y0, x1, y1, *color, width))
        if len(pending) >= _FLUSH_AT:
            self._flush()

    def color_at(self, x: float, y: float) -> tuple[int, int, int]:
        """RGB of the image under world point (x, y), as turtlesim's color_sensor."""
        if self._pending:
            self._flush()
        col, row = to_pixel(x, y)
        i = (row * PIXELS + col) * 3
        flat = self._flat
        return flat[i], flat[i + 1], flat[i + 2]

    def _flush(self) -> None:
        segments = np.asarray(self._pending, dtype=np.float64)
        self._pending.clear()
        self.version += 1
        top = _LAST_PX / METER_PX
        x0 = segments[:, 0] * METER_PX
        y0 = (top - segments[:, 1]) * METER_PX
        dx = segments[:, 2] * METER_PX - x0
        dy = (top - segments[:, 3]) * METER_PX - y0
        colors = segments[:, 4:7].astype(np.uint8)
        widths = segments[:, 7].astype(np.int64)
        # Sample every segment at most one pixel apart on both axes, so the
        # stamps along it join up.
        samples = np.ceil(np.maximum(np.abs(dx), np.abs(dy))).astype(np.int64) + 1
        seg = np.repeat(np.arange(len(segments)), samples)
        first = np.cumsum(samples) - samples
        t = (np.arange(seg.size) - first[seg]) / np.maximum(samples - 1, 1)[seg]
        px = np.floor(x0[seg] + t * dx[seg] + 0.5).astype(np.int64)
        py = np.floor(y0[seg] + t * dy[seg] + 0.5).astype(np.int64)
        sample_width = widths[seg]
        # A Qt pen of width w covers about w pixels across the line: stamp a
        # w x w square at every sample.  The stamps are written in one
        # assignment ordered by sample, so later segments overwrite earlier
        # ones (numpy assigns repeated indices in order).
        order, cols, rows = [], [], []
        for width in np.unique(sample_width):
            (which,) = np.nonzero(sample_width == width)
            lo = -((int(width) - 1) // 2)
            offsets = np.arange(lo, lo + max(int(width), 1))
            ox = np.tile(offsets, offsets.size)
            oy = np.repeat(offsets, offsets.size)
            order.append(np.repeat(which, ox.size))
            cols.append((px[which, None] + ox).ravel())
            rows.append((py[which, None] + oy).ravel())
        if len(order) == 1:
            sample, col, row = order[0], cols[0], rows[0]
        else:
            sort = np.argsort(np.concatenate(order), kind="stable")
            sample = np.concatenate(order)[sort]
            col = np.concatenate(cols)[sort]
            row = np.concatenate(rows)[sort]
        ok = (col >= 0) & (col <= _LAST_PX) & (row >= 0) & (row <= _LAST_PX)
        self._pixels[row[ok], col[ok]] = colors[seg[sample[ok]]]
