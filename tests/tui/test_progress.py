"""A student's lesson progress: kept under the XDG data folder, written
atomically, and a damaged file is a one-line warning, never a crash."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from turtletui.tui.progress import Progress, progress_file


def test_the_file_is_under_the_xdg_data_folder(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    assert progress_file() == tmp_path / "turtletui" / "progress.json"
    monkeypatch.delenv("XDG_DATA_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert progress_file() == tmp_path / "home" / ".local" / "share" / "turtletui" / "progress.json"


def test_checks_are_kept_and_read_back(tmp_path: Path) -> None:
    path = tmp_path / "deep" / "progress.json"
    progress = Progress(path)
    assert progress.lessons == {} and progress.warning is None
    progress.record("part6", 6, 10)
    progress.record("part6", 10, 10)
    progress.record("part6", 4, 10)  # a later failure keeps the pass and the best score
    again = Progress(path).get("part6")
    assert again.passed and again.best_score == 10 and again.max_score == 10 and again.checks == 3
    assert Progress(path).get("part7") is None
    assert [p.name for p in path.parent.iterdir()] == ["progress.json"]  # no temporary file left


@pytest.mark.parametrize("text", [
    "{not json",
    "[]",
    json.dumps({"version": 99, "lessons": {}}),
    json.dumps({"version": 1, "lessons": {"part6": {"passed": "yes"}}}),
    json.dumps({"version": 1, "lessons": {"part6": {"passed": "yes", "best_score": 1, "max_score": 1,
                                                    "checks": 1, "last_checked": 0}}}),
    "\udcff".encode("utf-8", "surrogateescape").decode("latin-1"),
])
def test_a_damaged_file_is_a_warning_and_the_next_check_repairs_it(tmp_path: Path, text: str) -> None:
    path = tmp_path / "progress.json"
    path.write_text(text, encoding="latin-1")
    progress = Progress(path)
    assert progress.lessons == {}
    assert progress.warning.startswith(f"{path}: your progress could not be read (")
    assert "\n" not in progress.warning
    progress.record("part6", 10, 10)
    assert Progress(path).get("part6").passed


def test_a_file_that_cannot_be_written_is_a_warning(tmp_path: Path) -> None:
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("")
    progress = Progress(blocker / "turtletui" / "progress.json")
    entry = progress.record("part6", 10, 10)
    assert entry.passed  # kept for this run of the app
    assert progress.warning.startswith("your progress could not be saved: ")
    assert "\n" not in progress.warning
