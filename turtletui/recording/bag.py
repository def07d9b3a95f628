"""``ros2 bag record | info | play`` over a live simulation, as the official
"Recording and playing back data" tutorial uses them::

    ros2 bag record /turtle1/cmd_vel /turtle1/pose -o subset
    ros2 bag info subset
    ros2 bag play subset

A bag is a rosbag2 folder with the mcap storage (turtletui.recording.mcap_file).
Recording and playing log as rosbag2's nodes do, in the graph's log; ``info``
prints what ``ros2 bag info`` prints (rosbag2_py's format_bag_metadata).
"""

from __future__ import annotations

import os
import time
from collections.abc import Collection, Iterator, Sequence
from pathlib import Path
from typing import Any

from turtletui.errors import TurtletuiError
from turtletui.graph.core import NS_PER_S, Graph, NodeRecord
from turtletui.graph.logs import ERROR, INFO, WARN
from turtletui.graph.qos import adapted
from turtletui.graph.simulated_node import SimulatedNode
from turtletui.interfaces import from_dict
from turtletui.recording.qos import (
    DEFAULT,
    OfferedQos,
    adapted_offer,
    mixed_offers_warning,
    parse_profiles,
)
from turtletui.recording.read import McapReadError, iter_messages, known_channels, mcap_file_of
from turtletui.recording.recorder import McapRecorder
from turtletui.sim import DT

RECORDER = "rosbag2_recorder"
PLAYER = "rosbag2_player"
_INDENT = " " * 19

LOOP_MIN_NS = round(DT * NS_PER_S)
"""``--loop``: a pass starts no sooner than this after the last one began."""


class BagError(TurtletuiError, ValueError):
    """A bag that cannot be recorded, read or played: one line naming it."""


def rosbag2_node(graph: Graph, name: str, owner: str) -> NodeRecord:
    """A node of rosbag2's (``rosbag2_recorder``, ``rosbag2_player``): rosbag2_transport's
    Recorder and Player are rclcpp nodes, with what every one has."""
    return SimulatedNode(graph, name, owner).node


def default_bag_name(now: float | None = None) -> str:
    """rosbag2's default output folder: ``rosbag2_YYYY_MM_DD-HH_MM_SS`` (local time)."""
    return time.strftime("rosbag2_%Y_%m_%d-%H_%M_%S", time.localtime(now))


class BagRecording:
    """``ros2 bag record``: ``topics`` (every topic when None, ``-a``) of
    ``sim`` (a turtletui.runtime.simulation.Simulation) into the rosbag2
    folder ``output`` until ``stop``.

    As rosbag2's recorder, a ``rosbag2_recorder`` node subscribes to the
    topics (``ros2 node list`` and ``ros2 topic info`` show it); a topic named
    that nobody publishes yet is recorded from when it appears.
    """

    def __init__(
        self,
        sim: Any,
        topics: Sequence[str] | None,
        output: str | os.PathLike[str] | None = None,
        *,
        node: NodeRecord | None = None,
    ) -> None:
        """``node``: the recorder's node, if the caller made it (else one is made)."""
        self.folder = Path(output if output is not None else default_bag_name())
        if self.folder.exists():
            raise BagError(f"Output folder '{self.folder}' already exists.")
        self._graph = graph = sim.graph
        try:
            self._recorder = McapRecorder(sim, f"{self.folder}/", topics=None if topics is None else list(topics))
        except OSError as err:
            raise BagError(str(err)) from None
        self.stopped = False
        self.node = node if node is not None else rosbag2_node(graph, RECORDER, RECORDER)
        self._log(f"Opened database '{self.folder / (self.folder.name + '_0.mcap')}' for READ_WRITE.")
        self._log("Listening for topics...")
        live = sorted(name for name, topic in graph.topics.items() if topic.publishers or topic.subscriptions)
        for name in live if topics is None else [t for t in dict.fromkeys(topics) if t in live]:
            topic = graph.topics[name]
            graph.add_subscription(self.node, name, topic.msg_type, 10, _ignore, qos=adapted(topic.publishers))
            self._log(f"Subscribed to topic '{name}'")
        self._log("Recording...")

    def _log(self, msg: str) -> None:
        self._graph.log(RECORDER, INFO, msg)

    def stop(self) -> None:
        """End the recording (Ctrl-C): the folder appears, complete; the
        recorder's node goes. BagError if the bag cannot be written."""
        if self.stopped:
            return
        self.stopped = True
        self._graph.remove_node(self.node)
        try:
            self._recorder.close(keep=True)
        except OSError as err:
            raise BagError(str(err)) from None
        self._log("Recording stopped")


def _ignore(msg: Any) -> None:
    """The recorder's subscriptions: what they receive is recorded by the tap."""


