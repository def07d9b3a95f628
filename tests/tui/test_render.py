"""The arena renderer (turtletui.tui.render): pure, so tested without Textual."""

from __future__ import annotations

import math

import numpy as np
import pytest
from rich.segment import Segment

from turtletui.sim import BACKGROUND, PEN_COLOR, World
from turtletui.tui.marks import HitMarks, pen_char, turtle_color
from turtletui.tui.render import (
    ASCII_BODY,
    ASCII_HEADS,
    ASCII_HIT,
    BODY,
    HEADS,
    HIT,
    HIT_COLORS,
    MIN_HEIGHT,
    MIN_WIDTH,
    OVERLAY_COLOR,
    TILE_COLOR,
    TOO_SMALL,
    ArenaRenderer,
    Overlay,
    downsample,
    heading_index,
    layout_for,
    normalise_overlays,
)

RED = (255, 0, 0)
GREEN = (0, 200, 0)
SIZES = [(80, 24), (160, 50), (100, 60), (200, 40), (MIN_WIDTH, MIN_HEIGHT), (1200, 400)]


def empty_world() -> World:
    return World(spawn_turtle1=False)


def text(line: list[Segment]) -> str:
    return "".join(segment.text for segment in line)


def cells(line: list[Segment]) -> list[tuple[str, Segment]]:
    """(character, segment) per cell of a line."""
    return [(char, segment) for segment in line for char in segment.text]


def colours_at(line: list[Segment], column: int) -> set[tuple[int, int, int]]:
    """The colours a cell shows: the upper pixel (fg of '▀') and the lower (bg)."""
    char, segment = cells(line)[column]
    shown = {segment.style.bgcolor.triplet}
    if char == "▀":
        shown.add(segment.style.color.triplet)
    return {tuple(colour) for colour in shown}


