from turtletui.compat.executors import *  # noqa: F401,F403
