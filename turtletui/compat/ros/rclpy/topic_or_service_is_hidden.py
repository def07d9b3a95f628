from turtletui.compat.names import topic_or_service_is_hidden  # noqa: F401
