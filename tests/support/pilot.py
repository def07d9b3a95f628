"""Driving the Textual app in tests: Pilot scenarios as plain tests, waiting
for the app, reading its panels."""

from __future__ import annotations

import asyncio
import functools
import os
import time
from pathlib import Path

from turtletui.tui.app import TurtleApp
from turtletui.tui.widgets.textlog import TextLog

SIZE = (120, 40)


def pilot_test(scenario):
    """Run an async Pilot scenario as a plain test (no async plugin needed)."""

    @functools.wraps(scenario)
    def test(*args, **kwargs) -> None:
        asyncio.run(scenario(*args, **kwargs))

    return test


def log_text(app: TurtleApp, selector: str = "#log-lines") -> str:
    """What a log panel holds (every entry kept, one per line)."""
    return "\n".join(app.query_one(selector, TextLog).entries)


def rewrite(path: Path, text: str) -> None:
    """Save ``path`` again with a modification time a second later than before,
    as an editor saving a file later would (no sleep to make the clock move)."""
    before = path.stat().st_mtime_ns
    path.write_text(text)
    later = before + 1_000_000_000
    os.utime(path, ns=(later, later))


async def wait_for(pilot, condition, timeout: float = 30.0) -> None:
    """Let the app run until ``condition()`` (a generous deadline: busy machines)."""
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "timed out waiting for the app"
        await pilot.pause(0.05)


async def type_command(pilot, line: str) -> None:
    """Type a ros2 command on the app's command line (opening it first) and run
    it: its first key pressed, the rest pasted (a key at a time, a long command
    took seconds while the simulation redraws)."""
    command = pilot.app.query_one("#command")
    if pilot.app.focused is not command:
        await pilot.press("colon")
    await pilot.press(line[0])
    command.insert_text_at_cursor(line[1:])
    await pilot.press("enter")
