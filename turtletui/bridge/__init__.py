"""turtletui on a real ROS 2 graph (``turtletui sim --ros``, ``turtletui run --ros``).

The simulation stays turtletui's own (``turtletui.runtime.simulation``); a
twin process started with a ROS 2 python (``ros_node.py``: the real rclpy,
no turtletui) gives each of its nodes a real twin on the DDS graph and
passes messages, service calls, goals, parameters and logs both ways
(``host.RosBridge``). Other processes' and machines' nodes show in the
simulation's graph, so the app's panels and its ros2 command line see them.

Nothing here imports rclpy: turtletui's Python and packages never meet
ROS's, and turtletui's own rclpy-shaped modules (``turtletui.compat``) never
reach the twin's process.
"""
