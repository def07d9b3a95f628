import warnings

from rclpy.event_handler import *  # noqa: F401,F403

warnings.warn("importing 'qos_event' is deprecated; import 'event_handler' instead", stacklevel=1)  # rclpy's
