from turtletui.compat.rclpy_api import ok, try_shutdown  # noqa: F401
from turtletui.compat.rclpy_api import utilities_remove_ros_args as remove_ros_args  # noqa: F401
