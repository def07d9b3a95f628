"""Obstacles in the app: drawn by the renderer, and the world the live session runs."""

from __future__ import annotations

import asyncio
import textwrap

import pytest
from rich.segment import Segment

from turtletui.sim import BACKGROUND, Box, Circle, World
from turtletui.tui.app import TurtleApp
from turtletui.tui.render import OBSTACLE_COLOR, ArenaRenderer
from turtletui.tui.session import LiveSession
from turtletui.worlds import WorldSpec

BOX = Box(1.0, 1.0, 4.0, 3.0)
"""Bottom left: arena x 1..4 m, y 1..3 m."""
DOT = Circle(9.0, 9.0, 0.2)
"""Smaller than a cell of a small arena."""


def colours(line: list[Segment]) -> set[tuple[int, int, int]]:
    shown = set()
    for segment in line:
        if segment.style is None:
            continue
        for colour in (segment.style.color, segment.style.bgcolor):
            if colour is not None:
                shown.add(colour.triplet)
    return shown


def arena_rows(renderer: ArenaRenderer, lines: list) -> list:
    layout = renderer.layout
    return lines[layout.top : layout.top + layout.rows]


def test_obstacles_are_filled_in_their_own_colour():
    renderer = ArenaRenderer()
    plain = arena_rows(renderer, renderer.frame(World(spawn_turtle1=False), 80, 30))
    assert not any(OBSTACLE_COLOR in colours(line) for line in plain)
    world = World(spawn_turtle1=False, obstacles=[BOX, DOT])
    rows = arena_rows(renderer, renderer.frame(world, 80, 30))
    with_obstacle = [i for i, line in enumerate(rows) if OBSTACLE_COLOR in colours(line)]
    layout = renderer.layout
    top_box = layout.pixel_of(2.5, 2.9)[1] // 2
    bottom_box = layout.pixel_of(2.5, 1.1)[1] // 2
    dot = layout.pixel_of(9.0, 9.0)[1] // 2
    box_lines = [i for i in with_obstacle if i > dot + 1]
    assert box_lines == list(range(top_box, bottom_box + 1))
    assert dot in with_obstacle and len(with_obstacle) - len(box_lines) <= 2  # 0.4 m: 2 pixels at most
    assert all(BACKGROUND in colours(line) for line in rows)


def test_obstacles_are_xs_in_ascii_apart_from_trails():
    renderer = ArenaRenderer()
    world = World(spawn_turtle1=False, obstacles=[BOX])
    lines = renderer.frame(world, 80, 30, ascii=True)
    layout = renderer.layout
    col0, row = layout.pixel_of(1.05, 2.0)
    col1, _ = layout.pixel_of(3.95, 2.0)
    text = "".join(segment.text for segment in lines[layout.top + row // 2])
    start = layout.left
    assert set(text[start + col0 : start + col1 + 1]) == {"X"}
    assert text[start + col1 + 2] == " " and text[start + col0 - 2] == " "
    empty = renderer.frame(World(spawn_turtle1=False), 80, 30, ascii=True)
    assert "X" not in "".join(segment.text for line in empty for segment in line)


def test_the_live_session_runs_in_the_world_it_is_given():
    spec = WorldSpec("boxed", obstacles=[BOX])
    session = LiveSession(world=spec, seed=4)
    try:
        world = session.sim.world
        assert world.obstacles == (BOX,) and world.seed == 4
        assert "turtle1" in world.turtles
    finally:
        session.close()
    plain = LiveSession()
    try:
        assert plain.sim.world.obstacles == ()
    finally:
        plain.close()


@pytest.mark.parametrize("world", ["lidar-course", "moon"])
def test_the_app_runs_the_lessons_world(tmp_path, monkeypatch, world):
    monkeypatch.setenv("TURTLETUI_DISABLE_PLUGIN_AUTOLOAD", "1")
    lesson = tmp_path / "lesson.md"
    lesson.write_text(
        textwrap.dedent(
            f"""\
            +++
            id = "roam"
            title = "Roam"
            world = "{world}"
            +++
            # Roam
            """
        ),
        encoding="utf-8",
    )

    async def scenario() -> None:
        app = TurtleApp(lesson=lesson)
        async with app.run_test(size=(100, 36)) as pilot:
            await pilot.pause(0.05)
            sim = app.session.sim
            if world == "moon":
                assert sim.world.obstacles == ()
                assert any("unknown world 'moon'" in record.msg for record in app.session.logs)
            else:
                assert len(sim.world.obstacles) > 4 and "/turtle1/scan" in sim.graph.topics

    asyncio.run(scenario())


def test_zoomed_in_an_obstacle_covers_more_cells_and_stays_where_it_is():
    from turtletui.tui.render import Camera

    world = World(obstacles=[BOX])
    world.teleport_absolute("turtle1", 2.5, 4.0, 0.0)  # the view follows turtle1, next to the box
    world.step()
    world.step()
    renderer = ArenaRenderer()

    def obstacle_cells(lines) -> int:
        return sum(
            1
            for line in arena_rows(renderer, lines)
            for segment in line
            if segment.style is not None and segment.style.bgcolor is not None
            and tuple(segment.style.bgcolor.triplet) == OBSTACLE_COLOR
            for _ in segment.text
        )

    whole = obstacle_cells(renderer.frame(world, 80, 24))
    camera = Camera()
    camera.zoom_in()
    camera.zoom_in()  # x2
    lines = renderer.frame(world, 80, 24, camera=camera)
    window = renderer.layout.window
    assert window.span == 250
    assert obstacle_cells(lines) >= 3 * whole  # twice as wide and twice as tall, less what is cut off
    # The box's corner (1, 3) is where the zoomed layout puts it.
    col, line = renderer.layout.cell_of(1.5, 2.5)
    assert 0 <= col < renderer.layout.size and 0 <= line < renderer.layout.rows
    assert OBSTACLE_COLOR in colours(lines[renderer.layout.top + line])
