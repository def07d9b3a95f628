"""Report writers (turtletui.grading.reports): every format against its schema,
hidden scenarios, injection from student data, and atomic writes."""

from __future__ import annotations

import base64
import csv
import io
import json
import os
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from turtletui.grading import reports
from turtletui.grading.reports import (
    FORMATS,
    ReportError,
    github_output_line,
    render_report,
    write_report,
)
from turtletui.grading.results import FAILED, PASSED, GradeReport, SubmissionResult, TestResult

LESSON = "part6-closed-loop"
HIDDEN_OUTPUT = "Hidden scenario: failed. Keep the turtle off the walls from any start."


def make_test(check: str, scenario: str, score: float, weight: float, output: str = "",
                hidden: bool = False) -> TestResult:
    return TestResult(
        name=f"{check} [{scenario}]", check=check, scenario=scenario, score=score,
        max_score=weight, status=PASSED if score == weight else FAILED,
        output=output or f"{check} on {scenario}: ok", hidden=hidden,
    )


def alice() -> SubmissionResult:
    tests = [
        make_test("no_wall_hits", "centre", 2.0, 2.0),
        make_test("keeps_moving", "centre", 1.0, 1.0),
        make_test("no_wall_hits", "hidden 1", 0.0, 2.0, HIDDEN_OUTPUT, hidden=True),
        make_test("keeps_moving", "hidden 1", 1.0, 1.0, "Hidden scenario: passed.", hidden=True),
    ]
    return SubmissionResult(
        submission="subs/alice.py", student="alice", score=4.0, max_score=6.0,
        tests=tests, execution_time=3.6,
    )


def bob_broken() -> SubmissionResult:
    return SubmissionResult(
        submission="subs/bob", student="bob", score=0.0, max_score=0.0,
        error="no controller found in subs/bob (no .py file)", execution_time=0.2,
    )


def evil() -> SubmissionResult:
    """A student whose id and log lines try to break the formats."""
    output = "log: \x1b[31mred\x1b[0m \x00 nul <tag> & \"quotes\" ]]> [bold]markup[/bold]\nsecond line"
    tests = [
        make_test("no_wall_hits", "centre", 0.0, 2.0, output),
        make_test("keeps_moving", "centre", 1.0, 1.0),
    ]
    return SubmissionResult(
        submission="subs/=HYPERLINK(1).py", student="=HYPERLINK(\"http://x\")", score=1.0,
        max_score=3.0, tests=tests, execution_time=1.0,
    )


def batch() -> GradeReport:
    return GradeReport(lesson=LESSON, submissions=[alice(), bob_broken(), evil()], max_score=6.0)


def single(sub: SubmissionResult) -> GradeReport:
    return GradeReport(lesson=LESSON, submissions=[sub], max_score=6.0)


# -- json ---------------------------------------------------------------------------


def test_json_has_the_documented_shape():
    data = json.loads(render_report(batch(), "json"))
    assert data["lesson"] == LESSON
    assert isinstance(data["submissions"], list) and len(data["submissions"]) == 3
    for sub in data["submissions"]:
        assert isinstance(sub["submission"], str)
        assert isinstance(sub["score"], (int, float))
        assert isinstance(sub["max_score"], (int, float))
        assert isinstance(sub["tests"], list)
        for test in sub["tests"]:
            assert {"name", "score", "max_score", "status", "output"} <= set(test)
            assert test["status"] in ("passed", "failed")
            assert isinstance(test["name"], str) and isinstance(test["output"], str)
    first, broken, _ = data["submissions"]
    assert first["submission"] == "subs/alice.py" and first["score"] == 4.0
    assert first["max_score"] == 6.0
    assert broken["error"].startswith("no controller") and broken["tests"] == []
    assert broken["max_score"] == 6.0  # the lesson's, when the submission has none


def test_json_keeps_hidden_tests_generic():
    data = json.loads(render_report(single(alice()), "json"))
    hidden = [t for t in data["submissions"][0]["tests"] if t["hidden"]]
    assert [t["name"] for t in hidden] == ["no_wall_hits [hidden 1]", "keeps_moving [hidden 1]"]
    assert hidden[0]["output"] == HIDDEN_OUTPUT


# -- gradescope -----------------------------------------------------------------------

GRADESCOPE_TOP = {
    "score", "execution_time", "output", "output_format", "test_output_format", "visibility", "stdout_visibility",
    "tests",
}
GRADESCOPE_TEST = {"name", "score", "max_score", "status", "output", "visibility"}
GRADESCOPE_VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}


