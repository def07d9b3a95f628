"""Numbers read from ROS 2 turtlesim (turtle_frame.cpp, turtle.cpp), with units."""

import math

PIXELS = 500
"""Width and height of turtlesim's window and pen image, in pixels."""

METER_PX = 45.0
"""Pixels per metre: the height of the turtle image."""

ARENA_SIZE = (PIXELS - 1) / METER_PX
"""Width and height of the arena in metres: 11.0888... m."""

CENTER = ARENA_SIZE / 2.0
"""Where turtle1 is spawned, in metres (x and y): 5.5444... m."""

DT = 0.016
"""Length of one update step in seconds (turtlesim's 16 ms timer, 62.5 Hz)."""

COMMAND_TIMEOUT = 1.0
"""Seconds after the last velocity command at which a turtle stops."""

ROTATE_TOLERANCE = 0.02
"""rad: a rotate_absolute goal succeeds when the heading is this close."""

ROTATE_SPEED = 1.0
"""rad/s: how fast a rotate_absolute goal turns the turtle."""

BACKGROUND = (69, 86, 255)
"""Default background colour (parameters background_r, _g, _b)."""

PEN_COLOR = (179, 184, 255)
"""Default pen colour of a new turtle."""

PEN_WIDTH = 3
"""Default pen width in pixels."""

QT_DEFAULT_PEN_WIDTH = 1
"""Width of a pen set with width 0: set_pen makes a new QPen, whose default is 1 px."""

_TWO_PI = 2.0 * math.pi


def normalize_angle(angle: float) -> float:
    """Map an angle in radians to [-pi, pi), as turtlesim's normalizeAngle."""
    return angle - _TWO_PI * math.floor((angle + math.pi) / _TWO_PI)
