from turtletui.compat.task import Future  # noqa: F401
