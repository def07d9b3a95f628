"""The nodes the simulator runs itself (turtlesim, teleop_turtle, rosbag2's
player and recorder, foxglove_bridge, ros2cli's hidden nodes), with what rcl
and their client library give every node on a real graph.

An rclcpp node (rclcpp::Node, read in node.cpp, node_parameters.cpp,
time_source.cpp and node_type_descriptions.cpp) has a ``/rosout``
publisher, a ``/parameter_events`` publisher and subscription (its
TimeSource's), the six parameter services, ``~/get_type_description`` (Iron
on), and the parameters ``use_sim_time``, ``start_type_description_service``
and ``qos_overrides./parameter_events.publisher.*`` (declared "so they are
visible") before its own. ros2cli's nodes are rclpy's: no parameter
services, no ``/parameter_events`` subscription, no ``qos_overrides``.

A successful set of a parameter (``ros2 param set``, a parameter client)
publishes a ParameterEvent; the declarations at start-up publish none (no
other process could have discovered the new node yet).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from turtletui.graph.core import NS_PER_S, Graph, NodeRecord, Publisher, Service
from turtletui.graph.parameter_services import rclcpp_refusal, serve_parameters, value_message
from turtletui.graph.qos import Policies
from turtletui.graph.type_description_service import PARAMETER as TYPE_DESCRIPTION_PARAMETER
from turtletui.graph.type_description_service import serve_type_descriptions
from turtletui.interfaces.builtin_interfaces import Time
from turtletui.interfaces.rcl_interfaces import (
    Log,
    Parameter,
    ParameterDescriptor,
    ParameterEvent,
    ParameterType,
)

PLUMBING_DEPTH = 1000
"""rcl's depth for /rosout and /parameter_events."""
ROSOUT_QOS = Policies.named("reliable", "transient_local")
"""rcl's /rosout publisher: reliable, transient local (keep last 1000)."""
PARAMETER_EVENTS = "/parameter_events"
USE_SIM_TIME = "use_sim_time"

OwnParameter = tuple[str, Any, ParameterDescriptor]
"""A parameter a node declares itself: name, value, descriptor (its type set)."""


def _declared(name: str, value: Any, kind: int, description: str = "", *, read_only: bool = False) -> OwnParameter:
    return name, value, ParameterDescriptor(name=name, type=kind, description=description, read_only=read_only)


def rclcpp_parameters(type_descriptions: bool = True) -> list[OwnParameter]:
    """What rclcpp::Node declares, in its order: its TimeSource's ``use_sim_time``,
    NodeTypeDescriptions' ``start_type_description_service`` (Iron on:
    ``type_descriptions``), and the QoS of its /parameter_events publisher
    (durability, history, depth, reliability, as declare_qos_parameters goes
    through a publisher's policies)."""
    prefix = f"qos_overrides.{PARAMETER_EVENTS}.publisher."
    qos = (
        ("durability", "volatile", ParameterType.PARAMETER_STRING),
        ("history", "keep_last", ParameterType.PARAMETER_STRING),
        ("depth", PLUMBING_DEPTH, ParameterType.PARAMETER_INTEGER),
        ("reliability", "reliable", ParameterType.PARAMETER_STRING),
    )
    started = _declared(
        TYPE_DESCRIPTION_PARAMETER, True, ParameterType.PARAMETER_BOOL,
        "Start the ~/get_type_description service for this node.", read_only=True,
    )
    return [
        _declared(USE_SIM_TIME, False, ParameterType.PARAMETER_BOOL),
        *([started] if type_descriptions else []),
        *(
            _declared(prefix + policy, value, kind, f"qos policy {{{policy}}} for publisher {{{PARAMETER_EVENTS}}}",
                      read_only=True)
            for policy, value, kind in qos
        ),
    ]


def rclpy_parameters(type_descriptions: bool = True) -> list[OwnParameter]:
    """What an rclpy node declares itself: ``use_sim_time`` and (Iron on:
    ``type_descriptions``) ``start_type_description_service``."""
    started = _declared(
        TYPE_DESCRIPTION_PARAMETER, True, ParameterType.PARAMETER_BOOL,
        "If enabled, start the ~/get_type_description service.", read_only=True,
    )
    return [_declared(USE_SIM_TIME, False, ParameterType.PARAMETER_BOOL), *([started] if type_descriptions else [])]


