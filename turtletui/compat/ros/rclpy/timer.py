from turtletui.compat.node import Rate, Timer  # noqa: F401
from turtletui.compat.timer import TimerInfo  # noqa: F401
