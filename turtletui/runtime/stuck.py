"""Where a sandboxed controller that stopped answering is stuck.

A callback in an endless loop (or blocked in a call that never returns) is
stopped after the step timeout; the report then names the line of the
student's file it was on, as an exception's report does. The child has
faulthandler dump every thread's stack, on SIGUSR2, into a memory file the
parent made (:func:`stack_file`, :func:`install`); the parent signals it
before stopping it and reads the dump (:func:`where_stuck`). What the child
wrote is untrusted: only frames of the controller's own file are taken,
each checked. Linux only (memfd); elsewhere reports say no more than before.
This module must not import numpy or Textual: the child imports it.
"""

from __future__ import annotations

import linecache
import os
import re
import signal
import time
from pathlib import Path

from turtletui.runtime.loader import frame_text

SIGNAL = signal.SIGUSR2
_DUMP_LIMIT = 1 << 16
"""Bytes of a dump read at most."""
_DUMP_WAIT = 0.5
"""Wall seconds the parent waits for the dump to be written."""
_FRAME = re.compile(r'^  File "(.+)", line (\d+) in (\S{1,200})$')
_WAITING = str(Path(__file__).resolve().parent) + os.sep
"""Where a thread of the child waits for its turn or for the simulator (turtletui.runtime)."""


def stack_file() -> int | None:
    """A memory file for the child's dump (its descriptor), or None where there are none."""
    try:
        return os.memfd_create("turtletui-stack")
    except (AttributeError, OSError):
        return None


def install(fd: int) -> None:
    """In the child: dump every thread's stack into ``fd`` on SIGUSR2."""
    import faulthandler

    try:
        faulthandler.register(SIGNAL, file=fd, all_threads=True, chain=False)
    except (OSError, ValueError, RuntimeError):
        pass


def where_stuck(pid: int, fd: int, path: Path) -> list[str]:
    """The stuck thread's innermost frame in the controller file ``path`` (as
    turtletui.runtime.loader.frame_text formats frames), asked of the child
    ``pid`` now; [] if it says nothing usable in time."""
    try:
        start = os.fstat(fd).st_size
        os.kill(pid, SIGNAL)
    except OSError:
        return []
    deadline = time.monotonic() + _DUMP_WAIT
    size = start
    while time.monotonic() < deadline:
        time.sleep(0.02)
        try:
            now = os.fstat(fd).st_size
        except OSError:
            return []
        if now > start and now == size:
            break  # written, and no longer growing
        size = now
    try:
        dump = os.pread(fd, min(size - start, _DUMP_LIMIT), start) if size > start else b""
    except OSError:
        return []
    return stuck_frame(dump.decode("utf-8", "replace"), path)


def stuck_frame(dump: str, path: Path) -> list[str]:
    """From a faulthandler dump of every thread: the innermost frame in
    ``path`` of a thread that is not waiting in turtletui's runtime (for its
    turn, a simulated sleep, the simulator's answer), formatted as a
    traceback line; [] if none."""
    target = str(path.resolve())
    for block in re.split(r"\n(?=(?:Current thread|Thread) 0x)", dump):
        frames = [m.groups() for m in map(_FRAME.match, block.splitlines()) if m]
        if not frames or frames[0][0].startswith(_WAITING):
            continue  # waiting, or nothing to say
        for filename, line, name in frames:  # most recent call first
            if filename == target and line.isdigit():
                linecache.checkcache(target)  # the file may have changed since it was last read
                return [frame_text(target, int(line), name, linecache.getline(target, int(line)))]
    return []
