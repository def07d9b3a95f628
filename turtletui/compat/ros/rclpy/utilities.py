from turtletui.compat.context import get_default_context  # noqa: F401
from turtletui.compat.rclpy_api import ok, shutdown, timeout_sec_to_nsec, try_shutdown  # noqa: F401
from turtletui.compat.rclpy_api import utilities_remove_ros_args as remove_ros_args  # noqa: F401
