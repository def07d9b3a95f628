from turtletui.compat.names import validate_full_topic_name  # noqa: F401
