"""Recording a run, written atomically: JSON Lines here, MCAP in
turtletui.recording (``open_recorder`` chooses by the path's name)."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from turtletui.errors import TurtletuiError
from turtletui.files import cannot_write_in
from turtletui.graph.core import Graph
from turtletui.graph.logs import LogRecord
from turtletui.interfaces import to_dict
from turtletui.recording.errors import RecordingWriteError


def _clean(value: Any) -> Any:
    """Non-finite floats as the strings "inf", "-inf", "nan": the file stays strict JSON."""
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    return value


def _seconds(t_ns: int) -> float:
    return round(t_ns / 1e9, 9)


def _log_event(t: float, record: LogRecord) -> dict[str, Any]:
    return {"t": t, "log": {"level": record.level_name, "node": record.node, "msg": record.msg}}


class RecordingError(TurtletuiError, ValueError):
    """A recording that cannot be read or replayed; one line naming the file."""


class Recorder:
    """Writes every topic message, service call and log line of a graph to
    ``path`` as JSON Lines; the file appears complete or not at all.

    ``earlier_logs`` are log lines the graph wrote before the recorder was
    attached (turtlesim's start lines); they are written first, after the
    ``header`` line (``{"recording": 1, ...header}``) if one is given: where
    the run started, for ``turtletui replay``.

    ``buffered`` keeps the events in memory and writes them only when the
    recording is kept (grading records every run, keeps the failed ones);
    it also leaves out turtlesim's colour sensor when nothing subscribes to it.
    """

    def __init__(
        self,
        graph: Graph,
        path: str | os.PathLike[str],
        earlier_logs: Iterable[LogRecord] = (),
        header: dict[str, Any] | None = None,
        *,
        buffered: bool = False,
    ) -> None:
        self.path = Path(path)
        if self.path.is_dir():
            raise RecordingWriteError(
                f"{path}: cannot write the record (is a folder; name a file such as run.jsonl or run.mcap,"
                " or a new folder for a rosbag2 bag, such as run/)"
            )
        self._tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
        self._file = None if buffered else self._open()
        self._buffer: list[tuple[int | float, str, Any]] | None = [] if buffered else None
        """(when, kind, payload): when is the graph's time in ns, or seconds for earlier logs."""
        self._graph = graph
        self._header = header
        if header is not None and not buffered:
            self._write({"recording": 1, **header})
        for record in earlier_logs:
            self._tap("log", record, round(record.t, 9))
        graph.taps.append(self._tap)
        graph.record_everything = not buffered

    def _open(self) -> Any:
        try:
            return open(self._tmp, "w", encoding="utf-8")  # noqa: SIM115
        except OSError as err:
            raise RecordingWriteError(f"{self.path}: cannot write the record ({err.strerror})") from None

    def _tap(self, kind: str, payload: Any, t: float | None = None) -> None:
        if self._buffer is not None:
            # messages are not changed after they are sent; seconds are worked out if kept
            self._buffer.append((self._graph.now_ns if t is None else t, kind, payload))
            return
        event = _event(_seconds(self._graph.now_ns) if t is None else t, kind, payload)
        if event is not None:
            self._write(event)

    def _write(self, event: dict[str, Any]) -> None:
        try:
            line = json.dumps(event, allow_nan=False)
        except ValueError:
            line = json.dumps(_clean(event), allow_nan=False)
        self._file.write(line + "\n")

    def close(self, keep: bool = True) -> None:
        """Finish the file (rename into place) or drop it; no temporary file is left."""
        if self._tap in self._graph.taps:
            self._graph.taps.remove(self._tap)
            self._graph.record_everything = False
        try:
            if self._buffer is not None and keep:
                self._file = self._open()
                if self._header is not None:
                    self._write({"recording": 1, **self._header})
                for when, kind, payload in self._buffer:
                    event = _event(_seconds(when) if when.__class__ is int else when, kind, payload)
                    if event is not None:
                        self._write(event)
            self._buffer = None
            if self._file is not None:
                self._file.close()
                if keep:
                    os.replace(self._tmp, self.path)
        except OSError as err:
            raise RecordingWriteError(f"{self.path}: cannot write the record ({err.strerror})") from None
        finally:
            self._tmp.unlink(missing_ok=True)


def _event(t: float, kind: str, payload: Any) -> dict[str, Any] | None:
    """The JSON object of one tapped event; None for kinds a record leaves out."""
    if kind == "topic":
        topic, msg = payload
        return {"t": t, "topic": topic.name, "type": topic.type_name, "msg": to_dict(msg)}
    if kind == "service":
        name, request, response = payload
        return {"t": t, "service": name, "request": to_dict(request), "response": to_dict(response)}
    if kind == "goal":
        name, goal = payload
        return {"t": t, "action": name, "goal": to_dict(goal)}
    if kind == "log":
        return _log_event(t, payload)
    return None


RECORD_SUFFIXES = (".jsonl", ".ndjson", ".json", ".mcap")
"""File names ``--record`` takes (besides ``NAME/``, a rosbag2 folder)."""


def open_recorder(
    sim: Any,
    path: str | os.PathLike[str],
    earlier_logs: Iterable[LogRecord] = (),
    header: dict[str, Any] | None = None,
    *,
    buffered: bool = False,
) -> Recorder | Any:
    """A recorder of ``sim`` (a Simulation) for ``path``, chosen by its name:
    ``run.mcap`` an MCAP file, a folder (``run/``) a rosbag2 bag, anything
    else JSON Lines. Both kinds ``close(keep)``."""
    from turtletui.recording.mcap_file import is_bag_folder

    if Path(path).suffix.lower() == ".mcap" or is_bag_folder(path):
        from turtletui.recording.recorder import McapRecorder

        return McapRecorder(sim, path, earlier_logs, header, buffered=buffered)
    return Recorder(sim.graph, path, earlier_logs, header, buffered=buffered)


def check_record_path(path: str | os.PathLike[str]) -> None:
    """RecordingWriteError (one line) if a recording could not be written at ``path``:
    a missing or unwritable folder, or a bag folder that is not empty."""
    from turtletui.recording.mcap_file import is_bag_folder

    target = Path(path)
    if is_bag_folder(path):
        if target.is_dir() and any(target.iterdir()):
            raise RecordingWriteError(f"{path}: cannot write the bag (the folder exists and is not empty)")
    elif target.is_dir():
        raise RecordingWriteError(f"{path}: cannot write the record (is a folder; name a file, or a bag folder as {path}/)")
    elif target.suffix.lower() not in RECORD_SUFFIXES:
        raise RecordingWriteError(
            f"{path}: cannot tell which kind of recording to write from its name: name it {target.stem}.jsonl"
            f" (JSON Lines), {target.stem}.mcap (MCAP) or {target.stem}/ (a rosbag2 folder)"
        )
    parent = target.parent
    if not parent.is_dir() or not os.access(parent, os.W_OK) or cannot_write_in(parent) is not None:
        raise RecordingWriteError(f"{path}: cannot write the recording (no writable folder {parent})")
