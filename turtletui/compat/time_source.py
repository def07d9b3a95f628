"""``rclpy.time_source.TimeSource``: a node's ``use_sim_time`` parameter and /clock.

As in rclpy, every node declares ``use_sim_time`` (default false). While it is
true the node's ROS clock reads the last rosgraph_msgs/msg/Clock received on
/clock, and 0 until one arrives: on ROS 2 without a simulator or
``ros2 bag play --clock`` publishing /clock, time stands still. turtletui
publishes no /clock of its own (its time is simulated anyway), so the first
node of a program to turn use_sim_time on while nothing publishes /clock
gets a one-time [turtletui] note saying why its time stands still. The
node's timers and rates follow the same clock (turtletui.compat.timer).
"""

from __future__ import annotations

import weakref
from typing import Any

from turtletui.compat.parameter import Parameter, SetParametersResult
from turtletui.compat.qos import QoSProfile, ReliabilityPolicy
from turtletui.compat.time import ClockType, ROSClock, Time
from turtletui.graph.logs import WARN

CLOCK_TOPIC = "/clock"
USE_SIM_TIME_NAME = "use_sim_time"

_NO_CLOCK = (
    "{node} uses simulated time (use_sim_time is true) but nothing publishes {topic} yet, so its clock "
    "reads 0 and stands still, and its timers wait, until something does, as on ROS 2 without a simulator or `ros2 bag play "
    "--clock`. turtletui's own time needs no /clock: leave use_sim_time false, or publish "
    "rosgraph_msgs/msg/Clock on {topic}."
)


class TimeSource:
    """Drives the ROS clocks attached to it from /clock while use_sim_time is true."""

    def __init__(self, *, node: Any = None) -> None:
        self._clock_sub: Any = None
        self._node_weak_ref: Any = None
        self._associated_clocks: set[ROSClock] = set()
        self._last_time_set = Time(clock_type=ClockType.ROS_TIME)
        self._ros_time_is_active = False
        if node is not None:
            self.attach_node(node)

    @property
    def ros_time_is_active(self) -> bool:
        return self._ros_time_is_active

    @ros_time_is_active.setter
    def ros_time_is_active(self, enabled: bool) -> None:
        if self._ros_time_is_active == enabled:
            return
        self._ros_time_is_active = enabled
        for clock in self._associated_clocks:
            clock._set_ros_time_is_active(enabled)
        if enabled:
            self._subscribe_to_clock_topic()
        elif self._clock_sub is not None:
            node = self._get_node()
            if node is not None:
                node.destroy_subscription(self._clock_sub)
            self._clock_sub = None

    def _subscribe_to_clock_topic(self) -> None:
        if self._clock_sub is not None:
            return
        node = self._get_node()
        if node is None:
            return
        from turtletui.interfaces.rosgraph_msgs import Clock

        self._clock_sub = node.create_subscription(
            Clock, CLOCK_TOPIC, self.clock_callback, QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
        )
        _tell_if_no_clock(node)

    def attach_node(self, node: Any) -> None:
        """Declare ``node``'s use_sim_time (if it has none) and follow it."""
        if self._node_weak_ref is not None:
            self.detach_node()
        self._node_weak_ref = weakref.ref(node)
        if not node.has_parameter(USE_SIM_TIME_NAME):
            node.declare_parameter(USE_SIM_TIME_NAME, False)
        param = node.get_parameter(USE_SIM_TIME_NAME)
        if param.type_ is Parameter.Type.BOOL:
            self.ros_time_is_active = param.value
        elif param.type_ is not Parameter.Type.NOT_SET:
            node.get_logger().error(f"Invalid type for parameter '{USE_SIM_TIME_NAME}' {param.type_!r} should be bool")
        node.add_on_set_parameters_callback(self._on_parameter_event)

    def detach_node(self) -> None:
        if self._clock_sub is not None:
            node = self._get_node()
            if node is None:
                raise RuntimeError("Unable to destroy previously created clock subscription")
            node.destroy_subscription(self._clock_sub)
        self._clock_sub = None
        self._node_weak_ref = None

    def attach_clock(self, clock: ROSClock) -> None:
        if not isinstance(clock, ROSClock):
            raise ValueError("Only clocks with type ROS_TIME can be attached.")
        clock.set_ros_time_override(self._last_time_set)
        clock._set_ros_time_is_active(self._ros_time_is_active)
        self._associated_clocks.add(clock)

    def clock_callback(self, msg: Any) -> None:
        self._last_time_set = Time.from_msg(msg.clock)
        for clock in self._associated_clocks:
            clock.set_ros_time_override(self._last_time_set)

    def _on_parameter_event(self, parameter_list: list[Parameter]) -> SetParametersResult:
        for parameter in parameter_list:
            if parameter.name == USE_SIM_TIME_NAME:
                if parameter.type_ is Parameter.Type.BOOL:
                    self.ros_time_is_active = parameter.value
                    break
                reason = f"{USE_SIM_TIME_NAME} parameter set to something besides a bool"
                node = self._get_node()
                if node is not None:
                    node.get_logger().error(reason)
                return SetParametersResult(successful=False, reason=reason)
        return SetParametersResult(successful=True, reason="")

    def _get_node(self) -> Any:
        return self._node_weak_ref() if self._node_weak_ref is not None else None


def _tell_if_no_clock(node: Any) -> None:
    """The one-time note of a program whose clock stopped for want of /clock."""
    context = node.context
    if context.told_no_clock or node.count_publishers(CLOCK_TOPIC):
        return
    context.told_no_clock = True
    text = _NO_CLOCK.format(node=node.get_fully_qualified_name(), topic=CLOCK_TOPIC)
    node._graph.log("turtletui", WARN, text)
