"""What a run sends out besides its log: the recording (``--record``) and the
live Foxglove view (``--foxglove``), opened and closed together, for
``turtletui run --headless`` (turtletui.api.run) and ``turtletui sim --headless``."""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from typing import Any

from turtletui.graph.logs import LogRecord


@contextmanager
def run_outputs(
    sim: Any,
    record: str | os.PathLike[str] | None = None,
    foxglove: str | None = None,
    earlier_logs: Iterable[LogRecord] = (),
) -> Iterator[None]:
    """Record ``sim`` (a Simulation) to ``record`` and serve it to Foxglove on
    ``foxglove`` (``HOST:PORT``) for the ``with`` block. ``earlier_logs`` were
    logged before (turtlesim's start lines). However the block ends (Ctrl-C,
    an error), the recording keeps what it has so far. Opening raises OSError
    or ValueError (one line); nothing is left open then."""
    recorder = None
    if record is not None:
        from turtletui.runtime.recorder import open_recorder

        recorder = open_recorder(sim, record, earlier_logs=earlier_logs)
    bridge = None
    if foxglove is not None:
        from turtletui.recording.foxglove import FoxgloveBridge

        try:
            bridge = FoxgloveBridge(sim, foxglove)
        except BaseException:
            if recorder is not None:
                recorder.close(keep=False)
            raise
    try:
        yield
    finally:
        if bridge is not None:
            bridge.close()
        if recorder is not None:
            recorder.close(keep=True)
