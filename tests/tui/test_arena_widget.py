"""ArenaView, the Line API widget, mounted in a minimal app (run_test, snapshots)."""

from __future__ import annotations

import asyncio
import functools
import math

import pytest
from textual.app import App, ComposeResult
from textual.geometry import Region

from turtletui.sim import BACKGROUND, World
from turtletui.sim.canvas import to_pixel
from turtletui.tui.render import ASCII_HEADS, HEADS, TOO_SMALL, Overlay
from turtletui.tui.widgets.arena import ArenaView


class ArenaApp(App):
    """Nothing but the arena, filling the screen."""

    def __init__(self, world: World | None, *, ascii: bool = False, overlays=(), **options) -> None:
        super().__init__()
        self.world = world
        self.arena_options = {"ascii": ascii, "overlays": overlays, **options}

    def compose(self) -> ComposeResult:
        yield ArenaView(self.world, **self.arena_options)


def drawn_world() -> World:
    """A fixed state: turtle1 drove part of a circle, a second turtle stands still."""
    world = World()
    world.step()
    for _ in range(120):
        world.command_velocity("turtle1", 2.0, 0.0, 1.0)
        world.step()
    world.spawn(2.0, 9.0, 3 * math.pi / 4, "turtle2")
    return world


def pilot_test(scenario):
    """Run an async Pilot scenario as a plain test (no async plugin needed)."""

    @functools.wraps(scenario)
    def test(*args, **kwargs) -> None:
        asyncio.run(scenario(*args, **kwargs))

    return test


def shown(view: ArenaView) -> list[str]:
    return [view.render_line(y).text for y in range(view.size.height)]


@pytest.mark.parametrize("size", [(80, 24), (160, 50)])
@pilot_test
async def test_the_arena_renders_at_common_sizes(size):
    world = drawn_world()
    app = ArenaApp(world)
    async with app.run_test(size=size) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        assert tuple(view.size) == size
        lines = shown(view)
        assert len(lines) == size[1]
        text = "\n".join(lines)
        heading = HEADS[round(world.turtles["turtle1"].theta / (math.pi / 4)) % 8]
        assert heading in text and HEADS[3] in text
        assert "┌" in text and "┘" in text
        assert lines[-1].split() == [str(m) for m in range(12)]
        screenshot = app.export_screenshot()
        assert heading in screenshot and HEADS[3] in screenshot


@pilot_test
async def test_a_small_widget_shows_a_message_instead():
    app = ArenaApp(drawn_world())
    async with app.run_test(size=(20, 10)) as pilot:
        await pilot.pause()
        lines = shown(app.query_one(ArenaView))
        assert " ".join(" ".join(lines).split()) == TOO_SMALL
        assert not any(arrow in line for line in lines for arrow in HEADS)


@pilot_test
async def test_refresh_frame_repaints_only_the_changed_lines(monkeypatch):
    world = drawn_world()
    world.set_pen("turtle1", 0, 0, 0, 0, 1)
    app = ArenaApp(world)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        regions: list[Region] = []
        refresh = view.refresh

        def spy(*args, **kwargs):
            regions.extend(args)
            return refresh(*args, **kwargs)

        monkeypatch.setattr(view, "refresh", spy)
        assert view.refresh_frame() == 0
        assert regions == []
        top = view.renderer.layout.top
        before = set(view.renderer.marks.items())
        world.teleport_absolute("turtle1", 9.0, 2.0, 0.0)
        world.step()
        changed = view.refresh_frame()
        moved = {top + line for (line, _), _ in before ^ set(view.renderer.marks.items())}
        # turtle1's and its name's lines, before and after, and nothing else.
        assert 4 <= changed == len(moved) and view.renderer.changed_lines == sorted(moved)
        assert sum(region.height for region in regions) == changed
        assert all(region.width == 80 for region in regions)
        await pilot.pause()
        layout = view.renderer.layout
        col, line = layout.cell_of(9.0, 2.0)
        assert view.render_line(layout.top + line).text[layout.left + col + 1] == HEADS[0]


@pilot_test
async def test_a_resize_redraws_at_the_new_size():
    app = ArenaApp(drawn_world())
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        assert view.renderer.layout.size == 42
        await pilot.resize_terminal(160, 50)
        await pilot.pause()
        assert tuple(view.size) == (160, 50)
        lines = shown(view)
        assert view.renderer.layout.size == 94
        assert all(len(line) == 160 for line in lines)
        await pilot.resize_terminal(30, 8)
        await pilot.pause()
        assert " ".join(" ".join(shown(view)).split()) == TOO_SMALL


