"""Split a class between machines, and keep with each part what the class was.

``turtletui grade CLASS --shard K/N`` grades part K of N. The split is a pure
function of the students' names, so every machine computes the same one
whatever its folder listing's order, its Python or its hash seed: the
students, in the order of the SHA-256 of their names, are cut into N
contiguous runs whose lengths differ by at most one. That keeps the parts
balanced (the slowest machine decides when the class is graded), and a
student added late moves at most one student across each boundary between
parts: every other result a part's results folder already holds is still its
own, so a rerun of each part grades the new student and at most two more.
(A split by the hash alone, student by student, never moves anyone, but its
parts are uneven: for 30 students on 4 machines the largest part has 10 or
more in 7 classes of 10, instead of 8.) Hash order rather than name order spreads students
whose names share a prefix (``late-...``, a section's) over the parts.

Every grading writes a :class:`ClassManifest` beside its results, signed like
them: the whole class as this machine found it (names, paths, fingerprints of
the files), which part it grades, and the conditions of the grading.
``turtletui grade merge`` reads it to put the parts back together in the
class's order and to say which students are missing.
"""

from __future__ import annotations

import hashlib
import re
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field, is_dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.errors import TurtletuiError
from turtletui.grading.store import STORE_VERSION
from turtletui.grading.submissions import Submission

if TYPE_CHECKING:
    from turtletui.grading.engine import GradingPlan
    from turtletui.grading.store import ResultStore

MANIFEST = "class.manifest"
"""The manifest's file name in a results folder (student results are
``*.json``, so no student's file can have this name)."""

_SHARD = re.compile(r"\s*(\d+)\s*/\s*(\d+)\s*")


class ShardError(TurtletuiError, ValueError):
    """A ``--shard`` that names no part of a class; one line."""


@dataclass(frozen=True)
class Shard:
    """Part ``index`` (counted from 1) of a class split in ``count`` parts."""

    index: int
    count: int

    def __str__(self) -> str:
        return f"{self.index}/{self.count}"


WHOLE_CLASS = Shard(1, 1)


def parse_shard(text: str) -> Shard:
    """``"K/N"`` as a :class:`Shard`; :class:`ShardError` for anything else."""
    match = _SHARD.fullmatch(text)
    if match is None:
        raise ShardError(f"--shard {text!r}: write K/N, part K of N (1/4 ... 4/4)")
    index, count = int(match[1]), int(match[2])
    if count < 1:
        raise ShardError(f"--shard {text}: N, the number of parts, must be at least 1")
    if index == 0:
        raise ShardError(
            f"--shard {text}: parts are counted from 1 (1/{count} ... {count}/{count}); "
            "a Kubernetes JOB_COMPLETION_INDEX counts from 0: use $((JOB_COMPLETION_INDEX + 1))"
        )
    if index > count:
        raise ShardError(f"--shard {text}: there are only {count} parts (1/{count} ... {count}/{count})")
    return Shard(index, count)


def _hash_order(student: str) -> tuple[str, str]:
    return hashlib.sha256(student.encode("utf-8")).hexdigest(), student


def split(students: Sequence[str], count: int) -> list[list[str]]:
    """The students of each of ``count`` parts (part 1 first), as described in
    the module's docstring; within a part, in the order given."""
    ordered = sorted(students, key=_hash_order)
    total = len(ordered)
    cut = [total * k // count for k in range(count + 1)]
    part_of = {student: k for k in range(count) for student in ordered[cut[k] : cut[k + 1]]}
    parts: list[list[str]] = [[] for _ in range(count)]
    for student in students:
        parts[part_of[student]].append(student)
    return parts


def part_of(submissions: Sequence[Submission], shard: Shard) -> list[Submission]:
    """The submissions of ``shard``'s part of the class, in the class's order."""
    mine = set(split([s.student for s in submissions], shard.count)[shard.index - 1])
    return [s for s in submissions if s.student in mine]


# -- the manifest -------------------------------------------------------------------------


@dataclass(frozen=True)
class Member:
    """One student of the class, as a grading found them."""

    student: str
    submission: str
    """The submission's path as named on the command line (as reports show it)."""
    fingerprint: str
    """:meth:`Submission.fingerprint`: a result counts only for these files."""


@dataclass(frozen=True)
class ClassManifest:
    """What one grading (one part of a class, or all of it) graded and how."""

    lesson: str
    key: str
    """The results' key (:func:`~turtletui.grading.store.store_key`): every
    part must have the same."""
    max_score: float
    shard: Shard
    members: tuple[Member, ...]
    """The whole class, in the order one machine's report lists it."""
    conditions: dict[str, Any] = field(default_factory=dict)
    """What the key is made of, readable: to say how two parts' gradings differ."""

    @property
    def students(self) -> list[str]:
        return [m.student for m in self.members]

    def part(self, index: int) -> list[str]:
        """The students of part ``index`` (from 1) of this class's split."""
        return split(self.students, self.shard.count)[index - 1]

    def as_dict(self) -> dict[str, Any]:
        return {
            "store": STORE_VERSION,
            "kind": "class manifest",
            "lesson": self.lesson,
            "key": self.key,
            "max_score": self.max_score,
            "shard": [self.shard.index, self.shard.count],
            "members": [asdict(m) for m in self.members],
            "conditions": self.conditions,
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> ClassManifest:
        """Raises KeyError, TypeError or ValueError for data that is not a manifest."""
        if data.get("kind") != "class manifest":
            raise ValueError("not a class manifest")
        index, count = data["shard"]
        return cls(
            lesson=str(data["lesson"]),
            key=str(data["key"]),
            max_score=float(data["max_score"]),
            shard=Shard(int(index), int(count)),
            members=tuple(Member(**m) for m in data["members"]),
            conditions=dict(data.get("conditions") or {}),
        )


def grading_conditions(plan: GradingPlan, limits: Any = None, time_limit: float | None = None) -> dict[str, Any]:
    """The parts of a results key a person can compare: turtletui's version,
    the lesson file's digest, the sandbox's limits, the time limit and the
    distro the grader chose."""
    from turtletui import __version__

    return {
        "turtletui": __version__,
        "lesson file": hashlib.sha256(plan.lesson.path.read_bytes()).hexdigest()[:16],
        "limits": _plain(limits),
        "time limit": time_limit,
        "distro": plan.distro,
    }


def _plain(value: Any) -> Any:
    """Limits as JSON can hold them."""
    if is_dataclass(value) and not isinstance(value, type):
        return {k: _plain(v) for k, v in asdict(value).items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    return repr(value)


def write_manifest(
    store: ResultStore,
    plan: GradingPlan,
    submissions: Sequence[Submission],
    shard: Shard = WHOLE_CLASS,
    conditions: dict[str, Any] | None = None,
) -> ClassManifest:
    """Sign and write the manifest of grading ``shard`` of the class
    ``submissions`` into ``store``'s folder, before any of it is graded (a
    part that dies half way leaves a manifest that says what it had to do)."""
    manifest = ClassManifest(
        lesson=plan.lesson.id,
        key=store.key,
        max_score=round(plan.max_score, 6),
        shard=shard,
        members=tuple(Member(s.student, str(s.path), s.fingerprint()) for s in submissions),
        conditions=conditions or {},
    )
    store.write_signed(manifest_path(store.folder), manifest.as_dict())
    return manifest


def manifest_path(folder: Path) -> Path:
    return folder / MANIFEST
