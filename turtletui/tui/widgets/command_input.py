"""The ros2 command line: an Input that remembers the commands typed, as a
shell does (up and down go through them)."""

from __future__ import annotations

from textual.binding import Binding
from textual.widgets import Input

MAX_HISTORY = 200


class CommandInput(Input):
    """One-line input with a history of the commands submitted."""

    BINDINGS = [
        Binding("up", "history(-1)", "Previous command", show=False),
        Binding("down", "history(1)", "Next command", show=False),
    ]

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.history: list[str] = []
        self._at = 0
        """Index in history being shown; len(history) is the new line."""
        self._draft = ""

    def remember(self, line: str) -> None:
        """Keep a submitted line (not twice in a row) and go back to a new line."""
        if line and (not self.history or self.history[-1] != line):
            self.history.append(line)
            del self.history[:-MAX_HISTORY]
        self._at = len(self.history)
        self._draft = ""

    def action_history(self, step: int) -> None:
        if not self.history:
            return
        if self._at == len(self.history):
            self._draft = self.value
        self._at = min(max(self._at + step, 0), len(self.history))
        self.value = self._draft if self._at == len(self.history) else self.history[self._at]
        self.cursor_position = len(self.value)
