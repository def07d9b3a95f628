"""``~/get_type_description``: the service every node serves from ROS 2 Iron on.

A node answers with the full description (and, if asked, the source files)
of a type it uses, found by its ``RIHS01_`` hash: the types of its
publishers, subscriptions, services, clients and actions, rcl's own
included (/rosout, /parameter_events, the parameter services, this
service). The answers are rcl's: ``"Failed to parse type hash"`` (with an
error line from the ``rcl`` logger) for a malformed hash, ``"Type not
currently in use by this node"`` for an unknown one; the type name of a
request is not looked at. Controllers' nodes serve it through rclpy's
TypeDescriptionService (turtletui.compat.type_description_service);
turtlesim through :func:`serve_type_descriptions`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from turtletui.graph.core import Graph, NodeRecord, Service
from turtletui.graph.logs import ERROR
from turtletui.interfaces import from_dict
from turtletui.interfaces.type_description_interfaces import (
    GetTypeDescription,
    TypeDescription,
    TypeSource,
)
from turtletui.interfaces.type_descriptions import Names, type_description, type_hash, type_sources

SERVICE = "get_type_description"
PARAMETER = "start_type_description_service"
"""The read-only parameter that turns the service off (``false``) when a node starts."""
HASH_PREFIX = "RIHS01_"
_HEX = frozenset("0123456789abcdefABCDEF")


def is_type_description_service(service: Service) -> bool:
    """Whether ``service`` is its node's ``~/get_type_description``."""
    return service.name == f"{service.node.fqn}/{SERVICE}"


def parse_type_hash(text: str) -> str | None:
    """``text`` as rosidl_parse_type_hash_string reads it (``RIHS01_`` and 64 hex
    digits, either case), in lower case; None if it refuses it."""
    if len(text) != len(HASH_PREFIX) + 64 or not text.startswith("RIHS") or text[4:6] != "01":
        return None
    value = text[len(HASH_PREFIX):]
    return "RIHS01_" + value.lower() if _HEX.issuperset(value) else None


def types_in_use(graph: Graph, node: NodeRecord) -> list[type]:
    """The interface classes ``node``'s endpoints on ``graph`` use, as rcl's type
    cache holds them: an action also brings the services and topics it is made of."""
    found: list[type] = []
    for topic in graph.channels():
        if any(p.node is node for p in topic.publishers) or any(s.node is node for s in topic.subscriptions):
            found.append(topic.msg_type)
    found += [s.srv_type for s in graph.services.values() if s.node is node]
    found += [c.srv_type for c in graph.clients if c.node is node]
    for action in [*graph.action_servers.values(), *graph.action_clients]:
        if action.node is node:
            impl = action.action_type.Impl
            found += [action.action_type, impl.SendGoalService, impl.GetResultService, impl.CancelGoalService,
                      impl.FeedbackMessage, impl.GoalStatusMessage]
    return found


def answer(request: Any, in_use: Iterable[type], names: Names = (), log_error: Callable[[str], None] | None = None) -> Any:
    """rcl's answer to a GetTypeDescription request from a node using the
    types ``in_use`` (``names``: package renames, see type_descriptions.Names)."""
    response = GetTypeDescription.Response()
    wanted = parse_type_hash(request.type_hash)
    if wanted is None:
        if log_error is not None:
            log_error(f"Failed to parse type hash '{request.type_hash}'")
        response.failure_reason = "Failed to parse type hash"
        return response
    cls = next((cls for cls in in_use if type_hash(cls, None, names) == wanted), None)
    if cls is None:
        response.failure_reason = "Type not currently in use by this node"
        return response
    response.type_description = from_dict(TypeDescription, type_description(cls, None, names))
    if request.include_type_sources:
        response.type_sources = [from_dict(TypeSource, source) for source in type_sources(cls, names)]
    response.successful = True
    return response


def serve_type_descriptions(graph: Graph, node: NodeRecord, names: Names = ()) -> Service:
    """Serve ``<node>/get_type_description`` for a node the graph runs itself
    (turtlesim, an rclcpp node); a malformed hash is logged as the ``rcl`` logger."""

    def handle(request: Any, respond: Callable[[Any], None]) -> None:
        respond(answer(request, types_in_use(graph, node), names, lambda text: graph.log("rcl", ERROR, text)))

    return graph.add_service(node, f"{node.fqn}/{SERVICE}", GetTypeDescription, handle)