def pixel_colour(renderer: ArenaRenderer, lines, x: float, y: float) -> tuple[int, int, int]:
    """The colour the frame shows for the arena pixel under (x, y) metres."""
    layout = renderer.layout
    col, row = layout.pixel_of(x, y)
    char, segment = cells(lines[layout.top + row // 2])[layout.left + col]
    if char == "▀" and row % 2 == 0:
        return tuple(segment.style.color.triplet)
    return tuple(segment.style.bgcolor.triplet)


def arena_colours(renderer: ArenaRenderer, lines) -> set[tuple[int, int, int]]:
    layout = renderer.layout
    seen: set[tuple[int, int, int]] = set()
    for line in lines[layout.top : layout.top + layout.rows]:
        for column in range(layout.left, layout.left + layout.size):
            seen |= colours_at(line, column)
    return seen


def find_glyphs(lines, glyphs: str) -> list[tuple[int, int, str]]:
    return [
        (y, x, char)
        for y, line in enumerate(lines)
        for x, (char, _) in enumerate(cells(line))
        if char in glyphs
    ]


# -- geometry -----------------------------------------------------------------
@pytest.mark.parametrize("size", SIZES)
def test_the_arena_is_the_largest_square_that_fits_and_is_centred(size):
    width, height = size
    renderer = ArenaRenderer()
    lines = renderer.frame(empty_world(), width, height)
    layout = renderer.layout
    assert len(lines) == height
    assert all(Segment.get_line_length(line) == width for line in lines)
    n = layout.size
    # Square pixels: N cells wide, N / 2 cells (N pixels) tall.
    assert n % 2 == 0 and layout.rows == n // 2
    assert n <= 500
    # Labels (2) and the left border before, the right border after.
    assert layout.left - 3 >= 0 and layout.left + n + 1 <= width
    # Top border above, bottom border and label line below.
    assert layout.top - 1 >= 0 and layout.top + layout.rows + 2 <= height
    assert n == 500 or n + 2 > min(width - 4, 2 * (height - 3))
    margin_left = layout.left - 3
    margin_right = width - (layout.left + n + 1)
    assert abs(margin_left - margin_right) <= 1
    margin_top = layout.top - 1
    margin_bottom = height - (layout.top + layout.rows + 2)
    assert abs(margin_top - margin_bottom) <= 1


def test_the_80x24_layout():
    layout = layout_for(80, 24)
    assert (layout.size, layout.rows, layout.left, layout.top) == (42, 21, 20, 1)
    assert layout_for(160, 50).size == 94


def test_the_border_encloses_the_arena():
    renderer = ArenaRenderer()
    lines = renderer.frame(empty_world(), 80, 24)
    layout = renderer.layout
    top = text(lines[layout.top - 1])
    assert top[layout.left - 1] == "┌" and top[layout.left + layout.size] == "┐"
    assert set(top[layout.left : layout.left + layout.size]) == {"─"}
    for line in lines[layout.top : layout.top + layout.rows]:
        row = text(line)
        assert row[layout.left - 1] in "│┤" and row[layout.left + layout.size] == "│"
    bottom = text(lines[layout.top + layout.rows])
    assert bottom[layout.left - 1] == "└" and bottom[layout.left + layout.size] == "┘"


# -- pen image ----------------------------------------------------------------
def test_an_empty_arena_is_the_background_colour():
    renderer = ArenaRenderer()
    lines = renderer.frame(empty_world(), 80, 24)
    assert arena_colours(renderer, lines) == {BACKGROUND}


@pytest.mark.parametrize("size", [(80, 24), (160, 50), (MIN_WIDTH, MIN_HEIGHT)])
def test_a_drawn_trail_shows_in_the_cells_under_it(size):
    world = empty_world()
    world.canvas.draw_segment(1.0, 3.0, 10.0, 3.0, RED, 3)  # a 3 pixel wide line
    world.canvas.draw_segment(8.0, 5.0, 8.0, 10.0, GREEN, 3)
    renderer = ArenaRenderer()
    lines = renderer.frame(world, *size)
    for x in np.linspace(1.0, 10.0, 25):
        assert pixel_colour(renderer, lines, x, 3.0) == RED, x
    for y in np.linspace(5.0, 10.0, 15):
        assert pixel_colour(renderer, lines, 8.0, y) == GREEN, y
    # Away from the lines: background.
    for x, y in [(0.5, 0.5), (5.0, 7.0), (10.5, 10.5), (0.5, 3.0), (10.8, 3.0), (8.0, 4.0)]:
        assert pixel_colour(renderer, lines, x, y) == BACKGROUND, (x, y)
    assert arena_colours(renderer, lines) == {BACKGROUND, RED, GREEN}


def test_a_trail_drawn_by_a_turtle_is_visible_at_80x24():
    world = World()
    world.step()  # the first tick only records the time
    world.teleport_absolute("turtle1", 2.0, 2.0, 0.0)
    world.step()
    world.set_pen("turtle1", 0, 0, 0, 0, 1)
    world.teleport_absolute("turtle1", 10.0, 10.0, 0.0)
    world.step()
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24)
    # The pen drew from the centre to (2, 2) with its default colour, then lifted.
    for t in np.linspace(0.1, 0.9, 9):
        x = y = 5.544 + t * (2.0 - 5.544)
        assert pixel_colour(renderer, lines, x, y) == PEN_COLOR
    assert pixel_colour(renderer, lines, 8.0, 8.0) == BACKGROUND


def test_downsampling_keeps_a_single_trail_pixel():
    pixels = np.empty((500, 500, 3), dtype=np.uint8)
    pixels[:] = BACKGROUND
    pixels[123, 321] = RED
    small = downsample(pixels, BACKGROUND, 42)
    assert small.shape == (42, 42)
    packed_red = RED[0] | RED[1] << 8 | RED[2] << 16
    packed_background = BACKGROUND[0] | BACKGROUND[1] << 8 | BACKGROUND[2] << 16
    assert np.count_nonzero(small == packed_red) == 1
    assert np.count_nonzero(small == packed_background) == 42 * 42 - 1
    row, col = np.argwhere(small == packed_red)[0]
    edges = np.arange(43) * 500 // 42  # block i covers pixels edges[i] .. edges[i + 1] - 1
    assert edges[row] <= 123 < edges[row + 1] and edges[col] <= 321 < edges[col + 1]
    assert (row, col) == (layout_for(80, 24).block_of(123), layout_for(80, 24).block_of(321))


def test_queued_segments_are_drawn_and_then_the_frame_is_stable():
    world = empty_world()
    renderer = ArenaRenderer()
    renderer.frame(world, 80, 24)
    world.canvas.draw_segment(1.0, 1.0, 9.0, 1.0, RED, 3)  # queued, not yet rasterised
    lines = renderer.frame(world, 80, 24)
    assert pixel_colour(renderer, lines, 5.0, 1.0) == RED
    assert renderer.changed_lines
    renderer.frame(world, 80, 24)
    assert renderer.changed_lines == []


def test_changing_the_background_recolours_the_arena():
    world = empty_world()
    renderer = ArenaRenderer()
    renderer.frame(world, 80, 24)
    world.set_background((10, 20, 30))
    lines = renderer.frame(world, 80, 24)
    assert arena_colours(renderer, lines) == {(10, 20, 30)}


# -- turtles ------------------------------------------------------------------
def turtle_at(renderer: ArenaRenderer, lines, name: str, x: float, y: float):
    """(body cell, head cell) of the turtle drawn at (x, y): ((line, column), ...)."""
    layout = renderer.layout
    col, line = layout.cell_of(x, y)
    return layout.top + line, layout.left + col


@pytest.mark.parametrize("k", range(8))
def test_a_turtle_is_a_body_and_a_head_on_the_side_it_faces(k):
    world = empty_world()
    world.spawn(3.0, 7.0, k * math.pi / 4, "turtle1")
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24)
    line, col = turtle_at(renderer, lines, "turtle1", 3.0, 7.0)
    # The body: its cell filled with the turtle's colour (turtle1: yellow).
    body_char, body = cells(lines[line])[col]
    assert body_char == BODY and tuple(body.style.bgcolor.triplet) == turtle_color("turtle1")
    # The head: the heading's triangle in the same colour, on the dark tile, next to the body.
    d_line, d_col = [(0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0), (1, 1)][k]
    head_char, head = cells(lines[line + d_line])[col + d_col]
    assert head_char == HEADS[k] and head.style.bold
    assert tuple(head.style.color.triplet) == turtle_color("turtle1")
    assert tuple(head.style.bgcolor.triplet) == TILE_COLOR
    assert find_glyphs(lines, HEADS) == [(line + d_line, col + d_col, HEADS[k])]
    ascii_lines = renderer.frame(world, 80, 24, ascii=True)
    assert text(ascii_lines[line])[col] == ASCII_BODY
    assert text(ascii_lines[line + d_line])[col + d_col] == ASCII_HEADS[k]


