from turtletui.compat.names import validate_node_name  # noqa: F401
