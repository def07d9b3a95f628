from turtletui.compat.node import check_for_type_support  # noqa: F401
