"""Stored results (turtletui.grading.store) are believed only when the grader
signed them and nothing they depend on changed."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

from support.grading import HONEST, WALL_HITTER, grade_cli

from turtletui.grading.store import signing_key


def progress(result) -> list[str]:
    return [line for line in result.stderr.splitlines() if line.startswith("[")]


def test_a_forged_or_edited_result_is_not_believed(tmp_path: Path, lesson: Path):
    student = tmp_path / "class" / "ben"
    student.mkdir(parents=True)
    (student / "controller.py").write_text(WALL_HITTER)
    results = tmp_path / "results"
    args = (tmp_path / "class", "--lesson", lesson, "--results", results, "--same-user", "--format", "json")
    first = grade_cli(*args)
    assert json.loads(first.stdout)["submissions"][0]["score"] == 1.0
    stored = results / "ben.json"
    data = json.loads(stored.read_text())
    # the student (or anyone without the key) edits the kept result: full marks
    data["result"]["score"] = 3.0
    stored.write_text(json.dumps(data))
    again = grade_cli(*args)
    assert json.loads(again.stdout)["submissions"][0]["score"] == 1.0
    assert "kept from an earlier run" not in again.stderr
    # ...while a result the grader signed itself is reused
    third = grade_cli(*args)
    assert "kept from an earlier run" in third.stderr


def test_results_inside_the_students_checkout_are_never_read(tmp_path: Path, lesson: Path):
    """As in a GitHub workflow: the checkout is graded from inside it, and a
    result file committed in it must not count, signed or not."""
    checkout = tmp_path / "repo"
    checkout.mkdir()
    subprocess.run(["git", "init", "-q", str(checkout)], check=True)
    (checkout / "controller.py").write_text(WALL_HITTER)
    results = checkout / "turtletui-grades"
    args = (checkout, "--lesson", lesson, "--results", results, "--same-user", "--format", "json")
    first = grade_cli(*args)
    assert first.exit_code == 0, first.stderr
    second = grade_cli(*args)
    assert "kept from an earlier run" not in second.stderr  # graded again: the store is in the checkout
    assert json.loads(second.stdout)["submissions"][0]["score"] == 1.0


def test_the_key_lives_outside_submissions_readable_only_by_its_owner(tmp_path: Path, monkeypatch):
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    key = signing_key()
    path = tmp_path / "data" / "turtletui" / "results.key"
    assert path.stat().st_mode & 0o777 == 0o600
    assert signing_key() == key and len(key) == 32
    monkeypatch.setenv("TURTLETUI_RESULTS_KEY", "a secret of this job")
    assert signing_key() != key


def test_a_changed_lesson_or_limit_regrades(tmp_path: Path, lesson: Path):
    student = tmp_path / "class" / "ann"
    student.mkdir(parents=True)
    (student / "controller.py").write_text(HONEST)
    args = (tmp_path / "class", "--lesson", lesson, "--results", tmp_path / "res", "--same-user")
    grade_cli(*args)
    assert "kept" in grade_cli(*args).stderr
    lesson.write_text(lesson.read_text().replace("weight = 1.0", "weight = 1.5"))
    assert "kept" not in grade_cli(*args).stderr
    assert os.listdir(tmp_path / "res")
