from turtletui.compat.task import Future, Task  # noqa: F401
