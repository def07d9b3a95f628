from rclpy.experimental.events_executor import EventsExecutor  # noqa: F401
