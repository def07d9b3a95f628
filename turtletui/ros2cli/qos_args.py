"""``ros2 topic echo`` and ``pub``'s QoS options, as ros2topic's api adds and reads them.

``echo`` subscribes with a profile that hears every publisher of the topic
unless told otherwise (its choose_qos); ``pub`` publishes with the profile
asked for, so ``--qos-reliability best_effort`` on ``/turtle1/cmd_vel`` waits
for ever for turtlesim's reliable subscription, as in ROS 2.
"""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from collections.abc import Sequence
from typing import Any

from turtletui.compat.qos import (
    KEEP_ALL_DEPTH,
    DurabilityPolicy,
    HistoryPolicy,
    QoSPresetProfiles,
    ReliabilityPolicy,
)
from turtletui.graph.qos import Policies, adapted, offer_counts
from turtletui.ros2cli.streams import DEFAULT_DEPTH


def add_qos_arguments(parser: ArgumentParser, subscribe_or_publish: str, default_profile: str) -> None:
    """ros2topic.api.add_qos_arguments, liveliness left out (the graph does not model it)."""
    parser.add_argument(
        "--qos-profile", choices=QoSPresetProfiles.short_keys(), default=default_profile,
        help=f"Quality of service preset profile to {subscribe_or_publish} with (default: {default_profile})")
    history = QoSPresetProfiles.get_from_short_key(default_profile).history.short_key
    parser.add_argument(
        "--qos-depth", metavar="N", type=int,
        help=f"Queue size setting to {subscribe_or_publish} with (overrides depth value of --qos-profile option)")
    parser.add_argument(
        "--qos-history", choices=HistoryPolicy.short_keys(),
        help=f"History of samples setting to {subscribe_or_publish} with (overrides history value of "
             f"--qos-profile option, default: {history})")
    parser.add_argument(
        "--qos-reliability", choices=ReliabilityPolicy.short_keys(),
        help=f"Quality of service reliability setting to {subscribe_or_publish} with (overrides reliability "
             "value of --qos-profile option, default: Compatible profile with running endpoints )")
    parser.add_argument(
        "--qos-durability", choices=DurabilityPolicy.short_keys(),
        help=f"Quality of service durability setting to {subscribe_or_publish} with (overrides durability "
             "value of --qos-profile option, default: Compatible profile with running endpoints )")


def _overridden(args: Namespace) -> bool:
    return any(getattr(args, key) is not None for key in ("qos_reliability", "qos_durability", "qos_depth",
                                                           "qos_history"))


def asked_qos(args: Namespace) -> tuple[Policies, int]:
    """The policies and queue depth the options ask for (ros2topic's qos_profile_from_short_keys)."""
    profile = QoSPresetProfiles.get_from_short_key(args.qos_profile)
    reliability, durability = int(profile.reliability), int(profile.durability)
    history, depth = profile.history, profile.depth
    if args.qos_history:
        history = HistoryPolicy.get_from_short_key(args.qos_history)
    if args.qos_durability:
        durability = int(DurabilityPolicy.get_from_short_key(args.qos_durability))
    if args.qos_reliability:
        reliability = int(ReliabilityPolicy.get_from_short_key(args.qos_reliability))
    if args.qos_depth and args.qos_depth >= 0:
        depth = args.qos_depth
    elif durability == DurabilityPolicy.TRANSIENT_LOCAL and depth == 0:
        depth = 1
    if history == HistoryPolicy.KEEP_ALL:
        depth = KEEP_ALL_DEPTH
    return Policies(reliability, durability), depth if depth > 0 else DEFAULT_DEPTH  # system_default: none


def echo_qos(args: Namespace, publishers: Sequence[Any]) -> tuple[Policies, int, list[str]]:
    """What ``ros2 topic echo`` subscribes with (its choose_qos): the options'
    profile, and unless a policy was given, reliable and transient local only
    if every publisher offers them; with the notes it prints."""
    policies, depth = asked_qos(args)
    if _overridden(args) or not publishers:
        return policies, depth, []
    reliable, kept, total = offer_counts(publishers)
    notes = []
    if 0 < reliable < total:
        notes.append("Some, but not all, publishers are offering QoSReliabilityPolicy.RELIABLE. Falling back to "
                     "QoSReliabilityPolicy.BEST_EFFORT as it will connect to all publishers")
    if 0 < kept < total:
        notes.append("Some, but not all, publishers are offering QoSDurabilityPolicy.TRANSIENT_LOCAL. Falling "
                     "back to QoSDurabilityPolicy.VOLATILE as it will connect to all publishers")
    return adapted(publishers), depth, notes
