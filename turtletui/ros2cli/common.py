"""What every ``ros2`` verb shares: the result type, the one-line error, name
hints, and look-ups in the graph that fail with a clear sentence."""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeVar

from turtletui.compat.distro import lacks_package_of, missing_package_reason, ros_type_name
from turtletui.graph.core import Graph, Topic
from turtletui.graph.introspection import GraphSnapshot, NodeInfo, snapshot
from turtletui.interfaces import Action, Message, Service, get_interface, interface_name

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli
    from turtletui.ros2cli.streams import Stream

T = TypeVar("T")


@dataclass
class CommandResult:
    """What one command printed at once, whether it failed, and what goes on."""

    lines: list[str] = field(default_factory=list)
    error: bool = False
    """True when the command failed; ``lines`` is then exactly one line."""
    stream: Stream | None = None
    """Set for commands that keep printing (echo, hz, pub, call, send_goal)."""


class CommandError(Exception):
    """A verb's one-line error (the dispatcher puts ``ros2 topic echo: `` before it)."""


class PlainError(CommandError):
    """An error printed as it is, without the command's name (as ros2 prints
    ``Parameter not set.`` or ``Setting parameter failed: ...``)."""


def name_list(entries: Sequence, *, count: bool, show_types: bool, hidden: bool = True) -> CommandResult:
    """What ``ros2 topic|service|action list`` prints: names (``-t``: with
    their types), or how many (``-c``); hidden names only with ``hidden``."""
    shown = [e for e in entries if hidden or not is_hidden(e.name)]
    if count:
        return CommandResult([str(len(shown))])
    return CommandResult([f"{e.name} [{', '.join(types_of(e))}]" if show_types else e.name for e in shown])


def types_of(entry: Any) -> list[str]:
    """The types of a listed topic, service or action (a topic may carry several)."""
    return getattr(entry, "types", None) or [entry.type]


def error(line: str) -> CommandResult:
    return CommandResult([line], error=True)


def hint(name: str, known: Sequence[str], quote: bool = False) -> str:
    """`` (did you mean /turtle1/pose?)`` for a close match, else ''."""
    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.6)
    if not close:
        return ""
    return f" (did you mean '{close[0]}'?)" if quote else f" (did you mean {close[0]}?)"


def absolute(name: str) -> str:
    """ros2 resolves relative names against the root namespace."""
    return name if name.startswith("/") else f"/{name}"


def is_hidden(name: str) -> bool:
    """ROS hides names with a part that starts with '_' (``/_ros2cli_1``)."""
    return any(part.startswith("_") for part in name.split("/"))


def one_line(text: str) -> str:
    """An exception's text as one line, pointing at ros2 commands rather than
    the Python helpers it may name."""
    text = " ".join(text.split())
    return re.sub(r"\(see all_interfaces\(\) for the (\d+) known types\)",
                  r"(see 'ros2 interface list' for the \1 known types)", text)


# -- look-ups -------------------------------------------------------------------------

def live_topic(graph: Graph, name: str) -> Topic | None:
    """The topic if some node publishes or subscribes to it (ROS forgets the rest)."""
    topic = graph.topics.get(name)
    if topic is None or not (topic.publishers or topic.subscriptions):
        return None
    return topic


def live_topic_names(graph: Graph) -> list[str]:
    return sorted(n for n, t in graph.topics.items() if t.publishers or t.subscriptions)


def topic_or_error(graph: Graph, name: str, what: str) -> Topic:
    topic = live_topic(graph, name)
    if topic is None:
        raise CommandError(f"topic '{name}' {what}{hint(name, live_topic_names(graph))}")
    return topic


def one_typed_topic(cli: Any, name: str, what: str, message_type: str | None) -> Topic:
    """The channel of live topic ``name`` that ``echo`` or ``hz`` listens to:
    the one of ``message_type`` when given, else its only type (ros2topic
    refuses a name with several: which would it choose?)."""
    first = topic_or_error(cli.graph, name, what)
    channels = [t for t in cli.graph.channels_of(name) if t.publishers or t.subscriptions]
    if message_type is None:
        if len(channels) > 1:
            types = ", ".join(sorted(t.type_name for t in channels))
            raise CommandError(f"Cannot echo topic '{name}', as it contains more than one type: [{types}]")
        return first
    cls = interface_or_error(cli, message_type, Message, "message")
    wanted = type_name(cli, cls)
    for channel in channels:
        if channel.type_name == wanted:
            return channel
    raise CommandError(f"topic '{name}' has type {', '.join(sorted(t.type_name for t in channels))}, not {wanted}")


