"""The turtlesim window as a Textual Line API widget.

``ArenaView`` holds the World (a plain model object, never a reactive: it
carries numpy arrays) and an ``ArenaRenderer`` that turns it into lines. The
app steps the simulation and then calls ``refresh_frame()``, which renders a
new frame and repaints only the lines that changed; ``render_line`` serves
strips from an LRU cache keyed on each line's content.
"""

from __future__ import annotations

import time
from collections.abc import Hashable, Iterable, Sequence
from contextlib import AbstractContextManager, nullcontext

from rich.style import Style
from textual import events
from textual.app import ComposeResult
from textual.cache import LRUCache
from textual.geometry import Region
from textual.reactive import reactive
from textual.strip import Strip
from textual.widget import Widget

from turtletui.sim import World
from turtletui.tui.cells import MODES
from turtletui.tui.marks import HitMarks
from turtletui.tui.picture import arena_picture
from turtletui.tui.render import (
    MIN_HEIGHT,
    MIN_WIDTH,
    ROWS_KEPT,
    TOO_SMALL,
    ArenaRenderer,
    Camera,
    Overlay,
    normalise_overlays,
)

PICTURE_SECONDS = 0.2
"""The picture (graphics protocol) is sent at most 5 times a second."""

__all__ = ["MIN_HEIGHT", "MIN_WIDTH", "MODES", "TOO_SMALL", "ArenaView", "Overlay"]