def bag_info(path: str | os.PathLike[str]) -> str:
    """What ``ros2 bag info PATH`` prints (times in local time)."""
    path = Path(path)
    summary, _, distro = _summary(path)
    stats = summary.statistics
    files = sorted(p.name for p in path.glob("*.mcap")) if path.is_dir() else [path.name]
    size = sum(p.stat().st_size for p in path.iterdir() if p.is_file()) if path.is_dir() else path.stat().st_size
    start = stats.message_start_time if stats.message_count else 0
    duration = stats.message_end_time - start if stats.message_count else 0
    lines = [
        "",
        "Files:             " + f"\n{_INDENT}".join(files),
        f"Bag size:          {_file_size(size)}",
        "Storage id:        mcap",
        f"ROS Distro:        {distro or 'unknown'}",
        f"Duration:          {_seconds(duration)}s",
        f"Start:             {_time_point(start)}",
        f"End:               {_time_point(start + duration)}",
        f"Messages:          {stats.message_count}",
    ]
    topics = []
    for channel_id, channel in summary.channels.items():
        schema = summary.schemas.get(channel.schema_id)
        topics.append(
            f"Topic: {channel.topic} | Type: {schema.name if schema else ''} | "
            f"Count: {stats.channel_message_counts.get(channel_id, 0)} | "
            f"Serialization Format: {channel.message_encoding}"
        )
    lines.append("Topic information: " + f"\n{_INDENT}".join(topics))
    lines += ["Service:           0", "Service information: "]
    return "\n".join(lines) + "\n"


def bag_topics(path: str | os.PathLike[str]) -> list[str]:
    """The topics of a bag, as ``ros2 bag info -t PATH`` prints them."""
    summary, _, _ = _summary(Path(path))
    return [channel.topic for channel in summary.channels.values()]


def _summary(path: Path, topics: Collection[str] | None = None) -> tuple[Any, dict[int, tuple[str, type]], str]:
    """(the MCAP summary, the channels turtletui can play (of ``topics``), the
    ROS distro it was recorded with) of a bag; BagError (one line) if it
    cannot be read."""
    if not path.exists():
        raise BagError(f"{path}: no such bag")
    try:
        from mcap.exceptions import McapError
        from mcap.reader import make_reader

        with open(mcap_file_of(path), "rb") as stream:
            reader = make_reader(stream)
            summary = reader.get_summary()
            channels = known_channels(reader, topics)
            distro = _ros_distro(reader)
    except McapReadError as err:
        raise BagError(str(err)) from None
    except (McapError, ValueError, KeyError, IndexError, EOFError) as err:
        raise BagError(f"{path}: not a readable bag ({err})") from None
    except OSError as err:
        raise BagError(f"{path}: cannot read the bag ({err.strerror})") from None
    if summary is None or summary.statistics is None:
        raise BagError(f"{path}: not a readable bag (no summary: was the recording cut short?)")
    return summary, channels, distro


def _ros_distro(reader: Any) -> str:
    for record in reader.iter_metadata():
        if record.name == "rosbag2":
            for line in record.metadata.get("serialized_metadata", "").splitlines():
                if line.startswith("ros_distro:"):
                    return line.partition(":")[2].strip().strip('"')
    return ""


def _seconds(ns: int) -> str:
    sec, nsec = divmod(ns, NS_PER_S)
    return f"{sec}.{nsec:09d}"


def _time_point(ns: int) -> str:
    sec = ns // NS_PER_S
    local = time.localtime(sec)
    return f"{time.strftime('%b', local)} {local.tm_mday:2d} {local.tm_year} {time.strftime('%H:%M:%S', local)}.{ns % NS_PER_S:09d} ({_seconds(ns)})"


def _file_size(size: int) -> str:
    units = ["B", "KiB", "MiB", "GiB", "TiB"]
    value, index = float(size), 0
    while value >= 1024 and index < 4:
        value /= 1024
        index += 1
    return f"{value:.{0 if index == 0 else 1}f} {units[index]}"