@pilot_test
async def test_ascii_and_overlays_can_be_switched_at_run_time():
    app = ArenaApp(drawn_world())
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        view.ascii = True
        await pilot.pause()
        lines = shown(view)
        assert all(line.isascii() for line in lines)
        assert any(glyph in line for line in lines for glyph in ASCII_HEADS)
        assert not any("." in line for line in lines)
        view.overlays = [(2.0, 2.0, 9.0, 9.0)]
        await pilot.pause()
        assert view.overlays == (Overlay(2.0, 2.0, 9.0, 9.0),)
        assert any("." in line for line in shown(view))


@pilot_test
async def test_without_a_world_the_view_is_blank_until_one_is_given():
    app = ArenaApp(None)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        assert all(not line.strip() for line in shown(view))
        assert view.refresh_frame() == 0
        view.world = drawn_world()
        await pilot.pause()
        assert any(HEADS[3] in line for line in shown(view))


@pilot_test
async def test_strips_come_from_the_cache():
    app = ArenaApp(drawn_world())
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        assert view.render_line(5) is view.render_line(5)
        assert view.render_line(0).cell_length == 80


@pytest.mark.parametrize("size", [(80, 24), (160, 50)], ids=["80x24", "wide"])
def test_snapshot_colour(snap_compare, size):
    assert snap_compare(ArenaApp(drawn_world(), overlays=[(2.0, 2.0, 9.0, 9.0)]), terminal_size=size)


@pytest.mark.parametrize("size", [(80, 24), (160, 50)], ids=["80x24", "wide"])
def test_snapshot_ascii(snap_compare, size):
    app = ArenaApp(drawn_world(), ascii=True, overlays=[(2.0, 2.0, 9.0, 9.0)])
    assert snap_compare(app, terminal_size=size)


@pytest.mark.parametrize("size", [(80, 24)], ids=["80x24"])
def test_snapshot_braille(snap_compare, size):
    assert snap_compare(ArenaApp(drawn_world(), mode="braille", overlays=[(2.0, 2.0, 9.0, 9.0)]), terminal_size=size)


@pilot_test
async def test_braille_shows_finer_trails_than_half_blocks():
    world = drawn_world()
    app = ArenaApp(world)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        assert not any(0x2800 < ord(char) <= 0x28FF for line in shown(view) for char in line)
        view.mode = "braille"
        await pilot.pause()
        lines = shown(view)
        assert view.renderer.layout.pixels == 2 * view.renderer.layout.size
        assert any(0x2800 < ord(char) <= 0x28FF for line in lines for char in line)
        with pytest.raises(ValueError, match="pixel mode"):
            view.mode = "sixels"


@pilot_test
async def test_zoom_follows_the_turtle_and_the_wheel_zooms():
    world = drawn_world()
    app = ArenaApp(world)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        assert view.renderer.layout.window.span == 500
        await pilot.scroll_up(view) if hasattr(pilot, "scroll_up") else view.zoom_in()
        await pilot.pause()
        view.zoom_in()
        await pilot.pause()
        window = view.renderer.layout.window
        assert window.span < 500
        turtle = world.turtles["turtle1"]
        col, row = to_pixel(turtle.x, turtle.y)
        assert window.col <= col < window.col + window.span and window.row <= row < window.row + window.span
        assert any(glyph in line for line in shown(view) for glyph in HEADS)
        # The scale shows the window's metres only.
        labels = [int(label) for label in shown(view)[-1].split()]
        assert labels and all(window.col <= m * 45 < window.col + window.span + 45 for m in labels)
        assert view.follow_next() == "turtle2"
        await pilot.pause()
        view.zoom_out()
        view.zoom_out()
        view.zoom_out()
        await pilot.pause()
        assert view.renderer.layout.window.span == 500


@pilot_test
async def test_in_a_graphics_terminal_the_picture_covers_the_arena():
    from textual_image.widget import TGPImage

    world = drawn_world()
    app = ArenaApp(world, graphics="kitty")
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        view = app.query_one(ArenaView)
        view.refresh_frame()
        await pilot.pause()
        picture = view.query_one("#arena-picture", TGPImage)
        layout = view.renderer.layout
        assert picture.display and picture.image.size == (500, 500)
        assert picture.region.x == layout.left and picture.region.y == layout.top
        assert (picture.region.width, picture.region.height) == (layout.size, layout.rows)
        assert picture.image.getpixel(to_pixel(0.5, 0.5)) == BACKGROUND
        # p cycles half blocks, braille, the picture; ASCII never shows it.
        assert view.cycle_drawing() == "half" and not picture.display
        assert view.cycle_drawing() == "braille"
        assert view.cycle_drawing() == "picture" and picture.display
        view.ascii = True
        await pilot.pause()
        assert not picture.display
