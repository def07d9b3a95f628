"""What grading produces: plain data that every report format is written from.

One :class:`TestResult` per check and scenario run ("no_wall_hits [centre]"),
gathered per student in a :class:`SubmissionResult`, and per lesson in a
:class:`GradeReport`. Scores are points: a check of weight W judged over N
scenario runs is N tests of W / N points each.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any

PASSED = "passed"
FAILED = "failed"


NOT_JUDGED = "not judged:"
"""How the output of a check that was not judged begins."""


@dataclass(frozen=True)
class TestResult:
    """One check judged on one scenario run."""

    __test__ = False  # not a pytest test class

    name: str
    """``check [scenario]``, e.g. ``no_wall_hits [random starts, seed 3]``."""
    check: str
    scenario: str
    """The scenario's label; ``hidden N`` for a hidden scenario."""
    score: float
    max_score: float
    status: str
    """:data:`PASSED` or :data:`FAILED`."""
    output: str
    """Feedback for the student: what was measured and, on failure, the lesson's hint."""
    hidden: bool = False

    @property
    def passed(self) -> bool:
        return self.status == PASSED

    @property
    def judged(self) -> bool:
        """False for a check that was not judged in its run (it earns nothing;
        its output says why: ``not judged: ...``)."""
        return not self.output.startswith(NOT_JUDGED)


@dataclass(frozen=True)
class Picture:
    """A failed scenario run drawn from above: the arena's walls, obstacles, the
    turtle's path, where it hit a wall and where it started."""

    scenario: str
    """The scenario's label, as in the tests' names."""
    png: str
    """The PNG image, base64-encoded (ready for a ``data:image/png;base64,`` URL)."""
    svg: str
    """The same picture as SVG text."""


@dataclass
class SubmissionResult:
    """One student's result for one lesson."""

    submission: str
    """The submission's path as given on the command line (file or folder)."""
    student: str
    """The student's identifier: the file's stem or the folder's name."""
    score: float = 0.0
    max_score: float = 0.0
    tests: list[TestResult] = field(default_factory=list)
    error: str | None = None
    """Why the submission could not be graded (no controller, ...): score 0."""
    execution_time: float = 0.0
    """Wall seconds its runs took, added up (runs side by side overlap: the
    sum may exceed the time grading it took; its time limit counts this)."""
    recordings: list[str] = field(default_factory=list)
    """Recordings of failed scenario runs (``turtletui replay`` plays them)."""
    graded: str = ""
    """Which file (relative to the submission) and executable were run."""
    pictures: list[Picture] = field(default_factory=list)
    """The trajectory of each failed visible scenario run, as pictures."""

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> SubmissionResult:
        fields = dict(data)
        fields["tests"] = [TestResult(**test) for test in data.get("tests", [])]
        fields["pictures"] = [Picture(**picture) for picture in data.get("pictures", [])]
        return cls(**fields)


@dataclass
class GradeReport:
    """Every submission graded against one lesson."""

    lesson: str
    submissions: list[SubmissionResult] = field(default_factory=list)
    max_score: float = 0.0
    """The lesson's total points (the same for every submission)."""
