from rclpy.action import client, graph, server  # noqa: E402,F401  (as rclpy's __init__ imports them)
from turtletui.compat.action import (  # noqa: F401
    ActionClient,
    get_action_client_names_and_types_by_node,
    get_action_names_and_types,
    get_action_server_names_and_types_by_node,
)
from turtletui.compat.action_server import ActionServer, CancelResponse, GoalResponse  # noqa: F401
