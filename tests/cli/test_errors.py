"""Every command: a TurtletuiError is the user's one-line error with status 2;
anything else is a bug, said in one line with status 3 and its traceback in a
file under the user's cache."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest
from support.grading import one_line_error
from typer.testing import CliRunner

from turtletui.cli import app
from turtletui.errors import TurtletuiError

USER_ERRORS = [
    ("turtletui.lessons.loader", "LessonError"),
    ("turtletui.runtime.recorder", "RecordingError"),
    ("turtletui.runtime.replay", "RecordingError"),
    ("turtletui.runtime.loader", "ControllerError"),
    ("turtletui.graph.core", "GraphError"),
    ("turtletui.interfaces", "InterfaceError"),
    ("turtletui.worlds.spec", "WorldError"),
    ("turtletui.sim.world", "SimError"),
    ("turtletui.compat.ros_args", "RosArgsError"),
    ("turtletui.grading.integrity", "IntegrityError"),
    ("turtletui.grading.engine", "GradingError"),
    ("turtletui.grading.autograder", "AutograderError"),
    ("turtletui.grading.reports", "ReportError"),
    ("turtletui.grading.submissions", "SubmissionError"),
    ("turtletui.errors", "UsageError"),
    ("turtletui.recording.errors", "RecordingWriteError"),
    ("turtletui.recording.errors", "FoxgloveError"),
    ("turtletui.recording.bag", "BagError"),
    ("turtletui.recording.read", "McapReadError"),
    ("turtletui.grading.wheel", "WheelError"),
    ("turtletui.grading.formats.roster", "RosterError"),
    ("turtletui.tui.terminal", "TerminalError"),
]


@pytest.fixture(autouse=True)
def _cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("TURTLETUI_DISABLE_PLUGIN_AUTOLOAD", "1")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    return tmp_path / "cache"


@pytest.mark.parametrize(("module", "name"), USER_ERRORS)
def test_every_user_facing_error_is_a_turtletui_error(module: str, name: str):
    error = getattr(importlib.import_module(module), name)
    assert issubclass(error, TurtletuiError)


def test_a_turtletui_error_from_any_command_is_one_line_and_status_2(monkeypatch: pytest.MonkeyPatch):
    from turtletui.lessons import loader

    def broken(*args, **kwargs):
        raise loader.LessonError("lessons/x.md:3: unknown field 'tittle'\n(did you mean 'title'?)")

    monkeypatch.setattr(loader, "discover_lessons", broken)
    result = CliRunner().invoke(app, ["lessons"])
    assert one_line_error(result) == (
        "turtletui: error: lessons/x.md:3: unknown field 'tittle' (did you mean 'title'?)\n"
    )


def internal_error_file(result) -> Path:
    """The CLI said "internal error" in one line, exit status 3: the file it names."""
    assert result.exit_code == 3, (result.exit_code, result.stdout, result.stderr)
    (line,) = result.stderr.splitlines()
    assert line.startswith("turtletui: internal error: ")
    assert "Traceback" not in result.stdout + result.stderr
    return Path(line.rsplit("(details in ", 1)[1].rstrip(")"))


@pytest.mark.parametrize(
    ("command", "module", "function"),
    [
        (["lessons"], "turtletui.lessons.loader", "discover_lessons"),
        (["checks"], "turtletui.grading.engine", "available_checks"),
        (["plugins"], "turtletui.plugins.manager", "describe_plugins"),
    ],
    ids=["lessons", "checks", "plugins"],
)
def test_a_bug_is_an_internal_error_with_its_traceback_in_the_cache(
    command, module, function, monkeypatch: pytest.MonkeyPatch, _cache: Path
):
    def buggy(*args, **kwargs):
        raise ValueError("a bug, not bad input")  # a ValueError too: only TurtletuiError is input

    monkeypatch.setattr(importlib.import_module(module), function, buggy)
    result = CliRunner().invoke(app, command)
    details = internal_error_file(result)
    assert "ValueError: a bug, not bad input" in result.stderr
    assert details.parent == _cache / "turtletui" / "errors"
    text = details.read_text()
    assert text.startswith("Traceback") and "buggy" in text and "a bug, not bad input" in text


def test_an_unwritable_cache_puts_the_traceback_in_the_temporary_folder(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
):
    from turtletui.grading import engine

    blocked = tmp_path / "not-a-folder"
    blocked.write_text("")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocked))
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    monkeypatch.setattr("tempfile.tempdir", None)

    def buggy(*args, **kwargs):
        raise KeyError(1)

    monkeypatch.setattr(engine, "available_checks", buggy)
    details = internal_error_file(CliRunner().invoke(app, ["checks"]))
    assert details.parent == tmp_path / "tmp" and "KeyError: 1" in details.read_text()


def test_ctrl_c_is_not_an_internal_error(monkeypatch: pytest.MonkeyPatch):
    from turtletui.grading import engine

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(engine, "available_checks", interrupted)
    result = CliRunner().invoke(app, ["checks"])
    assert result.exit_code != 3 and "internal error" not in result.stderr


def test_usage_errors_are_one_line_naming_the_option_and_the_value(_cache: Path):
    bad = CliRunner().invoke(app, ["autograder", "github", "--bogus"])
    assert bad.exit_code == 2 and "No such option: --bogus" in bad.stderr
    assert bad.stderr.strip().splitlines() == [bad.stderr.strip()]
    for args, option, value in [
        (["run", "x.py", "--headless", "-d", "abc"], "--duration", "'abc'"),
        (["sim", "--headless", "--seed=1.5"], "--seed", "'1.5'"),
    ]:
        wrong = CliRunner().invoke(app, args)
        assert wrong.exit_code == 2 and wrong.stderr.startswith(f"turtletui: error: {option}: "), wrong.stderr
        assert wrong.stderr.count(value) == 1 and len(wrong.stderr.strip().splitlines()) == 1, wrong.stderr
    helped = CliRunner().invoke(app, ["autograder", "--help"])
    assert helped.exit_code == 0 and "gradescope" in helped.stdout
    assert "internal error" not in bad.stderr + helped.stderr
    assert not (_cache / "turtletui").exists()


def test_a_controller_file_that_cannot_be_read_is_one_line_naming_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    # as for a file of another user's that this one may not read (root reads every file, so the
    # refusal is made here): one line naming the file and the cause, no traceback
    node = tmp_path / "node.py"
    node.write_text("import rclpy\n")
    real_read_bytes = Path.read_bytes

    def refused(path: Path) -> bytes:
        if path == node:
            raise PermissionError(13, "Permission denied", str(path))
        return real_read_bytes(path)

    monkeypatch.setattr(Path, "read_bytes", refused)
    result = CliRunner().invoke(app, ["run", str(node), "--headless", "--duration", "1"])
    stderr = one_line_error(result)
    assert f"{node}: cannot be read (Permission denied): check its permissions" in stderr
