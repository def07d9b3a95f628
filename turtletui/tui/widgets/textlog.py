"""A log of text lines that wraps at the pane's real width.

Textual's RichLog wraps each line once, when it is written, at
``max(min_width, width)`` (min_width 78 by default): in a narrower pane the
rest of the line is cut off, and lines written before a resize keep their old
wrapping. TextLog keeps the entries themselves and wraps them at the width
the widget has now, again after every resize. It keeps a bounded window of
the latest entries and says how many older ones went ("1,234 older lines").
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable

from rich.segment import Segment
from rich.text import Text
from textual.events import Resize
from textual.geometry import Size
from textual.scroll_view import ScrollView
from textual.strip import Strip


class TextLog(ScrollView, can_focus=True):
    """Lines of text, wrapped at the current width, the latest ``max_entries`` kept."""

    DEFAULT_CSS = """
    TextLog {
        background: $surface;
        color: $foreground;
        overflow-x: hidden;
        overflow-y: scroll;
        &:focus {
            background-tint: $foreground 5%;
        }
    }
    """

    def __init__(self, max_entries: int = 5000, *, id: str | None = None,
                 classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.max_entries = max_entries
        """Entries kept; older ones are counted in ``older``."""
        self.older = 0
        """Entries that left the window (or never reached it)."""
        self._entries: deque[Text] = deque()
        self._heights: deque[int] = deque()
        """Wrapped lines per entry, at ``_width``."""
        self._strips: list[Strip] = []
        """The wrapped lines of every entry, from ``_first`` on."""
        self._first = 0
        self._width = 0
        """The width the entries are wrapped at (0: not known yet)."""

    # -- writing ------------------------------------------------------------------------
    def write(self, text: Text | str) -> None:
        """Append one entry (it may wrap over several lines)."""
        self.write_all([text])

    def write_all(self, texts: Iterable[Text | str]) -> None:
        """Append entries, then scroll once."""
        follow = self._following()
        header = self._header_lines()
        removed = 0
        for text in texts:
            entry = Text(text) if isinstance(text, str) else text
            entry.expand_tabs()
            self._entries.append(entry)
            height = self._wrap_into(entry, self._strips) if self._width else 0
            self._heights.append(height)
            if len(self._entries) > self.max_entries:
                removed += self._drop_oldest()
        self._compact()
        self._update_size(follow, removed - (self._header_lines() - header))

    def skip(self, count: int) -> None:
        """Count entries that were lost before they reached the log."""
        if count > 0:
            self.older += count
            self.refresh()

    def clear(self) -> None:
        """Remove every entry (``older`` is kept: the owner decides)."""
        self._entries.clear()
        self._heights.clear()
        self._strips = []
        self._first = 0
        self._update_size(True, 0)

    @property
    def entries(self) -> list[str]:
        """The plain text of the entries kept, oldest first."""
        return [entry.plain for entry in self._entries]

    @property
    def visible_lines(self) -> list[str]:
        """The wrapped lines on screen now, as plain text (for tests and tools)."""
        return [self.render_line(y).text for y in range(self.size.height)]

    # -- internals -----------------------------------------------------------------------
    def _drop_oldest(self) -> int:
        self._entries.popleft()
        height = self._heights.popleft()
        self._first += height
        self.older += 1
        return height

    def _compact(self) -> None:
        if self._first > 4096 and self._first * 2 > len(self._strips):
            del self._strips[: self._first]
            self._first = 0

    def _wrap_into(self, entry: Text, out: list[Strip]) -> int:
        console = self.app.console
        options = console.options.update_width(self._width)
        lines = Segment.split_lines(console.render(entry, options))
        strips = [Strip(line).adjust_cell_length(self._width) for line in lines] or [Strip.blank(self._width)]
        out.extend(strips)
        return len(strips)

    def _rewrap(self, width: int) -> None:
        self._width = width
        strips: list[Strip] = []
        heights = deque(self._wrap_into(entry, strips) for entry in self._entries)
        self._strips, self._heights, self._first = strips, heights, 0

    def _header_lines(self) -> int:
        return 1 if self.older else 0

    def _line_count(self) -> int:
        return self._header_lines() + len(self._strips) - self._first

    def _following(self) -> bool:
        return self.scroll_y >= self.max_scroll_y

    def _update_size(self, follow: bool, shift: int) -> None:
        """New size; follow the end, or move up by ``shift`` lines (the lines
        that went above) so that the lines being read stay in place."""
        self.virtual_size = Size(self._width, self._line_count())
        if follow:
            self.scroll_end(animate=False, immediate=False, x_axis=False)
        elif shift:
            self.scroll_to(y=max(0, self.scroll_y - shift), animate=False, immediate=True)
        self.refresh()

    def on_resize(self, event: Resize) -> None:
        width = self.scrollable_content_region.width
        if width > 0 and width != self._width:
            follow = self._following()
            self._rewrap(width)
            self._update_size(follow, 0)

    def render_line(self, y: int) -> Strip:
        width = self.scrollable_content_region.width
        index = self.scroll_offset.y + y
        if self.older and index == 0:
            note = Text(f"... {self.older:,} older lines", style="dim italic", no_wrap=True)
            strip = Strip(note.render(self.app.console)).crop_extend(0, width, None)
            return strip.apply_style(self.rich_style)
        index += self._first - self._header_lines()
        if not self._first <= index < len(self._strips):
            return Strip.blank(width, self.rich_style)
        strip = self._strips[index]
        if width != self._width:
            strip = strip.crop_extend(0, width, None)
        return strip.apply_style(self.rich_style)
