from turtletui.compat.exceptions import *  # noqa: F401,F403
from turtletui.compat.executors import ExternalShutdownException  # noqa: F401
from turtletui.compat.ros_args import RosArgsError as UnknownROSArgsError  # noqa: F401
