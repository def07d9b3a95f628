from turtletui.compat.logging import *  # noqa: F401,F403
