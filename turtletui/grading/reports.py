"""Write a :class:`~turtletui.grading.results.GradeReport` in the formats that
instructors upload: a terminal table, JSON, JUnit XML, Gradescope's results.json,
a gradebook CSV, GitHub Classroom's autograding ``result`` output (for the
service retired on 2026-08-28), and those of :mod:`turtletui.grading.formats`:
Classroom 50, PrairieLearn, Canvas's and Moodle's gradebook imports.

Every writer works from the report's data only. Hidden scenarios arrive with a
generic name and output (``no_wall_hits [hidden 1]``) and no writer adds
anything about them. :func:`write_report` replaces the output file atomically:
a reader sees the old report or the new one, never half of one.

Sources for the platform formats:

- Gradescope: the autograder specification,
  https://gradescope-autograders.readthedocs.io/en/latest/specs/ ("Output format").
- JUnit: valid against both Jenkins' junit-4.xsd and the Apache Ant schema
  (windyroad/JUnit-Schema JUnit.xsd), which is the stricter: ``<testsuites>``
  without attributes, each ``<testsuite>`` with ``package``, ``id``,
  ``timestamp`` (no time zone), ``hostname``, ``<properties>`` first and
  ``<system-out>``/``<system-err>`` last, at most one outcome per test case.
- GitHub Classroom (retired 2026-08-28, kept for repositories still using it):
  classroom-resources/autograding-grading-reporter
  (src/main.js decodes ``<RUNNER>_RESULTS`` from base64 and parses JSON;
  src/notify-classroom.js sums ``max_score`` and every test's ``score``;
  src/console-results.js prints ``name`` and ``message``), and the field names
  that classroom-resources/autograding-io-grader (src/main.js) emits:
  ``{version: 1, status, max_score, tests: [{name, status, message, test_code,
  filename, line_no, duration, score}]}`` with statuses ``pass``/``fail``/``error``.
"""

from __future__ import annotations

import base64
import csv
import datetime as dt
import html
import io
import json
import os
import re
import socket
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.errors import TurtletuiError
from turtletui.grading.results import GradeReport, SubmissionResult, TestResult
from turtletui.messages import one_line, plural

if TYPE_CHECKING:  # rich is imported only when a table is drawn
    from rich.console import Console

    from turtletui.grading.formats.roster import Roster

FORMATS = (
    "table", "json", "junit", "gradescope", "prairielearn", "classroom50", "canvas", "moodle", "csv", "github",
)
"""Every format :func:`render_report` knows, the ``--format`` choices."""

SINGLE_SUBMISSION_FORMATS = ("gradescope", "prairielearn", "classroom50", "github")
"""Formats whose platform grades one submission per container or workflow run."""

ROSTER_FORMATS = ("canvas", "moodle")
"""Formats that write a gradebook for an LMS, matched against its roster."""

HIDDEN_CHOICES = ("summary", "after_published", "after_due_date", "hidden", "visible")
"""How Gradescope shows hidden scenarios: ``summary`` (one test, no details: the
student sees their total) or a Gradescope visibility for each test of them."""


@dataclass
class ReportOptions:
    """What some formats need besides the report."""

    roster: Roster | None = None
    """The class list of canvas and moodle (an LMS export)."""
    hidden: str = "summary"
    """Gradescope: one of :data:`HIDDEN_CHOICES`."""
    environ: Mapping[str, str] | None = None
    """classroom50: the runner's environment (default: this process's)."""
    warnings: list[str] = field(default_factory=list)
    """Filled while rendering: students a roster does not have, and the like."""

GRADESCOPE_HIDDEN_VISIBILITY = "after_published"
"""Gradescope visibility of each hidden-scenario test when the instructor asks
for them one by one (``--hidden-tests after_published``).

Gradescope hides a student's total while any test of theirs is not visible, so
by default (``summary``) hidden scenarios are one visible test instead,
"hidden scenarios: 2 of 3 passed", with their points and no details: the
student sees the total and cannot tune their code to the hidden starts.
"""


class ReportError(TurtletuiError, ValueError):
    """A report that cannot be rendered or written; the message is one line."""


# -- shared helpers -------------------------------------------------------------------


