from turtletui.compat.logging import LoggingSeverity, RcutilsLogger  # noqa: F401
