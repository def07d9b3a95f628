"""What the terminal can show, decided before the app takes it over: the
arena's pixel mode (half blocks or braille) and whether it can show the real
turtlesim picture through a graphics protocol (Kitty's, or Sixel: iTerm2,
WezTerm, foot, mlterm, Konsole, xterm -ti vt340). No Textual.

Asking a terminal about graphics means writing a query and waiting for an
answer that a terminal without graphics never sends (textual-image waits
0.1 s), so it is asked only when the environment names a terminal known to
have them, or when ``--pixels graphics`` says so. Terminal multiplexers
(tmux, screen) do not pass images through: there the answer is no.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from typing import NamedTuple

from turtletui.errors import TurtletuiError

PIXEL_CHOICES = ("auto", "half", "braille", "graphics")
"""Values of ``turtletui run --pixels``."""

GRAPHICS_TERMINALS = ("xterm-kitty", "xterm-ghostty", "foot", "foot-extra", "mlterm", "contour", "wezterm")
"""TERM values of terminals with a graphics protocol."""
GRAPHICS_PROGRAMS = ("WezTerm", "iTerm.app", "ghostty", "mlterm", "konsole")
"""TERM_PROGRAM values of terminals with a graphics protocol."""
BRAILLE_TERMINALS = ("xterm-kitty", "xterm-ghostty", "foot", "foot-extra", "wezterm")
BRAILLE_PROGRAMS = ("WezTerm", "ghostty")
"""Terminals that draw braille cells themselves, whatever the font."""


class TerminalError(TurtletuiError, ValueError):
    """A drawing option that does not exist."""


class Drawing(NamedTuple):
    """How the app draws the arena."""

    pixels: str
    """"half" or "braille" (turtletui.tui.cells)."""
    graphics: str | None
    """"kitty" or "sixel" to show the picture through that protocol; None: text cells."""


def multiplexed(env: Mapping[str, str]) -> bool:
    """Inside tmux or screen (which do not pass graphics through)."""
    term = env.get("TERM", "")
    return bool(env.get("TMUX") or env.get("STY")) or term.startswith(("screen", "tmux"))


def _names(env: Mapping[str, str], terms, programs, variables) -> bool:
    """Whether the environment names one of these terminals (never through tmux or screen)."""
    if multiplexed(env):
        return False
    return (
        env.get("TERM", "") in terms
        or env.get("TERM_PROGRAM", "") in programs
        or any(name in env for name in variables)
    )


def may_have_graphics(env: Mapping[str, str]) -> bool:
    """Whether the environment names a terminal with a graphics protocol."""
    return _names(env, GRAPHICS_TERMINALS, GRAPHICS_PROGRAMS, ("KITTY_WINDOW_ID", "WEZTERM_PANE", "KONSOLE_VERSION"))


def draws_braille(env: Mapping[str, str]) -> bool:
    """Whether the terminal draws braille itself (so no font can lack it)."""
    return _names(env, BRAILLE_TERMINALS, BRAILLE_PROGRAMS, ("KITTY_WINDOW_ID",))


def probe_graphics() -> str | None:
    """Ask the terminal which graphics protocol it speaks (through textual-image,
    which queries it when imported): "sixel", "kitty" or None."""
    import sys

    if not (sys.__stdout__ and sys.__stdout__.isatty() and sys.__stdin__ and sys.__stdin__.isatty()):
        return None
    try:
        from textual_image import renderable
    except ImportError:
        return None
    found = {renderable.SixelImage: "sixel", renderable.TGPImage: "kitty"}.get(renderable.Image)
    if found is not None:
        # Its widgets ask the terminal for the size of a cell in pixels when
        # imported, which works only before the app reads the terminal's input.
        import textual_image.widget  # noqa: F401
    return found


def served(env: Mapping[str, str]) -> bool:
    """Whether the app draws through a Textual driver of its own (textual-serve's
    web driver: a browser's xterm.js), not in the terminal TERM names."""
    return bool(env.get("TEXTUAL_DRIVER"))


def choose_drawing(
    option: str = "auto",
    *,
    ascii: bool = False,
    env: Mapping[str, str] | None = None,
    probe: Callable[[], str | None] = probe_graphics,
) -> Drawing:
    """The drawing for ``--pixels option``: ``half`` and ``braille`` as named;
    ``graphics`` the picture if the terminal answers (else the best text
    mode); ``auto`` the picture where the environment names a graphics
    terminal that answers, braille where the terminal draws braille itself,
    half blocks elsewhere. ``--ascii`` is always text. In a browser
    (``served``) ``auto`` and ``graphics`` are half blocks, which xterm.js
    draws itself; braille there depends on the browser's fonts."""
    if option not in PIXEL_CHOICES:
        raise TerminalError(f"expected one of {', '.join(PIXEL_CHOICES)}, got {option!r}")
    env = os.environ if env is None else env
    if ascii:
        return Drawing("half", None)
    if option in ("half", "braille"):
        return Drawing(option, None)
    if served(env):
        return Drawing("half", None)  # TERM is the server's terminal, not the browser's
    pixels = "braille" if draws_braille(env) else "half"
    wanted = option == "graphics" or may_have_graphics(env)
    return Drawing(pixels, probe() if wanted and not multiplexed(env) else None)
