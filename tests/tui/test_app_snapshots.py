"""The whole app at 80x24, as a student first sees it and with the help
open. Time stands still (a clock that never moves), so the pictures are
the same on every run."""

from __future__ import annotations

from turtletui.tui.app import TurtleApp


def still_app() -> TurtleApp:
    return TurtleApp(clock=lambda: 0.0)


def test_snapshot_app_80x24(snap_compare):
    assert snap_compare(still_app(), terminal_size=(80, 24))


def test_snapshot_help_80x24(snap_compare):
    assert snap_compare(still_app(), terminal_size=(80, 24), press=["question_mark"])


def test_snapshot_console_80x24(snap_compare):
    keys = ["colon", *"ros2 topic info /turtle1/cmd_vel -v", "enter"]
    assert snap_compare(still_app(), terminal_size=(80, 24), press=keys)
