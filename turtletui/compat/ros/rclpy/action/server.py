from turtletui.compat.action_server import (  # noqa: F401
    ActionServer,
    CancelResponse,
    GoalEvent,
    GoalResponse,
    RCLError,
    ServerGoalHandle,
    default_cancel_callback,
    default_goal_callback,
    default_handle_accepted_callback,
)
