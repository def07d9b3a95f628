from turtletui.interfaces.turtlesim import RotateAbsolute  # noqa: F401
