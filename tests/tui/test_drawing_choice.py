"""How the arena is drawn in a given terminal (turtletui.tui.terminal) and the
real picture for graphics terminals (turtletui.tui.picture): no Textual."""

from __future__ import annotations

import io
import math

import numpy as np
import pytest
from PIL import Image

from turtletui.sim import BACKGROUND, PEN_COLOR, World
from turtletui.sim.canvas import to_pixel
from turtletui.tui.marks import turtle_color
from turtletui.tui.picture import arena_picture, png_bytes
from turtletui.tui.render import OBSTACLE_COLOR, OVERLAY_COLOR, Window
from turtletui.tui.terminal import Drawing, TerminalError, choose_drawing


def never(*args):
    raise AssertionError("the terminal must not be asked")


@pytest.mark.parametrize(
    ("env", "answer", "expected"),
    [
        ({"TERM": "xterm-kitty", "KITTY_WINDOW_ID": "1"}, "kitty", Drawing("braille", "kitty")),
        ({"TERM": "xterm-256color", "TERM_PROGRAM": "WezTerm"}, "sixel", Drawing("braille", "sixel")),
        ({"TERM": "xterm-256color", "TERM_PROGRAM": "iTerm.app"}, "sixel", Drawing("half", "sixel")),
        ({"TERM": "foot"}, None, Drawing("braille", None)),  # named, but it did not answer
    ],
)
def test_auto_asks_terminals_known_for_graphics(env, answer, expected):
    asked = []
    drawing = choose_drawing("auto", env=env, probe=lambda: asked.append(1) or answer)
    assert drawing == expected and asked == [1]


@pytest.mark.parametrize(
    "env",
    [
        {"TERM": "xterm-256color"},
        {"TERM": "linux"},
        {"TERM": "screen-256color", "KITTY_WINDOW_ID": "1"},  # screen inside kitty
        {"TERM": "xterm-kitty", "TMUX": "/tmp/tmux-0/default,1,0"},
    ],
)
def test_auto_never_asks_plain_terminals_or_multiplexers(env):
    assert choose_drawing("auto", env=env, probe=never) == Drawing("half", None)


def test_named_modes_and_ascii_never_ask():
    kitty = {"TERM": "xterm-kitty"}
    assert choose_drawing("half", env=kitty, probe=never) == Drawing("half", None)
    assert choose_drawing("braille", env={}, probe=never) == Drawing("braille", None)
    assert choose_drawing("auto", ascii=True, env=kitty, probe=never) == Drawing("half", None)
    assert choose_drawing("graphics", ascii=True, env=kitty, probe=never) == Drawing("half", None)


def test_graphics_asks_any_terminal_but_not_through_tmux():
    assert choose_drawing("graphics", env={"TERM": "xterm"}, probe=lambda: "sixel") == Drawing("half", "sixel")
    assert choose_drawing("graphics", env={"TERM": "xterm"}, probe=lambda: None) == Drawing("half", None)
    assert choose_drawing("graphics", env={"TERM": "tmux-256color"}, probe=never) == Drawing("half", None)


def test_in_a_browser_auto_is_half_blocks_whatever_terminal_the_server_runs_in():
    """turtletui serve started in kitty: TERM is kitty's, the app draws in xterm.js."""
    web = {"TERM": "xterm-kitty", "KITTY_WINDOW_ID": "1", "TEXTUAL_DRIVER": "textual.drivers.web_driver:WebDriver"}
    assert choose_drawing("auto", env=web, probe=never) == Drawing("half", None)
    assert choose_drawing("graphics", env=web, probe=never) == Drawing("half", None)
    assert choose_drawing("braille", env=web, probe=never) == Drawing("braille", None)


def test_an_unknown_choice_is_one_clear_error():
    with pytest.raises(TerminalError, match="expected one of auto, half, braille, graphics, got 'sixels'"):
        choose_drawing("sixels", env={})


# -- the picture ---------------------------------------------------------------------------
def drawn_world() -> World:
    world = World()
    world.step()
    for _ in range(150):
        world.command_velocity("turtle1", 2.0, 0.0, 0.8)
        world.step()
    world.set_pen("turtle1", 255, 0, 0, 5, 0)
    for _ in range(60):
        world.command_velocity("turtle1", 2.0, 0.0, 0.0)
        world.step()
    world.spawn(2.0, 2.0, math.pi / 2, "turtle2")
    return world


def decoded(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))


def test_the_png_is_the_pen_raster_where_no_turtle_is():
    world = drawn_world()
    picture = decoded(png_bytes(arena_picture(world)))
    assert picture.shape == (500, 500, 3)
    pen = np.asarray(world.canvas.pixels)
    away = np.ones((500, 500), dtype=bool)
    for turtle in world.turtles.values():
        col, row = to_pixel(turtle.x, turtle.y)
        away[max(row - 25, 0) : row + 26, max(col - 25, 0) : col + 26] = False
    assert np.array_equal(picture[away], pen[away])
    # The trail is really there, in both pen colours.
    colours = {tuple(c) for c in picture[away].reshape(-1, 3)}
    assert {BACKGROUND, PEN_COLOR, (255, 0, 0)} <= colours


def test_each_turtle_is_a_sprite_in_its_colour_facing_its_heading():
    world = drawn_world()
    picture = arena_picture(world)
    for name, turtle in world.turtles.items():
        col, row = to_pixel(turtle.x, turtle.y)
        assert tuple(picture[row, col]) == turtle_color(name)  # the shell's centre
        # The head is ahead of the shell: 17 px along the heading, dark skin, not the floor.
        head_col = round(col + 17 * math.cos(turtle.theta))
        head_row = round(row - 17 * math.sin(turtle.theta))
        assert tuple(picture[head_row, head_col]) == tuple(c // 3 for c in turtle_color(name))
        # 17 px to its side there is no head: the sprite is longer than it is wide.
        side = picture[round(row - 17 * math.cos(turtle.theta)), round(col - 17 * math.sin(turtle.theta))]
        assert tuple(side) != tuple(c // 3 for c in turtle_color(name))


def test_obstacles_overlays_hits_and_the_zoom_window():
    from turtletui.sim import Box

    world = World(spawn_turtle1=False, obstacles=[Box(1.0, 1.0, 2.0, 2.0)])
    picture = arena_picture(world, overlays=[(6.0, 6.0, 9.0, 9.0)], hits=[(11.0888, 5.0, 0)])
    col, row = to_pixel(1.5, 1.5)
    assert tuple(picture[row, col]) == OBSTACLE_COLOR
    c0, r0 = to_pixel(6.0, 9.0)
    c1, _ = to_pixel(9.0, 9.0)
    edge = [tuple(p) for p in picture[r0, c0 : c1 + 1]]
    assert OVERLAY_COLOR in edge and BACKGROUND in edge  # dashed
    col, row = to_pixel(11.0888, 5.0)
    assert (255, 40, 40) in {tuple(p) for p in picture[row - 12 : row + 13, col - 12 : col + 1].reshape(-1, 3)}
    window = Window(100, 200, 250)
    assert np.array_equal(arena_picture(world, window=window), arena_picture(world)[200:450, 100:350])
    assert decoded(png_bytes(picture, (120, 120))).shape == (120, 120, 3)
