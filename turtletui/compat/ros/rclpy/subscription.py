from turtletui.compat.message_info import MessageInfo  # noqa: F401
from turtletui.compat.node import Subscription  # noqa: F401
