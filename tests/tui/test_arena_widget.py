"""ArenaView, the Line API widget, mounted in a minimal app (run_test, snapshots)."""

from __future__ import annotations

import asyncio
import functools
import math

import pytest
from textual.app import App, ComposeResult
from textual.geometry import Region

from turtletui.sim import World
from turtletui.tui.render import ARROWS, ASCII_ARROWS, TOO_SMALL, Overlay
from turtletui.tui.widgets.arena import ArenaView


class ArenaApp(App):
    """Nothing but the arena, filling the screen."""

    def __init__(self, world: World | None, *, ascii: bool = False, overlays=()) -> None:
        super().__init__()
        self.world = world
        self.arena_options = {"ascii": ascii, "overlays": overlays}

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
        heading = ARROWS[round(world.turtles["turtle1"].theta / (math.pi / 4)) % 8]
        assert heading in text and "↖" in text
        assert "┌" in text and "┘" in text
        assert lines[-1].split() == [str(m) for m in range(12)]
        screenshot = app.export_screenshot()
        assert heading in screenshot and "↖" in screenshot


@pilot_test
async def test_a_small_widget_shows_a_message_instead():
    app = ArenaApp(drawn_world())
    async with app.run_test(size=(20, 10)) as pilot:
        await pilot.pause()
        lines = shown(app.query_one(ArenaView))
        assert " ".join(" ".join(lines).split()) == TOO_SMALL
        assert not any(arrow in line for line in lines for arrow in ARROWS)


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
        world.teleport_absolute("turtle1", 9.0, 2.0, 0.0)
        world.step()
        assert view.refresh_frame() == 2
        assert len(regions) == 2
        assert all(region.height == 1 and region.width == 80 for region in regions)
        await pilot.pause()
        layout = view.renderer.layout
        col, row = layout.cell_of(9.0, 2.0)
        assert view.render_line(layout.top + row // 2).text[layout.left + col] == "→"


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
        assert any(glyph in line for line in lines for glyph in ASCII_ARROWS)
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
        assert any("↖" in line for line in shown(view))


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
