"""The pen raster draws lines the way turtlesim's Qt pen does (square caps, width across the line)."""

import numpy as np

from turtletui.sim.canvas import UNPAINTED, PenCanvas, to_pixel
from turtletui.sim.constants import BACKGROUND, METER_PX

RED, GREEN, BLUE = (255, 0, 0), (0, 255, 0), (0, 0, 255)


def painted(canvas: PenCanvas, color: tuple[int, int, int]) -> np.ndarray:
    pixels = canvas.pixels
    return np.argwhere(np.all(pixels == np.array(color, dtype=np.uint8), axis=2))


def test_a_zero_length_line_is_a_width_by_width_square():
    canvas = PenCanvas()
    canvas.draw_segment(5.0, 5.0, 5.0, 5.0, RED, 3)
    cells = painted(canvas, RED)
    assert len(cells) == 9
    row, col = to_pixel(5.0, 5.0)[::-1]
    assert {tuple(c) for c in cells} == {(row + dr, col + dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1)}


def test_a_horizontal_line_covers_its_length_plus_square_caps():
    canvas = PenCanvas()
    canvas.draw_segment(1.0, 9.0, 4.0, 9.0, BLUE, 1)
    cells = painted(canvas, BLUE)
    assert np.unique(cells[:, 0]).tolist() == [to_pixel(1.0, 9.0)[1]]
    assert cells[:, 1].min() == round(1.0 * METER_PX)
    assert cells[:, 1].max() == round(4.0 * METER_PX)


def test_a_diagonal_line_is_as_thick_across_as_its_width():
    canvas = PenCanvas()
    canvas.draw_segment(1.0, 1.0, 3.0, 3.0, GREEN, 3)
    cells = painted(canvas, GREEN)
    per_column = [int((cells[:, 1] == col).sum()) for col in (80, 100, 120)]
    # 3 px across a 45 degree line is 3 * sqrt(2) = 4.2 px down a column.
    assert all(4 <= n <= 5 for n in per_column)


def test_later_segments_paint_over_earlier_ones():
    canvas = PenCanvas()
    canvas.draw_segment(2.0, 5.0, 8.0, 5.0, RED, 5)
    canvas.draw_segment(5.0, 2.0, 5.0, 8.0, GREEN, 5)
    assert canvas.color_at(5.0, 5.0) == GREEN
    assert canvas.color_at(3.0, 5.0) == RED


def test_clear_shows_the_background_and_the_sensor_reads_transparent_white():
    canvas = PenCanvas()
    canvas.draw_segment(2.0, 5.0, 8.0, 5.0, RED, 5)
    canvas.clear((10, 20, 30))
    # turtlesim's pen layer is transparent white where unpainted: the sensor
    # reads (255, 255, 255), the screen shows the background beneath.
    assert canvas.color_at(5.0, 5.0) == UNPAINTED == (255, 255, 255)
    assert canvas.pixels.shape == (500, 500, 3)
    assert tuple(canvas.pixels[0, 0]) == (10, 20, 30)
    assert not canvas.painted.any()
    assert PenCanvas().color_at(0.0, 0.0) == UNPAINTED
    assert tuple(PenCanvas().pixels[0, 0]) == BACKGROUND


def test_a_new_background_keeps_the_trails():
    canvas = PenCanvas()
    canvas.draw_segment(2.0, 5.0, 8.0, 5.0, RED, 5)
    version = canvas.version
    canvas.set_background((10, 20, 30))
    assert canvas.changed_since(version) == (0, 499, 0, 499)
    assert canvas.color_at(5.0, 5.0) == RED
    col, row = to_pixel(5.0, 5.0)
    assert tuple(canvas.pixels[row, col]) == RED
    assert tuple(canvas.pixels[0, 0]) == (10, 20, 30)
    assert canvas.painted[row, col] and not canvas.painted[0, 0]
    # a trail in the old background colour stays that colour
    canvas.draw_segment(1.0, 1.0, 2.0, 1.0, (10, 20, 30), 3)
    canvas.set_background(BACKGROUND)
    col, row = to_pixel(1.5, 1.0)
    assert tuple(canvas.pixels[row, col]) == (10, 20, 30)
    assert canvas.color_at(1.5, 1.0) == (10, 20, 30)


def test_pixels_are_read_only():
    canvas = PenCanvas()
    assert not canvas.pixels.flags.writeable


def test_changed_since_bounds_what_was_drawn():
    canvas = PenCanvas()
    start = canvas.version
    assert canvas.changed_since(start) is None
    canvas.draw_segment(2.0, 5.0, 3.0, 5.0, RED, 3)
    r0, r1, c0, c1 = canvas.changed_since(start)
    row = to_pixel(2.0, 5.0)[1]
    assert (r0, r1) == (row - 1, row + 1)
    assert c0 == to_pixel(2.0, 5.0)[0] - 1 and c1 == to_pixel(3.0, 5.0)[0] + 1
    assert canvas.changed_since(canvas.version) is None
    canvas.clear()
    assert canvas.changed_since(start) == (0, 499, 0, 499)
