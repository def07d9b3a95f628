"""Write a run as an MCAP file (``run.mcap``) or a rosbag2 folder (``run/``).

Both hold the channels of turtletui.recording.stream in an MCAP file with
profile ``ros2``, ``ros2msg`` schemas, CDR messages, zstd-compressed chunks,
each channel's ``offered_qos_profiles`` and rosbag2's own "rosbag2"
metadata record, so ``ros2 bag info|play``, Foxglove, Lichtblick and
PlotJuggler open them. A folder adds ``metadata.yaml`` beside
``<folder>_0.mcap``, as ``ros2 bag record -o <folder>`` does. A "turtletui"
metadata record keeps
where the run started, for ``turtletui replay``.

Nothing appears until the recording is complete: the file is written under
a temporary name (the folder as a temporary folder) and renamed.
"""

from __future__ import annotations

import json
import os
import shutil
from collections.abc import Callable, Collection
from pathlib import Path
from typing import Any

from turtletui.interfaces import interface_name
from turtletui.recording import rosbag2
from turtletui.recording.errors import RecordingWriteError
from turtletui.recording.qos import profiles_yaml
from turtletui.recording.scene import Scene
from turtletui.recording.schema import message_definition
from turtletui.recording.stream import Channel, RosStream
from turtletui.recording.type_hash import type_hash

TURTLETUI_METADATA = "turtletui"
"""Name of the metadata record with the run's header (start, seed, duration...)."""

_CHUNK_SIZE = 1024 * 1024


class McapSink:
    """An open MCAP writer that RosStream writes into."""

    def __init__(self, stream: Any, distro: str = rosbag2.ROS_DISTRO) -> None:
        try:
            from mcap.writer import CompressionType, Writer
        except ImportError:
            raise RecordingWriteError("writing MCAP needs the mcap package (pip install mcap)") from None
        from turtletui import __version__

        self._writer = Writer(stream, chunk_size=_CHUNK_SIZE, compression=CompressionType.ZSTD)
        self._writer.start(profile="ros2", library=f"turtletui {__version__}")
        self._schemas: dict[str, int] = {}
        self.start_ns: int | None = None
        self.end_ns = 0
        self.message_count = 0
        self.distro = distro

    def add_channel(self, channel: Channel) -> None:
        schema_id = self._schemas.get(channel.type_name)
        if schema_id is None:
            schema_id = self._schemas[channel.type_name] = self._writer.register_schema(
                channel.type_name, "ros2msg", message_definition(channel.type_name).encode()
            )
        channel.id = self._writer.register_channel(
            channel.topic,
            "cdr",
            schema_id,
            {"offered_qos_profiles": profiles_yaml(channel.qos), "topic_type_hash": type_hash(channel.type_name)},
        )

    def write(self, channel: Channel, log_time_ns: int, data: bytes) -> None:
        if self.start_ns is None or log_time_ns < self.start_ns:
            self.start_ns = log_time_ns
        if log_time_ns > self.end_ns:
            self.end_ns = log_time_ns
        self.message_count += 1
        self._writer.add_message(channel.id, log_time_ns, data, log_time_ns, channel.count)

    def bag_info(self, channels: list[Channel], file_name: str) -> rosbag2.BagInfo:
        start = self.start_ns or 0
        topics = [
            rosbag2.TopicInfo(channel.topic, channel.type_name, channel.qos, channel.count, type_hash(channel.type_name))
            for channel in channels
        ]
        return rosbag2.BagInfo(
            [file_name], start, max(self.end_ns - start, 0), self.message_count, topics, self.distro
        )

    def finish(self, bag: rosbag2.BagInfo, header: dict[str, Any] | None) -> None:
        self._writer.add_metadata("rosbag2", {"serialized_metadata": rosbag2.serialized_metadata(bag)})
        if header is not None:
            self._writer.add_metadata(TURTLETUI_METADATA, {"header": json.dumps(header, sort_keys=True)})
        self._writer.finish()


def is_bag_folder(path: str | os.PathLike[str]) -> bool:
    """Whether ``--record PATH`` names a rosbag2 folder: it ends with a
    separator (``run/``). An existing folder named without one stays an
    error, so a typo cannot turn a file's name into a folder."""
    return os.fspath(path).endswith(("/", os.sep))


class McapWriter:
    """Writes one recording: ``feed`` events, then ``close``."""

    def __init__(
        self,
        path: str | os.PathLike[str],
        *,
        epoch_ns: int,
        scene: Scene,
        topics: Collection[str] | None = None,
        distro: str = rosbag2.ROS_DISTRO,
        type_name: Callable[[type], str] = interface_name,
    ) -> None:
        """``distro`` and ``type_name`` (the graph's type_name_of): the run's
        distro and how it names types, as the bag records them."""
        self.folder = is_bag_folder(path)
        self.path = Path(os.fspath(path).rstrip("/" + os.sep) or ".")
        if self.folder:
            if self.path.exists() and any(self.path.iterdir()):
                raise RecordingWriteError(f"{path}: cannot write the bag (the folder exists and is not empty)")
            self._tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
            shutil.rmtree(self._tmp, ignore_errors=True)
            self._file_name = f"{self.path.name}_0.mcap"
            target = self._tmp / self._file_name
        else:
            self._tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
            target = self._tmp
        try:
            if self.folder:
                self._tmp.mkdir()
            self._file = open(target, "wb")  # noqa: SIM115
        except OSError as err:
            raise RecordingWriteError(f"{path}: cannot write the recording ({err.strerror})") from None
        try:
            self._sink = McapSink(self._file, distro)
        except BaseException:
            self._file.close()
            self._discard()
            raise
        self.stream = RosStream(self._sink, epoch_ns=epoch_ns, scene=scene, topics=topics, type_name=type_name)

    def close(self, keep: bool = True, header: dict[str, Any] | None = None) -> None:
        """Finish and rename into place (``keep``), or drop; nothing temporary is left."""
        try:
            if keep:
                self.stream.finish()
                name = self._file_name if self.folder else self.path.name
                bag = self._sink.bag_info(self.stream.channels, name)
                self._sink.finish(bag, header)
            self._file.close()
            if keep:
                if self.folder:
                    (self._tmp / "metadata.yaml").write_text(rosbag2.metadata_yaml(bag), encoding="utf-8")
                    if self.path.exists():
                        self.path.rmdir()  # empty (checked at the start)
                os.replace(self._tmp, self.path)
        except OSError as err:
            raise RecordingWriteError(f"{self.path}: cannot write the recording ({err.strerror})") from None
        finally:
            self._discard()

    def _discard(self) -> None:
        if self._tmp.is_dir():
            shutil.rmtree(self._tmp, ignore_errors=True)
        else:
            self._tmp.unlink(missing_ok=True)
