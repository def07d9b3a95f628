"""turtletui's rclpy: the API of ROS 2's rclpy over a simulated graph."""
from rclpy import (  # noqa: F401,E402
    action,
    callback_groups,
    clock,
    duration,
    event_handler,
    executors,
    logging,
    node,
    parameter,
    qos,
    signals,
    task,
    time,
)
from turtletui.compat.context import get_default_context  # noqa: F401
from turtletui.compat.executors import get_global_executor  # noqa: F401
from turtletui.compat.rclpy_api import (  # noqa: F401
    create_node,
    init,
    ok,
    shutdown,
    spin,
    spin_once,
    spin_until_future_complete,
    try_shutdown,
)
