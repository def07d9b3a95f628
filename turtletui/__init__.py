"""turtletui: ROS 2's turtlesim as a terminal teaching tool.

The package is layered (see the README): ``sim`` (physics), ``graph`` (a small
ROS-like middleware), ``compat`` (the rclpy-shaped API handed to controller
code), ``plugins``, ``runtime`` (hosting controllers), ``api`` (the library
entry points) and the front ends ``cli`` and ``tui``.
"""

__version__ = "0.1.0"
