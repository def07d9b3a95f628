"""Read an MCAP recording or a rosbag2 folder back as replayable events.

The events are those of a JSON Lines record (turtletui.runtime.replay):
``{"t", "topic", "type", "msg"}``, ``{"t", "service", "request", "response"}``,
``{"t", "action", "goal"}`` and ``{"t", "log": {...}}``, with messages as
plain dicts that the replay checks like any untrusted input. Messages are
decoded with mcap_ros2's decoder from the file's own schemas, so a bag
recorded on a real ROS system replays too (its ``/turtle1/cmd_vel``, say);
channels of types turtletui does not know are skipped.
"""

from __future__ import annotations

import json
import os
import struct
from collections.abc import Collection, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from turtletui.errors import TurtletuiError
from turtletui.graph.logs import LEVEL_NAMES
from turtletui.interfaces import InterfaceError, Message
from turtletui.recording.mcap_file import TURTLETUI_METADATA
from turtletui.recording.qos import OfferedQos, parse_profiles
from turtletui.recording.schema import interface_of
from turtletui.recording.stream import GOAL_SUFFIX, REQUEST_SUFFIX, RESPONSE_SUFFIX, ROSOUT_TOPIC

SIMULATOR_TOPICS = ("/pose", "/color_sensor", "/scan", "/tf", "/turtlesim/scene", "/tf_static", "/clock")
"""What the simulator publishes (or a recording derives from it): not replayed."""


class McapReadError(TurtletuiError, ValueError):
    """A recording that cannot be read; one line naming the file."""


def mcap_file_of(path: Path) -> Path:
    """The MCAP file of a recording: the file itself, or a rosbag2 folder's first."""
    if not path.is_dir():
        return path
    files = sorted(path.glob("*.mcap"), key=lambda p: (len(p.name), p.name))
    if files:
        return files[0]
    if any(path.glob("*.db3")):
        raise McapReadError(f"{path}: a sqlite3 bag; convert it with ros2 bag convert, or record with -s mcap")
    raise McapReadError(f"{path}: no .mcap file in this folder (not a rosbag2 bag with the mcap storage)")


@contextmanager
def _decoding_reader(path: Path) -> Iterator[Any]:
    """An MCAP reader with mcap_ros2's decoder on a recording or rosbag2
    folder, its file open for the ``with`` block; anything unreadable, also
    within the block, is a McapReadError naming the file."""
    if not path.exists():
        raise McapReadError(f"{path}: no such recording")
    file = mcap_file_of(path)
    try:
        from mcap.exceptions import McapError
        from mcap.reader import make_reader
        from mcap_ros2.decoder import DecoderFactory
    except ImportError:
        raise McapReadError(f"{path}: reading MCAP needs the mcap and mcap-ros2-support packages") from None
    try:
        with open(file, "rb") as stream:
            yield make_reader(stream, decoder_factories=[DecoderFactory()])
    except (McapError, ValueError, KeyError, IndexError, EOFError, NotImplementedError, struct.error) as err:
        raise McapReadError(f"{file}: not a readable MCAP recording ({_reason(err)})") from None
    except OSError as err:
        raise McapReadError(f"{file}: cannot read the recording ({err.strerror})") from None


def read_mcap(
    path: str | os.PathLike[str], *, everything: bool = False
) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """(header, events) of an MCAP recording or rosbag2 folder; McapReadError if unreadable.

    Events are what a replay feeds in: the controllers' messages, service
    calls, goals and the log. With ``everything``, every message of every
    channel turtletui can decode, as a topic event (what ``ros2 bag play``
    publishes)."""
    with _decoding_reader(Path(path)) as reader:
        header = _header(reader)
        summary = reader.get_summary()
        epoch = header.pop("epoch_ns", None)
        if epoch is None:
            stats = summary.statistics if summary is not None else None
            epoch = stats.message_start_time if stats is not None else 0
        events = list(_events(reader, int(epoch), everything))
    return header, events


def recorded_offers(path: str | os.PathLike[str]) -> dict[str, list[OfferedQos]]:
    """What the publishers of each topic of an MCAP recording or rosbag2
    folder offered, as its channels' ``offered_qos_profiles`` say."""
    with _decoding_reader(Path(path)) as reader:
        summary = reader.get_summary()
        channels = summary.channels.values() if summary is not None else ()
        return {c.topic: parse_profiles((c.metadata or {}).get("offered_qos_profiles", "")) for c in channels}