@pytest.mark.parametrize(
    ("theta", "index"),
    [
        (0.0, 0),
        (0.39, 0),
        (0.40, 1),
        (-math.pi / 2, 6),
        (-math.pi, 4),
        (math.pi, 4),
        (3 * math.pi / 4, 3),
        (-3 * math.pi / 4, 5),
        (-0.8, 7),
        (2 * math.pi + 1.57, 2),
    ],
)
def test_headings_round_to_the_nearest_of_eight(theta, index):
    assert heading_index(theta) == index


def test_the_name_is_written_beside_the_turtle_in_its_colour():
    world = empty_world()
    world.spawn(5.0, 5.0, 0.0, "turtle2")
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24)
    line, col = turtle_at(renderer, lines, "turtle2", 5.0, 5.0)
    above = text(lines[line - 1])
    start = above.index("turtle2")
    assert start <= col < start + len("turtle2")
    _, segment = cells(lines[line - 1])[start]
    assert tuple(segment.style.color.triplet) == turtle_color("turtle2") != turtle_color("turtle1")
    # Facing north the head is above: the name goes below.
    world.teleport_absolute("turtle2", 5.0, 5.0, math.pi / 2)
    world.step()
    world.step()
    lines = renderer.frame(world, 80, 24)
    assert "turtle2" in text(lines[line + 1]) and "turtle2" not in text(lines[line - 1])
    assert "turtle2" in text(renderer.frame(world, 80, 24, ascii=True)[line + 1])


def test_a_turtle_at_the_wall_keeps_its_head_inside_the_arena():
    world = empty_world()
    world.spawn(11.08, 5.0, 0.0, "turtle1")  # against the east wall, facing it
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24)
    layout = renderer.layout
    [(line, col, glyph)] = find_glyphs(lines, HEADS)
    assert glyph == HEADS[0] and col == layout.left + layout.size - 1
    assert cells(lines[line])[col - 1][0] == BODY


