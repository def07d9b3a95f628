from turtletui.interfaces.sensor_msgs import *  # noqa: F401,F403
