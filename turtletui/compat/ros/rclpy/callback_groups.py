from turtletui.compat.callback_groups import *  # noqa: F401,F403
