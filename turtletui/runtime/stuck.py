"""Where a sandboxed controller that stopped answering is stuck.

A callback in an endless loop (or blocked in a call that never returns) is
stopped after the step timeout; the report then names the line of the
student's file it was on, as an exception's report does. The child has
faulthandler dump every thread's stack, on SIGUSR2, into a memory file the
parent made (:func:`stack_file`, :func:`install`); the parent signals it
before stopping it and reads the dump (:func:`where_stuck`). What the child
wrote is untrusted: only frames of the student's own files are taken
(turtletui.runtime.loader.own_files: the controller file and the modules of
its folder), each checked. Linux only (memfd); elsewhere reports say no more than before.
This module must not import numpy or Textual: the child imports it.
"""

from __future__ import annotations

import linecache
import os
import re
import signal
import stat
import time
from collections.abc import Callable
from pathlib import Path

from turtletui.runtime.loader import frame_text, own_files

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
    """The stuck thread's innermost frame in the student's files (as
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
    """From a faulthandler dump of every thread: the innermost frame in the
    student's own files (the controller file ``path``, a helper module of its
    folder or package) of a thread that is not waiting in turtletui's runtime
    (for its turn, a simulated sleep, the simulator's answer), formatted as a
    traceback line; [] if none. ``path`` is the controller file."""
    mine = own_files(path)
    for block in re.split(r"\n(?=(?:Current thread|Thread) 0x)", dump):
        frames = [m.groups() for m in map(_FRAME.match, block.splitlines()) if m]
        if not frames or frames[0][0].startswith(_WAITING):
            continue  # waiting, or nothing to say
        for filename, line, name in frames:  # most recent call first
            if line.isdigit() and mine(filename) and _source_file(filename, mine):
                linecache.checkcache(filename)  # the file may have changed since it was last read
                return [frame_text(filename, int(line), name, linecache.getline(filename, int(line)))]
    return []


def _source_file(filename: str, mine: Callable[[str], bool]) -> bool:
    """Whether ``filename`` (named by the child: untrusted) is a plain file of
    the student's that this process may read a line of: not a link out of
    their folder (to a file only the grader may read), not a pipe."""
    real = os.path.realpath(filename)
    try:
        regular = stat.S_ISREG(os.stat(real).st_mode)
    except (OSError, ValueError):
        return False
    return regular and (real == filename or mine(real))
