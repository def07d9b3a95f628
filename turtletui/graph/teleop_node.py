"""turtle_teleop_key's node, ``teleop_turtle`` (ros_tutorials' teleop_turtle_key.cpp).

An rclcpp node with what every one has (turtletui.graph.simulated_node), its
parameters ``scale_angular`` and ``scale_linear`` (doubles, 2.0), a
``turtle1/cmd_vel`` publisher (reliable, volatile; keep last 1 up to Iron,
turtlesim's ``topic_qos()``, keep last 7, from Jazzy on) and a
``turtle1/rotate_absolute`` action client. The app's arrow keys and a
grading scenario's scripted drive publish from it.
"""

from __future__ import annotations

from typing import Any

from turtletui.graph.core import Graph, Publisher
from turtletui.graph.qos import DEFAULT as DEFAULT_QOS
from turtletui.graph.simulated_node import SimulatedNode
from turtletui.interfaces.geometry_msgs import Twist
from turtletui.interfaces.rcl_interfaces import ParameterDescriptor, ParameterType
from turtletui.interfaces.turtlesim import RotateAbsolute

NAME = "teleop_turtle"
SCALES = ("scale_angular", "scale_linear")
"""Its parameters, in the order it declares them (both 2.0)."""
_CMD_VEL_DEPTH = {"humble": 1, "iron": 1}
"""Its cmd_vel publisher's depth up to Iron; from Jazzy on 7 (turtlesim's topic_qos)."""

HEADINGS = {
    "g": 0.0,
    "t": 0.7854,
    "r": 1.5708,
    "e": 2.3562,
    "d": 3.1416,
    "c": -2.3562,
    "v": -1.5708,
    "b": -0.7854,
}
"""Its rotate_absolute goals by key, as it sends them (rad)."""


class TeleopNode:
    """``teleop_turtle`` on ``graph`` for ``owner``, as in ROS 2 ``distro``."""

    def __init__(self, graph: Graph, owner: str, distro: str, *, turtle: str = "turtle1") -> None:
        self.graph = graph
        self.ros = SimulatedNode(
            graph, NAME, owner,
            parameters=[
                (name, 2.0, ParameterDescriptor(name=name, type=ParameterType.PARAMETER_DOUBLE)) for name in SCALES
            ],
        )
        self.node = self.ros.node
        self.cmd_vel: Publisher = graph.add_publisher(
            self.node, f"/{turtle}/cmd_vel", Twist, _CMD_VEL_DEPTH.get(distro, 7), qos=DEFAULT_QOS
        )
        self.rotate_absolute = graph.add_action_client(self.node, f"/{turtle}/rotate_absolute", RotateAbsolute)

    def key_twist(self, linear: float, angular: float) -> Twist:
        """The Twist an arrow key makes: ``linear`` and ``angular`` (-1, 0 or 1)
        times its ``scale_linear`` and ``scale_angular``, as they are set now."""
        msg = Twist()
        msg.angular.z = self.node.parameters["scale_angular"] * angular
        msg.linear.x = self.node.parameters["scale_linear"] * linear
        return msg

    def publish(self, msg: Any) -> None:
        """Publish ``msg`` on its cmd_vel topic."""
        self.graph.publish(self.cmd_vel.topic, msg, None, self.cmd_vel)
