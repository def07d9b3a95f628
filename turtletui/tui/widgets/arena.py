"""The turtlesim window as a Textual Line API widget.

``ArenaView`` holds the World (a plain model object, never a reactive: it
carries numpy arrays) and an ``ArenaRenderer`` that turns it into lines. The
app steps the simulation and then calls ``refresh_frame()``, which renders a
new frame and repaints only the lines that changed; ``render_line`` serves
strips from an LRU cache keyed on each line's content.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable, Sequence
from contextlib import AbstractContextManager, nullcontext

from rich.style import Style
from textual.cache import LRUCache
from textual.events import Resize
from textual.geometry import Region
from textual.reactive import reactive
from textual.strip import Strip
from textual.widget import Widget

from turtletui.sim import World
from turtletui.tui.render import (
    MIN_HEIGHT,
    MIN_WIDTH,
    TOO_SMALL,
    ArenaRenderer,
    Overlay,
    normalise_overlays,
)

__all__ = ["MIN_HEIGHT", "MIN_WIDTH", "TOO_SMALL", "ArenaView", "Overlay"]


class ArenaView(Widget):
    """The arena: pen image in half-block pixels, turtles as arrows, a metre scale.

    Below ``MIN_WIDTH`` x ``MIN_HEIGHT`` cells it shows ``TOO_SMALL`` instead;
    without a world (``None``, e.g. until the app has built its session) it is
    blank. Focusable, so the app can park the focus here while keys drive the
    turtle.
    """

    can_focus = True

    DEFAULT_CSS = """
    ArenaView {
        width: 1fr;
        height: 1fr;
    }
    """

    ascii: reactive[bool] = reactive(False)
    """Plain ASCII, no colour: '#' trail, '.' overlay, '>' '^' '<' 'v' '/' '\\' turtles."""

    overlays: reactive[tuple[Overlay, ...]] = reactive(())
    """Rectangles in metres drawn as dotted outlines under the turtles.

    Assign Overlay objects or (x0, y0, x1, y1[, (r, g, b)]) tuples.
    """

    def __init__(
        self,
        world: World | None,
        *,
        ascii: bool = False,
        overlays: Iterable[Overlay | Sequence] = (),
        name: str | None = None,
        id: str | None = None,
        classes: str | None = None,
    ) -> None:
        super().__init__(name=name, id=id, classes=classes)
        self._world = world
        self.lock: AbstractContextManager = nullcontext()
        """Held while the world is read: the app's ticker thread changes it."""
        self.renderer = ArenaRenderer()
        """Renders the world; its ``lines`` are what this widget shows."""
        self._strips: LRUCache[tuple[Hashable, Style, int], Strip] = LRUCache(1024)
        self.set_reactive(ArenaView.ascii, ascii)
        self.set_reactive(ArenaView.overlays, normalise_overlays(overlays))

    @property
    def world(self) -> World | None:
        """The World shown; assigning another one redraws everything."""
        return self._world

    @world.setter
    def world(self, world: World | None) -> None:
        self._world = world
        self._redraw()

    def validate_overlays(self, overlays: Iterable[Overlay | Sequence]) -> tuple[Overlay, ...]:
        return normalise_overlays(overlays)

    def watch_ascii(self) -> None:
        self._redraw()

    def watch_overlays(self) -> None:
        self._redraw()

    def on_resize(self, event: Resize) -> None:
        self._redraw()

    def refresh_frame(self) -> int:
        """Render the world as it is now and repaint the lines that changed.

        Call after simulation steps. Returns how many lines were repainted
        (0 when nothing visible changed, which costs a few microseconds).
        """
        if not self.is_mounted or self._world is None:
            return 0
        width, height = self.size
        self._render_frame()
        changed = self.renderer.changed_lines
        for start, stop in _runs(changed):
            self.refresh(Region(0, start, width, stop - start))
        return len(changed)

    def render_line(self, y: int) -> Strip:
        renderer = self.renderer
        width, height = self.size
        if self._world is None:
            return Strip.blank(width, self.rich_style)
        if renderer.size != (width, height):
            # First paint at this size: on_resize may not have run yet.
            self._render_frame()
        if not 0 <= y < len(renderer.lines):
            return Strip.blank(width, self.rich_style)
        base = self.rich_style
        key = (renderer.line_keys[y], base, width)
        strip = self._strips.get(key)
        if strip is None:
            strip = Strip(renderer.lines[y], width).apply_style(base)
            self._strips[key] = strip
        return strip

    def _render_frame(self) -> None:
        if self._world is None:
            return
        width, height = self.size
        with self.lock:
            self.renderer.frame(self._world, width, height, ascii=self.ascii, overlays=self.overlays)

    def _redraw(self) -> None:
        if self.is_mounted:
            self._render_frame()
            self.refresh()


def _runs(lines: list[int]) -> list[tuple[int, int]]:
    """Sorted line numbers as (start, stop) runs of consecutive lines."""
    runs: list[tuple[int, int]] = []
    for line in lines:
        if runs and runs[-1][1] == line:
            runs[-1] = (runs[-1][0], line + 1)
        else:
            runs.append((line, line + 1))
    return runs
