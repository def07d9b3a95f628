from turtletui.compat.logging import LoggingSeverity  # noqa: F401
