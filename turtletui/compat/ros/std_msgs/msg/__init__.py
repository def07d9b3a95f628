from turtletui.interfaces.std_msgs import *  # noqa: F401,F403
