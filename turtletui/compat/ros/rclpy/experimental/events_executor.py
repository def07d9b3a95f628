from turtletui.compat.executors import EventsExecutor  # noqa: F401
