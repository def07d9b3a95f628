"""`turtletui autograder gradescope|github --lesson ID -o DIR`."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from support.grading import one_line_error
from typer.testing import CliRunner

from turtletui import __version__
from turtletui.cli import app


@pytest.fixture(autouse=True)
def _no_installed_plugins(monkeypatch):
    monkeypatch.setenv("TURTLETUI_DISABLE_PLUGIN_AUTOLOAD", "1")


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


def test_gradescope_writes_the_autograder(tmp_path: Path):
    out = tmp_path / "gs"
    result = invoke("autograder", "gradescope", "--lesson", "part6-closed-loop", "-o", str(out))
    assert result.exit_code == 0, result.output
    assert f"wrote {out / 'run_autograder'}" in result.stdout
    assert os.access(out / "run_autograder", os.X_OK)
    # turtletui's own wheel travels in the bundle: no package index has this version
    wheel = out / f"turtletui-{__version__}-py3-none-any.whl"
    assert wheel.is_file()
    assert f"pip install /autograder/source/{wheel.name}" in (out / "setup.sh").read_text()
    # A bundled lesson comes with the installed turtletui: nothing to copy.
    assert not (out / "turtletui_lessons").exists()


def test_github_writes_the_workflow(tmp_path: Path):
    result = invoke(
        "autograder", "github", "--lesson", "part6-closed-loop", "--output", str(tmp_path),
        "--requirement", "turtletui>=0.1",
    )
    assert result.exit_code == 0, result.output
    text = (tmp_path / ".github" / "workflows" / "classroom.yml").read_text()
    assert "--lesson part6-closed-loop --format github" in text
    assert "pip install 'turtletui>=0.1'" in text


def test_a_custom_lesson_folder_is_copied(tmp_path: Path):
    lessons = tmp_path / "lessons"
    lessons.mkdir()
    (lessons / "maze.md").write_text('+++\nid = "maze"\ntitle = "Maze"\n+++\n# Maze\n')
    out = tmp_path / "gs"
    result = invoke(
        "autograder", "gradescope", "--lesson", "maze", "-o", str(out), "--lessons", str(lessons)
    )
    assert result.exit_code == 0, result.output
    assert (out / "turtletui_lessons" / "maze.md").is_file()
    assert "--lessons /autograder/source/turtletui_lessons" in (out / "run_autograder").read_text()


def test_unknown_lesson_is_a_one_line_error(tmp_path: Path):
    result = invoke("autograder", "gradescope", "--lesson", "part6-closed-lop", "-o", str(tmp_path))
    message = one_line_error(result)
    assert "no lesson 'part6-closed-lop'" in message and "part6-closed-loop" in message
    assert os.listdir(tmp_path) == []
    result = invoke("autograder", "github", "--lesson", "nope", "-o", str(tmp_path))
    one_line_error(result)


def test_existing_files_need_force(tmp_path: Path):
    args = ("autograder", "github", "--lesson", "part6-closed-loop", "-o", str(tmp_path))
    assert invoke(*args).exit_code == 0
    message = one_line_error(invoke(*args))
    assert "classroom.yml already exists; use --force to overwrite it" in message
    assert invoke(*args, "--force").exit_code == 0


def test_help_lists_both_platforms():
    result = invoke("autograder", "--help")
    assert result.exit_code == 0
    assert "gradescope" in result.stdout and "github" in result.stdout