def ros_view(cli: Any) -> GraphSnapshot:
    """The graph as the ros2 tools show it: every node with what rcl gives it
    (/rosout, /parameter_events, the parameter services ...), which
    turtletui's graph keeps for every node (turtletui.graph.simulated_node,
    turtletui.compat.node), and the hidden topics and services behind every
    action (``<action>/_action/...``)."""
    return snapshot(cli.graph, action_endpoints=True)


def action_behind(name: str) -> str | None:
    """The action whose hidden topic or service ``name`` is
    (``/turtle1/rotate_absolute`` for ``/turtle1/rotate_absolute/_action/status``), or None."""
    action, marker, _ = name.rpartition("/_action/")
    return action if marker and action else None


def action_type_shown(graph: Graph, action: str) -> str:
    """The type of ``action`` as ``ros2 action send_goal`` takes it, or TYPE if no server offers it."""
    return dict(graph.action_names_and_types()).get(action, ["TYPE"])[0]


def hidden_error(kind: str, verb: str, name: str) -> CommandError:
    """A hidden name a verb was not told to consider, said in one line (ros2
    ``topic type`` exits 1 and ``service info`` says ``Unknown service``)."""
    return CommandError(
        f"{kind} '{name}' is hidden (a part of its name starts with '_'): "
        f"try 'ros2 {kind} --include-hidden-{kind}s {verb} {name}'"
    )


def node_or_error(snap: GraphSnapshot, name: str) -> NodeInfo:
    wanted = absolute(name)
    for node in snap.nodes:
        if node.name == wanted:
            return node
    raise CommandError(f"node '{wanted}' not found{hint(wanted, [n.name for n in snap.nodes])}")


def visible_nodes(snap: GraphSnapshot) -> list[NodeInfo]:
    return [n for n in snap.nodes if not n.name.rsplit("/", 1)[-1].startswith("_")]


def entity_or_error(table: Mapping[str, T], name: str, kind: str, what: str) -> T:
    """The service (or action server...) called ``name`` in one of the graph's
    tables; else ``service '/spwn' is not available (did you mean /spawn?)``."""
    name = absolute(name)
    found = table.get(name)
    if found is None:
        raise CommandError(f"{kind} '{name}' {what}{hint(name, sorted(table))}")
    return found


def kind_word(cls: type) -> str:
    if issubclass(cls, Service):
        return "service"
    if issubclass(cls, Action):
        return "action"
    return "message"


def interface_or_error(cli: Ros2Cli, name: str, base: type, what: str) -> type:
    """The interface class called ``name``; it must be a ``what`` (message...)
    type of the run's distro (ros2cli's own sentence when its package is not)."""
    if lacks_package_of(name, cli.distro):
        raise CommandError(f"The passed {what} type is invalid ({missing_package_reason(cli.distro)})")
    cls = get_interface(name)
    if not issubclass(cls, base):
        raise CommandError(f"'{name}' is a {kind_word(cls)} type, not a {what} type")
    return cls


def type_name(cli: Ros2Cli, cls: type) -> str:
    """The full name of an interface class as the run's distro has it."""
    return ros_type_name(interface_name(cls), cli.distro)


def message_repr(cli: Ros2Cli, msg: Any) -> str:
    """``repr(msg)`` with the package names of the run's distro
    (``turtlesim_msgs.srv.Spawn_Request(...)`` from Kilted on), whatever the
    names this process's messages print with."""
    text, cls = repr(msg), type(msg)
    prefix = getattr(cls, "_REPR_PREFIX", "")
    if not prefix or not text.startswith(prefix):
        return text
    return type_name(cli, cls).replace("/", ".") + text[len(prefix):]


def check_type(cli: Ros2Cli, cls: type, actual: str, what: str) -> None:
    """The type a user named must be the one the graph has."""
    wanted = type_name(cli, cls)
    if wanted != actual:
        raise CommandError(f"{what} has type {actual}, not {wanted}")
