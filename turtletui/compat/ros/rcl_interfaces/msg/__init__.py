from turtletui.interfaces.rcl_interfaces import *  # noqa: F401,F403
