"""The errors of writing a recording or serving it live (standard library only)."""

from __future__ import annotations

from turtletui.errors import TurtletuiError


class RecordingWriteError(TurtletuiError, OSError):
    """A recording that cannot be written (an OSError, as its cause was); one
    line naming the path."""


class FoxgloveError(TurtletuiError, OSError):
    """A live view that cannot be served (foxglove-sdk missing, an address in
    use); one line."""
