"""The platform formats against their contracts: JUnit against both XML
schemas, Classroom 50's result.json, PrairieLearn's results.json, Gradescope's
hidden-scenario summary, Canvas's gradebook (round trip) and Moodle's import."""

from __future__ import annotations

import base64
import csv
import io
import json
import zlib
from pathlib import Path

import pytest
import xmlschema
from test_reports import alice, batch, bob_broken, evil, single

from turtletui.grading.formats.classroom50 import whole_points
from turtletui.grading.formats.roster import read_roster
from turtletui.grading.reports import ReportError, ReportOptions, render_report
from turtletui.grading.results import GradeReport, Picture

SCHEMAS = Path(__file__).parent / "schemas"

# -- junit ------------------------------------------------------------------------


@pytest.mark.parametrize("schema", ["junit-jenkins.xsd", "junit-ant.xsd"])
def test_junit_is_valid_against_both_schemas(schema: str):
    validator = xmlschema.XMLSchema(SCHEMAS / schema)
    validator.validate(render_report(batch(), "junit"))  # raises with the reason
    validator.validate(render_report(GradeReport(lesson="x"), "junit"))


def test_the_ant_schema_refuses_what_jenkins_accepts():
    """The check can fail: totals on <testsuites> are Jenkins-only."""
    text = render_report(batch(), "junit").replace("<testsuites>", '<testsuites tests="3">')
    assert xmlschema.XMLSchema(SCHEMAS / "junit-jenkins.xsd").is_valid(text)
    assert not xmlschema.XMLSchema(SCHEMAS / "junit-ant.xsd").is_valid(text)


# -- classroom 50 -----------------------------------------------------------------------

RUNNER = {
    "CLASSROOM": "robots", "ASSIGNMENT": "part6", "SUBMISSION_TAG": "submit/2026-09-01T10-00-00Z-abc1234",
    "COMMIT_URL": "https://github.com/o/r/commit/abc", "RELEASE_URL": "https://github.com/o/r/releases/tag/x",
}


def check_classroom50(data: dict) -> None:
    """What Classroom 50's collector checks of a result.json (its validate_result)."""
    assert data["schema"] == "classroom50/result/v1"
    for field in ("classroom", "assignment", "submission", "commit", "release", "review", "datetime"):
        assert isinstance(data[field], str) and data[field], field
    assert data["submission"].startswith("submit/")
    for holder in (data, *data["tests"]):
        for field in ("score", "max-score"):
            assert type(holder[field]) is int and holder[field] >= 0, (field, holder)
        assert holder["score"] <= holder["max-score"]
    for test in data["tests"]:
        assert isinstance(test["test-name"], str) and test["test-name"]
        assert type(test["passed"]) is bool
    assert data["score"] == sum(t["score"] for t in data["tests"])
    assert data["max-score"] == sum(t["max-score"] for t in data["tests"])


def test_classroom50_result_follows_the_contract():
    data = json.loads(render_report(single(alice()), "classroom50", ReportOptions(environ=RUNNER)))
    check_classroom50(data)
    assert data["classroom"] == "robots" and data["review"] == RUNNER["COMMIT_URL"]
    assert data["max-score"] == 6 and data["score"] == 4
    broken = json.loads(render_report(single(bob_broken()), "classroom50", ReportOptions(environ=RUNNER)))
    check_classroom50(broken)
    assert broken["score"] == 0 and "could not be graded" in broken["tests"][0]["message"]


def test_whole_points_keep_each_checks_weight():
    from test_reports import make_test

    tests = [make_test("walls", f"s{i}", 2 / 3, 2 / 3) for i in range(3)] + [make_test("moving", "s0", 1.0, 1.0)]
    assert whole_points(tests) == [1, 1, 0, 1]


# -- prairielearn ---------------------------------------------------------------------------


def test_prairielearn_score_is_a_fraction_and_hidden_runs_are_summarised():
    sub = alice()
    sub.pictures.append(Picture("centre", base64.b64encode(b"\x89PNG").decode(), "<svg/>"))
    data = json.loads(render_report(single(sub), "prairielearn"))
    assert data["gradable"] is True and data["score"] == pytest.approx(4 / 6)
    assert all({"name", "points", "max_points", "output"} <= set(t) for t in data["tests"])
    names = [t["name"] for t in data["tests"]]
    assert "hidden scenarios: 0 of 1 passed" in names and not any("hidden 1" in n for n in names)
    assert data["images"] == [{"label": "scenario centre", "url": "data:image/png;base64," + sub.pictures[0].png}]
    broken = json.loads(render_report(single(bob_broken()), "prairielearn"))
    assert broken["gradable"] is False and "no controller" in broken["format_errors"][0]


# -- gradescope --------------------------------------------------------------------------


def test_gradescope_shows_hidden_runs_as_one_visible_summary_test():
    data = json.loads(render_report(single(alice()), "gradescope"))
    assert all(t["visibility"] == "visible" for t in data["tests"])
    summary = [t for t in data["tests"] if t["name"].startswith("hidden scenarios")]
    assert summary == [
        {"name": "hidden scenarios: 0 of 1 passed", "score": 1.0, "max_score": 3.0, "status": "failed",
         "output": "Scenarios you cannot see, graded like the others.", "visibility": "visible"}
    ]
    assert sum(t["max_score"] for t in data["tests"]) == 6.0 and data["score"] == 4.0
    detailed = json.loads(render_report(single(alice()), "gradescope", ReportOptions(hidden="after_published")))
    assert [t["visibility"] for t in detailed["tests"]].count("after_published") == 2


# -- canvas -------------------------------------------------------------------------------

