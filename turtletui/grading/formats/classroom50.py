"""Classroom 50's ``result.json`` (schema ``classroom50/result/v1``), the file
its runner reads after an autograder ran in the student's repository.

The contract (foundation50/classroom50 wiki, "Advanced Autograding", "The
result.json contract"): ``schema``, ``classroom``, ``assignment``,
``submission``, ``commit``, ``release``, ``review`` (strings, from the runner's
environment), ``datetime`` (UTC ISO 8601), ``score`` and ``max-score``
(non-negative integers: the sums of the tests'), and ``tests`` of
``{test-name, passed, score, max-score}`` with integer points; extra fields on
a test are kept. Points are whole numbers there: each check's points are
spread over its scenario runs as whole points (largest remainder), so a check
of 2 points judged in 3 runs is worth 1 + 1 + 0.
"""

from __future__ import annotations

import datetime as dt
import json
import os
from collections.abc import Mapping
from typing import Any

from turtletui.grading.reports import _max_score, _only_submission
from turtletui.grading.results import GradeReport, TestResult

SCHEMA = "classroom50/result/v1"
RUNNER_FIELDS = {
    "classroom": "CLASSROOM",
    "assignment": "ASSIGNMENT",
    "submission": "SUBMISSION_TAG",
    "commit": "COMMIT_URL",
    "release": "RELEASE_URL",
    "review": "REVIEW_URL",
}
"""result.json field -> the runner's environment variable that carries it."""


def whole_points(tests: list[TestResult]) -> list[int]:
    """Each test's maximum in whole points, so that every check keeps its weight
    rounded to a whole number (largest remainder within the check)."""
    by_check: dict[str, list[int]] = {}
    for i, test in enumerate(tests):
        by_check.setdefault(test.check, []).append(i)
    points = [0] * len(tests)
    for indexes in by_check.values():
        exact = [tests[i].max_score for i in indexes]
        floors = [int(v) for v in exact]
        short = round(sum(exact)) - sum(floors)
        for k in sorted(range(len(indexes)), key=lambda k: exact[k] - floors[k], reverse=True)[: max(0, short)]:
            floors[k] += 1
        for i, value in zip(indexes, floors, strict=True):
            points[i] = value
    return points


def classroom50_result(report: GradeReport, environ: Mapping[str, str] | None = None) -> dict[str, Any]:
    """The result.json object for the report's one submission."""
    environ = os.environ if environ is None else environ
    sub = _only_submission(report, "classroom50")
    now = dt.datetime.now(dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    data: dict[str, Any] = {"schema": SCHEMA}
    for field, variable in RUNNER_FIELDS.items():
        if environ.get(variable):
            data[field] = environ[variable]
    if "review" not in data and "commit" in data:
        data["review"] = data["commit"]
    data["datetime"] = now
    data["graded_at"] = now
    if sub.error is not None:
        most = round(_max_score(report, sub))
        tests = [
            {
                "test-name": "submission",
                "passed": False,
                "score": 0,
                "max-score": most,
                "message": f"Your submission could not be graded: {sub.error}",
            }
        ]
    else:
        tests = [
            {
                "test-name": test.name,
                "passed": test.passed,
                "score": most if test.passed else 0,
                "max-score": most,
                "message": test.output,
            }
            for test, most in zip(sub.tests, whole_points(sub.tests), strict=True)
        ]
    data["score"] = sum(t["score"] for t in tests)
    data["max-score"] = sum(t["max-score"] for t in tests)
    data["tests"] = tests
    if sub.graded:
        data["graded"] = sub.graded
    return data


def render_classroom50(report: GradeReport, environ: Mapping[str, str] | None = None) -> str:
    """``result.json`` as text."""
    return json.dumps(classroom50_result(report, environ), indent=2, ensure_ascii=False) + "\n"
