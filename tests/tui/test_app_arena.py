"""The arena in the app, with Pilot: the open lesson's overlays, hit marks from
the live simulation, zoom, the side panel's width and --ascii on every widget."""

from __future__ import annotations

from support.pilot import pilot_test, wait_for
from textual.widgets import ContentSwitcher

from turtletui.plugins.bundled import lessons_dir
from turtletui.tui.app import SIDE_MIN, TurtleApp
from turtletui.tui.render import HIT_COLORS
from turtletui.tui.widgets.arena import ArenaView, Overlay
from turtletui.tui.widgets.splitter import Splitter

PART6 = lessons_dir() / "part6_closed_loop.md"
PART3 = lessons_dir() / "part3_first_node.md"


def screen_text(app: TurtleApp) -> str:
    return "\n".join(strip.text for strip in app.screen._compositor.render_strips())


@pilot_test
async def test_the_open_lessons_overlays_are_drawn_and_only_its_own() -> None:
    app = TurtleApp([], lesson=PART6)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        assert app.query_one(ArenaView).overlays == (Overlay(2.0, 2.0, 9.0, 9.0),)
    for lesson in (PART3, None):
        app = TurtleApp([], lesson=lesson)
        async with app.run_test(size=(80, 24)) as pilot:
            await pilot.pause()
            assert app.query_one(ArenaView).overlays == ()


@pilot_test
async def test_driving_into_the_wall_leaves_a_mark_in_the_arena() -> None:
    app = TurtleApp([])
    async with app.run_test(size=(120, 40)) as pilot:
        arena = app.query_one(ArenaView)

        def marked() -> bool:
            # The turtle pushing against the wall covers the mark in its cell:
            # the border beside it shows the hit too.
            turtle = app.session.sim.world.turtles["turtle1"]
            layout = arena.renderer.layout
            line = arena.renderer.lines[layout.top + layout.cell_of(turtle.x, turtle.y)[1]]
            return any(s.style is not None and s.style.color is not None and
                       tuple(s.style.color.triplet) == HIT_COLORS[0] for s in line)

        async def drive() -> bool:
            await pilot.press("up")  # 2 m/s east, for 1 s; the wall is 5.5 m away
            return marked()

        for _ in range(80):
            if await drive():
                break
            await pilot.pause(0.1)
        await wait_for(pilot, marked, timeout=60)
        turtle = app.session.sim.world.turtles["turtle1"]
        assert turtle.wall_hits >= 1
        [(x, y, level)] = app.session.hits.visible(app.session.sim.world.time)
        assert x > 11.0 and abs(y - turtle.y) < 0.01 and level == 0


@pilot_test
async def test_zoom_keys_and_the_side_panel_width() -> None:
    app = TurtleApp([])
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause()
        arena = app.query_one(ArenaView)
        await pilot.press("z")
        await pilot.press("z")
        await pilot.pause()
        assert arena.camera.zoom == 2.0 and arena.renderer.layout.window.span == 250
        await pilot.press("Z")
        await pilot.pause()
        assert arena.camera.zoom == 1.5
        await pilot.press("p")
        await pilot.pause()
        assert arena.mode == "braille"
        side = app.query_one(ContentSwitcher)
        width = side.outer_size.width
        await pilot.press("less_than_sign")
        await pilot.pause()
        assert side.outer_size.width == width + 4
        for _ in range(40):
            await pilot.press("greater_than_sign")
        await pilot.pause()
        assert side.outer_size.width == SIDE_MIN
        # Drag the splitter to column 60: the panel takes what is right of it.
        splitter = app.query_one(Splitter)
        await pilot.mouse_down(splitter)
        await pilot.hover(offset=(60, 10))
        await pilot.mouse_up(offset=(60, 10))
        await pilot.pause()
        assert side.outer_size.width == 120 - 60 - 1
        assert arena.size.width == 120 - side.outer_size.width - 1


@pilot_test
async def test_ascii_means_every_widget_is_ascii() -> None:
    app = TurtleApp([], lesson=PART6, ascii=True)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        seen = []
        for key in ("1", "2", "3", "4", "5"):
            await pilot.press(key)
            await pilot.pause(0.2)
            seen.append(screen_text(app))
        await pilot.press("colon")
        await pilot.pause()
        seen.append(screen_text(app))
        await pilot.press("escape")
        await pilot.press("ctrl+p")
        await pilot.pause(0.3)
        seen.append(screen_text(app))
        for text in seen:
            odd = {char for char in text if not char.isascii()}
            assert not odd, odd
        assert "|" in seen[0] and "+--" in seen[0]
    app = TurtleApp([], lesson=PART6)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.pause()
        assert any(not char.isascii() for char in screen_text(app))  # the filter is what made it ASCII


def test_a_replayed_run_marks_its_wall_hits(tmp_path) -> None:
    from turtletui.api import run
    from turtletui.runtime.replay import install_replay, read_recording
    from turtletui.tui.session import LiveSession

    controller = tmp_path / "into_the_wall.py"
    controller.write_text(
        "import rclpy\n"
        "from rclpy.node import Node\n"
        "from geometry_msgs.msg import Twist\n\n\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    node = Node('into_the_wall')\n"
        "    publisher = node.create_publisher(Twist, '/turtle1/cmd_vel', 10)\n"
        "    msg = Twist()\n"
        "    msg.linear.x = 5.0\n"
        "    node.create_timer(0.1, lambda: publisher.publish(msg))\n"
        "    rclpy.spin(node)\n"
    )
    record = tmp_path / "run.jsonl"
    result = run([controller], duration=3.0, record=record)
    assert result.wall_hits >= 1
    session = LiveSession()
    install_replay(session.sim, read_recording(record))
    with session.lock:
        session.sim.run_until(round(3.0 * 1e9))
        shown = session.hits.visible(session.sim.world.time)
    assert shown and all(x > 11.0 for x, _, _ in shown)
