"""JSON Lines recording of a run, written atomically."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from turtletui.graph.core import Graph
from turtletui.graph.logs import LogRecord
from turtletui.interfaces import to_dict


def _clean(value: Any) -> Any:
    """Non-finite floats as the strings "inf", "-inf", "nan": the file stays strict JSON."""
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    return value


def _log_event(t: float, record: LogRecord) -> dict[str, Any]:
    return {"t": t, "log": {"level": record.level_name, "node": record.node, "msg": record.msg}}


class Recorder:
    """Writes every topic message, service call and log line of a graph to
    ``path`` as JSON Lines; the file appears complete or not at all.

    ``earlier_logs`` are log lines the graph wrote before the recorder was
    attached (turtlesim's start lines); they are written first, after the
    ``header`` line (``{"recording": 1, ...header}``) if one is given: where
    the run started, for ``turtletui replay``.
    """

    def __init__(
        self,
        graph: Graph,
        path: str | os.PathLike[str],
        earlier_logs: Iterable[LogRecord] = (),
        header: dict[str, Any] | None = None,
    ) -> None:
        self.path = Path(path)
        if self.path.is_dir():
            raise OSError(f"{path}: cannot write the record (is a folder; name a file such as run.jsonl)")
        self._tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
        try:
            self._file = open(self._tmp, "w", encoding="utf-8")  # noqa: SIM115
        except OSError as err:
            raise OSError(f"{path}: cannot write the record ({err.strerror})") from None
        self._graph = graph
        if header is not None:
            self._write({"recording": 1, **header})
        for record in earlier_logs:
            self._write(_log_event(round(record.t, 9), record))
        graph.taps.append(self._tap)
        graph.record_everything = True

    def _tap(self, kind: str, payload: Any) -> None:
        t = round(self._graph.now_ns / 1e9, 9)
        if kind == "topic":
            topic, msg = payload
            event = {"t": t, "topic": topic.name, "type": topic.type_name, "msg": to_dict(msg)}
        elif kind == "service":
            name, request, response = payload
            event = {"t": t, "service": name, "request": to_dict(request), "response": to_dict(response)}
        elif kind == "goal":
            name, goal = payload
            event = {"t": t, "action": name, "goal": to_dict(goal)}
        elif kind == "log":
            event = _log_event(t, payload)
        else:
            return
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
            self._file.close()
            if keep:
                os.replace(self._tmp, self.path)
        except OSError as err:
            raise OSError(f"{self.path}: cannot write the record ({err.strerror})") from None
        finally:
            self._tmp.unlink(missing_ok=True)
