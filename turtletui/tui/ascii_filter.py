"""``--ascii`` for the whole screen: a Textual line filter that turns every
character the widgets draw (borders, scrollbars, the select's arrow,
Markdown's bullets, the command palette's icons ...) into ASCII of the same
width. Textual applies line filters to every line of every widget, so no
widget, ours or Textual's, can slip a Unicode character through.
"""

from __future__ import annotations

import unicodedata
from functools import lru_cache

from rich.cells import cell_len
from rich.segment import Segment
from textual.color import Color
from textual.filter import LineFilter

_KNOWN = {
    "…": ".",
    "•": "*",
    "·": ".",
    "‣": ">",
    "▪": "*",
    "⭘": "o",
    "✓": "v",
    "✔": "v",
    "✗": "x",
    "✕": "x",
    "×": "x",
    "⏎": "<",
    "⌫": "<",
    "‘": "'",
    "’": "'",
    "“": '"',
    "”": '"',
    "–": "-",
    "—": "-",
    "\u00a0": " ",
}


@lru_cache(maxsize=4096)
def ascii_char(char: str) -> str:
    """One character as ASCII of the same cell width."""
    if char.isascii():
        return char
    width = max(cell_len(char), 0)
    if width == 0:
        return ""  # combining marks, zero-width joiners
    known = _KNOWN.get(char)
    if known is None:
        known = _by_name(char)
    return (known * width)[:width] if len(known) == 1 else known.ljust(width)[:width]


def _by_name(char: str) -> str:
    name = unicodedata.name(char, "")
    code = ord(char)
    if 0x2500 <= code <= 0x257F:  # box drawing
        if "HORIZONTAL" in name and "VERTICAL" not in name:
            return "-"
        if "VERTICAL" in name and "HORIZONTAL" not in name:
            return "|"
        if "DIAGONAL" in name:
            return "/" if "UPPER RIGHT TO LOWER LEFT" in name else "\\"
        return "+"
    if 0x2580 <= code <= 0x259F:  # block elements: solid shapes read as '#', slivers as blanks
        return "#" if ("FULL" in name or "SHADE" in name or "HALF" in name or "QUADRANT" in name) else " "
    if 0x2800 <= code <= 0x28FF:  # braille
        return "." if code != 0x2800 else " "
    for words, ascii in (
        (("LEFTWARDS", "LEFT-POINTING", "LEFT POINTING"), "<"),
        (("RIGHTWARDS", "RIGHT-POINTING", "RIGHT POINTING"), ">"),
        (("UPWARDS", "UP-POINTING", "UP POINTING"), "^"),
        (("DOWNWARDS", "DOWN-POINTING", "DOWN POINTING"), "v"),
    ):
        if any(word in name for word in words):
            return ascii
    if "CIRCLE" in name or "BULLET" in name:
        return "o"
    if "SQUARE" in name or "RECTANGLE" in name or "BLOCK" in name:
        return "#"
    if "TRIANGLE" in name:
        return "^"
    if "DASH" in name or "HYPHEN" in name or "MINUS" in name or "LINE" in name:
        return "-"
    plain = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode()
    return plain or "?"


def to_ascii(text: str) -> str:
    """``text`` with every character replaced by ASCII of the same width."""
    return text if text.isascii() else "".join(ascii_char(char) for char in text)


class AsciiFilter(LineFilter):
    """Turns the text of every segment into ASCII; styles and controls are kept."""

    def apply(self, segments: list[Segment], background: Color) -> list[Segment]:
        return [
            segment if segment.control or segment.text.isascii() else Segment(to_ascii(segment.text), segment.style)
            for segment in segments
        ]
