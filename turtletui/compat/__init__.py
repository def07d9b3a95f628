"""The rclpy-shaped API handed to controller code.

Implementation lives in this package; ``ros/`` holds thin packages named like
ROS's (rclpy, geometry_msgs, turtlesim, ...) that re-export it. ``install()``
puts ``ros/`` first on sys.path: turtletui calls it only in processes that run
controller code, so a real ROS installation elsewhere is never shadowed.
"""

from __future__ import annotations

import sys
from pathlib import Path

SHIM_PATH = str(Path(__file__).with_name("ros"))
ROS_PACKAGES = (
    "rclpy",
    "geometry_msgs",
    "std_msgs",
    "std_srvs",
    "sensor_msgs",
    "nav_msgs",
    "example_interfaces",
    "tf2_msgs",
    "tf2_py",
    "tf2_geometry_msgs",
    "tf2_ros",
    "visualization_msgs",
    "builtin_interfaces",
    "rcl_interfaces",
    "rosgraph_msgs",
    "lifecycle_msgs",
    "action_msgs",
    "unique_identifier_msgs",
    "service_msgs",
    "type_description_interfaces",
    "turtlesim",
    "turtlesim_msgs",
    "rosidl_parser",
)


def install(distro: str | None = None) -> None:
    """Make ``import rclpy`` (and the message packages) resolve to turtletui's,
    as in ROS 2 ``distro`` (the default when None: see turtletui.compat.distro),
    where only one of ``turtlesim`` and ``turtlesim_msgs`` exists."""
    from turtletui.compat.distro import install_finder, resolve_distro, show_types_as

    distro = resolve_distro(distro)
    install_finder(distro)
    show_types_as(distro)
    if sys.path[:1] != [SHIM_PATH]:
        if SHIM_PATH in sys.path:
            sys.path.remove(SHIM_PATH)
        sys.path.insert(0, SHIM_PATH)
    for name in list(sys.modules):
        top = name.partition(".")[0]
        if top in ROS_PACKAGES:
            module = sys.modules[name]
            origin = getattr(module, "__file__", None) or ""
            if not origin.startswith(SHIM_PATH):
                # A real ROS package imported earlier would win over ours.
                del sys.modules[name]
