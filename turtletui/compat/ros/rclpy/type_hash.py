from turtletui.compat.graph_info import TypeHash  # noqa: F401