def test_gradescope_results_json_follows_the_spec():
    data = json.loads(render_report(single(alice()), "gradescope"))
    assert set(data) == GRADESCOPE_TOP
    assert data["score"] == 4.0
    assert isinstance(data["execution_time"], int) and data["execution_time"] == 4
    assert isinstance(data["output"], str)
    assert data["visibility"] in GRADESCOPE_VISIBILITY
    assert data["stdout_visibility"] in GRADESCOPE_VISIBILITY
    assert len(data["tests"]) == 3  # two visible tests and the summary of the hidden ones
    assert data["output_format"] == "html" and data["test_output_format"] == "text"
    for test in data["tests"]:
        assert set(test) == GRADESCOPE_TEST
        assert isinstance(test["score"], float) and isinstance(test["max_score"], float)
        assert test["status"] in ("passed", "failed")
        assert test["visibility"] in GRADESCOPE_VISIBILITY
    assert sum(t["score"] for t in data["tests"]) == data["score"]


def test_gradescope_hidden_scenarios_are_shown_only_after_publishing_and_stay_generic():
    options = reports.ReportOptions(hidden="after_published")
    data = json.loads(render_report(single(alice()), "gradescope", options))
    visible = [t for t in data["tests"] if t["visibility"] == "visible"]
    hidden = [t for t in data["tests"] if t["visibility"] != "visible"]
    assert [t["name"] for t in visible] == ["no_wall_hits [centre]", "keeps_moving [centre]"]
    assert {t["visibility"] for t in hidden} == {"after_published"}
    text = json.dumps(hidden)
    # Nothing about the scenario beyond its generic label: no start pose, seed or world.
    for secret in ("random starts", "seed", "x=", "theta", "centre"):
        assert secret not in text
    assert hidden[0]["output"] == HIDDEN_OUTPUT
    # the visible ones, each check counted once (not once per scenario run)
    assert data["output"].startswith(f"<p>Lesson {LESSON}: 2 of 2 checks passed")
    assert "Hidden scenarios were graded too." in data["output"]


def test_gradescope_submission_error_scores_zero_with_the_error_as_output():
    data = json.loads(render_report(single(bob_broken()), "gradescope"))
    assert set(data) == GRADESCOPE_TOP
    assert data["score"] == 0
    assert "no controller found" in data["output"]
    assert data["tests"] == []


def test_gradescope_refuses_a_batch():
    with pytest.raises(ReportError, match="one submission") as err:
        render_report(batch(), "gradescope")
    assert "\n" not in str(err.value)


# -- junit ----------------------------------------------------------------------------


def test_junit_parses_and_counts_tests_failures_and_errors():
    root = ET.fromstring(render_report(batch(), "junit").encode("utf-8"))
    assert root.tag == "testsuites"
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == ["alice", "bob", "=HYPERLINK(\"http://x\")"]
    alice_suite, bob_suite, evil_suite = suites
    assert (alice_suite.get("tests"), alice_suite.get("failures"), alice_suite.get("errors")) == (
        "4", "1", "0"
    )
    cases = alice_suite.findall("testcase")
    assert [c.get("name") for c in cases] == [
        "no_wall_hits [centre]", "keeps_moving [centre]",
        "no_wall_hits [hidden 1]", "keeps_moving [hidden 1]",
    ]
    assert {c.get("classname") for c in cases} == {f"{LESSON}.alice"}
    assert all(float(c.get("time")) >= 0 for c in cases)
    failure = cases[2].find("failure")
    assert failure is not None and failure.text == HIDDEN_OUTPUT
    assert failure.get("message") == HIDDEN_OUTPUT
    assert cases[0].find("failure") is None
    (error_case,) = bob_suite.findall("testcase")
    assert (bob_suite.get("tests"), bob_suite.get("errors")) == ("1", "1")
    assert "no controller found" in error_case.find("error").get("message")
    assert (evil_suite.get("tests"), evil_suite.get("failures")) == ("2", "1")
    # the Ant schema allows no attributes on <testsuites>: the totals are the suites'
    assert root.attrib == {}
    totals = [sum(int(s.get(k)) for s in suites) for k in ("tests", "failures", "errors")]
    assert totals == [7, 2, 1]


def test_junit_survives_control_characters_and_markup_in_log_lines():
    text = render_report(single(evil()), "junit")
    assert "\x00" not in text and "\x1b" not in text
    root = ET.fromstring(text.encode("utf-8"))
    failure = root.find("testsuite/testcase/failure")
    assert "\\x1b[31mred" in failure.text and "\\x00 nul" in failure.text
    assert "<tag> & \"quotes\" ]]>" in failure.text
    assert failure.get("message").startswith("log: ")


# -- csv ------------------------------------------------------------------------------


