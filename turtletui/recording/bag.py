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
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from turtletui.errors import TurtletuiError
from turtletui.graph.core import NS_PER_S
from turtletui.graph.logs import INFO
from turtletui.interfaces import from_dict
from turtletui.recording.read import McapReadError, mcap_file_of, read_mcap
from turtletui.recording.recorder import McapRecorder
from turtletui.recording.schema import interface_of

RECORDER = "rosbag2_recorder"
PLAYER = "rosbag2_player"
_INDENT = " " * 19


class BagError(TurtletuiError, ValueError):
    """A bag that cannot be recorded, read or played: one line naming it."""


def default_bag_name(now: float | None = None) -> str:
    """rosbag2's default output folder: ``rosbag2_YYYY_MM_DD-HH_MM_SS`` (local time)."""
    return time.strftime("rosbag2_%Y_%m_%d-%H_%M_%S", time.localtime(now))


class BagRecording:
    """``ros2 bag record``: ``topics`` (every topic when None, ``-a``) of
    ``sim`` (a turtletui.runtime.simulation.Simulation) into the rosbag2
    folder ``output`` until ``stop``."""

    def __init__(self, sim: Any, topics: Sequence[str] | None, output: str | os.PathLike[str] | None = None) -> None:
        self.folder = Path(output if output is not None else default_bag_name())
        if self.folder.exists():
            raise BagError(f"Output folder '{self.folder}' already exists.")
        self._graph = sim.graph
        try:
            self._recorder = McapRecorder(sim, f"{self.folder}/", topics=None if topics is None else list(topics))
        except OSError as err:
            raise BagError(str(err)) from None
        log = self._log
        log(f"Opened database '{self.folder / (self.folder.name + '_0.mcap')}' for READ_WRITE.")
        log("Listening for topics...")
        for topic in topics if topics is not None else sorted(self._graph.topics):
            log(f"Subscribed to topic '{topic}'")
        log("Recording...")

    def _log(self, msg: str) -> None:
        self._graph.log(RECORDER, INFO, msg)

    def stop(self) -> None:
        """End the recording (Ctrl-C): the folder appears, complete."""
        try:
            self._recorder.close(keep=True)
        except OSError as err:
            raise BagError(str(err)) from None
        self._log("Recording stopped")


def bag_info(path: str | os.PathLike[str]) -> str:
    """What ``ros2 bag info PATH`` prints (times in local time)."""
    path = Path(path)
    if not path.exists():
        raise BagError(f"{path}: no such bag")
    try:
        from mcap.exceptions import McapError
        from mcap.reader import make_reader

        file = mcap_file_of(path)
        with open(file, "rb") as stream:
            summary = make_reader(stream).get_summary()
            distro = _ros_distro(make_reader(stream))
    except McapReadError as err:
        raise BagError(str(err)) from None
    except (McapError, ValueError, KeyError, IndexError, EOFError) as err:
        raise BagError(f"{path}: not a readable bag ({err})") from None
    except OSError as err:
        raise BagError(f"{path}: cannot read the bag ({err.strerror})") from None
    if summary is None or summary.statistics is None:
        raise BagError(f"{path}: not a readable bag (no summary: was the recording cut short?)")
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


@dataclass
class BagPlayback:
    """``ros2 bag play``: a bag's messages published again at their recorded pace."""

    path: Path
    messages: int
    duration_ns: int
    timers: list[Any] = field(default_factory=list, repr=False)
    published: int = 0

    @property
    def done(self) -> bool:
        return self.published >= self.messages

    def stop(self) -> None:
        """Stop publishing (Ctrl-C)."""
        for timer in self.timers:
            timer.canceled = True


def play_bag(sim: Any, path: str | os.PathLike[str]) -> BagPlayback:
    """Publish every message of the bag at ``path`` into ``sim``'s graph from
    now on, each at its recorded offset, from a ``rosbag2_player`` node (topics
    of types turtletui does not know are skipped, as ROS skips unknown types)."""
    path = Path(path)
    try:
        _, events = read_mcap(path, everything=True)
    except McapReadError as err:
        raise BagError(str(err)) from None
    graph = sim.graph
    node = graph.add_node(PLAYER, owner=PLAYER)
    publishers: dict[str, Any] = {}
    first = events[0]["t"] if events else 0.0
    duration = round((events[-1]["t"] - first) * NS_PER_S) if events else 0
    playback = BagPlayback(path, len(events), duration)
    graph.log(PLAYER, INFO, f"Playing {path}: {len(events)} messages, {_seconds(duration)} s")

    def publisher(topic: str, cls: type) -> Any:
        found = publishers.get(topic)
        if found is None:
            found = publishers[topic] = graph.add_publisher(node, topic, cls, 10)
        return found

    for event in events:
        cls = interface_of(event["type"])
        try:
            msg = from_dict(cls, event["msg"])
        except ValueError as err:
            raise BagError(f"{path}: {event['topic']} at t={event['t']:.3f} s: {err}") from None
        delay = max(round((event["t"] - first) * NS_PER_S), 0) + 1
        send = _sender(graph, publisher(event["topic"], cls), msg, playback)
        playback.timers.append(graph.call_later(node, delay, send))
    return playback


def _sender(graph: Any, pub: Any, msg: Any, playback: BagPlayback) -> Callable[[], None]:
    def send() -> None:
        graph.publish(pub.topic, msg, source=PLAYER)
        playback.published += 1

    return send