def _ignore_event(event: Any) -> None:
    """rclcpp's own /parameter_events subscription (its TimeSource's): nothing here needs it."""


class SimulatedNode:
    """A node of the simulator's on ``graph``: ``parameters`` are its own
    (after the built-in ones); ``on_set(name, value)`` applies a set of one of
    them (its own checks and what the value changes), returning why it
    refuses, or None; without it a set must pass rclcpp's checks (declared,
    type, read-only, range). An accepted value is recorded on the graph.
    ``use_sim_time`` can only stay false: the simulator's nodes keep its clock."""

    def __init__(
        self,
        graph: Graph,
        name: str,
        owner: str,
        *,
        namespace: str = "",
        rclcpp: bool = True,
        parameters: Iterable[OwnParameter] = (),
        on_set: Callable[[str, Any], str | None] | None = None,
    ) -> None:
        self.graph = graph
        # ros2cli's rclpy nodes serve no parameters: nothing outside can set them
        self.node: NodeRecord = graph.add_node(
            name, namespace, owner, parameter_setter=self.set_parameter if rclcpp else None, rclcpp=rclcpp
        )
        self._on_set = on_set
        served = graph.type_description_names is not None  # Iron on
        builtin = rclcpp_parameters(served) if rclcpp else rclpy_parameters(served)
        self._builtin = {parameter for parameter, _, _ in builtin}
        self.descriptors: dict[str, ParameterDescriptor] = {}
        for parameter, value, descriptor in [*builtin, *parameters]:
            self.descriptors[parameter] = descriptor
            graph.set_parameter(self.node, parameter, value)
        self.parameter_services: list[Service] = (
            serve_parameters(graph, self.node, self.descriptors) if rclcpp else []
        )
        self.type_descriptions: Service | None = None
        if served:
            self.type_descriptions = serve_type_descriptions(graph, self.node, graph.type_description_names)
        self.rosout: Publisher = graph.add_publisher(self.node, "/rosout", Log, PLUMBING_DEPTH, qos=ROSOUT_QOS)
        self.parameter_events: Publisher = graph.add_publisher(
            self.node, PARAMETER_EVENTS, ParameterEvent, PLUMBING_DEPTH
        )
        if rclcpp:
            graph.add_subscription(self.node, PARAMETER_EVENTS, ParameterEvent, PLUMBING_DEPTH, _ignore_event)

    @property
    def fqn(self) -> str:
        return self.node.fqn

    def set_parameter(self, name: str, value: Any) -> str | None:
        """Set one of the node's parameters (``ros2 param set``, the parameter
        services); returns why it refuses, or None."""
        if name not in self._builtin and self._on_set is not None:
            reason = self._on_set(name, value)
        else:
            reason = rclcpp_refusal(Parameter(name=name, value=value_message(value)), self.descriptors.get(name),
                                    self.node)
            if not reason and name == USE_SIM_TIME and value:
                reason = f"{self.fqn} keeps the simulation's clock: use_sim_time can only be false here"
        if reason:
            return reason
        self.graph.set_parameter(self.node, name, value)
        now = self.graph.stamp_ns
        event = ParameterEvent(
            stamp=Time(sec=now // NS_PER_S, nanosec=now % NS_PER_S),
            node=self.fqn,
            changed_parameters=[Parameter(name=name, value=value_message(value))],
        )
        self.graph.publish(self.parameter_events.topic, event, publisher=self.parameter_events)
        return None

    def stop_type_description_service(self) -> None:
        """What ``-p start_type_description_service:=false`` does: no ``~/get_type_description``."""
        if self.type_descriptions is not None:
            self.graph.remove_service(self.type_descriptions)
            self.type_descriptions = None
        self.graph.set_parameter(self.node, TYPE_DESCRIPTION_PARAMETER, False)
