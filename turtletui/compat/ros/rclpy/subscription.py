from turtletui.compat.node import Subscription  # noqa: F401