def test_csv_has_one_row_per_student_and_a_column_per_check():
    rows = list(csv.reader(io.StringIO(render_report(batch(), "csv"))))
    assert rows[0] == ["student", "score", "max_score", "no_wall_hits", "keeps_moving", "graded", "error"]
    assert len(rows) == 4
    assert rows[1] == ["alice", "4", "6", "2", "2", "", ""]
    assert rows[2][:6] == ["bob", "0", "6", "0", "0", ""]
    assert "no controller found" in rows[2][6]  # a 0 not earned says why
    assert rows[3][1:] == ["1", "3", "0", "1", "", ""]


def test_csv_neutralises_formula_injection():
    rows = list(csv.reader(io.StringIO(render_report(batch(), "csv"))))
    assert rows[3][0] == "'=HYPERLINK(\"http://x\")"
    for prefix in ("=", "+", "-", "@"):
        sub = alice()
        sub.student = f"{prefix}cmd|' /C calc'!A0"
        (row,) = list(csv.reader(io.StringIO(render_report(single(sub), "csv"))))[1:]
        assert row[0].startswith("'" + prefix)


# -- github ---------------------------------------------------------------------------


def decode_github(report: GradeReport) -> dict:
    encoded = render_report(report, "github")
    assert "\n" not in encoded
    return json.loads(base64.b64decode(encoded, validate=True).decode("utf-8"))


def test_github_result_is_base64_json_the_reporter_reads():
    data = decode_github(single(alice()))
    assert set(data) == {"version", "status", "max_score", "tests"}
    assert data["version"] == 1 and data["status"] == "fail" and data["max_score"] == 6.0
    for test in data["tests"]:
        assert {"name", "status", "score", "message", "test_code", "filename", "line_no",
                "duration"} <= set(test)
        assert test["status"] in ("pass", "fail")
        assert isinstance(test["line_no"], int) and isinstance(test["duration"], int)
    # The reporter adds up the tests' scores (notify-classroom.js).
    assert sum(t["score"] for t in data["tests"]) == 4.0
    assert data["tests"][2]["message"] == HIDDEN_OUTPUT


def test_github_scores_add_up_after_rounding():
    thirds = [make_test("no_wall_hits", f"s{i}", 1 / 3, 1 / 3) for i in range(3)]
    sub = SubmissionResult("a.py", "a", score=1.0, max_score=1.0, tests=thirds)
    data = decode_github(GradeReport(LESSON, [sub], max_score=1.0))
    assert data["status"] == "pass"
    assert round(sum(t["score"] for t in data["tests"]), 6) == 1.0


def test_github_submission_error_has_status_error():
    data = decode_github(single(bob_broken()))
    assert data["status"] == "error" and data["max_score"] == 6.0
    assert sum(t["score"] for t in data["tests"]) == 0
    assert "no controller found" in data["tests"][0]["message"]


def test_github_output_line_and_single_submission():
    line = github_output_line(single(alice()))
    assert line.startswith("result=") and "\n" not in line
    assert line.removeprefix("result=") == render_report(single(alice()), "github")
    with pytest.raises(ReportError, match="one submission"):
        render_report(batch(), "github")


# -- table ----------------------------------------------------------------------------


def test_table_shows_scores_failing_checks_and_a_summary():
    assert "3 submissions" in render_report(batch(), "table")  # the terminal's width
    text = reports.render_table(batch(), width=120)
    assert "alice" in text and "4/6" in text
    assert "no_wall_hits [hidden 1]" in text and "Keep the turtle off the walls" in text
    assert "keeps_moving [centre]" not in text.split("bob")[0]  # passing checks are not listed
    assert "no controller found" in text
    assert "3 submissions, mean score 1.67/6" in text
    assert "[bold]markup[/bold]" in text  # student text is not read as rich markup
    # A log line cannot send escape sequences to the instructor's terminal.
    assert "\x1b" not in text and "\\x1b[31mred" in text


def test_table_counts_checks_not_check_and_scenario_runs_in_the_right_number():
    text = reports.render_table(batch(), width=120)
    # alice's two checks ran in two scenarios each: one of them failed once
    assert "1 of 2 checks failed" in text
    lone = SubmissionResult(
        submission="subs/carol.py", student="carol", score=0.0, max_score=1.0,
        tests=[make_test("circle", "centre", 0.0, 0.5), make_test("circle", "hidden 1", 0.0, 0.5, hidden=True)],
    )
    text = reports.render_table(single(lone), width=120)
    assert "1 of 1 check failed" in text and "1 submission, mean score" in text


def test_table_fits_the_width_and_print_table_uses_the_console():
    from rich.console import Console

    text = reports.render_table(batch(), width=60)
    assert max(len(line) for line in text.splitlines()) <= 60
    console = Console(file=io.StringIO(), width=100, color_system=None)
    reports.print_table(single(alice()), console=console)
    assert "1 submission, mean score 4.00/6" in console.file.getvalue()


