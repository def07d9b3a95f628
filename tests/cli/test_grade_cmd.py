"""`turtletui grade`: exit statuses, bad input as one-line errors (per student:
in that student's row), the report formats written for a real graded class,
and whom student code runs as."""

from __future__ import annotations

import base64
import csv
import io
import json
import os
import pwd
from pathlib import Path

import pytest
from support.grading import (
    HONEST,
    MAX_SCORE,
    SYNTAX_ERROR,
    WALL_HITTER,
    grade_cli,
    make_class,
    one_line_error,
    stored_results,
    write_lesson,
)

from turtletui.grading.integrity import IntegrityError, check_runtime_readable


@pytest.fixture
def lesson(tmp_path: Path) -> Path:
    return write_lesson(tmp_path)


# -- exit status ------------------------------------------------------------------------


@pytest.fixture
def klass(tmp_path: Path) -> Path:
    """ann passes everything (3 points), ben hits the wall in both scenarios (1 point)."""
    return make_class(tmp_path / "class", {"ann": HONEST, "ben": WALL_HITTER})


def grade_class(klass: Path, lesson: Path, *args: str | Path, env: dict[str, str] | None = None):
    results = klass.parent / "results"
    return grade_cli(klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "2", *args, env=env)


def test_exit_status_is_0_whatever_the_scores_and_1_below_fail_under(klass: Path, lesson: Path):
    graded = grade_class(klass, lesson, "--format", "csv")
    assert graded.exit_code == 0, graded.stderr
    assert "ben,1,3," in graded.stdout
    # the same results (kept) against --fail-under: 1 when a student is below it
    below = grade_class(klass, lesson, "--format", "csv", "--fail-under", "3")
    assert below.exit_code == 1, below.stderr
    assert below.stdout == graded.stdout  # the report is written all the same
    assert "turtletui: 1 scored under --fail-under 3: ben (1)" in below.stderr  # and who is below says why
    assert grade_class(klass, lesson, "--format", "csv", "--fail-under", "1").exit_code == 0


def test_distro_reaches_every_worker_and_results_of_another_distro_are_not_reused(klass: Path, lesson: Path):
    # ann and ben import turtlesim.msg, which Kilted no longer has (turtlesim_msgs)
    before = dict(os.environ)
    jazzy = grade_class(klass, lesson, "--format", "csv", "--distro", "jazzy")
    assert jazzy.exit_code == 0, jazzy.stderr
    assert "ann,3,3," in jazzy.stdout
    kilted = grade_class(klass, lesson, "--format", "csv", "--distro", "kilted")
    assert kilted.exit_code == 0, kilted.stderr
    assert "ann,0,3,0,0," in kilted.stdout  # crashed at import: no check passes
    assert dict(os.environ) == before  # an option, not a change to the grader's environment
    again = grade_class(klass, lesson, "--format", "csv", "--distro", "jazzy")
    assert again.stdout == jazzy.stdout


def test_an_internal_error_is_status_3_with_one_line_and_the_details_in_a_file(
    klass: Path, lesson: Path, monkeypatch: pytest.MonkeyPatch
):
    from turtletui.grading import batch

    def broken(*args, **kwargs):
        raise RuntimeError("grader bug")

    monkeypatch.setattr(batch, "grade_submissions", broken)
    result = grade_class(klass, lesson)
    assert result.exit_code == 3
    (line,) = result.stderr.splitlines()
    assert line.startswith("turtletui: internal error: RuntimeError: grader bug (details in ")
    details = Path(line.rsplit("(details in ", 1)[1].rstrip(")"))
    try:
        assert "Traceback" in details.read_text() and "grader bug" in details.read_text()
    finally:
        details.unlink()
    assert "Traceback" not in result.stdout + result.stderr


# -- bad input -----------------------------------------------------------------------------