class BagPlayback:
    """``ros2 bag play``: a bag's messages published again into ``sim``'s graph
    (anything with a ``graph``) from a ``rosbag2_player`` node, each at its
    recorded offset from the first divided by ``rate``; with ``loop`` again
    from the start until stopped; ``topics`` limits it to those. Messages are
    read from the file as they come due, so a long bag starts at once and
    memory stays flat. Topics of types turtletui does not know are skipped,
    as ROS skips unknown types. Time is the simulation's: at x2 the bag plays
    twice as fast on the wall clock, as the turtle moves."""

    def __init__(
        self,
        sim: Any,
        path: str | os.PathLike[str],
        *,
        rate: float = 1.0,
        loop: bool = False,
        topics: Collection[str] | None = None,
        node: NodeRecord | None = None,
    ) -> None:
        """``node``: the player's node, if the caller made it (else one is made)."""
        if not rate > 0:
            raise BagError(f"the rate must be a positive number, got {rate}")
        self.path = Path(path)
        self.rate = rate
        self.loop = loop
        self._topics = None if topics is None else frozenset(topics)
        self.messages, self.duration_ns, offers = _playable(self.path, self._topics)
        """Messages played in one pass, and the time from the first to the last (ns)."""
        self.published = 0
        """Messages published so far (every pass)."""
        self.done = False
        """True once the bag was played to its end (never with ``loop``) or stopped."""
        self._graph = sim.graph
        self.node = node if node is not None else rosbag2_node(self._graph, PLAYER, PLAYER)
        self._publishers = self._make_publishers(offers)
        self._reader: Iterator[tuple[int, str, type, dict[str, Any]]] | None = None
        self._next: tuple[int, str, type, dict[str, Any]] | None = None
        self._timer: Any = None
        self._pass_start = self._first = 0
        pace = "" if rate == 1.0 else f" at x{rate:g}"
        again = ", in a loop" if loop else ""
        self._log(INFO, f"Playing {self.path}: {self.messages} messages, {_seconds(self.duration_ns)} s{pace}{again}")
        self._start_pass(self._graph.now_ns)

    def stop(self) -> None:
        """Stop publishing (Ctrl-C); the player's node goes."""
        self._end()

    # -- internals --------------------------------------------------------------------
    def _log(self, level: int, msg: str) -> None:
        self._graph.log(PLAYER, level, msg)

    def _start_pass(self, start_ns: int) -> None:
        self._close_reader()
        self._reader = iter_messages(self.path, self._topics)
        # what is due at once goes out from a timer, in the next pump: 1 ns on
        self._pass_start, self._first = max(start_ns, self._graph.now_ns + 1), -1
        self._read_next()
        if self._next is None:
            self._end()
            return
        self._schedule()

    def _read_next(self) -> None:
        try:
            item = next(self._reader, None)
        except McapReadError as err:
            self._log(ERROR, str(err))
            item = None
        if item is None:
            self._next = None
            return
        t_ns, topic, cls, fields = item
        if self._first < 0:
            self._first = t_ns
        due = self._pass_start + round(max(t_ns - self._first, 0) / self.rate)
        self._next = (due, topic, cls, fields)

    def _schedule(self) -> None:
        delay = self._next[0] - self._graph.now_ns
        self._timer = self._graph.call_later(self.node, delay, self._publish_due)

    def _publish_due(self) -> None:
        graph = self._graph
        now = graph.now_ns
        while self._next is not None and self._next[0] <= now:
            _, topic, cls, fields = self._next
            try:
                msg = from_dict(cls, fields)
            except ValueError as err:
                self._log(ERROR, f"{self.path}: {topic}: cannot play this message ({err}): stopping")
                self._end()
                return
            publisher = self._publishers[topic]
            graph.publish(publisher.topic, msg, None, publisher)
            self.published += 1
            self._read_next()
        if self._next is not None:
            self._schedule()
        elif self.loop and self.published:
            # a bag with no length loops no faster than turtlesim steps
            self._start_pass(max(now, self._pass_start + LOOP_MIN_NS))
        else:
            self._end()

    def _make_publishers(self, offers: dict[str, tuple[type, list[OfferedQos]]]) -> dict[str, Any]:
        """rosbag2's player makes a publisher for every topic it plays before
        it plays (so the first messages may go before anyone discovered it),
        keep last 10 with the QoS the recorded publishers offered."""
        publishers = {}
        for topic, (cls, profiles) in offers.items():
            offer = adapted_offer(profiles)
            if offer is None:
                self._graph.log("rosbag2_storage", WARN, mixed_offers_warning(topic))
                offer = DEFAULT
            publishers[topic] = self._graph.add_publisher(self.node, topic, cls, 10, qos=offer.policies())
        return publishers

    def _close_reader(self) -> None:
        if self._reader is not None:
            self._reader.close()  # closes the file
            self._reader = None

    def _end(self) -> None:
        if self.done:
            return
        self.done = True
        if self._timer is not None:
            self._timer.canceled = True
        self._close_reader()
        self._graph.remove_node(self.node)


def _playable(path: Path, topics: Collection[str] | None) -> tuple[int, int, dict[str, tuple[type, list[OfferedQos]]]]:
    """(messages turtletui can play, ns from the first message to the last,
    {topic: (message class, what its recorded publishers offered)}) of a bag."""
    summary, channels, _ = _summary(path, topics)
    stats = summary.statistics
    count = sum(stats.channel_message_counts.get(channel_id, 0) for channel_id in channels)
    duration = stats.message_end_time - stats.message_start_time if stats.message_count else 0
    offers = {}
    for channel_id, (topic, cls) in sorted(channels.items()):
        metadata = summary.channels[channel_id].metadata or {}
        offers[topic] = (cls, parse_profiles(metadata.get("offered_qos_profiles", "")))
    return count, duration, offers
