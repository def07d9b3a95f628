"""How arena pixels become terminal cells: half blocks or braille dots.

``half``: a cell shows two square pixels stacked, "▀" with the upper pixel as
its colour and the lower as its background; any terminal with true colour.
``braille``: a cell shows 2 x 4 pixels as braille dots (U+2800..U+28FF), four
times the detail of half blocks for thin trails; each cell has two colours,
the dots' and the background's, so where a cell holds several pen colours
the one that differs most from the floor wins. A cell whose 8 pixels all
have one colour is painted solid. No Textual, no Rich: numpy arrays of
packed colours in, packed cell values out.
"""

from __future__ import annotations

import numpy as np

MODES = ("half", "braille")
"""Pixel modes, plainest first."""

CELL_PIXELS = {"half": (1, 2), "braille": (2, 4)}
"""Pixels a cell shows in each mode: (across, down)."""

UPPER_HALF = "▀"
BRAILLE_BASE = 0x2800

# Braille dot bits by pixel (row, column) within the 2 x 4 cell (Unicode's dot order).
_BRAILLE_BITS = np.array([[0x01, 0x08], [0x02, 0x10], [0x04, 0x20], [0x40, 0x80]], dtype=np.uint64)

LOW32 = 0xFFFFFFFF
LOW24 = 0xFFFFFF


def encode(image: np.ndarray, mode: str, background: int) -> np.ndarray:
    """Cell values (rows, columns) uint64 of an (H, W) image of packed 0xBBGGRR pixels.

    half: upper << 32 | lower. braille: dots << 56 | fg << 24 | bg, where
    ``dots`` are the braille bits of the pixels shown in ``fg`` (0 for a
    solid cell of colour ``bg``). ``background`` is the floor's packed colour.
    """
    if mode == "half":
        upper = image[0::2].astype(np.uint64)
        lower = image[1::2].astype(np.uint64)
        return upper << np.uint64(32) | lower
    rows, cols = image.shape[0] // 4, image.shape[1] // 2
    blocks = image[: rows * 4, : cols * 2].reshape(rows, 4, cols, 2).transpose(0, 2, 1, 3)
    bits = np.uint32(background)
    key = blocks ^ bits  # 0 for the floor; larger = farther from it
    fg = key.max(axis=(2, 3))
    bg = key.min(axis=(2, 3))
    on = key == fg[:, :, None, None]
    dots = (on.astype(np.uint64) * _BRAILLE_BITS).sum(axis=(2, 3), dtype=np.uint64)
    dots[fg == bg] = 0
    fg = (fg ^ bits).astype(np.uint64)
    bg = (bg ^ bits).astype(np.uint64)
    bg = np.where(dots == 0, fg, bg)  # solid: the one colour is the background
    return dots << np.uint64(56) | fg << np.uint64(24) | bg


def glyph(mode: str, value: int) -> tuple[str, int | None, int]:
    """(character, foreground or None, background) of one cell value."""
    if mode == "half":
        upper, lower = value >> 32, value & LOW32
        return (" ", None, lower) if upper == lower else (UPPER_HALF, upper, lower)
    dots = value >> 56
    if not dots:
        return " ", None, value & LOW24
    return chr(BRAILLE_BASE + dots), value >> 24 & LOW24, value & LOW24


def background_of(mode: str, value: int) -> int:
    """The background colour a character drawn over this cell should keep."""
    return value & (LOW32 if mode == "half" else LOW24)
