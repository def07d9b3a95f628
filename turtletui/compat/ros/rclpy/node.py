from turtletui.compat.node import *  # noqa: F401,F403
from turtletui.compat.node import Client, Node, Publisher, Rate, Service, Subscription, Timer  # noqa: F401
from turtletui.compat.parameter import Parameter  # noqa: F401
