from turtletui.compat.tf2.buffer import Buffer  # noqa: F401
