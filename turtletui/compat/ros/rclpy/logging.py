from turtletui.compat.logging import *  # noqa: F401,F403
from turtletui.compat.logging import LoggingSeverity, RcutilsLogger, get_logger, set_logger_level  # noqa: F401