def _points(value: float) -> float:
    """A score as JSON writes it: rounded so float noise (0.30000000000000004) goes."""
    return round(float(value), 4)


def _max_score(report: GradeReport, submission: SubmissionResult) -> float:
    """The submission's maximum, falling back to the lesson's (an unusable
    submission may carry no tests and 0 as its own maximum)."""
    return submission.max_score or report.max_score


def _only_submission(report: GradeReport, fmt: str) -> SubmissionResult:
    if len(report.submissions) != 1:
        raise ReportError(
            f"the {fmt} format holds one submission (the platform grades each in its own "
            f"container), but this report has {len(report.submissions)}; grade one "
            f"submission, or use --format json, junit or csv for a batch"
        )
    return report.submissions[0]


def _check_names(report: GradeReport) -> list[str]:
    """Check names in the order they are first seen (the lesson's order)."""
    names: dict[str, None] = {}
    for submission in report.submissions:
        for test in submission.tests:
            names.setdefault(test.check, None)
    return list(names)


def hidden_summary(tests: Sequence[TestResult]) -> tuple[str, float, float] | None:
    """(name, points, maximum) of one test standing for all the hidden ones:
    ``hidden scenarios: 2 of 3 passed`` counts runs, a run passing when all its
    checks passed; None when there are none."""
    hidden = [t for t in tests if t.hidden]
    if not hidden:
        return None
    runs: dict[str, bool] = {}
    for test in hidden:
        runs[test.scenario] = runs.get(test.scenario, True) and test.passed
    name = f"hidden scenarios: {sum(runs.values())} of {len(runs)} passed"
    return name, sum(t.score for t in hidden), sum(t.max_score for t in hidden)


def _checks_of(tests: Iterable[TestResult]) -> list[str]:
    """The checks (not check x scenario runs) these tests judge, in order."""
    return list(dict.fromkeys(test.check for test in tests))


def _test_seconds(submission: SubmissionResult) -> float:
    """Seconds per test: :class:`SubmissionResult` records only the submission's
    wall time, so it is shared evenly among its tests."""
    if not submission.tests:
        return submission.execution_time
    return submission.execution_time / len(submission.tests)


# Control characters a student's log line may carry. XML 1.0 forbids C0 controls
# even escaped (ElementTree writes them raw, which makes the whole file unreadable),
# and a terminal obeys them and C1 ones (ESC and CSI sequences: colours, clearing the
# screen, setting the clipboard). Tab and newline stay.
_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\ud800-\udfff\ufffe\uffff]")


def _printable(text: str) -> str:
    """``text`` with control characters shown as ``\\xNN`` (``\\r`` too, as XML would
    turn it into a newline)."""
    return _CONTROL.sub(lambda m: f"\\x{ord(m.group()):02x}", str(text))


_xml_text = _printable


# -- json ---------------------------------------------------------------------------


def _test_dict(test: TestResult) -> dict[str, Any]:
    return {
        "name": test.name,
        "score": _points(test.score),
        "max_score": _points(test.max_score),
        "status": test.status,
        "output": test.output,
        "check": test.check,
        "scenario": test.scenario,
        "hidden": test.hidden,
    }


def render_json(report: GradeReport) -> str:
    """``{"lesson", "max_score", "submissions": [{"submission", "student", "score",
    "max_score", "error", "execution_time", "graded", "tests": [...], "recordings":
    [...], "pictures": [{"scenario", "png_base64", "svg"}]}]}``."""
    data = {
        "lesson": report.lesson,
        "max_score": _points(report.max_score),
        "submissions": [
            {
                "submission": sub.submission,
                "student": sub.student,
                "score": _points(sub.score),
                "max_score": _points(_max_score(report, sub)),
                "error": sub.error,
                "execution_time": round(sub.execution_time, 3),
                "graded": sub.graded,
                "tests": [_test_dict(test) for test in sub.tests],
                "recordings": list(sub.recordings),
                "pictures": [
                    {"scenario": p.scenario, "png_base64": p.png, "svg": p.svg} for p in sub.pictures
                ],
            }
            for sub in report.submissions
        ],
    }
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


# -- gradescope -----------------------------------------------------------------------


