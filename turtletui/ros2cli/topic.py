"""``ros2 topic``: list, echo, hz, info, type, find, pub."""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from typing import TYPE_CHECKING, Any

from turtletui.compat.distro import type_description_names
from turtletui.compat.graph_info import TopicEndpointTypeEnum, endpoints_info, gid_text
from turtletui.graph.core import NS_PER_S
from turtletui.graph.introspection import TopicInfo
from turtletui.graph.qos import policy_names
from turtletui.interfaces import Message, get_interface
from turtletui.interfaces.rcl_interfaces import Log
from turtletui.interfaces.type_descriptions import type_hash
from turtletui.ros2cli.arguments import (
    Command,
    Verb,
    list_options,
    nonnegative_int,
    positive_float,
    positive_int,
)
from turtletui.ros2cli.common import (
    CommandError,
    CommandResult,
    absolute,
    action_behind,
    action_type_shown,
    check_type,
    hidden_error,
    hint,
    interface_or_error,
    is_hidden,
    live_topic,
    live_topic_names,
    name_list,
    one_typed_topic,
    ros_view,
    topic_or_error,
    type_name,
)
from turtletui.ros2cli.qos_args import add_qos_arguments, asked_qos, echo_qos
from turtletui.ros2cli.streams import EchoStream, HzStream, PubStream, RosoutEchoStream
from turtletui.ros2cli.values import message_values

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

MAX_PUB_RATE_HZ = 100.0
"""``ros2 topic pub -r`` is capped here so a typo cannot flood the graph."""

HZ_WINDOW = 10000
"""ros2topic's DEFAULT_WINDOW_SIZE."""


# -- list ----------------------------------------------------------------------------

def _list_arguments(parser: ArgumentParser) -> None:
    list_options(parser, "topic", "--count-topics", "--include-hidden-topics")


