"""JSON Lines recording of a run, written atomically."""

from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any

from turtletui.graph.core import Graph
from turtletui.interfaces import to_dict


def _clean(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_clean(v) for v in value]
    return value


class Recorder:
    """Writes every topic message, service call and log line of a graph to
    ``path`` as JSON Lines; the file appears complete or not at all."""

    def __init__(self, graph: Graph, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        self._tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
        try:
            self._file = open(self._tmp, "w", encoding="utf-8")  # noqa: SIM115
        except OSError as err:
            raise OSError(f"{path}: cannot write the record ({err.strerror})") from None
        self._graph = graph
        graph.taps.append(self._tap)

    def _tap(self, kind: str, payload: Any) -> None:
        t = round(self._graph.now_ns / 1e9, 9)
        if kind == "topic":
            topic, msg = payload
            event = {"t": t, "topic": topic.name, "type": topic.type_name, "msg": to_dict(msg)}
        elif kind == "service":
            name, request, response = payload
            event = {"t": t, "service": name, "request": to_dict(request), "response": to_dict(response)}
        else:
            event = {"t": t, "log": {"level": payload.level_name, "node": payload.node, "msg": payload.msg}}
        try:
            line = json.dumps(event, allow_nan=False)
        except ValueError:
            line = json.dumps(_clean(event))
        self._file.write(line + "\n")

    def close(self, keep: bool = True) -> None:
        """Finish the file (rename into place) or drop it."""
        if self._tap in self._graph.taps:
            self._graph.taps.remove(self._tap)
        self._file.close()
        if keep:
            os.replace(self._tmp, self.path)
        else:
            self._tmp.unlink(missing_ok=True)
