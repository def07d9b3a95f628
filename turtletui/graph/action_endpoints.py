"""The hidden topics and services behind every action, as rcl_action makes them.

An action server publishes ``<action>/_action/feedback`` (``<Action>_FeedbackMessage``)
and ``<action>/_action/status`` (``action_msgs/msg/GoalStatusArray``) and serves
``<action>/_action/send_goal``, ``cancel_goal`` and ``get_result``; an action client
subscribes to the two topics and is a client of the three services. rclpy's
graph queries list them (``get_topic_names_and_types``, ``count_publishers`` ...);
their names are hidden (a part starts with "_"), so ros2's list verbs show them
only when asked and rqt_graph not at all.

turtletui's graph carries goals, feedback and results itself (Graph.send_goal),
so nothing travels on these endpoints: the graph's queries derive them from its
action servers and clients (Graph.action_topic_endpoints and
action_service_endpoints), which every host mirrors.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

from turtletui.graph.qos import DEFAULT, Policies

if TYPE_CHECKING:
    from turtletui.graph.core import ActionClientRecord, ActionServer, NodeRecord

FEEDBACK_QOS = DEFAULT
"""The feedback topic's (rmw_qos_profile_default, depth 10: rclpy's and rclcpp_action's)."""
STATUS_QOS = Policies.named("reliable", "transient_local")
"""The status topic's (rcl_action_qos_profile_status_default: reliable, transient local, depth 1)."""


class ActionTopic(NamedTuple):
    """A hidden topic of an action, as the graph's queries name it."""

    name: str
    type_name: str


class ActionTopicEndpoint(NamedTuple):
    """A publisher (server) or subscription (client) of a hidden action topic; it
    reads as a graph Publisher or Subscription does for the queries."""

    node: NodeRecord
    topic: ActionTopic
    qos: Policies
    depth: int
    owner: str


class ActionServiceEndpoint(NamedTuple):
    """A server (action server) or client (action client) of a hidden action service."""

    node: NodeRecord
    name: str
    type_name: str
    owner: str


def topic_endpoints(record: ActionServer | ActionClientRecord) -> tuple[ActionTopicEndpoint, ...]:
    """The feedback and status endpoints of an action server (publishers) or client (subscriptions)."""
    action, type_name = record.name, record.type_name
    return (
        ActionTopicEndpoint(
            record.node, ActionTopic(f"{action}/_action/feedback", f"{type_name}_FeedbackMessage"),
            FEEDBACK_QOS, 10, record.owner,
        ),
        ActionTopicEndpoint(
            record.node, ActionTopic(f"{action}/_action/status", "action_msgs/msg/GoalStatusArray"),
            STATUS_QOS, 1, record.owner,
        ),
    )


def service_endpoints(record: ActionServer | ActionClientRecord) -> tuple[ActionServiceEndpoint, ...]:
    """The send_goal, cancel_goal and get_result endpoints of an action server
    (servers) or client (clients)."""
    action, type_name = record.name, record.type_name
    return tuple(
        ActionServiceEndpoint(record.node, name, service_type, record.owner)
        for name, service_type in (
            (f"{action}/_action/send_goal", f"{type_name}_SendGoal"),
            (f"{action}/_action/cancel_goal", "action_msgs/srv/CancelGoal"),
            (f"{action}/_action/get_result", f"{type_name}_GetResult"),
        )
    )
