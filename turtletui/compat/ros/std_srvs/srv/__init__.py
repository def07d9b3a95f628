from turtletui.interfaces.std_srvs import *  # noqa: F401,F403
