from turtletui.compat.action import GoalStatus  # noqa: F401
