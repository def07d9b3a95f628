from turtletui.compat.type_support import check_for_type_support  # noqa: F401
