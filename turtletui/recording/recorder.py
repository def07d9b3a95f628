"""Record a run's graph as MCAP (a file or a rosbag2 folder): the tap side.

The tap only notes what happened (time, kind, payload), as the JSON Lines
recorder does; messages are serialized in batches (a live recording, every
few thousand events) or only if the recording is kept (``buffered``: grading
records every run and keeps the failed ones).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import Any

from turtletui.graph.core import Graph
from turtletui.graph.logs import LogRecord
from turtletui.interfaces.turtlesim import Pose
from turtletui.recording.mcap_file import McapWriter
from turtletui.recording.scene import Scene

_FLUSH_EVERY = 4096


class McapRecorder:
    """Writes every topic message, service call, goal and log line of a run,
    with /tf and the scene derived from turtlesim's poses and calls.

    ``sim`` gives the graph, the world and the turtlesim node (a
    turtletui.runtime.simulation.Simulation). ``earlier_logs`` were logged
    before the recorder was attached (turtlesim's start lines); ``header``
    (where the run started, for ``turtletui replay``) is stored as the file's
    "turtletui" metadata record.
    """

    def __init__(
        self,
        sim: Any,
        path: str | os.PathLike[str],
        earlier_logs: Iterable[LogRecord] = (),
        header: dict[str, Any] | None = None,
        *,
        buffered: bool = False,
    ) -> None:
        self.path = path
        self._graph: Graph = sim.graph
        self._world = sim.world
        self._turtlesim = sim.turtlesim
        self._header = header
        self._background = self._world.background
        self._scene = Scene(tuple(self._world.obstacles), self._background, list(self._world.turtles))
        self._events: list[tuple[int, str, Any]] = [
            (round(record.t * 1e9), "log", record) for record in earlier_logs
        ]
        self._buffered = buffered
        self._writer = None if buffered else self._open()
        self._graph.taps.append(self._tap)
        self._graph.record_everything = not buffered

    def _open(self) -> McapWriter:
        return McapWriter(self.path, epoch_ns=self._graph.epoch_ns, scene=self._scene)

    def _tap(self, kind: str, payload: Any) -> None:
        events = self._events
        now = self._graph.now_ns
        if kind == "topic":
            msg = payload[1]
            if msg.__class__ is Pose:
                name = payload[0].name
                turtle = name[1:-5]
                if name.endswith("/pose") and self._turtlesim.published(turtle, msg):
                    kind, payload = "pose", (payload[0], msg, turtle)
                    background = self._world.background
                    if background != self._background:
                        self._background = background
                        events.append((now, "background", background))
        events.append((now, kind, payload))
        if self._writer is not None and len(events) >= _FLUSH_EVERY:
            self._flush(self._writer)

    def _flush(self, writer: McapWriter) -> None:
        feed = writer.stream.feed
        for t_ns, kind, payload in self._events:
            feed(t_ns, kind, payload)
        self._events = []

    def close(self, keep: bool = True) -> None:
        """Finish the recording (rename into place) or drop it; nothing temporary is left."""
        if self._tap in self._graph.taps:
            self._graph.taps.remove(self._tap)
            self._graph.record_everything = False
        writer = self._writer
        if writer is None:
            if not keep:
                self._events = []
                return
            writer = self._open()
        try:
            if keep:
                self._flush(writer)
        finally:
            self._events = []
            writer.close(keep=keep, header=self._header)
