"""`turtletui run --pixels graphics` in a pseudo-terminal that plays a Sixel
terminal: it answers the device-attributes query with Sixel support, and the
app must then send the arena as Sixel images (a DCS ... q sequence) that start
with turtlesim's background colour."""

from __future__ import annotations

import fcntl
import os
import pty
import re
import select
import struct
import sys
import termios
import time
from pathlib import Path

import pytest

import turtletui

COLS, ROWS = 120, 40
SIXEL = re.compile(rb"\x1bP[0-9;]*q(.*?)\x1b\\", re.DOTALL)
"""A Sixel image: DCS, parameters, q, the data, ST."""


def test_a_sixel_terminal_gets_the_picture_as_sixels() -> None:
    pid, fd = pty.fork()
    if pid == 0:  # the child: the app on the pty (pixel size given, as terminals do)
        try:
            fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", ROWS, COLS, COLS * 10, ROWS * 20))
            env = {k: v for k, v in os.environ.items() if k not in ("TMUX", "STY", "NO_COLOR")}
            env["TERM"] = "xterm-256color"
            env["PYTHONPATH"] = str(Path(turtletui.__file__).resolve().parents[1])
            os.execve(sys.executable, [sys.executable, "-m", "turtletui", "run", "--pixels", "graphics"], env)
        finally:
            os._exit(127)
    seen = b""
    answered = False
    deadline = time.monotonic() + 60.0
    try:
        while time.monotonic() < deadline and len(SIXEL.findall(seen)) < 2:
            ready, _, _ = select.select([fd], [], [], 0.1)
            if not ready:
                continue
            try:
                chunk = os.read(fd, 65536)
            except OSError:
                break
            seen += chunk
            if not answered and b"\x1b[c" in seen:
                os.write(fd, b"\x1b[?62;4;22c")  # a VT220 with Sixel graphics (4)
                answered = True
        os.write(fd, b"q")
    finally:
        _reap(pid, fd)
    assert answered, "the app never asked the terminal about graphics"
    images = SIXEL.findall(seen)
    assert images, seen[-500:]
    # Raster attributes, then colour 0: turtlesim's blue (69, 86, 255) in percent
    # (27, 34, 100), give or take the palette's rounding: the quantised palette
    # depends on what else is in the picture when it is sent (27;33;100 seen).
    assert images[0].startswith(b'"1;1;'), images[0][:80]
    colour = re.search(rb"#0;2;(\d+);(\d+);(\d+)", images[0])
    assert colour, images[0][:80]
    assert [int(c) for c in colour.groups()] == pytest.approx([27, 34, 100], abs=1), images[0][:80]


def _reap(pid: int, fd: int) -> None:
    """Let the app quit (reading what it still writes), or kill it after 10 s."""
    end = time.monotonic() + 10.0
    exited = False
    while time.monotonic() < end and not exited:
        exited = os.waitpid(pid, os.WNOHANG)[0] != 0
        if select.select([fd], [], [], 0.1)[0]:
            try:
                os.read(fd, 65536)
            except OSError:
                pass
    if not exited:
        os.kill(pid, 9)
        os.waitpid(pid, 0)
    os.close(fd)