def test_a_turtle_on_its_trail_is_still_visible():
    world = World()
    world.command_velocity("turtle1", 2.0, 0.0, 0.0)
    for _ in range(30):
        world.step()
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24)
    [(y, x, glyph)] = find_glyphs(lines, HEADS)
    assert glyph == HEADS[0]
    _, segment = cells(lines[y])[x]
    assert tuple(segment.style.bgcolor.triplet) == TILE_COLOR  # dark under the head, on any trail
    assert tuple(cells(lines[y])[x - 2][1].style.bgcolor.triplet) == PEN_COLOR  # the trail behind it


def test_several_turtles_are_each_drawn_in_their_own_colour():
    world = empty_world()
    names = ("turtle1", "turtle2", "turtle3", "turtle4")
    for name, (x, y) in zip(names, [(1.0, 1.0), (10.0, 10.0), (1.0, 10.0), (10.0, 4.0)], strict=True):
        world.spawn(x, y, 0.0, name)
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 160, 50)
    colours = set()
    for name in names:
        turtle = world.turtles[name]
        line, col = turtle_at(renderer, lines, name, turtle.x, turtle.y)
        _, body = cells(lines[line])[col]
        colours.add(tuple(body.style.bgcolor.triplet))
        assert any(name in text(lines[line + d]) for d in (-1, 1))
    assert colours == {turtle_color(name) for name in names} and len(colours) == 4
    assert len(find_glyphs(lines, HEADS)) == 4


def test_turtle_colours_are_fixed_by_name():
    assert turtle_color("turtle1") != turtle_color("turtle2")
    assert turtle_color("alice") == turtle_color("alice")
    assert turtle_color("turtle1") == turtle_color("turtle9")  # the palette's 8 colours repeat


# -- hit marks ------------------------------------------------------------------
def test_hit_marks_fade_in_steps_and_go():
    world = empty_world()
    renderer = ArenaRenderer()
    levels = []
    for level in range(3):
        lines = renderer.frame(world, 80, 24, hits=[(11.0888, 5.0, level)])
        [(line, col, _)] = find_glyphs(lines, HIT)
        levels.append(tuple(cells(lines[line])[col][1].style.color.triplet))
    assert levels == list(HIT_COLORS)
    assert col == renderer.layout.left + renderer.layout.size - 1  # on the wall it hit
    lines = renderer.frame(world, 80, 24, ascii=True, hits=[(11.0888, 5.0, 0)])
    assert text(lines[line])[col] == ASCII_HIT


def test_a_wall_hit_also_marks_the_border_beside_it():
    world = empty_world()
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24, hits=[(11.0888, 5.0, 0), (3.0, 0.0, 2)])
    layout = renderer.layout
    _, line = layout.cell_of(11.0888, 5.0)
    char, segment = cells(lines[layout.top + line])[layout.left + layout.size]
    assert char == "│" and tuple(segment.style.color.triplet) == HIT_COLORS[0]
    col, _ = layout.cell_of(3.0, 0.0)
    char, segment = cells(lines[layout.top + layout.rows])[layout.left + col]
    assert char in "─┬" and tuple(segment.style.color.triplet) == HIT_COLORS[2]
    ascii = renderer.frame(world, 80, 24, ascii=True, hits=[(11.0888, 5.0, 0)])
    assert text(ascii[layout.top + line])[layout.left + layout.size] == ASCII_HIT
    assert len(text(ascii[layout.top + line])) == 80


def test_hit_marks_follow_wall_hits_of_the_world():
    world = World()
    marks = HitMarks()
    for _ in range(80):  # 1.28 s at 5 m/s from x = 5.5: into the east wall
        world.command_velocity("turtle1", 5.0, 0.0, 0.0)
        world.step()
        for event in world.take_events():
            marks.record(event, world.time)
    shown = marks.visible(world.time)
    assert len(shown) == 1  # pushing along the wall refreshes one mark
    x, y, level = shown[0]
    assert x == pytest.approx(11.0888, abs=1e-3) and y == pytest.approx(5.5444, abs=1e-3) and level == 0
    assert marks.visible(world.time + 1.5)[0][2] == 1
    assert marks.visible(world.time + 3.1) == ()
    world.clear()
    for event in world.take_events():
        marks.record(event, world.time)
    assert marks.visible(world.time) == ()


