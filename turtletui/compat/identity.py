"""How turtletui's rclpy classes present themselves: under rclpy's module names.

``print(node)`` shows ``<rclpy.node.Node object at 0x...>``, ``type(pub)``
``<class 'rclpy.publisher.Publisher'>`` and a traceback's last line
``rclpy.exceptions.ParameterNotDeclaredException: ...``, as with the real
rclpy, not turtletui's modules (the message classes are named as
rosidl_generator_py names them for the same reason). Each compat module
names its own classes at its end; the names are those the real rclpy's
classes report in ROS 2 Kilted (``rclpy._rclpy_pybind11`` for those rclpy
takes from its C extension).
"""

from __future__ import annotations


def as_rclpy(module: str, *classes: type) -> None:
    """Give ``classes`` rclpy's ``module`` as their ``__module__``."""
    for cls in classes:
        cls.__module__ = module
