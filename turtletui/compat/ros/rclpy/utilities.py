from turtletui.compat.context import get_default_context  # noqa: F401
from turtletui.compat.message_info import RMW_IMPLEMENTATION
from turtletui.compat.rclpy_api import ok, timeout_sec_to_nsec  # noqa: F401
from turtletui.compat.rclpy_api import utilities_remove_ros_args as remove_ros_args  # noqa: F401
from turtletui.compat.rclpy_api import utilities_shutdown as shutdown  # noqa: F401
from turtletui.compat.rclpy_api import utilities_try_shutdown as try_shutdown  # noqa: F401


def get_rmw_implementation_identifier() -> str:
    """The rmw turtletui behaves as (Fast DDS, ROS 2's default)."""
    return RMW_IMPLEMENTATION
