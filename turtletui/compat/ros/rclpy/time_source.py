from turtletui.compat.time_source import CLOCK_TOPIC, USE_SIM_TIME_NAME, TimeSource  # noqa: F401
