"""Every lesson found pays for its task only: degenerate and cheating
controllers score at most 30 % of it, right ones written differently from
the reference at least 90 %, and the reference full marks, sandboxed too.

The controllers are described in tests/support/corpus.py. Most run
in-process: they are our own test code, and a sandboxed run of a long lesson
costs several times more. A sample runs sandboxed, as students' files do:
every reference and starter, the first right alternative of each lesson
whose scenarios last at most SHORT simulated seconds in all, each generic
controller once (on the shortest lessons), and the cheats marked
``# corpus: sandboxed`` (they chain service calls within one simulated
instant, which only the sandbox bounds). Results are shared with the lesson
tests through the ``grade`` fixture (the starters are graded sandboxed there
too).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from support.corpus import (
    CORPUS,
    GENERIC,
    LEAST_RIGHT,
    SANDBOXED_MARK,
    SOLVES,
    generic_controllers,
    lesson_files,
)

from turtletui.grading.results import SubmissionResult
from turtletui.lessons.loader import discover_lessons
from turtletui.plugins.manager import collect_controllers, get_plugin_manager

LESSONS = discover_lessons()
IDS = [lesson.id for lesson in LESSONS]
DEGENERATE = 0.3
"""At most this share of a lesson's points for a controller that does not do its task."""
RIGHT = 0.9
"""At least this share for one that does it, however it is written."""


def share(result: SubmissionResult) -> float:
    assert result.error is None, result.error
    return result.score / result.max_score


def earned(result: SubmissionResult) -> str:
    """What earned points, for an assertion message."""
    return "; ".join(f"{t.name}: {t.output.splitlines()[0] if t.output else 'passed'}" for t in result.tests if t.passed)


def lost(result: SubmissionResult) -> str:
    return "; ".join(f"{t.name}: {t.output.splitlines()[0] if t.output else ''}" for t in result.tests if not t.passed)


@pytest.fixture(scope="session")
def generic(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    return generic_controllers(tmp_path_factory.mktemp("generic"))


def simulated_seconds(lesson) -> float:
    return sum(scenario.duration * len(scenario.seeds) for scenario in lesson.scenarios)


SHORT = 120.0
"""Simulated seconds of all its scenarios up to which a lesson grades a right
alternative sandboxed too (longer ones, Part 6's 9 minutes, in-process only)."""
SHORTEST = sorted(IDS, key=lambda i: simulated_seconds(LESSONS[IDS.index(i)]))
SANDBOXED_GENERIC = {(SHORTEST[n % len(SHORTEST)], name) for n, name in enumerate(GENERIC)}
"""Each generic controller graded sandboxed once, on one of the shortest lessons."""


@pytest.mark.parametrize(("lesson_id", "name"), [(i, n) for i in IDS for n in GENERIC], ids=lambda v: v)
def test_a_degenerate_controller_scores_little(grade, generic, lesson_id, name):
    result = grade(lesson_id, generic[name], in_process=(lesson_id, name) not in SANDBOXED_GENERIC)
    if name in SOLVES.get(lesson_id, set()):
        assert share(result) >= RIGHT, lost(result)
    else:
        assert share(result) <= DEGENERATE, earned(result)


@pytest.mark.parametrize("lesson", LESSONS, ids=IDS)
def test_the_unchanged_starter_scores_little(grade, lesson):
    assert share(grade(lesson.id, lesson.starter_path)) <= DEGENERATE


CHEATS = [(i, path) for i in IDS for path in lesson_files(i, "cheat")]


@pytest.mark.parametrize(("lesson_id", "path"), CHEATS, ids=[f"{i}-{p.stem}" for i, p in CHEATS])
def test_a_lessons_cheats_score_little(grade, lesson_id, path):
    result = grade(lesson_id, path, in_process=SANDBOXED_MARK not in path.read_text(encoding="utf-8"))
    assert share(result) <= DEGENERATE, earned(result)


RIGHTS = [
    (lesson.id, path, n == 0 and simulated_seconds(lesson) <= SHORT)
    for lesson in LESSONS
    for n, path in enumerate(lesson_files(lesson.id, "right"))
]


@pytest.mark.parametrize(("lesson_id", "path", "sandboxed"), RIGHTS, ids=[f"{i}-{p.stem}" for i, p, _ in RIGHTS])
def test_a_right_alternative_scores_well(grade, lesson_id, path, sandboxed):
    result = grade(lesson_id, path, in_process=not sandboxed)
    assert share(result) >= RIGHT, lost(result)


@pytest.mark.parametrize("lesson", LESSONS, ids=IDS)
def test_the_reference_scores_full_marks_sandboxed(grade, lesson):
    reference = collect_controllers(get_plugin_manager())[lesson.reference]
    assert reference.path is not None
    result = grade(lesson.id, reference.path)
    assert result.score == result.max_score, lost(result)


@pytest.mark.parametrize("lesson", LESSONS, ids=IDS)
def test_every_lesson_has_right_alternatives_in_the_corpus(lesson):
    rights = lesson_files(lesson.id, "right")
    assert len(rights) >= LEAST_RIGHT, f"add {LEAST_RIGHT} right_*.py to {CORPUS / lesson.id}"


def test_every_corpus_folder_is_a_lesson():
    folders = {p.name for p in CORPUS.iterdir() if p.is_dir() and p.name not in {"generic", "__pycache__"}}
    assert folders <= set(IDS)
