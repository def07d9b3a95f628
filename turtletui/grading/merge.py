"""One report from the results folders of a class graded in parts
(``turtletui grade merge DIR...``), the same as one machine grading it all.

Every file read must carry the signature of this machine's results key (the
one the parts signed with: ``$TURTLETUI_RESULTS_KEY``, shared by every part
and the merge), and every part must have graded the same class, under the same
lesson, checks, plugins, limits and turtletui version; anything else is
refused with one line naming the folder or file. The report lists the class in
the order one machine lists it, each result as the part that graded it kept
it, its recordings where they are now (in that part's folder).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from turtletui.errors import TurtletuiError
from turtletui.grading.results import GradeReport, SubmissionResult
from turtletui.grading.shards import ClassManifest, manifest_path
from turtletui.grading.store import (
    KEY_ENV,
    STORE_VERSION,
    SignatureError,
    existing_signing_key,
    read_signed,
    recordings_folder,
    result_path,
)

NAMES_SHOWN = 8
"""Students named in one line about missing ones; the rest are counted."""


class MergeError(TurtletuiError, ValueError):
    """Results folders that cannot be merged; one line saying which and why."""


@dataclass(frozen=True)
class Part:
    """One results folder and the manifest it holds."""

    folder: Path
    manifest: ClassManifest


@dataclass
class Merged:
    """The merged report and what it lacks."""

    report: GradeReport
    parts: list[Part]
    missing: dict[str, str] = field(default_factory=dict)
    """Student -> why there is no result for them (in the class's order)."""

    def missing_line(self) -> str:
        """One line naming the students without a result, grouped by why."""
        groups: dict[str, list[str]] = {}
        for student, why in self.missing.items():
            groups.setdefault(why, []).append(student)
        count = len(self.missing)
        said = "; ".join(f"{_names(students)} ({why})" for why, students in groups.items())
        whom = "1 student" if count == 1 else f"{count} students"
        return f"{whom} of {len(self.parts[0].manifest.members)} {'has' if count == 1 else 'have'} no result: {said}"


def _names(students: list[str]) -> str:
    shown = ", ".join(students[:NAMES_SHOWN])
    return shown if len(students) <= NAMES_SHOWN else f"{shown} and {len(students) - NAMES_SHOWN} more"


def results_secret() -> bytes:
    """The key the parts signed with; MergeError when this machine has none
    (a new key would match no signature)."""
    try:
        secret = existing_signing_key()
    except OSError as err:
        raise MergeError(f"the results key cannot be used: {err}") from None
    if secret is None:
        raise MergeError(
            f"no results key here: set {KEY_ENV} to the secret the parts were graded with"
        )
    return secret


def read_part(folder: Path, secret: bytes) -> Part:
    """A results folder's manifest, its signature checked."""
    if not folder.is_dir():
        raise MergeError(f"{folder}: no such results folder")
    path = manifest_path(folder)
    try:
        data = read_signed(path, secret)
        if data.get("store") != STORE_VERSION:
            raise MergeError(f"{path}: written by another version of turtletui (results format {data.get('store')})")
        manifest = ClassManifest.from_dict(data)
    except FileNotFoundError:
        raise MergeError(
            f"{folder}: no {path.name}: not a results folder of `turtletui grade` (give the --results folder of each part)"
        ) from None
    except OSError as err:
        raise MergeError(f"{path}: cannot be read ({err.strerror or err})") from None
    except SignatureError as err:
        raise MergeError(f"{err}: {_edited_or_other_key()}") from None
    except (KeyError, TypeError, ValueError) as err:
        raise MergeError(f"{path}: not a class manifest ({err})") from None
    return Part(folder, manifest)


def _edited_or_other_key() -> str:
    return f"it was edited, or signed with another key (every part and the merge must share {KEY_ENV})"


def merge_results(folders: Sequence[Path], *, secret: bytes | None = None) -> Merged:
    """The report of the class whose parts were graded into ``folders``
    (MergeError when they cannot be put together); students without a result
    are left out of it and listed in :attr:`Merged.missing`."""
    if not folders:
        raise MergeError("name the results folder of each part")
    secret = results_secret() if secret is None else secret
    parts = _distinct([read_part(Path(folder), secret) for folder in folders])
    first = parts[0]
    for other in parts[1:]:
        _check_same_grading(first, other)
    by_index = _by_index(parts)
    missing: dict[str, str] = {}
    count = first.manifest.shard.count
    for index in range(1, count + 1):
        if index not in by_index:
            for student in first.manifest.part(index):
                missing[student] = f"part {index}/{count}: no results folder given"
    found: dict[str, SubmissionResult] = {}
    for index, part in by_index.items():
        for member in part.manifest.members:
            if member.student not in part.manifest.part(index):
                continue
            result, why = _result(part, member.student, member.fingerprint, secret)
            if result is None:
                missing[member.student] = f"part {index}/{count} in {part.folder}: {why}"
            else:
                found[member.student] = result
    results = [found[s] for s in first.manifest.students if s in found]
    ordered_missing = {s: missing[s] for s in first.manifest.students if s in missing}
    report = GradeReport(lesson=first.manifest.lesson, submissions=results, max_score=first.manifest.max_score)
    return Merged(report, parts, ordered_missing)


def _distinct(parts: list[Part]) -> list[Part]:
    """The parts, each folder once (a folder named twice is one folder)."""
    seen: dict[Path, Part] = {}
    for part in parts:
        seen.setdefault(part.folder.resolve(), part)
    return list(seen.values())


def _check_same_grading(first: Part, other: Part) -> None:
    a, b = first.manifest, other.manifest
    where = f"{other.folder} and {first.folder}"
    if a.key != b.key:
        raise MergeError(f"{where} were graded differently: {_difference(a, b)}; grade every part the same way")
    if a.shard.count != b.shard.count:
        raise MergeError(
            f"{where} are parts of different splits ({b.shard} and {a.shard}): every part of a class "
            "is graded with the same N in --shard K/N"
        )
    if a.members != b.members:
        raise MergeError(f"{where} graded different classes: {_class_difference(a, b)}; give every part the same submissions")


def _difference(a: ClassManifest, b: ClassManifest) -> str:
    """What differs between two gradings, as far as their manifests tell."""
    if a.lesson != b.lesson:
        return f"lesson {b.lesson!r} and lesson {a.lesson!r}"
    for name in ("turtletui", "lesson file", "time limit"):
        if a.conditions.get(name) != b.conditions.get(name):
            return f"{name} {b.conditions.get(name)} and {a.conditions.get(name)}"
    limits_a, limits_b = _limits(a), _limits(b)
    for name in sorted(set(limits_a) | set(limits_b)):
        if limits_a.get(name) != limits_b.get(name):
            return f"limit {name} {limits_b.get(name)} and {limits_a.get(name)}"
    return "other checks or plugins"


def _limits(manifest: ClassManifest) -> dict:
    limits = manifest.conditions.get("limits")
    return limits if isinstance(limits, dict) else {}


def _class_difference(a: ClassManifest, b: ClassManifest) -> str:
    mine, theirs = {m.student: m for m in a.members}, {m.student: m for m in b.members}
    only_b = [s for s in theirs if s not in mine]
    only_a = [s for s in mine if s not in theirs]
    if only_b or only_a:
        said = []
        if only_b:
            said.append(f"only the first has {_names(only_b)}")
        if only_a:
            said.append(f"only the second has {_names(only_a)}")
        return ", ".join(said)
    files = [s for s in mine if mine[s].fingerprint != theirs[s].fingerprint]
    if files:
        return f"the files of {_names(files)} differ"
    paths = [s for s in mine if mine[s].submission != theirs[s].submission]
    if paths:
        first = paths[0]
        return (
            f"{first}'s submission is {theirs[first].submission} in the first and {mine[first].submission} "
            "in the second (reports name it: grade every part from the same folder)"
        )
    return "the students are in another order"


def _by_index(parts: list[Part]) -> dict[int, Part]:
    by_index: dict[int, Part] = {}
    for part in parts:
        index = part.manifest.shard.index
        if index in by_index:
            twice = part.manifest.part(index)
            raise MergeError(
                f"part {part.manifest.shard} is in both {by_index[index].folder} and {part.folder}: "
                f"{_names(twice) or 'no student'} would be counted twice; merge one of them"
            )
        by_index[index] = part
    return by_index


def _result(part: Part, student: str, fingerprint: str, secret: bytes) -> tuple[SubmissionResult | None, str]:
    """A student's result in a part's folder, or None and why there is none.
    A file that is not as the grader signed it stops the merge."""
    path = result_path(part.folder, student)
    try:
        data = read_signed(path, secret)
    except FileNotFoundError:
        return None, "not graded (did it stop?)"
    except OSError as err:
        raise MergeError(f"{path}: cannot be read ({err.strerror or err})") from None
    except SignatureError as err:
        raise MergeError(f"{err}: {_edited_or_other_key()}") from None
    if data.get("store") != STORE_VERSION or data.get("key") != part.manifest.key:
        return None, "only a result of an earlier grading is there"
    if data.get("student") != student or data.get("fingerprint") != fingerprint:
        return None, "only a result of other files is there"
    try:
        result = SubmissionResult.from_dict(data["result"])
    except (KeyError, TypeError, ValueError) as err:
        raise MergeError(f"{path}: not a result ({err})") from None
    result.recordings = [_moved(part.folder, student, recording) for recording in result.recordings]
    return result, ""


def _moved(folder: Path, student: str, recording: str) -> str:
    """Where a recording the part kept in its results folder is now: in
    ``folder``, as the merge was told of it."""
    kept = Path(recording)
    place = recordings_folder(folder, student)
    if kept.parent.name == place.name and kept.parent.parent.name == "recordings":
        return str(place / kept.name)
    return recording