# -- scale --------------------------------------------------------------------
def test_metre_ticks_and_labels_at_80x24():
    renderer = ArenaRenderer()
    lines = renderer.frame(empty_world(), 80, 24)
    layout = renderer.layout
    bottom = text(lines[layout.top + layout.rows])
    labels = text(lines[layout.top + layout.rows + 1])
    assert labels.split() == [str(m) for m in range(12)]
    assert bottom.count("┬") == 12
    for m in range(12):
        col = layout.left + layout.block_of(round(m * 45))
        assert bottom[col] == "┬"
        assert labels[col : col + len(str(m))] == str(m)
    # x = 0 is the first arena column, y = 0 the last arena line, y = 11 the first.
    assert labels[layout.left] == "0"
    left_labels = {}
    for line in range(layout.top, layout.top + layout.rows):
        row = text(lines[line])
        label = row[layout.left - 3 : layout.left - 1].strip()
        if label:
            assert row[layout.left - 1] == "┤"
            left_labels[int(label)] = line
    assert sorted(left_labels) == list(range(12))
    assert left_labels[0] == layout.top + layout.rows - 1
    assert left_labels[11] == layout.top
    assert all(left_labels[m] > left_labels[m + 1] for m in range(11))


def test_as_many_labels_as_fit_at_the_minimum_size():
    renderer = ArenaRenderer()
    lines = renderer.frame(empty_world(), MIN_WIDTH, MIN_HEIGHT)
    layout = renderer.layout
    labels = text(lines[layout.top + layout.rows + 1]).split()
    assert labels[0] == "0" and 2 <= len(labels) < 12
    step = int(labels[1])
    assert labels == [str(m) for m in range(0, 12, step)]
    left = [
        text(line)[layout.left - 3 : layout.left - 1].strip()
        for line in lines[layout.top : layout.top + layout.rows]
    ]
    left = [int(label) for label in left if label]
    assert 0 in left and len(left) == len(set(left)) >= 2


# -- overlays -----------------------------------------------------------------
def test_an_overlay_is_a_dotted_outline_under_the_turtles():
    world = empty_world()
    world.spawn(2.0, 2.0, 0.0, "t")  # on the corner of the box
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 160, 50, overlays=[(2.0, 2.0, 9.0, 9.0)])
    layout = renderer.layout
    assert OVERLAY_COLOR in arena_colours(renderer, lines)
    for x, y in [(9.0, 9.0), (2.0, 9.0), (9.0, 2.0)]:
        assert pixel_colour(renderer, lines, x, y) == OVERLAY_COLOR
    # Dotted: along an edge, overlay and background pixels alternate.
    c0, r0 = layout.pixel_of(2.0, 9.0)
    c1, _ = layout.pixel_of(9.0, 9.0)
    line = lines[layout.top + r0 // 2]
    edge = []
    for col in range(c0, c1 + 1):
        char, segment = cells(line)[layout.left + col]
        upper = segment.style.color if char == "▀" else segment.style.bgcolor
        lower = segment.style.bgcolor
        edge.append(tuple((upper if r0 % 2 == 0 else lower).triplet))
    assert edge.count(OVERLAY_COLOR) >= (c1 - c0) // 2
    assert BACKGROUND in edge
    # Inside and outside the box: background.
    for x, y in [(5.5, 5.5), (1.0, 1.0), (10.0, 10.0), (5.5, 1.5), (9.5, 5.5)]:
        assert pixel_colour(renderer, lines, x, y) == BACKGROUND
    # The turtle on the corner is drawn over the outline.
    col, line = layout.cell_of(2.0, 2.0)
    assert cells(lines[layout.top + line])[layout.left + col][0] == BODY
    assert cells(lines[layout.top + line])[layout.left + col + 1][0] == HEADS[0]


def test_overlays_take_a_colour_and_any_corner_order():
    world = empty_world()
    renderer = ArenaRenderer()
    purple = (200, 0, 200)
    lines = renderer.frame(world, 80, 24, overlays=[Overlay(8.0, 8.0, 3.0, 3.0, purple)])
    assert arena_colours(renderer, lines) == {BACKGROUND, purple}
    assert normalise_overlays([(1, 2, 3, 4)]) == (Overlay(1.0, 2.0, 3.0, 4.0, OVERLAY_COLOR),)


# -- ASCII --------------------------------------------------------------------
def test_ascii_mode_is_plain_ascii_without_style():
    world = World()
    world.command_velocity("turtle1", 2.0, 0.0, 1.0)
    for _ in range(60):
        world.step()
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24, ascii=True, overlays=[(2, 2, 9, 9)])
    assert len(lines) == 24
    for line in lines:
        for segment in line:
            assert segment.style is None
            assert segment.text.isascii()
        assert len(text(line)) == 80
    layout = renderer.layout
    arena = "".join(
        text(line)[layout.left : layout.left + layout.size]
        for line in lines[layout.top : layout.top + layout.rows]
    )
    assert set(arena) <= set(" #.@turtle1") | set(ASCII_HEADS)
    assert "#" in arena and "." in arena and "turtle1" in arena
    assert arena.count("@") == 1
    top = text(lines[layout.top - 1])
    assert top.strip() == "+" + "-" * layout.size + "+"
    assert text(lines[layout.top])[layout.left - 1] in "|+"
    assert text(lines[layout.top + layout.rows + 1]).split() == [str(m) for m in range(12)]


