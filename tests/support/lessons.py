"""Grade controllers against the bundled lessons, each (lesson, controller) once per session
(tests/lessons/conftest.py makes a Grader the ``grade`` fixture)."""

from __future__ import annotations

from pathlib import Path

from turtletui.grading.engine import GradingPlan, grade_controllers, prepare
from turtletui.grading.results import SubmissionResult
from turtletui.lessons.loader import find_lesson
from turtletui.runtime import forkserver
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.resolve import resolve_controllers

SOLUTIONS = Path(__file__).parents[1] / "lessons" / "solutions"
"""Wrong (and alternative right) solutions, one folder per lesson."""


class Grader:
    """Grades each (lesson, controller) once: several tests read the same result."""

    def __init__(self) -> None:
        self._plans: dict[str, GradingPlan] = {}
        self._results: dict[tuple[str, str], SubmissionResult] = {}

    def plan(self, lesson_id: str) -> GradingPlan:
        if lesson_id not in self._plans:
            self._plans[lesson_id] = prepare(find_lesson(lesson_id))
        return self._plans[lesson_id]

    def __call__(self, lesson_id: str, controller: str | Path, *, in_process: bool = False) -> SubmissionResult:
        """Grade a registered controller name (the reference) or a file: sandboxed,
        as students' files are, or ``in_process`` (trusted test code only: faster)."""
        key = (lesson_id, str(controller), in_process)
        if key not in self._results:
            if in_process:
                specs = [ControllerSpec(name=Path(controller).stem, path=Path(controller), trusted=True)]
            else:
                specs = resolve_controllers([controller])
            # a file's runs fork from one warm interpreter, as `turtletui grade` does
            with forkserver.serving():
                self._results[key] = grade_controllers(self.plan(lesson_id), specs)
        return self._results[key]


def judged(test) -> bool:
    """Whether a test was judged (not gated by a failed requirement, a crash or a broken rule)."""
    return not test.output.startswith("not judged")


def failed_checks(result: SubmissionResult) -> set[str]:
    """Checks (by title) that were judged and failed in some run."""
    return {test.check for test in result.tests if not test.passed and judged(test)}


def not_judged(result: SubmissionResult) -> dict[str, set[str]]:
    """Check title -> scenarios where it was not judged."""
    out: dict[str, set[str]] = {}
    for test in result.tests:
        if not judged(test):
            out.setdefault(test.check, set()).add(test.scenario)
    return out


def feedback_of(result: SubmissionResult, check: str) -> list[str]:
    return [test.output for test in result.tests if test.check == check and not test.passed and judged(test)]


def check_of(test) -> str:
    """The check's name (a labelled check is shown as 'name: label')."""
    return test.check.split(":")[0]


def failed(result: SubmissionResult) -> dict[str, set[str]]:
    """Check name -> scenarios where it was judged and failed."""
    out: dict[str, set[str]] = {}
    for test in result.tests:
        if not test.passed and judged(test):
            out.setdefault(check_of(test), set()).add(test.scenario)
    return out


def feedback(result: SubmissionResult, check: str) -> str:
    """The feedback of every judged, failed test of ``check`` (any label), one per line."""
    return "\n".join(t.output for t in result.tests if check_of(t) == check and not t.passed and judged(t))
