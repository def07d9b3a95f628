from turtletui.compat.names import expand_topic_name  # noqa: F401