def _list(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    return name_list(ros_view(cli).topics, count=args.count_topics, show_types=args.show_types,
                     hidden=args.include_hidden_topics)


# -- echo ----------------------------------------------------------------------------

def _echo_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("topic_name", help="Name of the ROS topic to listen to (e.g. '/chatter')")
    parser.add_argument("message_type", nargs="?",
                        help="Type of the ROS message (e.g. 'std_msgs/msg/String')")
    add_qos_arguments(parser, "subscribe", "sensor_data")
    parser.add_argument("--field", type=str, default=None,
                        help="Echo a selected field of a message. Use '.' to select sub-fields. "
                             "For example, to echo the position field of a nav_msgs/msg/Odometry "
                             "message: 'ros2 topic echo /odom --field pose.pose.position'")
    parser.add_argument("--once", action="store_true",
                        help="Print the first message received and then exit.")


def _echo(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    name = absolute(args.topic_name)
    if name == "/rosout" and any(t.name == name for t in ros_view(cli).topics):  # logs are not messages here
        if args.message_type is not None:
            check_type(cli, interface_or_error(cli, args.message_type, Message, "message"), "rcl_interfaces/msg/Log", f"topic '{name}'")
        path = _field_path(cli, Log, args.field) if args.field is not None else []
        return cli.start(RosoutEchoStream(cli, line, None, args.once, path))
    _refuse_action_topic(cli, name)
    topic = one_typed_topic(cli, name, "does not appear to be published yet", args.message_type)
    path = _field_path(cli, topic.msg_type, args.field) if args.field is not None else []
    qos, depth, notes = echo_qos(args, topic.publishers)
    result = cli.start(EchoStream(cli, line, topic, args.once, path, qos, depth))
    result.lines[:0] = notes
    return result


def _field_path(cli: Ros2Cli, cls: type, text: str) -> list[str]:
    path = [part for part in text.split(".") if part]
    if not path:
        raise CommandError(f"Invalid field value '{text}'")
    current: Any = cls
    for part in path:
        specs = {s.name: s for s in getattr(current, "_FIELDS", ())}
        if part not in specs:
            names = ", ".join(specs) or "none"
            raise CommandError(f"invalid field '{text}' of {type_name(cli, cls)} (fields: {names})")
        current = specs[part].msg_cls if specs[part].kind == "msg" and not specs[part].array else None
    return path


# -- hz ------------------------------------------------------------------------------

def _hz_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("topic_name", help="Name of the ROS topic to listen to (e.g. '/chatter')")
    parser.add_argument("--window", "-w", dest="window_size", type=positive_int, default=HZ_WINDOW,
                        metavar="WINDOW",
                        help=f"window size, in # of messages, for calculating rate (default: {HZ_WINDOW})")


def _hz(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    name = absolute(args.topic_name)
    _refuse_action_topic(cli, name)
    topic = one_typed_topic(cli, name, "does not appear to be published yet", None)
    return cli.start(HzStream(cli, line, topic, args.window_size))


def _refuse_action_topic(cli: Ros2Cli, name: str) -> None:
    """An action's hidden feedback or status topic carries nothing in turtletui
    (its graph hands goals, feedback and results over itself): echoing, timing
    or publishing there would wait forever. Say so, and what shows them instead."""
    action = action_behind(name)
    graph = cli.graph
    if action is None or live_topic(graph, name) is not None:
        return
    if graph.publishers_of(name) or graph.subscriptions_of(name):
        raise CommandError(
            f"turtletui sends nothing on the hidden topics of action '{action}': 'ros2 action send_goal "
            f"--feedback {action} {action_type_shown(graph, action)} GOAL' prints a goal's feedback and result"
        )


# -- info, type, find ------------------------------------------------------------------

def _info_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("topic_name", help="Name of the ROS topic to get info (e.g. '/chatter')")
    parser.add_argument("--verbose", "-v", action="store_true",
                        help="Prints detailed information like the node name, node namespace, "
                             "topic type, GUID and QoS Profile of the publishers and subscribers "
                             "to this topic")


def _shown_topic(cli: Ros2Cli, name: str) -> TopicInfo:
    """The topic as ros2 shows it: a live one, /rosout or /parameter_events
    (which turtletui's graph may not keep), or an action's hidden one."""
    found = next((t for t in ros_view(cli).topics if t.name == name), None)
    if found is None:
        topic_or_error(cli.graph, name, "does not exist")  # raises, with a hint
    return found


def _info(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    # ros2 topic info considers hidden topics always
    name = absolute(args.topic_name)
    shown = _shown_topic(cli, name)
    graph = cli.graph
    publishers, subscriptions = graph.publishers_of(name), graph.subscriptions_of(name)
    types = shown.types
    type_line = f"Type: {types[0] if len(types) == 1 else types}"  # several: as a Python list, as ros2topic
    if not args.verbose or not (publishers or subscriptions):
        return CommandResult([type_line, f"Publisher count: {len(shown.publishers)}",
                              f"Subscription count: {len(shown.subscribers)}"])
    lines = [type_line, ""]
    for title, kind, endpoints in (("Publisher", TopicEndpointTypeEnum.PUBLISHER, publishers),
                                   ("Subscription", TopicEndpointTypeEnum.SUBSCRIPTION, subscriptions)):
        lines += [f"{title} count: {len(endpoints)}", ""]
        # the GIDs a program's get_*_info_by_topic gives them
        for endpoint, info in zip(endpoints, endpoints_info(endpoints, kind), strict=True):
            reliability, durability = policy_names(endpoint.qos)
            lines += [
                f"Node name: {endpoint.node.name}",
                f"Node namespace: {endpoint.node.namespace or '/'}",
                f"Topic type: {endpoint.topic.type_name}",
                *_hash_line(cli, endpoint.topic.type_name),
                f"Endpoint type: {kind.name}",
                f"GID: {gid_text(info.endpoint_gid)}",
                "QoS profile:",
                f"  Reliability: {reliability}",
                "  History (Depth): UNKNOWN",  # what Fast DDS shares of another endpoint
                f"  Durability: {durability}",
                "  Lifespan: Infinite",
                "  Deadline: Infinite",
                "  Liveliness: AUTOMATIC",
                "  Liveliness lease duration: Infinite",
                "",
            ]
    return CommandResult(lines)


def _hash_line(cli: Ros2Cli, name: str) -> list[str]:
    """``Topic type hash: RIHS01_...`` as ros2 prints it from Iron on (none in Humble)."""
    names = type_description_names(cli.distro)
    if names is None:
        return []
    return [f"Topic type hash: {type_hash(get_interface(name), None, names)}"]


def _type_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("topic_name", help="Name of the ROS topic to get type (e.g. '/chatter')")


def _type(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    name = absolute(args.topic_name)
    shown = _shown_topic(cli, name)
    if is_hidden(name) and not args.include_hidden_topics:
        raise hidden_error("topic", "type", name)
    return CommandResult(shown.types)


def _find_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("topic_type",
                        help="Name of the ROS topic type to filter for (e.g. 'std_msg/msg/String')")
    list_options(parser, "topic", "--count-topics", "--include-hidden-topics", show_types=False)


def _find(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    wanted = type_name(cli, interface_or_error(cli, args.topic_type, Message, "message"))
    found = [t for t in ros_view(cli).topics if wanted in t.types]
    return name_list(found, count=args.count_topics, show_types=False, hidden=args.include_hidden_topics)


# -- pub -------------------------------------------------------------------------------

def _pub_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("topic_name", help="Name of the ROS topic to publish to (e.g. '/chatter')")
    parser.add_argument("message_type", help="Type of the ROS message (e.g. 'std_msgs/String')")
    parser.add_argument("values", nargs="?", default="{}",
                        help="Values to fill the message with in YAML format "
                             "(e.g. 'data: Hello World'), otherwise the message will be "
                             "published with default values")
    parser.add_argument("-r", "--rate", metavar="N", type=positive_float, default=1.0,
                        help="Publishing rate in Hz (default: 1)")
    parser.add_argument("-p", "--print", metavar="N", type=int, default=1,
                        help="Only print every N-th published message (default: 1)")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("-1", "--once", action="store_true", help="Publish one message and exit")
    group.add_argument("-t", "--times", type=nonnegative_int, default=0,
                       help="Publish this number of times and then exit")
    parser.add_argument("-w", "--wait-matching-subscriptions", type=nonnegative_int, default=None,
                        help="Wait until finding the specified number of matching subscriptions. "
                             "Defaults to 1 when using \"-1\"/\"--once\"/\"--times\", otherwise defaults to 0.")
    add_qos_arguments(parser, "publish", "default")


def _pub(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    name = absolute(args.topic_name)
    _refuse_action_topic(cli, name)
    cls = interface_or_error(cli, args.message_type, Message, "message")
    topic = None
    if live_topic(cli.graph, name) is not None:
        topic = one_typed_topic(cli, name, "", args.message_type)  # a type the topic has
    msg = message_values(args.values, cls, "message")
    rate = args.rate
    notes = []
    if rate > MAX_PUB_RATE_HZ:
        notes.append(f"WARNING: rate limited to {MAX_PUB_RATE_HZ:g} Hz in turtletui")
        rate = MAX_PUB_RATE_HZ
    if topic is None or not topic.subscriptions:
        near = hint(name, [n for n in live_topic_names(cli.graph) if n != name])
        if near:
            notes.append(f"WARNING: nothing subscribes to '{name}' yet{near}")
    times = 1 if args.once else args.times
    wait = args.wait_matching_subscriptions
    if wait is None:
        wait = 1 if times else 0
    qos, depth = asked_qos(args)
    result = cli.start(PubStream(cli, line, name, msg, round(NS_PER_S / rate), times, args.print, wait, qos, depth))
    result.lines[:0] = notes
    return result


COMMAND = Command("topic", "Various topic related sub-commands", verbs=(
    Verb("echo", "Output messages from a topic", _echo_arguments, _echo),
    Verb("find", "Output a list of available topics of a given type", _find_arguments, _find),
    Verb("hz", "Print the average publishing rate to screen", _hz_arguments, _hz),
    Verb("info", "Print information about a topic", _info_arguments, _info),
    Verb("list", "Output a list of available topics", _list_arguments, _list),
    Verb("pub", "Publish a message to a topic", _pub_arguments, _pub),
    Verb("type", "Print a topic's type", _type_arguments, _type),
), add_arguments=lambda parser: parser.add_argument(
    "--include-hidden-topics", action="store_true", help="Consider hidden topics as well"))
