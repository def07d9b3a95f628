"""PrairieLearn's external-grading ``results.json`` (docs/externalGrading.md,
"Grading results"): ``score`` in [0, 1], ``gradable``, ``message``,
``output``, ``tests`` of ``{name, description, points, max_points, message,
output}`` and ``images`` of ``{label, url}`` with ``data:`` URLs. The file
must stay under 1 MB. An upload that cannot be graded (no controller, a
syntax error) is ``gradable: false`` with ``format_errors``: the student loses
no attempt. Hidden scenarios show as one summary test without details.
"""

from __future__ import annotations

import json
from typing import Any

from turtletui.grading.reports import _max_score, _only_submission, _points, hidden_summary
from turtletui.grading.results import GradeReport

MAX_BYTES = 1_000_000
"""PrairieLearn's limit on results.json; pictures are dropped to stay under it."""


def prairielearn_result(report: GradeReport) -> dict[str, Any]:
    sub = _only_submission(report, "prairielearn")
    if sub.error is not None:
        return {
            "gradable": False,
            "format_errors": [f"Your submission could not be graded: {sub.error}"],
            "message": f"Your submission could not be graded: {sub.error}",
        }
    most = _max_score(report, sub)
    tests = [
        {
            "name": test.name,
            "description": f"{test.check} in scenario {test.scenario}",
            "points": _points(test.score),
            "max_points": _points(test.max_score),
            "message": "passed" if test.passed else "failed",
            "output": test.output,
        }
        for test in sub.tests
        if not test.hidden
    ]
    summary = hidden_summary(sub.tests)
    if summary is not None:
        name, points, max_points = summary
        tests.append(
            {"name": name, "description": "scenarios graded without showing them", "points": _points(points),
             "max_points": _points(max_points), "message": "", "output": ""}
        )
    passed = sum(t.passed for t in sub.tests)
    data: dict[str, Any] = {
        "gradable": True,
        "score": round(sub.score / most, 6) if most else 0.0,
        "message": f"Lesson {report.lesson}: {passed} of {len(sub.tests)} checks passed; graded {sub.graded}.",
        "output": "",
        "tests": tests,
        "images": [
            {"label": f"scenario {p.scenario}", "url": f"data:image/png;base64,{p.png}"} for p in sub.pictures
        ],
    }
    while data["images"] and len(json.dumps(data)) > MAX_BYTES:
        data["images"].pop()
    return data


def render_prairielearn(report: GradeReport) -> str:
    return json.dumps(prairielearn_result(report), indent=2, ensure_ascii=False) + "\n"
