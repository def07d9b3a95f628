from turtletui.compat.qos import *  # noqa: F401,F403
