"""Record a run's graph as MCAP (a file or a rosbag2 folder).

The tap only notes what happened (turtletui.recording.tap); messages are
serialized in batches (a live recording, every few thousand events) or only
if the recording is kept (``buffered``: grading records every run and keeps
the failed ones).
"""

from __future__ import annotations

import os
from collections.abc import Collection, Iterable
from typing import Any

from turtletui.graph.logs import LogRecord
from turtletui.recording.mcap_file import McapWriter
from turtletui.recording.rosbag2 import ROS_DISTRO
from turtletui.recording.tap import RunTap

_FLUSH_EVERY = 4096


class McapRecorder:
    """Writes every topic message, service call, goal and log line of a run,
    with /tf and the scene derived from turtlesim's poses and calls.

    ``sim`` gives the graph, the world and the turtlesim node (a
    turtletui.runtime.simulation.Simulation). ``earlier_logs`` were logged
    before the recorder was attached (turtlesim's start lines); ``header``
    (where the run started, for ``turtletui replay``) is stored as the file's
    "turtletui" metadata record. ``topics`` limits the recording to those
    topics (``ros2 bag record TOPIC...``).
    """

    def __init__(
        self,
        sim: Any,
        path: str | os.PathLike[str],
        earlier_logs: Iterable[LogRecord] = (),
        header: dict[str, Any] | None = None,
        *,
        buffered: bool = False,
        topics: Collection[str] | None = None,
    ) -> None:
        self.path = path
        self._topics = topics
        self._header = header
        self._distro = getattr(sim, "distro", None) or ROS_DISTRO
        self._tap = RunTap(sim, earlier_logs, everything=not buffered)
        self._scene = self._tap.scene()
        self._writer = None if buffered else self._open()
        if self._writer is not None:
            self._tap.graph.taps.append(self._flush_when_full)

    def _open(self) -> McapWriter:
        graph = self._tap.graph
        return McapWriter(
            self.path, epoch_ns=graph.epoch_ns, scene=self._scene, topics=self._topics, distro=self._distro,
            type_name=graph.type_name_of,
        )

    def _flush_when_full(self, kind: str, payload: Any) -> None:
        if len(self._tap.events) >= _FLUSH_EVERY:
            self._flush(self._writer)

    def _flush(self, writer: McapWriter) -> None:
        feed = writer.stream.feed
        for t_ns, kind, payload in self._tap.take():
            feed(t_ns, kind, payload)

    def close(self, keep: bool = True) -> None:
        """Finish the recording (rename into place) or drop it; nothing temporary is left."""
        self._tap.detach()
        graph = self._tap.graph
        if self._flush_when_full in graph.taps:
            graph.taps.remove(self._flush_when_full)
        writer = self._writer
        if writer is None:
            if not keep:
                self._tap.take()
                return
            writer = self._open()
        try:
            if keep:
                self._flush(writer)
        finally:
            self._tap.take()
            writer.close(keep=keep, header=self._header)
