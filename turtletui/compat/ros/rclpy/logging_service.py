from turtletui.compat.logging_service import LoggingService  # noqa: F401
