from turtletui.interfaces.geometry_msgs import *  # noqa: F401,F403