def test_every_format_renders_and_unknown_formats_are_refused():
    for fmt in FORMATS:
        if fmt != "canvas":  # canvas needs the roster: tests/grading/test_report_formats.py
            assert render_report(single(alice()), fmt)
    with pytest.raises(ReportError, match="unknown report format 'yaml'"):
        render_report(batch(), "yaml")


# -- writing ----------------------------------------------------------------------------


def test_write_report_writes_the_rendered_text(tmp_path: Path):
    path = tmp_path / "results.json"
    write_report(single(alice()), "gradescope", path)
    assert json.loads(path.read_text(encoding="utf-8"))["score"] == 4.0
    assert os.listdir(tmp_path) == ["results.json"]
    write_report(single(alice()), "github", tmp_path / "result.txt")
    assert (tmp_path / "result.txt").read_text().strip() == render_report(single(alice()), "github")


def test_a_failing_write_leaves_the_old_report_and_no_temporary_file(tmp_path, monkeypatch):
    path = tmp_path / "report.json"
    path.write_text("old report", encoding="utf-8")

    def fail_replace(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(reports.os, "replace", fail_replace)
    with pytest.raises(ReportError) as err:
        write_report(batch(), "json", path)
    message = str(err.value)
    assert message == f"cannot write {path}: No space left on device"
    assert path.read_text(encoding="utf-8") == "old report"
    assert os.listdir(tmp_path) == ["report.json"]


def test_a_render_error_never_touches_the_file(tmp_path: Path):
    path = tmp_path / "results.json"
    path.write_text("old", encoding="utf-8")
    with pytest.raises(ReportError):
        write_report(batch(), "gradescope", path)
    assert path.read_text(encoding="utf-8") == "old"


def test_an_unwritable_path_is_a_one_line_error(tmp_path: Path):
    # a path under a file cannot be written by anyone, root included
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("")
    target = blocker / "grades.csv"
    with pytest.raises(ReportError) as err:
        write_report(batch(), "csv", target)
    assert str(err.value).startswith(f"cannot write {target}: ")
    assert "\n" not in str(err.value)


def test_a_permission_error_is_a_one_line_error(tmp_path, monkeypatch):
    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(reports.tempfile, "mkstemp", refuse)
    path = tmp_path / "grades.csv"
    with pytest.raises(ReportError) as err:
        write_report(batch(), "csv", path)
    assert str(err.value) == f"cannot write {path}: Permission denied"
    assert not path.exists()


def test_a_missing_folder_or_a_folder_as_path_is_a_one_line_error(tmp_path: Path):
    missing = tmp_path / "no" / "such" / "grades.csv"
    with pytest.raises(ReportError) as err:
        write_report(batch(), "csv", missing)
    assert str(err.value) == f"cannot write {missing}: No such file or directory"
    with pytest.raises(ReportError, match="it is a folder"):
        write_report(batch(), "csv", tmp_path)


def test_a_new_report_gets_the_usual_file_mode(tmp_path: Path):
    path = tmp_path / "grades.csv"
    write_report(batch(), "csv", path)
    assert path.stat().st_mode & 0o777 == 0o666 & ~reports._umask()


def test_a_check_that_was_not_judged_is_not_shown_as_failed():
    tests = [
        make_test("distance", "centre", 0.0, 0.5, output="0 m (needs >= 5 m)"),
        make_test("no_crash", "centre", 0.0, 0.5,
                  output="not judged: no_crash counts only in runs where distance passes; here distance did not"),
    ]
    idle = SubmissionResult(submission="subs/idle.py", student="idle", score=0.0, max_score=1.0, tests=tests)
    text = reports.render_table(single(idle), width=120)
    assert "1 of 2 checks failed, 1 not judged" in text
    assert "✗ distance [centre]" in text and "- no_crash: not judged [centre]" in text
    assert "✗ no_crash" not in text


def test_a_crash_is_not_hidden_behind_the_runs_where_its_check_was_not_judged():
    # go-to-goal's math.atan(dy / dx): no goal reached in the first run (so
    # no_crash is not judged there), a ZeroDivisionError in the second
    waiting = "not judged: no_crash counts only in runs where time_to_goal passes; here it did not"
    crash = "controller go.py crashed at t=0.100 s: ZeroDivisionError: float division by zero"
    tests = [
        make_test("no_crash", "goal to the left", 0.0, 0.5, output=waiting),
        make_test("no_crash", "goal behind", 0.0, 0.5, output=crash),
    ]
    sub = SubmissionResult(submission="subs/atan.py", student="atan", score=0.0, max_score=1.0, tests=tests)
    text = reports.render_table(single(sub), width=200)
    assert "✗ no_crash [goal behind]" in text and "ZeroDivisionError" in text
    assert "- no_crash: not judged [goal to the left]" in text and "counts only in runs" in text
    assert "[goal to the left; goal behind]" not in text
