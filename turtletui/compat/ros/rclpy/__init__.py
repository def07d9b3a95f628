"""turtletui's rclpy: the API of ROS 2's rclpy over a simulated graph."""
# The submodules rclpy's __init__ imports, and no others: ``rclpy.exceptions.X``
# works after ``import rclpy`` alone, ``rclpy.node`` and the modules it imports
# once ``rclpy.node`` is imported (rclpy/node.py), ``rclpy.action`` only once
# imported itself, as under ROS.
from rclpy import (  # noqa: F401,E402
    callback_groups,
    constants,
    context,
    duration,
    exceptions,
    guard_condition,
    impl,
    parameter,
    qos,
    signals,
    task,
    utilities,
)

# the names rclpy's __init__ imports, which programs use as rclpy.X (the parameters
# tutorial's rclpy.Parameter.Type.STRING)
from rclpy.context import Context  # noqa: F401
from rclpy.parameter import Parameter  # noqa: F401
from rclpy.qos import QoSProfile, qos_profile_rosout_default  # noqa: F401
from rclpy.signals import SignalHandlerOptions, install_signal_handlers, uninstall_signal_handlers  # noqa: F401
from rclpy.task import Future  # noqa: F401
from rclpy.utilities import get_rmw_implementation_identifier  # noqa: F401
from turtletui.compat.context import get_default_context  # noqa: F401
from turtletui.compat.executors import get_global_executor  # noqa: F401
from turtletui.compat.rclpy_api import (  # noqa: F401
    create_node,
    init,
    ok,
    shutdown,
    spin,
    spin_once,
    spin_until_future_complete,
    try_shutdown,
)
