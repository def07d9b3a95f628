"""A log of text lines that wraps at the pane's real width.

Textual's RichLog wraps each line once, when it is written, at
``max(min_width, width)`` (min_width 78 by default): in a narrower pane the
rest of the line is cut off, and lines written before a resize keep their old
wrapping. TextLog keeps the entries themselves and wraps them at the width
the widget has now, again after every resize. It keeps a bounded window of
the latest entries and says how many older ones went ("1,234 older lines").
"""

from __future__ import annotations

from bisect import bisect_right
from collections import OrderedDict
from collections.abc import Iterable

from rich.segment import Segment
from rich.text import Text
from textual.events import Resize
from textual.geometry import Size
from textual.scroll_view import ScrollView
from textual.strip import Strip

WRAPPED_KEPT = 256
"""Entries whose wrapped lines are kept ready (more than a screen's worth)."""


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
        self._entries: list[Text] = []
        self._starts: list[int] = []
        """The first wrapped line of each entry, at ``_width``, counted from the
        first line ever written (so dropping entries renumbers nothing)."""
        self._head = 0
        """Index of the oldest kept entry in ``_entries`` (the ones before it
        have left the window and are deleted in batches)."""
        self._end = 0
        """The line after the last entry's last line."""
        self._width = 0
        """The width the entries are wrapped at (0: not known yet)."""
        self._wrapped: OrderedDict[int, list[Strip]] = OrderedDict()
        """Wrapped lines of recently written or shown entries, by absolute entry
        number. Only these are kept as strips: a Textual Strip is some twenty
        objects the garbage collector tracks (its caches refer to the strip
        itself once it has been on screen), and 5,000 entries' worth of them
        made every full collection pause the app for a quarter second."""
        self._dropped = 0
        """Absolute number of ``_entries[0]``."""

    # -- writing ------------------------------------------------------------------------
    def write(self, text: Text | str) -> None:
        """Append one entry (it may wrap over several lines)."""
        self.write_all([text])

    def write_all(self, texts: Iterable[Text | str]) -> None:
        """Append entries, then scroll once."""
        follow = self._following()
        header = self._header_lines()
        first = self._first_line()
        for text in texts:
            entry = Text(text) if isinstance(text, str) else text
            entry.expand_tabs()
            number = self._dropped + len(self._entries)
            self._entries.append(entry)
            self._starts.append(self._end)
            if self._width:
                strips = self._wrap(entry)
                self._remember(number, strips)
                self._end += len(strips)
            if len(self._entries) - self._head > self.max_entries:
                self._head += 1
                self.older += 1
        self._compact()
        removed = self._first_line() - first
        self._update_size(follow, removed - (self._header_lines() - header))

    def skip(self, count: int) -> None:
        """Count entries that were lost before they reached the log."""
        if count > 0:
            self.older += count
            self.refresh()

    def clear(self) -> None:
        """Remove every entry (``older`` is kept: the owner decides)."""
        self._dropped += len(self._entries)
        self._entries, self._starts, self._head = [], [], 0
        self._wrapped.clear()
        self._update_size(True, 0)

    @property
    def entries(self) -> list[str]:
        """The plain text of the entries kept, oldest first."""
        return [entry.plain for entry in self._entries[self._head:]]

    @property
    def visible_lines(self) -> list[str]:
        """The wrapped lines on screen now, as plain text (for tests and tools)."""
        return [self.render_line(y).text for y in range(self.size.height)]

    # -- internals -----------------------------------------------------------------------
    def _first_line(self) -> int:
        return self._starts[self._head] if self._head < len(self._entries) else self._end

    def _compact(self) -> None:
        if self._head > 4096 and self._head * 2 > len(self._entries):
            del self._entries[: self._head]
            del self._starts[: self._head]
            self._dropped += self._head
            self._head = 0

    def _wrap(self, entry: Text) -> list[Strip]:
        console = self.app.console
        options = console.options.update_width(self._width)
        lines = Segment.split_lines(console.render(entry, options))
        return [Strip(line).adjust_cell_length(self._width) for line in lines] or [Strip.blank(self._width)]

    def _remember(self, number: int, strips: list[Strip]) -> None:
        self._wrapped[number] = strips
        if len(self._wrapped) > WRAPPED_KEPT:
            self._wrapped.popitem(last=False)

    def _strips_of(self, index: int) -> list[Strip]:
        """The wrapped lines of ``_entries[index]``, wrapped again if need be."""
        number = self._dropped + index
        strips = self._wrapped.get(number)
        if strips is None:
            strips = self._wrap(self._entries[index])
            self._remember(number, strips)
        else:
            self._wrapped.move_to_end(number)
        return strips

    def _rewrap(self, width: int) -> None:
        self._width = width
        self._wrapped.clear()
        line = self._first_line()
        kept_from = len(self._entries) - WRAPPED_KEPT
        for index in range(self._head, len(self._entries)):
            self._starts[index] = line
            strips = self._wrap(self._entries[index])
            if index >= kept_from:  # the latest: what a log that follows shows next
                self._remember(self._dropped + index, strips)
            line += len(strips)
        self._end = line

    def _header_lines(self) -> int:
        return 1 if self.older else 0

    def _line_count(self) -> int:
        return self._header_lines() + self._end - self._first_line()

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
        line = self._first_line() + index - self._header_lines()
        if not self._first_line() <= line < self._end:
            return Strip.blank(width, self.rich_style)
        entry = bisect_right(self._starts, line, self._head) - 1
        strip = self._strips_of(entry)[line - self._starts[entry]]
        if width != self._width:
            strip = strip.crop_extend(0, width, None)
        return strip.apply_style(self.rich_style)
