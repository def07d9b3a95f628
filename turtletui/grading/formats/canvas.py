"""A gradebook CSV that Canvas imports ("Grades" > "Import"), made from the
gradebook the instructor exported ("Export" > "Export Current Gradebook View").

Canvas identifies a row by its first columns (Student, ID, SIS User ID, SIS
Login ID, Section; Integration ID where the export has it): they are kept as
exported. The lesson gets one column: the exported assignment column whose
name is the lesson's id (with Canvas's " (12345)" assignment number) when there
is one, so the import updates that assignment, else a new column named after
the lesson, which Canvas imports as a new assignment. The "Points Possible"
row gives its maximum. Students are matched to grading folders by SIS Login
ID, ID, SIS User ID or name; a student with no folder keeps an empty cell
(Canvas leaves the grade as it was).
"""

from __future__ import annotations

import csv
import io
import re

from turtletui.grading.formats.roster import Roster, match_students
from turtletui.grading.reports import ReportError, _csv_number, _max_score
from turtletui.grading.results import GradeReport

IDENTITY = ("Student", "ID", "SIS User ID", "SIS Login ID", "Integration ID", "Section")
MATCH_BY = ("SIS Login ID", "ID", "SIS User ID", "Integration ID", "Student")
POINTS_POSSIBLE = "    Points Possible"
"""As Canvas writes it in its exports (indented)."""


def lesson_column(roster: Roster, lesson: str) -> str:
    """The exported column for the lesson (``part6-closed-loop (4721)``), or the lesson id."""
    for title in roster.header:
        if re.sub(r"\s*\(\d+\)\s*$", "", title).strip().casefold() == lesson.casefold():
            return title
    return lesson


def render_canvas(report: GradeReport, roster: Roster | None) -> tuple[str, list[str]]:
    """The import CSV and the students that match no row of the roster."""
    if roster is None:
        raise ReportError("--format canvas needs --roster EXPORT.csv: the gradebook exported from Canvas")
    if roster.column("Student") is None or roster.column("ID") is None:
        raise ReportError(
            f"{roster.path}: not a Canvas gradebook export (it has no Student and ID columns)"
        )
    identity = [title for title in roster.header if title.strip() in IDENTITY]
    column = lesson_column(roster, report.lesson)
    results = {sub.student: sub for sub in report.submissions}
    matched, unmatched = match_students(roster, list(results), MATCH_BY)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow([*identity, column])
    most = report.max_score or max((_max_score(report, s) for s in report.submissions), default=0.0)
    writer.writerow([POINTS_POSSIBLE, *[""] * (len(identity) - 1), _csv_number(most)])
    for index, row in enumerate(roster.students):
        cells = [roster.cell(row, title) for title in identity]
        student = matched.get(index)
        if student is None:
            score = ""
        else:
            sub = results[student]
            score = _csv_number(0.0 if sub.error is not None else sub.score)
        writer.writerow([*cells, score])
    return out.getvalue(), unmatched