def test_a_plugin_file_runs_once_per_command_however_many_runs(klass: Path, lesson: Path, tmp_path: Path):
    log = tmp_path / "imports.log"
    plugin = tmp_path / "my_checks.py"
    plugin.write_text(
        "from turtletui.plugins import hookimpl\n"
        f"open({str(log)!r}, 'a').write('imported\\n')\n"
        "@hookimpl\n"
        "def turtletui_register_checks(register):\n"
        "    register('always', lambda trace, thresholds: True)\n",
        encoding="utf-8",
    )
    graded = grade_class(klass, lesson, "--plugin", plugin, "--format", "csv")
    assert graded.exit_code == 0, graded.stderr
    assert "ann,3,3," in graded.stdout
    assert log.read_text() == "imported\n"  # 4 runs on 2 workers: the workers fork with it


def test_a_missing_lesson_is_a_one_line_error(klass: Path):
    stderr = one_line_error(grade_cli(klass, "--lesson", "no-such-lesson", "--same-user"))
    assert "no-such-lesson" in stderr


def test_a_missing_path_and_an_empty_folder_are_one_line_errors(tmp_path: Path, lesson: Path):
    stderr = one_line_error(grade_cli(tmp_path / "nowhere", "--lesson", lesson, "--same-user"))
    assert f"{tmp_path / 'nowhere'}: no such file or folder" in stderr
    (tmp_path / "empty").mkdir()
    stderr = one_line_error(grade_cli(tmp_path / "empty", "--lesson", lesson, "--same-user"))
    assert f"{tmp_path / 'empty'}: empty folder" in stderr
    (tmp_path / "notes").mkdir()
    (tmp_path / "notes" / "notes.txt").write_text("to do\n")
    stderr = one_line_error(grade_cli(tmp_path / "notes", "--lesson", lesson, "--same-user"))
    assert f"{tmp_path / 'notes'}: no Python (.py) file and no student's folder in it" in stderr


def test_a_check_the_lesson_names_that_does_not_exist_is_a_one_line_error(klass: Path, lesson: Path):
    text = lesson.read_text()
    lesson.write_text(text.replace('name = "wall_hits"', 'name = "wall_hitz"'))
    line = text[: text.index('name = "wall_hits"')].count("\n")  # the [[checks]] table's line, or its name's
    stderr = one_line_error(grade_class(klass, lesson))
    assert "'wall_hitz' is not a registered check (did you mean 'wall_hits'?)" in stderr
    assert f"{lesson}:" in stderr
    assert any(f"{lesson}:{n}:" in stderr for n in (line, line + 1)), stderr


def test_per_student_problems_are_in_their_rows_with_score_0_and_the_rest_is_graded(tmp_path: Path, lesson: Path):
    klass = make_class(
        tmp_path / "class",
        {
            "ann": HONEST,
            "bin": b"\x7fELF\x02\x01\x01\x00\x00\x00" + bytes(range(256)),
            "syn": SYNTAX_ERROR,
            # Python reads these two (a byte order mark, a coding declaration): so does turtletui
            "bom": b"\xef\xbb\xbf" + HONEST.encode(),
            "latin": b"# -*- coding: latin-1 -*-\n# caf\xe9\n" + HONEST.encode(),
            "cp": b"# caf\xe9 without a declaration\n" + HONEST.encode(),
        },
    )
    (klass / "pipe").mkdir()
    os.mkfifo(klass / "pipe" / "controller.py")  # read, it would block the grader for ever
    (klass / "link").mkdir()
    (klass / "link" / "controller.py").symlink_to("/nonexistent/controller.py")
    (klass / "nocode").mkdir()
    (klass / "nocode" / "README.md").write_text("I forgot to upload it\n")
    (klass / "two").mkdir()
    (klass / "two" / "a.py").write_text(HONEST)
    (klass / "two" / "b.py").write_text(HONEST)
    (klass / "grades.xlsx").write_bytes(b"PK\x03\x04")
    result = grade_class(klass, lesson, "--format", "json")
    assert result.exit_code == 0, result.stderr
    assert "Traceback" not in result.stdout + result.stderr
    rows = {s["student"]: s for s in json.loads(result.stdout)["submissions"]}
    for right in ("ann", "bom", "latin"):
        assert rows[right]["score"] == MAX_SCORE and rows[right]["error"] is None, rows[right]
    expected = {
        "bin": "is a binary file, not Python source",
        "syn": "SyntaxError",
        "cp": "controller.py:1: is not utf-8 text (byte 5); save it as UTF-8",
        "pipe": "controller.py is not a regular file (a pipe or a device?)",
        "link": "controller.py is a link (to /nonexistent/controller.py), which is not graded",
        "nocode": "no controller",
        "two": "several possible controllers (a.py, b.py)",
    }
    assert "grades" not in rows  # a file that is not Python is nobody's submission
    for student, words in expected.items():
        row = rows[student]
        assert row["score"] == 0 and row["tests"] == [], row
        assert words in row["error"] and "\n" not in row["error"], row["error"]
        assert row["max_score"] == MAX_SCORE
    # ... each with a one-line progress line, and its result kept like any other
    progress = [line for line in result.stderr.splitlines() if line.startswith("[")]
    assert len(progress) == len(rows) == 10
    assert sorted(stored_results(klass.parent / "results")) == sorted(rows)