class ArenaView(Widget):
    """The arena: pen image in true-colour cells, turtles as named two-cell
    tiles, hit marks, a metre scale; zoom follows a turtle.

    Below ``MIN_WIDTH`` x ``MIN_HEIGHT`` cells it shows ``TOO_SMALL`` instead;
    without a world (``None``, e.g. until the app has built its session) it is
    blank. Focusable, so the app can park the focus here while keys drive the
    turtle. The mouse wheel over it zooms.
    """

    can_focus = True

    DEFAULT_CSS = """
    ArenaView {
        width: 1fr;
        height: 1fr;
    }
    """

    ascii: reactive[bool] = reactive(False)
    """Plain ASCII, no colour: a character per pen colour ('#' turtlesim's own),
    'X' obstacles, '.' overlays, '@' and '>' '^' '<' 'v' '/' '\\' turtles, '!' hits."""

    mode: reactive[str] = reactive("half")
    """Pixel mode of the colour drawing: "half" (half blocks) or "braille"
    (2 x 4 dots a cell, finer trails where the font has braille)."""

    overlays: reactive[tuple[Overlay, ...]] = reactive(())
    """Rectangles in metres drawn as dotted outlines under the turtles.

    Assign Overlay objects or (x0, y0, x1, y1[, (r, g, b)]) tuples.
    """

    def __init__(
        self,
        world: World | None,
        *,
        ascii: bool = False,
        mode: str = "half",
        overlays: Iterable[Overlay | Sequence] = (),
        hits: HitMarks | None = None,
        graphics: str | None = None,
        name: str | None = None,
        id: str | None = None,
        classes: str | None = None,
    ) -> None:
        super().__init__(name=name, id=id, classes=classes)
        self._world = world
        self.lock: AbstractContextManager = nullcontext()
        """Held while the world is read: the app's ticker thread changes it."""
        self.hits = hits
        """Wall and obstacle hits to mark (the session's); None: none shown."""
        self.camera = Camera()
        """Zoom level and the turtle the zoomed view follows."""
        self.renderer = ArenaRenderer()
        """Renders the world; its ``lines`` are what this widget shows."""
        self._strips: LRUCache[tuple[Hashable, Style, int], Strip] = LRUCache(ROWS_KEPT)
        self.graphics = graphics
        """The terminal's graphics protocol ("kitty", "sixel") or None: with one,
        ``picture`` shows turtlesim's real picture over the arena's cells."""
        self.picture = graphics is not None
        """Whether the picture is shown (a graphics protocol and not ASCII)."""
        self._picture_stale = True
        """Whether the frame changed since the picture was last sent."""
        self._picture_at = float("-inf")
        self.set_reactive(ArenaView.ascii, ascii)
        self.set_reactive(ArenaView.mode, self.validate_mode(mode))
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

    def validate_mode(self, mode: str) -> str:
        if mode not in MODES:
            raise ValueError(f"pixel mode must be one of {', '.join(MODES)}, got {mode!r}")
        return mode

    def watch_ascii(self) -> None:
        self._redraw()

    def watch_mode(self) -> None:
        self._redraw()

    def watch_overlays(self) -> None:
        self._redraw()

    def on_resize(self, event: events.Resize) -> None:
        self._redraw()

    def compose(self) -> ComposeResult:
        if self.graphics is not None:
            from textual_image.widget import SixelImage, TGPImage

            image_class = SixelImage if self.graphics == "sixel" else TGPImage
            yield image_class(id="arena-picture")

    def cycle_drawing(self) -> str:
        """Half blocks, braille, then the picture (with a graphics protocol);
        returns the drawing now shown."""
        choices = [*MODES, *(["picture"] if self.graphics is not None else [])]
        current = "picture" if self.picture else self.mode
        chosen = choices[(choices.index(current) + 1) % len(choices)]
        self.picture = chosen == "picture"
        if not self.picture:
            self.mode = chosen
        self._redraw()
        return chosen

    # -- zoom ------------------------------------------------------------------------
    def zoom_in(self) -> float:
        """Zoom in one step (the view follows the turtle); returns the zoom."""
        zoom = self.camera.zoom_in()
        self._redraw()
        return zoom

    def zoom_out(self) -> float:
        zoom = self.camera.zoom_out()
        self._redraw()
        return zoom

    def follow_next(self) -> str | None:
        """Follow the next turtle when zoomed; returns its name."""
        if self._world is None:
            return None
        with self.lock:
            name = self.camera.follow_next(self._world)
        self._redraw()
        return name

    def on_mouse_scroll_up(self, event: events.MouseScrollUp) -> None:
        event.stop()
        self.zoom_in()

    def on_mouse_scroll_down(self, event: events.MouseScrollDown) -> None:
        event.stop()
        self.zoom_out()

    # -- drawing -------------------------------------------------------------------
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
        if self.graphics is not None:
            self._show_picture()
        return len(changed)

    def _show_picture(self, now: float | None = None) -> None:
        """Send the picture again if the frame changed, at most every PICTURE_SECONDS
        (each one is a new image for the terminal to receive and scale)."""
        image = self.query_one("#arena-picture")
        layout = self.renderer.layout
        shown = self.picture and not self.ascii and layout is not None
        image.display = shown
        if not shown:
            return
        now = time.monotonic() if now is None else now
        self._picture_stale |= bool(self.renderer.changed_lines)
        if not self._picture_stale or now - self._picture_at < PICTURE_SECONDS:
            return
        self._picture_stale, self._picture_at = False, now
        from PIL import Image

        with self.lock:
            picture = arena_picture(
                self._world,
                overlays=self.overlays,
                hits=self.hits.visible(self._world.time) if self.hits is not None else (),
                window=layout.window,
            )
        image.styles.offset = (layout.left, layout.top)
        image.styles.width = layout.size
        image.styles.height = layout.rows
        image.image = Image.fromarray(picture, "RGB")

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
        world = self._world
        if world is None:
            return
        width, height = self.size
        with self.lock:
            hits = self.hits.visible(world.time) if self.hits is not None else ()
            self.renderer.frame(
                world,
                width,
                height,
                ascii=self.ascii,
                overlays=self.overlays,
                mode=self.mode,
                camera=self.camera,
                hits=hits,
            )

    def _redraw(self) -> None:
        if self.is_mounted:
            self._render_frame()
            self.refresh()
            if self.graphics is not None:
                self._picture_stale, self._picture_at = True, float("-inf")
                self._show_picture()


def _runs(lines: list[int]) -> list[tuple[int, int]]:
    """Sorted line numbers as (start, stop) runs of consecutive lines."""
    runs: list[tuple[int, int]] = []
    for line in lines:
        if runs and runs[-1][1] == line:
            runs[-1] = (runs[-1][0], line + 1)
        else:
            runs.append((line, line + 1))
    return runs
