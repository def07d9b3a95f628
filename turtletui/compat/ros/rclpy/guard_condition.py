from turtletui.compat.guard_condition import GuardCondition  # noqa: F401