def iter_messages(
    path: str | os.PathLike[str], topics: Collection[str] | None = None
) -> Iterator[tuple[int, str, type, dict[str, Any]]]:
    """Every message of a recording or bag that turtletui can decode (of
    ``topics`` only, when given), in log-time order, read as it is asked for:
    (log time in ns, topic, message class, the message as the plain dict
    ``from_dict`` takes). The file stays open until the iterator ends or is
    closed. McapReadError (one line) if the file is unreadable, also midway."""
    with _decoding_reader(Path(path)) as reader:
        classes = known_channels(reader, topics)
        if not classes:
            return
        wanted = sorted({topic for topic, _ in classes.values()})
        for _, channel, message, decoded in reader.iter_decoded_messages(topics=wanted, log_time_order=True):
            topic, cls = classes[channel.id]
            yield message.log_time, topic, cls, plain(cls, decoded)


def known_channels(reader: Any, topics: Collection[str] | None = None) -> dict[int, tuple[str, type]]:
    """{channel id: (topic, message class)} of a reader's channels whose type
    turtletui knows (of ``topics`` only, when given)."""
    summary = reader.get_summary()
    if summary is None:
        return {}
    found = {}
    for channel in summary.channels.values():
        if topics is not None and channel.topic not in topics:
            continue
        cls = _class_of(summary.schemas.get(channel.schema_id))
        if cls is not None:
            found[channel.id] = (channel.topic, cls)
    return found


def _header(reader: Any) -> dict[str, Any]:
    for record in reader.iter_metadata():
        if record.name == TURTLETUI_METADATA:
            header = json.loads(record.metadata.get("header", "{}"))
            if not isinstance(header, dict):
                raise ValueError("the turtletui metadata is not a JSON object")
            return header
    return {}


def _wanted(topic: str) -> bool:
    return topic == ROSOUT_TOPIC or not topic.endswith(SIMULATOR_TOPICS) and not topic.endswith(RESPONSE_SUFFIX)


def _events(reader: Any, epoch_ns: int, everything: bool) -> Iterator[dict[str, Any]]:
    classes: dict[int, type | None] = {}
    for schema, channel, message, decoded in _decoded(reader, everything):
        cls = classes.get(channel.id, 0)
        if cls == 0:
            cls = classes[channel.id] = _class_of(schema)
        if cls is None:
            continue
        t = max(message.log_time - epoch_ns, 0) / 1e9
        topic = channel.topic
        if everything:
            yield {"t": t, "topic": topic, "type": cls._TYPE_NAME, "msg": plain(cls, decoded)}
        elif topic == ROSOUT_TOPIC:
            level = LEVEL_NAMES.get(decoded.level, str(decoded.level))
            yield {"t": t, "log": {"level": level, "node": decoded.name, "msg": decoded.msg}}
        elif topic.endswith(REQUEST_SUFFIX):
            yield {"t": t, "service": topic[: -len(REQUEST_SUFFIX)], "request": plain(cls, decoded), "response": {}}
        elif topic.endswith(GOAL_SUFFIX):
            yield {"t": t, "action": topic[: -len(GOAL_SUFFIX)], "goal": plain(cls, decoded)}
        else:
            yield {"t": t, "topic": topic, "type": cls._TYPE_NAME, "msg": plain(cls, decoded)}


def _decoded(reader: Any, everything: bool) -> Iterator[tuple[Any, Any, Any, Any]]:
    """Decoded messages of the channels a replay uses (the others stay undecoded)."""
    summary = reader.get_summary()
    topics = None
    if summary is not None and not everything:
        topics = [channel.topic for channel in summary.channels.values() if _wanted(channel.topic)]
    yield from reader.iter_decoded_messages(topics=topics, log_time_order=True)


def _class_of(schema: Any) -> type | None:
    if schema is None:
        return None
    try:
        cls = interface_of(schema.name)
    except (InterfaceError, ValueError):
        return None
    return cls if isinstance(cls, type) and issubclass(cls, Message) else None


def plain(cls: type, decoded: Any) -> dict[str, Any]:
    """A decoded message as the nested dict ``from_dict`` takes, by turtletui's fields."""
    out: dict[str, Any] = {}
    for spec in cls._FIELDS:
        value = getattr(decoded, spec.name, None)
        if value is None:
            continue
        out[spec.name] = _value(spec, value)
    return out


def _value(spec: Any, value: Any) -> Any:
    if spec.array == 0:
        return _scalar(spec, value)
    return [_scalar(spec, item) for item in value]


def _scalar(spec: Any, value: Any) -> Any:
    if spec.kind == "msg":
        return plain(spec.msg_cls, value)
    if spec.kind == "float":
        return float(value)
    if spec.kind == "bool":
        return bool(value)
    if spec.kind in ("int", "byte") and not isinstance(value, bool):
        return int(value)
    return value


def _reason(err: BaseException) -> str:
    text = str(err).strip().splitlines()
    return text[0] if text else type(err).__name__
