from turtletui.interfaces.builtin_interfaces import *  # noqa: F401,F403