def test_ascii_trail_cells_follow_the_pen_image():
    world = empty_world()
    world.canvas.draw_segment(1.0, 3.0, 10.0, 3.0, PEN_COLOR, 3)
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24, ascii=True)
    layout = renderer.layout
    col0, row = layout.pixel_of(1.0, 3.0)
    col1, _ = layout.pixel_of(10.0, 3.0)
    line = text(lines[layout.top + row // 2])[layout.left : layout.left + layout.size]
    assert set(line[col0 : col1 + 1]) == {"#"}
    assert line.count("#") <= col1 - col0 + 3


def test_each_pen_colour_has_its_own_ascii_character():
    # Part 7: red on one side of x = 5.5, green on the other; both were '#'.
    world = empty_world()
    world.canvas.draw_segment(1.0, 3.0, 5.0, 3.0, (255, 0, 0), 3)
    world.canvas.draw_segment(6.0, 3.0, 10.0, 3.0, (0, 255, 0), 3)
    world.canvas.draw_segment(1.0, 8.0, 10.0, 8.0, PEN_COLOR, 3)
    renderer = ArenaRenderer()
    lines = renderer.frame(world, 80, 24, ascii=True)
    layout = renderer.layout

    def chars_at(x0: float, x1: float, y: float) -> set[str]:
        c0, row = layout.pixel_of(x0, y)
        c1, _ = layout.pixel_of(x1, y)
        return set(text(lines[layout.top + row // 2])[layout.left + c0 : layout.left + c1 + 1])

    assert chars_at(1.5, 4.5, 3.0) == {pen_char((255, 0, 0))} == {"*"}
    assert chars_at(6.5, 9.5, 3.0) == {pen_char((0, 255, 0))} == {"+"}
    assert chars_at(1.5, 9.5, 8.0) == {"#"}
    distinct = {pen_char(rgb) for rgb in [(255, 0, 0), (255, 255, 0), (0, 255, 0), (0, 255, 255), (0, 0, 255), (255, 0, 255), (255, 255, 255), (0, 0, 0), PEN_COLOR]}
    assert len(distinct) == 9


# -- what changed -------------------------------------------------------------
def test_the_first_frame_changes_every_line_and_an_unchanged_world_none():
    world = World()
    renderer = ArenaRenderer()
    first = renderer.frame(world, 80, 24)
    assert renderer.changed_lines == list(range(24))
    keys = list(renderer.line_keys)
    second = renderer.frame(world, 80, 24)
    assert renderer.changed_lines == []
    assert second == first and renderer.line_keys == keys
    world.step()  # the first tick only records the time: nothing moves
    world.step()
    renderer.frame(world, 80, 24)
    assert renderer.changed_lines == []


def marked_lines(renderer: ArenaRenderer) -> set[int]:
    """Screen lines holding a turtle's cells or its name."""
    return {renderer.layout.top + line for line, _ in renderer.marks}


def test_a_moving_turtle_changes_only_its_old_and_new_lines():
    world = World()
    world.set_pen("turtle1", 0, 0, 0, 0, 1)
    renderer = ArenaRenderer()
    renderer.frame(world, 160, 50)
    before = marked_lines(renderer)
    assert len(before) == 2  # the turtle's line and its name's
    world.teleport_absolute("turtle1", 5.544, 8.0, math.pi / 2)
    world.step()
    world.step()
    renderer.frame(world, 160, 50)
    after = marked_lines(renderer)
    assert len(after) == 3 and not before & after  # head above, name below
    assert renderer.changed_lines == sorted(before | after)
    # Turning in place changes only the lines around the turtle.
    world.teleport_relative("turtle1", 0.0, -math.pi / 2)
    world.step()
    renderer.frame(world, 160, 50)
    assert set(renderer.changed_lines) <= after | marked_lines(renderer)
    assert renderer.changed_lines


def test_a_drawing_turtle_changes_a_few_lines_per_step():
    world = World()
    renderer = ArenaRenderer()
    renderer.frame(world, 80, 24)
    world.step()
    counts = []
    for _ in range(100):
        world.command_velocity("turtle1", 2.0, 0.0, 1.0)
        world.step()
        renderer.frame(world, 80, 24)
        counts.append(len(renderer.changed_lines))
    assert max(counts) <= 6  # the old and new lines of its head, body and name
    assert sum(counts) > 0 and sorted(counts)[len(counts) // 2] <= 3


def test_equal_line_keys_mean_equal_lines():
    world = World()
    renderer = ArenaRenderer()
    seen: dict = {}
    for step in range(40):
        world.command_velocity("turtle1", 2.0, 0.0, 1.5)
        world.step()
        for ascii in (False, True):
            lines = renderer.frame(world, 80, 24, ascii=ascii, overlays=[(2, 2, 9, 9)])
            for key, line in zip(renderer.line_keys, lines, strict=True):
                assert seen.setdefault(key, line) == line, step


def test_a_resize_or_a_mode_change_changes_every_line():
    world = World()
    renderer = ArenaRenderer()
    renderer.frame(world, 80, 24)
    renderer.frame(world, 100, 24)
    assert renderer.changed_lines == list(range(24))
    renderer.frame(world, 100, 24, ascii=True)
    assert renderer.changed_lines == list(range(24))


# -- too small ----------------------------------------------------------------
@pytest.mark.parametrize("size", [(0, 0), (0, 5), (5, 0), (1, 1), (10, 3), (23, 40), (200, 11)])
def test_too_small_shows_the_message(size):
    width, height = size
    renderer = ArenaRenderer()
    lines = renderer.frame(World(), width, height)
    assert renderer.layout is None
    assert len(lines) == height
    assert all(Segment.get_line_length(line) == width for line in lines)
    shown = " ".join(text(line).strip() for line in lines).split()
    if width >= 20 and height >= 4:
        assert " ".join(shown) == TOO_SMALL
    for word in shown:
        assert word in TOO_SMALL
    assert not find_glyphs(lines, HEADS)
    renderer.frame(World(), width, height)
    assert renderer.changed_lines == []


def test_the_minimum_size_shows_the_arena():
    renderer = ArenaRenderer()
    lines = renderer.frame(World(), MIN_WIDTH, MIN_HEIGHT)
    assert renderer.layout is not None
    assert len(find_glyphs(lines, HEADS)) == 1


def test_a_new_world_is_never_mistaken_for_the_old_one():
    renderer = ArenaRenderer()
    for colour in (RED, GREEN, RED):
        world = empty_world()  # same canvas version each time
        world.canvas.draw_segment(1.0, 5.0, 10.0, 5.0, colour, 3)
        lines = renderer.frame(world, 80, 24)
        assert pixel_colour(renderer, lines, 5.0, 5.0) == colour
        del world


def test_incremental_downsample_matches_a_full_one() -> None:
    import numpy as np

    from turtletui.sim import World
    from turtletui.tui.render import downsample_packed

    world = World()
    world.step()
    canvas = world.canvas
    version = canvas.version
    image = downsample_packed(canvas.packed, canvas.background, 94)
    for i in range(200):
        world.command_velocity("turtle1", 2.0, 0.0, 1.0 if i < 120 else -2.0)
        world.step()
        if i % 7 == 0:
            box = canvas.changed_since(version)
            image = downsample_packed(canvas.packed, canvas.background, 94, image, box)
            version = canvas.version
            assert np.array_equal(image, downsample_packed(canvas.packed, canvas.background, 94))
