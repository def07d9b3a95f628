from turtletui.compat.destroyable import InvalidHandle  # noqa: F401
from turtletui.compat.executors import ExternalShutdownException  # noqa: F401
from turtletui.compat.node import (  # noqa: F401
    InvalidParameterTypeException,
    ParameterAlreadyDeclaredException,
    ParameterNotDeclaredException,
)
from turtletui.compat.ros_args import RosArgsError as UnknownROSArgsError  # noqa: F401