CANVAS_EXPORT = """\
Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (1201),part6-closed-loop (4721),Current Score
    Points Possible,,,,,10.00,10.00,(read only)
"Lovelace, Ada",101,S101,alice,Robotics 1,8.00,,80.00
"Hopper, Grace",102,S102,ghopper,Robotics 1,9.00,,90.00
"Turing, Alan",103,S103,aturing,Robotics 2,7.00,,70.00
"""


def test_canvas_export_round_trips(tmp_path: Path):
    export = tmp_path / "export.csv"
    export.write_text(CANVAS_EXPORT, encoding="utf-8-sig")
    grace = alice()
    grace.student, grace.score = "grace_hopper", 5.0
    report = GradeReport(lesson="part6-closed-loop", submissions=[alice(), grace, evil()], max_score=6.0)
    options = ReportOptions(roster=read_roster(export))
    text = render_report(report, "canvas", options)
    rows = list(csv.reader(io.StringIO(text)))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "part6-closed-loop (4721)"]
    assert rows[1] == ["    Points Possible", "", "", "", "", "6"]
    assert rows[2:] == [
        ["Lovelace, Ada", "101", "S101", "alice", "Robotics 1", "4"],  # by SIS Login ID
        ["Hopper, Grace", "102", "S102", "ghopper", "Robotics 1", "5"],  # by name
        ["Turing, Alan", "103", "S103", "aturing", "Robotics 2", ""],  # no folder: left as it was
    ]
    assert options.warnings == ['=HYPERLINK("http://x"): no student of that name or id in the roster']
    # what we wrote reads back as a Canvas gradebook: the same students, the grades in place
    written = tmp_path / "import.csv"
    written.write_text(text)
    again = read_roster(written)
    assert [again.cell(r, "SIS Login ID") for r in again.students] == ["alice", "ghopper", "aturing"]
    assert [again.cell(r, "part6-closed-loop (4721)") for r in again.students] == ["4", "5", ""]
    assert again.meta == [rows[1]]


def test_canvas_without_a_canvas_export_is_a_one_line_error(tmp_path: Path):
    with pytest.raises(ReportError, match="needs --roster"):
        render_report(batch(), "canvas")
    other = tmp_path / "other.csv"
    other.write_text("name,mark\nann,3\n")
    with pytest.raises(ReportError, match="not a Canvas gradebook export"):
        render_report(batch(), "canvas", ReportOptions(roster=read_roster(other)))


# -- moodle --------------------------------------------------------------------------------


def test_moodle_import_has_an_identifier_a_grade_and_feedback(tmp_path: Path):
    rows = list(csv.reader(io.StringIO(render_report(batch(), "moodle"))))
    assert rows[0] == ["Username", "part6-closed-loop", "part6-closed-loop feedback"]
    assert rows[1][:2] == ["alice", "4"] and rows[1][2].startswith("Failed: no_wall_hits")
    assert rows[2][:2] == ["bob", "0"] and rows[2][2].startswith("Not graded:")
    assert rows[3][0].startswith("'=")  # a formula in a name is disarmed
    export = tmp_path / "moodle.csv"
    export.write_text("First name,Last name,ID number,Email address\nAda,Lovelace,101,ada@uni.edu\n")
    sub = alice()
    sub.student = "ada"
    report = GradeReport(lesson="part6-closed-loop", submissions=[sub], max_score=6.0)
    rows = list(csv.reader(io.StringIO(render_report(report, "moodle", ReportOptions(roster=read_roster(export))))))
    assert rows[0][0] == "Email address" and rows[1][:2] == ["ada@uni.edu", "4"]


# -- pictures ------------------------------------------------------------------------------


def test_pictures_are_real_pngs_and_svgs():
    import numpy as np

    from turtletui.grading.pictures import drawing_of, render_png, render_svg
    from turtletui.sim import Box

    xy = np.array([[5.5, 5.5], [8.0, 7.0], [11.0888, 8.0], [11.0888, 8.5], [9.0, 9.0]])
    drawing = drawing_of(xy, (5.5, 5.5, 0.0), obstacles=(Box(1.0, 1.0, 2.0, 2.0),), arena=11.0888)
    assert drawing.hits.tolist() == [[11.0888, 8.0]]  # the first pose against the wall
    png = render_png(drawing, size=100)
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
    width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    assert (width, height) == (100, 100)
    idat = png[png.index(b"IDAT") + 4 : png.index(b"IEND") - 8]
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8).reshape(100, 1 + 300)
    pixels = raw[:, 1:].reshape(100, 100, 3)
    assert (pixels == (255, 255, 255)).all(axis=2).any()  # the path is drawn
    assert (pixels == (150, 150, 160)).all(axis=2).any()  # and the obstacle
    svg = render_svg(drawing)
    assert svg.startswith("<svg") and "<polyline" in svg and "hit at x=11.09, y=8.00" in svg


def test_replay_png_draws_a_recording(tmp_path: Path):
    from support.grading import WALL_HITTER
    from typer.testing import CliRunner

    from turtletui.cli import app

    node = tmp_path / "node.py"
    node.write_text(WALL_HITTER)
    record = tmp_path / "run.jsonl"
    ran = CliRunner().invoke(app, ["run", str(node), "--headless", "--duration", "5", "--record", str(record), "-q"])
    assert ran.exit_code == 0, ran.output
    drawn = CliRunner().invoke(app, ["replay", str(record), "--png", str(tmp_path / "run.png")])
    assert drawn.exit_code == 0, drawn.output
    assert (tmp_path / "run.png").read_bytes().startswith(b"\x89PNG")
    assert "1 wall or obstacle hit marked" in drawn.stderr