def test_an_unwritable_output_is_a_one_line_error_and_loses_no_result(klass: Path, lesson: Path, tmp_path: Path):
    graded = grade_class(klass, lesson, "--format", "json")
    assert graded.exit_code == 0, graded.stderr
    kept = stored_results(tmp_path / "results")
    assert sorted(kept) == ["ann", "ben"]

    blocker = tmp_path / "a file"
    blocker.write_text("not a folder\n")
    # in a file's "folder"; a folder; a folder only the kernel writes (even root cannot)
    for bad in (blocker / "report.json", tmp_path, Path("/proc/report.json")):
        stderr = one_line_error(grade_class(klass, lesson, "--format", "json", "--output", bad, "--force"))
        assert f"cannot write {bad}" in stderr
    # refused before grading anyone: the results kept earlier are all there, unchanged
    assert stored_results(tmp_path / "results") == kept
    # a results folder that cannot be made is bad input too
    stderr = one_line_error(grade_cli(klass, "--lesson", lesson, "--results", blocker / "r", "--same-user"))
    assert str(blocker / "r") in stderr
    stderr = one_line_error(grade_cli(klass, "--lesson", lesson, "--results", blocker, "--same-user"))
    assert f"{blocker}: cannot write results there (it is a file, not a folder)" in stderr


# -- report formats ------------------------------------------------------------------------


def test_json_output_has_the_documented_shape(klass: Path, lesson: Path, tmp_path: Path):
    out = tmp_path / "report.json"
    result = grade_class(klass, lesson, "--format", "json", "--output", out)
    assert result.exit_code == 0, result.stderr
    assert result.stdout == ""
    report = json.loads(out.read_text())
    assert set(report) == {"lesson", "max_score", "submissions"}
    assert (report["lesson"], report["max_score"]) == ("tiny-walls", MAX_SCORE)
    for sub in report["submissions"]:
        assert set(sub) == {
            "submission", "student", "score", "max_score", "error", "execution_time", "graded", "tests",
            "recordings", "pictures",
        }
        assert sub["max_score"] == MAX_SCORE and sub["error"] is None and sub["execution_time"] > 0
        assert sum(t["score"] for t in sub["tests"]) == pytest.approx(sub["score"])
        for test in sub["tests"]:
            assert set(test) == {"name", "score", "max_score", "status", "output", "check", "scenario", "hidden"}
            assert test["status"] in ("passed", "failed")
    ann, ben = report["submissions"]
    assert (ann["student"], ann["score"], ben["student"], ben["score"]) == ("ann", 3.0, "ben", 1.0)
    assert [t["name"] for t in ben["tests"]] == [
        "wall_hits [centre]", "wall_hits [hidden 1]", "no_crash [centre]", "no_crash [hidden 1]"
    ]


def test_csv_has_one_row_per_student(klass: Path, lesson: Path):
    result = grade_class(klass, lesson, "--format", "csv")
    assert result.exit_code == 0, result.stderr
    rows = list(csv.reader(io.StringIO(result.stdout)))
    assert rows == [
        ["student", "score", "max_score", "wall_hits", "no_crash", "graded", "error"],
        ["ann", "3", "3", "2", "1", "controller.py", ""],
        ["ben", "1", "3", "0", "1", "controller.py", ""],
    ]


