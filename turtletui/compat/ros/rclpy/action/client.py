from turtletui.compat.action import ActionClient, ClientGoalHandle  # noqa: F401
