"""The turtletui command itself: --version, and the commands it lists."""

from __future__ import annotations

from typer.testing import CliRunner

import turtletui
from turtletui.cli import app


def test_version_prints_the_version_without_a_command():
    result = CliRunner().invoke(app, ["--version"])
    assert result.exit_code == 0, result.output
    assert result.stdout == f"turtletui {turtletui.__version__}\n"


def test_help_lists_every_command():
    result = CliRunner().invoke(app, ["--help"])
    assert result.exit_code == 0
    for command in ("run", "lessons", "lesson", "new", "grade", "checks", "replay", "autograder", "plugins"):
        assert f" {command} " in result.stdout or f" {command}\n" in result.stdout, command
