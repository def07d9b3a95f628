from turtletui.compat.exceptions import *  # noqa: F401,F403
from turtletui.compat.executors import ExternalShutdownException  # noqa: F401
from turtletui.compat.rcl_error import UnknownROSArgsError  # noqa: F401
