from turtletui.compat.time import ClockType, Duration, Time  # noqa: F401  (rclpy.time imports them too)