def render_gradescope(report: GradeReport, hidden: str = "summary") -> str:
    """Gradescope's results.json for the report's one submission; ``hidden``
    says how hidden scenarios show (:data:`HIDDEN_CHOICES`)."""
    if hidden not in HIDDEN_CHOICES:
        raise ReportError(f"hidden tests: {hidden!r}; choose one of {', '.join(HIDDEN_CHOICES)}")
    sub = _only_submission(report, "gradescope")
    if sub.error is not None:
        output = html.escape(f"Your submission could not be graded: {sub.error}")
    else:
        # Counts of visible tests only: the summary must not describe hidden scenarios.
        visible = [test for test in sub.tests if not test.hidden]
        checks = _checks_of(visible)
        passed = [check for check in checks if check not in _checks_of(t for t in visible if not t.passed)]
        output = html.escape(
            f"Lesson {report.lesson}: {len(passed)} of {plural(len(checks), 'check')} passed "
            f"in every scenario you can see. Graded: {sub.graded}."
        )
        if len(visible) < len(sub.tests):
            output += " Hidden scenarios were graded too."
        output = f"<p>{output}</p>" + "".join(
            f'<p>Scenario {html.escape(p.scenario)}:<br><img alt="the turtle\'s path in scenario '
            f'{html.escape(p.scenario)}" src="data:image/png;base64,{p.png}"></p>'
            for p in sub.pictures
        )
    tests = [
        {
            "name": test.name,
            "score": _points(test.score),
            "max_score": _points(test.max_score),
            "status": "passed" if test.passed else "failed",
            "output": test.output,
            "visibility": "visible" if not test.hidden else hidden,
        }
        for test in sub.tests
        if not (test.hidden and hidden == "summary")
    ]
    summary = hidden_summary(sub.tests) if hidden == "summary" else None
    if summary is not None:
        name, points, most = summary
        tests.append(
            {
                "name": name,
                "score": _points(points),
                "max_score": _points(most),
                "status": "passed" if points == most else "failed",
                "output": "Scenarios you cannot see, graded like the others.",
                "visibility": "visible",
            }
        )
    data = {
        # The top-level score overrides the sum of the tests' scores (spec); an
        # unusable submission scores 0.
        "score": 0.0 if sub.error is not None else _points(sub.score),
        "execution_time": int(round(sub.execution_time)),
        "output": output,
        "output_format": "html",
        "test_output_format": "text",
        "visibility": "visible",
        # stdout is the grader's own log: for the instructor's debugging only.
        "stdout_visibility": "hidden",
        "tests": tests,
    }
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


# -- junit ----------------------------------------------------------------------------


def _first_line(text: str) -> str:
    for line in str(text).splitlines():
        if line.strip():
            return line.strip()
    return ""


