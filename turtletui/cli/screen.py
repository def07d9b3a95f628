"""Whether the app has a screen to draw on: a terminal, or a Textual driver
that brings its own (textual-serve runs the app under its web driver, with
pipes instead of a terminal)."""

from __future__ import annotations

import os
import sys

from turtletui.cli.errors import fail


def has_screen() -> bool:
    """A terminal on stdin and stdout, or a driver chosen through TEXTUAL_DRIVER."""
    if os.environ.get("TEXTUAL_DRIVER"):
        return True
    return sys.stdout.isatty() and sys.stdin.isatty()


def require_screen(instead: str) -> None:
    """Exit with a one-line error saying what to run ``instead`` when there is no screen."""
    if not has_screen():
        fail(f"no terminal to draw the app in; {instead}")
