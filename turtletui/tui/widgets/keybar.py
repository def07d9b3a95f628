"""The key bar at the bottom: the most useful keys that fit the width.

Textual's Footer puts every shown binding in one row and, at 80 columns,
squeezes them until some vanish and the rest overlap. The key bar instead
drops the least important keys first, so Help and Quit are always there;
the help screen lists every key.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

from rich.text import Text
from textual.events import Click, Resize
from textual.widgets import Static


class KeyHint(NamedTuple):
    key: str
    label: str
    action: str
    """The app action a click runs (without ``app.``); '' for none."""
    priority: int
    """Lower is kept longer when the bar is too narrow."""


SEPARATOR = "  "

APP_KEYS = (
    KeyHint("?", "Help", "help", 0),
    KeyHint("space", "Pause", "pause", 2),
    KeyHint("n", "Step", "step", 6),
    KeyHint("1-5", "Panels", "panel('log')", 3),
    KeyHint(":", "ros2", "command_line", 1),
    KeyHint("k", "Check", "check_lesson", 1),
    KeyHint("E", "Editor", "editor", 3),
    KeyHint("l", "Lessons", "lessons", 4),
    KeyHint("s", "Stop node", "toggle_controllers", 5),
    KeyHint("q", "Quit", "quit", 0),
)
"""The arena's keys, most useful first when the bar is narrow."""

COMMAND_LINE_KEYS = (
    KeyHint("Enter", "Run", "", 0),
    KeyHint("^C", "Stop command", "interrupt", 0),
    KeyHint("Up/Dn", "History", "", 2),
    KeyHint("Esc", "Arena", "focus_arena", 0),
    KeyHint("F1", "Help", "help", 1),
)
"""The keys while the ros2 command line has the focus."""

EDITOR_KEYS = (
    KeyHint("^S", "Save", "", 0),
    KeyHint("^C", "Copy", "", 2),
    KeyHint("^Z", "Undo", "", 3),
    KeyHint("Esc", "Arena", "focus_arena", 0),
    KeyHint("F1", "Help", "help", 1),
)
"""The keys while the editor has the focus (the others type into it)."""


def fit_keys(keys: Sequence[KeyHint], width: int) -> list[KeyHint]:
    """The keys to show in ``width`` columns: by priority, in their own order."""
    chosen: set[int] = set()
    used = 0
    for index in sorted(range(len(keys)), key=lambda i: keys[i].priority):
        hint = keys[index]
        size = len(hint.key) + 1 + len(hint.label) + (len(SEPARATOR) if chosen else 1)
        if used + size > width:
            continue
        chosen.add(index)
        used += size
    return [hint for index, hint in enumerate(keys) if index in chosen]


class KeyBar(Static):
    """One line of keys; click one to run it."""

    DEFAULT_CSS = """
    KeyBar {
        height: 1;
        background: $footer-background;
        color: $footer-foreground;
    }
    """

    def __init__(self, keys: Sequence[KeyHint] = (), *, id: str | None = None) -> None:
        super().__init__(id=id)
        self._keys = list(keys)
        self._shown: list[tuple[int, int, KeyHint]] = []
        """(first column, last column + 1, hint) of every key on screen."""

    def set_keys(self, keys: Sequence[KeyHint]) -> None:
        if list(keys) != self._keys:
            self._keys = list(keys)
            self._draw()

    def on_resize(self, event: Resize) -> None:
        self._draw()

    def _draw(self) -> None:
        width = self.size.width
        text = Text(" ")
        self._shown = []
        for i, hint in enumerate(fit_keys(self._keys, width)):
            if i:
                text.append(SEPARATOR)
            start = text.cell_len
            text.append(hint.key, style="bold reverse")
            text.append(" " + hint.label)
            self._shown.append((start, text.cell_len, hint))
        self.update(text)

    @property
    def shown(self) -> list[str]:
        """The keys on the bar now (for tests)."""
        return [hint.key for _, _, hint in self._shown]

    async def on_click(self, event: Click) -> None:
        for start, end, hint in self._shown:
            if start <= event.x < end and hint.action:
                await self.app.run_action(hint.action)
                return