def _timestamp() -> str:
    """Now (or ``$SOURCE_DATE_EPOCH``), in UTC without a time zone, as the Ant
    schema's pattern wants it."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    when = dt.datetime.fromtimestamp(int(epoch), dt.timezone.utc) if epoch and epoch.isdigit() else None
    return (when or dt.datetime.now(dt.timezone.utc)).strftime("%Y-%m-%dT%H:%M:%S")


def render_junit(report: GradeReport) -> str:
    """JUnit XML: a ``<testsuite>`` per submission, a ``<testcase>`` per check and
    scenario (``<failure>`` when it failed), an ``<error>`` testcase for a
    submission that could not be graded."""
    root = ET.Element("testsuites")
    timestamp = _timestamp()
    hostname = _xml_text(socket.gethostname() or "localhost").strip() or "localhost"
    for number, sub in enumerate(report.submissions):
        classname = _xml_text(f"{report.lesson}.{sub.student}")
        suite = ET.SubElement(
            root, "testsuite", name=_xml_text(sub.student).strip() or "submission",
            package=_xml_text(report.lesson), id=str(number), timestamp=timestamp, hostname=hostname,
        )
        properties = ET.SubElement(suite, "properties")
        for name, value in (
            ("submission", sub.submission),
            ("graded", sub.graded),
            ("score", f"{_points(sub.score):g}"),
            ("max_score", f"{_points(_max_score(report, sub)):g}"),
        ):
            ET.SubElement(properties, "property", name=name, value=_xml_text(value))
        tests = failures = errors = 0
        if sub.error is not None:
            case = ET.SubElement(
                suite, "testcase", classname=classname, name="submission",
                time=f"{sub.execution_time:.3f}",
            )
            error = ET.SubElement(
                case, "error", message=_xml_text(one_line(sub.error)), type="SubmissionError"
            )
            error.text = _xml_text(sub.error)
            tests, errors = 1, 1
        share = _test_seconds(sub)
        for test in sub.tests:
            case = ET.SubElement(
                suite, "testcase", classname=classname, name=_xml_text(test.name),
                time=f"{share:.3f}",
            )
            tests += 1
            if not test.passed:
                failures += 1
                message = _first_line(test.output) or f"{test.check} failed"
                failure = ET.SubElement(
                    case, "failure", message=_xml_text(message), type="CheckFailed"
                )
                failure.text = _xml_text(test.output)
        ET.SubElement(suite, "system-out").text = ""
        ET.SubElement(suite, "system-err").text = ""
        suite.set("tests", str(tests))
        suite.set("failures", str(failures))
        suite.set("errors", str(errors))
        suite.set("time", f"{sub.execution_time:.3f}")
    ET.indent(root)
    body = ET.tostring(root, encoding="unicode")
    return f'<?xml version="1.0" encoding="UTF-8"?>\n{body}\n'


# -- csv ------------------------------------------------------------------------------

# A spreadsheet runs a cell that starts with one of these as a formula (OWASP, "CSV
# Injection"); tab and carriage return are on OWASP's list as well.
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def _csv_cell(text: str) -> str:
    """``text`` safe to open in a spreadsheet: a leading apostrophe disarms formulas."""
    return f"'{text}" if text.startswith(_FORMULA_START) else text


def _csv_number(value: float) -> str:
    return f"{_points(value):g}"


def render_csv(report: GradeReport) -> str:
    """A gradebook CSV: ``student,score,max_score,<check>...,graded,error``, one
    row per student, each check column the points of that check summed over
    its scenarios, the file (and executable) graded, and why a submission
    could not be graded (empty when it was): a 0 for a syntax error or a
    missing file is then told apart from a 0 earned."""
    checks = _check_names(report)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["student", "score", "max_score", *(_csv_cell(c) for c in checks), "graded", "error"])
    for sub in report.submissions:
        per_check = dict.fromkeys(checks, 0.0)
        for test in sub.tests:
            per_check[test.check] += test.score
        score = 0.0 if sub.error is not None else sub.score
        writer.writerow(
            [
                _csv_cell(sub.student),
                _csv_number(score),
                _csv_number(_max_score(report, sub)),
                *(_csv_number(per_check[c]) for c in checks),
                _csv_cell(sub.graded),
                _csv_cell(" ".join((sub.error or "").split())),
            ]
        )
    return out.getvalue()


# -- github classroom ------------------------------------------------------------------


def _apportion(values: Sequence[float], digits: int = 2) -> list[float]:
    """``values`` rounded to ``digits`` decimals so that they still add up to their
    rounded sum (largest remainder): three tests of 1/3 point give 0.34, 0.33, 0.33,
    not 0.99 in total, since the reporter adds the tests' scores itself."""
    scale = 10**digits
    scaled = [v * scale for v in values]
    floors = [int(s // 1) for s in scaled]
    short = round(sum(scaled)) - sum(floors)
    by_remainder = sorted(range(len(values)), key=lambda i: scaled[i] - floors[i], reverse=True)
    for i in by_remainder[: max(0, short)]:
        floors[i] += 1
    return [f / scale for f in floors]


def github_result(report: GradeReport) -> dict[str, Any]:
    """The autograding result JSON (before base64) for the report's one submission."""
    sub = _only_submission(report, "github")
    max_score = _max_score(report, sub)
    if sub.error is not None:
        return {
            "version": 1,
            "status": "error",
            "max_score": _points(max_score),
            "tests": [
                {
                    "name": "submission",
                    "status": "error",
                    "score": 0,
                    "max_score": _points(max_score),
                    "message": f"Your submission could not be graded: {sub.error}",
                    "test_code": "",
                    "filename": sub.submission,
                    "line_no": 0,
                    "duration": int(round(sub.execution_time * 1000)),
                }
            ],
        }
    scores = _apportion([test.score for test in sub.tests])
    duration_ms = int(round(_test_seconds(sub) * 1000))
    return {
        "version": 1,
        "status": "pass" if all(test.passed for test in sub.tests) else "fail",
        "max_score": _points(max_score),
        "tests": [
            {
                "name": test.name,
                "status": "pass" if test.passed else "fail",
                "score": score,
                "max_score": _points(test.max_score),
                "message": test.output,
                "test_code": "",
                "filename": sub.submission,
                "line_no": 0,
                "duration": duration_ms,
            }
            for test, score in zip(sub.tests, scores, strict=True)
        ],
    }


def render_github(report: GradeReport) -> str:
    """The base64 ``result`` output GitHub Classroom's grading reporter reads
    (GitHub Classroom was retired on 2026-08-28: use classroom50 for new courses)."""
    text = json.dumps(github_result(report), ensure_ascii=False, separators=(",", ":"))
    return base64.b64encode(text.encode("utf-8")).decode("ascii")


def github_output_line(report: GradeReport) -> str:
    """``result=<base64>``: the line to append to ``$GITHUB_OUTPUT`` (base64 has no
    newline, so the one-line form of a step output is enough)."""
    return f"result={render_github(report)}"


# -- table ----------------------------------------------------------------------------


def _table(report: GradeReport) -> Any:
    """The report as a rich renderable: a table and a summary line."""
    from rich.console import Group
    from rich.table import Table
    from rich.text import Text

    # Text objects, never plain strings: a student's name or log line may contain
    # "[bold]", which rich would otherwise read as markup.
    table = Table(title=Text(f"Lesson {report.lesson}"), expand=False, show_lines=False)
    table.add_column("Student", overflow="fold")
    table.add_column("Score", justify="right", no_wrap=True)
    table.add_column("Feedback", overflow="fold", ratio=1)
    for sub in report.submissions:
        max_score = _max_score(report, sub)
        score = Text(f"{_points(sub.score):g}/{_points(max_score):g}")
        if sub.error is not None:
            table.add_row(
                Text(_printable(sub.student), style="bold"), score,
                Text(f"error: {_printable(sub.error)}", style="red"),
            )
            continue
        checks = _checks_of(sub.tests)
        failed = _checks_of(test for test in sub.tests if not test.passed and test.judged)
        unjudged = [c for c in _checks_of(t for t in sub.tests if not t.passed) if c not in failed]
        if not failed and not unjudged:
            summary = Text("all checks passed", style="green")
        else:
            words = [f"{len(failed)} of {plural(len(checks), 'check')} failed"]
            if unjudged:
                words.append(f"{len(unjudged)} not judged")
            summary = Text(", ".join(words), style="yellow")
        if sub.graded:
            summary.append(f" ({_printable(sub.graded)})", style="dim")
        table.add_row(Text(_printable(sub.student), style="bold"), score, summary)
        for (check, judged), tests in _failed_by_check(sub.tests).items():
            first = tests[0]
            where = "; ".join(t.scenario for t in tests)
            if judged:
                feedback = Text(f"✗ {_printable(check)} [{_printable(where)}]", style="red")
            else:  # it earned nothing, but it did not fail: the output says what it waits for
                feedback = Text(f"- {_printable(check)}: not judged [{_printable(where)}]", style="yellow")
            if first.output:
                # what was measured in the first of them, and the lesson's hint once
                feedback.append(f"\n{_printable(first.output)}", style="default")
            lost = sum(t.max_score - t.score for t in tests)
            table.add_row(Text(""), Text(f"-{_points(lost):g}", style="dim"), feedback)
    count = len(report.submissions)
    mean = sum(0.0 if s.error else s.score for s in report.submissions) / count if count else 0.0
    summary = Text(
        f"{plural(count, 'submission')}, mean score "
        f"{mean:.2f}/{_points(report.max_score):g}"
    )
    return Group(table, summary)


def _failed_by_check(tests: Sequence[TestResult]) -> dict[tuple[str, bool], list[TestResult]]:
    """Failed tests grouped by check, in the lesson's order, the runs where it
    failed apart from those where it was not judged: each group's first output
    then speaks for all of them (a crash is never hidden behind a "not judged")."""
    failed = [test for test in tests if not test.passed]
    grouped: dict[tuple[str, bool], list[TestResult]] = {}
    for check in _checks_of(failed):
        for judged in (True, False):
            runs = [test for test in failed if test.check == check and test.judged is judged]
            if runs:
                grouped[check, judged] = runs
    return grouped


def print_table(report: GradeReport, console: Console | None = None) -> None:
    """Print the report as a table on ``console`` (a new stdout console by default)."""
    from rich.console import Console

    (console or Console()).print(_table(report))


def render_table(report: GradeReport, width: int | None = None) -> str:
    """The table as plain text, ``width`` columns wide (the terminal's by default)."""
    import shutil

    from rich.console import Console

    out = io.StringIO()
    console = Console(
        file=out,
        width=width or shutil.get_terminal_size().columns,
        color_system=None,
        force_terminal=False,
        highlight=False,
    )
    console.print(_table(report))
    return out.getvalue()


# -- entry points -----------------------------------------------------------------------

_RENDERERS = {
    "table": render_table,
    "json": render_json,
    "junit": render_junit,
    "csv": render_csv,
    "github": render_github,
}


def render_report(report: GradeReport, fmt: str, options: ReportOptions | None = None) -> str:
    """The report as text in ``fmt``, one of :data:`FORMATS`."""
    options = options or ReportOptions()
    if fmt == "gradescope":
        return render_gradescope(report, options.hidden)
    if fmt == "classroom50":
        from turtletui.grading.formats.classroom50 import render_classroom50

        return render_classroom50(report, options.environ)
    if fmt == "prairielearn":
        from turtletui.grading.formats.prairielearn import render_prairielearn

        return render_prairielearn(report)
    if fmt in ROSTER_FORMATS:
        from turtletui.grading.formats.canvas import render_canvas
        from turtletui.grading.formats.moodle import render_moodle

        text, unmatched = (render_canvas if fmt == "canvas" else render_moodle)(report, options.roster)
        options.warnings += [f"{student}: no student of that name or id in the roster" for student in unmatched]
        return text
    try:
        renderer = _RENDERERS[fmt]
    except KeyError:
        raise ReportError(
            f"unknown report format {fmt!r}; choose one of {', '.join(FORMATS)}"
        ) from None
    return renderer(report)


def write_report(report: GradeReport, fmt: str, path: str | Path, options: ReportOptions | None = None) -> None:
    """Render the report and replace ``path`` with it atomically: a temporary file
    in the same folder, flushed to disk, then renamed over ``path``. On failure
    ``path`` is untouched and no temporary file is left; :class:`ReportError`
    says why in one line."""
    text = render_report(report, fmt, options)
    if fmt == "github":
        text += "\n"
    write_text_atomic(Path(path), text)


def write_text_atomic(path: Path, text: str) -> None:
    """Replace ``path`` with ``text`` (UTF-8) atomically; :class:`ReportError` on failure."""
    if path.is_dir():
        raise ReportError(f"cannot write {path}: it is a folder")
    folder = path.parent
    tmp_name: str | None = None
    try:
        fd, tmp_name = tempfile.mkstemp(dir=folder, prefix=f".{path.name}.", suffix=".tmp")
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as tmp:
            tmp.write(text)
            tmp.flush()
            os.fsync(tmp.fileno())
        # mkstemp makes the file 0600; give it the mode a plain open() would.
        os.chmod(tmp_name, _new_file_mode(path))
        os.replace(tmp_name, path)
        tmp_name = None
    except OSError as err:
        reason = err.strerror or one_line(str(err))
        raise ReportError(f"cannot write {path}: {reason}") from err
    finally:
        if tmp_name is not None:
            try:
                os.unlink(tmp_name)
            except FileNotFoundError:
                pass


def _new_file_mode(path: Path) -> int:
    try:
        return path.stat().st_mode & 0o777  # keep an existing report's mode
    except OSError:
        return 0o666 & ~_umask()


def _umask() -> int:
    """The process's umask, read without changing it (os.umask would, for a moment,
    for every thread): Linux shows it in /proc; elsewhere assume the usual 022."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    return 0o022
