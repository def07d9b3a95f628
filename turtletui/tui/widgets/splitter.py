"""The line between the arena and the side panel: drag it to resize the panel."""

from __future__ import annotations

from rich.segment import Segment
from textual import events
from textual.message import Message
from textual.strip import Strip
from textual.widget import Widget


class Splitter(Widget):
    """A one-column vertical line; dragging it with the mouse posts ``Dragged``
    with the column the pointer is on (screen coordinates)."""

    DEFAULT_CSS = """
    Splitter {
        width: 1;
        height: 100%;
        color: $primary;
    }
    Splitter:hover, Splitter.-dragging {
        color: $accent;
    }
    """

    class Dragged(Message):
        """The splitter was dragged to screen column ``x``."""

        def __init__(self, x: int) -> None:
            super().__init__()
            self.x = x

    def __init__(self, *, ascii: bool = False, id: str | None = None) -> None:
        super().__init__(id=id)
        self._char = "|" if ascii else "│"
        self._dragging = False

    def render_line(self, y: int) -> Strip:
        return Strip([Segment(self._char, self.rich_style)], 1)

    def on_mouse_down(self, event: events.MouseDown) -> None:
        event.stop()
        self._dragging = True
        self.add_class("-dragging")
        self.capture_mouse()

    def on_mouse_move(self, event: events.MouseMove) -> None:
        if self._dragging:
            event.stop()
            self.post_message(self.Dragged(event.screen_x))

    def on_mouse_up(self, event: events.MouseUp) -> None:
        if self._dragging:
            event.stop()
            self._dragging = False
            self.remove_class("-dragging")
            self.release_mouse()
