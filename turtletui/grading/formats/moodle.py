"""A CSV for Moodle's grade import ("Grades" > "Import" > "CSV file").

Moodle maps one column to a user field (the identifier: e-mail address,
username or ID number) and the others to grade items and their feedback. With
a roster (Moodle's own grade export, or any CSV with an "Email address",
"Username" or "ID number" column) folders are matched to its students by that
identifier or by name, and the identifier written is the roster's; without
one, the folder names are the identifiers (as e-mail addresses when they all
look like one, else as usernames).
"""

from __future__ import annotations

import csv
import io

from turtletui.grading.formats.roster import Roster, match_students
from turtletui.grading.reports import ReportError, _csv_cell, _csv_number
from turtletui.grading.results import GradeReport, SubmissionResult

IDENTIFIERS = ("Email address", "Username", "ID number")


def _feedback(sub: SubmissionResult) -> str:
    if sub.error is not None:
        return f"Not graded: {sub.error}"
    failed = sorted({t.check for t in sub.tests if not t.passed})
    graded = f" (graded {sub.graded})" if sub.graded else ""
    if not failed:
        return f"All checks passed{graded}."
    return f"Failed: {', '.join(failed)}{graded}."


def render_moodle(report: GradeReport, roster: Roster | None) -> tuple[str, list[str]]:
    """The import CSV and the students that match no row of the roster."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    grade_column = report.lesson
    rows: list[tuple[str, SubmissionResult]] = []
    unmatched: list[str] = []
    if roster is None:
        emails = all("@" in sub.student for sub in report.submissions)
        identifier = "Email address" if emails and report.submissions else "Username"
        rows = [(sub.student, sub) for sub in report.submissions]
    else:
        identifier = next((name for name in IDENTIFIERS if roster.column(name) is not None), None)
        if identifier is None:
            raise ReportError(
                f"{roster.path}: the roster has no {', '.join(IDENTIFIERS[:-1])} or {IDENTIFIERS[-1]} column "
                "for Moodle to match students by"
            )
        results = {sub.student: sub for sub in report.submissions}
        matched, unmatched = match_students(roster, list(results), IDENTIFIERS)
        rows = [(roster.cell(roster.students[i], identifier), results[s]) for i, s in sorted(matched.items())]
    writer.writerow([identifier, grade_column, f"{grade_column} feedback"])
    for ident, sub in rows:
        score = 0.0 if sub.error is not None else sub.score
        writer.writerow([_csv_cell(ident), _csv_number(score), _csv_cell(_feedback(sub))])
    return out.getvalue(), unmatched