def test_gradescope_with_two_submissions_is_a_one_line_error(klass: Path, lesson: Path):
    stderr = one_line_error(grade_class(klass, lesson, "klass_again", "--format", "gradescope"))
    assert "klass_again: no such file" in stderr
    stderr = one_line_error(grade_class(klass, lesson, klass, "--format", "gradescope"))
    assert "--format gradescope reports one submission" in stderr and "got 2" in stderr


def test_gradescope_grades_a_folder_of_folders_as_one_ambiguous_upload(klass: Path, lesson: Path):
    """The platform hands over one upload: two folders in it are two candidates, not two students."""
    result = grade_class(klass, lesson, "--format", "gradescope")
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)
    assert data["score"] == 0.0
    assert "several possible controllers (ann/controller.py, ben/controller.py)" in data["output"]
    # an instructor who meant the class is told what to use instead
    assert "one student per subfolder? this format grades one upload" in data["output"]
    assert "--format table, json or csv" in data["output"]


def test_github_appends_a_result_line_to_github_output(klass: Path, lesson: Path, tmp_path: Path):
    github_output = tmp_path / "github_output"
    github_output.write_text("earlier=step\n")
    result = grade_cli(
        klass / "ben", "--lesson", lesson, "--results", tmp_path / "results", "--same-user",
        "--format", "github", env={"GITHUB_OUTPUT": str(github_output)},
    )
    assert result.exit_code == 0, result.stderr
    earlier, line = github_output.read_text().splitlines()
    assert earlier == "earlier=step"
    assert line.startswith("result=")
    assert line[len("result="):] == result.stdout.strip()
    decoded = json.loads(base64.b64decode(line[len("result="):]))
    assert decoded["version"] == 1 and decoded["status"] == "fail" and decoded["max_score"] == MAX_SCORE
    assert sum(t["score"] for t in decoded["tests"]) == pytest.approx(1.0)


# -- whom student code runs as ------------------------------------------------------------

SNOOP = """\
import os
import rclpy
from rclpy.node import Node

RESULTS = "RESULTS_FOLDER"
LESSON = "LESSON_FILE"


def tried(action):
    try:
        action()
        return "yes"
    except OSError as err:
        return type(err).__name__


def main():
    rclpy.init()
    node = Node("snoop")
    results = tried(lambda: os.listdir(RESULTS))
    lesson = tried(lambda: open(LESSON).read())
    raise RuntimeError(f"uid={os.getuid()} results={results} lesson={lesson}")
"""


def crash_output(json_report: str) -> str:
    (sub,) = json.loads(json_report)["submissions"]
    return next(t["output"] for t in sub["tests"] if t["name"] == "no_crash [centre]")


def test_student_code_runs_unprivileged_when_the_grader_is_root(tmp_path: Path, lesson: Path):
    results = tmp_path / "results"
    klass = make_class(
        tmp_path / "class",
        {"snoop": SNOOP.replace("RESULTS_FOLDER", str(results)).replace("LESSON_FILE", str(lesson))},
    )
    results.mkdir()
    (results / "other.json").write_text("{}")
    args = (klass, "--lesson", lesson, "--results", results, "--format", "json", "-j", "1")
    if os.geteuid() != 0:
        # an ordinary grader: the student's code runs as that user
        result = grade_cli(*args)
        assert result.exit_code == 0, result.stderr
        crash = crash_output(result.stdout)
        assert f"uid={os.getuid()} results=yes lesson=yes" in crash
        return
    try:
        check_runtime_readable()
    except IntegrityError as err:
        # root, with turtletui or Python where user nobody cannot read them:
        # refuse, naming the folder, rather than run student code as root
        stderr = one_line_error(grade_cli(*args))
        assert "grading as root runs student code as user 'nobody', who cannot read" in stderr
        blocked = str(err).split("who cannot read ", 1)[1].split(" ")[0]
        assert Path(blocked).exists() and not os.stat(blocked).st_mode & 0o001
        assert f"cannot read {blocked} " in stderr
        return
    # root, and the runtime is readable: the student's code runs as nobody
    result = grade_cli(*args)
    assert result.exit_code == 0, result.stderr
    crash = crash_output(result.stdout)
    nobody = pwd.getpwnam("nobody").pw_uid
    assert f"uid={nobody} results=PermissionError lesson=PermissionError" in crash
