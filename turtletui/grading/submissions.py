"""Find the students' submissions among the paths an instructor names.

A path is one of: a ``.py`` file (one student, named after the file), a folder
with Python files in it (one student, named after the folder), or a folder of
folders (a class: one student per subfolder). In a student's folder the
controller is the one Python file with a ``main`` function (the lesson's
starter file name breaks a tie).
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from pathlib import Path

MAX_SOURCE_BYTES = 1024 * 1024
"""A controller file larger than this is refused (it is not a student's node)."""

_MAIN = re.compile(rb"^\s*def\s+main\s*\(", re.MULTILINE)


class SubmissionError(ValueError):
    """A path that names no submission at all; one line naming the path."""


@dataclass(frozen=True)
class Submission:
    """One student's work."""

    student: str
    path: Path
    """The file or folder as named (or found in a class folder)."""
    controller: Path | None
    """The file to run; None when ``error`` says why there is none."""
    error: str | None = None

    def fingerprint(self) -> str:
        """Hash of the student's Python files: a result is reused only for the same code."""
        digest = hashlib.sha256()
        folder = self.path if self.path.is_dir() else None
        files = sorted(folder.rglob("*.py")) if folder else [self.path]
        for file in files:
            try:
                data = file.read_bytes()
            except OSError:
                data = b"<unreadable>"
            digest.update(str(file.relative_to(folder) if folder else file.name).encode() + b"\0")
            digest.update(hashlib.sha256(data).digest())
        return digest.hexdigest()


def _hidden(path: Path) -> bool:
    return path.name.startswith((".", "__")) or path.name == "node_modules"


def _python_files(folder: Path) -> list[Path]:
    return sorted(p for p in folder.iterdir() if p.suffix == ".py" and p.is_file() and not _hidden(p))


def _pick_controller(folder: Path, starter: str | None) -> tuple[Path | None, str | None]:
    files = _python_files(folder)
    if not files:
        return None, f"{folder}: no controller: the folder has no Python (.py) file"
    if len(files) == 1:
        return files[0], None
    with_main = []
    for file in files:
        try:
            head = file.read_bytes()[:MAX_SOURCE_BYTES]
        except OSError:
            continue
        if _MAIN.search(head):
            with_main.append(file)
    if len(with_main) == 1:
        return with_main[0], None
    candidates = with_main or files
    if starter is not None:
        for file in candidates:
            if file.name == starter:
                return file, None
    names = ", ".join(f.name for f in candidates)
    return None, f"{folder}: several possible controllers ({names}): keep one file with a main() function"


def _file_problem(path: Path) -> str | None:
    if path.suffix != ".py":
        return f"{path}: not a Python file (a controller is a .py file)"
    try:
        size = path.stat().st_size
    except OSError as err:
        return f"{path}: cannot read it ({err.strerror})"
    if size > MAX_SOURCE_BYTES:
        return f"{path}: {size} bytes is too large for a controller (at most {MAX_SOURCE_BYTES})"
    return None


def _student(path: Path, error: str | None = None, starter: str | None = None) -> Submission:
    if path.is_dir():
        controller, error = _pick_controller(path, starter)
        if controller is not None:
            error = _file_problem(controller)
        return Submission(path.name, path, None if error else controller, error)
    error = _file_problem(path)
    return Submission(path.stem, path, None if error else path, error)


def find_submissions(paths: list[Path], *, starter: str | None = None) -> list[Submission]:
    """Every student's submission under ``paths``, in a stable order, with
    unique student names (a clash gets ``-2``, ``-3``...). Raises SubmissionError
    for a path that does not exist or a folder with nothing to grade."""
    found: list[Submission] = []
    for path in paths:
        if not path.exists():
            raise SubmissionError(f"{path}: no such file or folder")
        if path.is_file():
            found.append(_student(path, starter=starter))
            continue
        if _python_files(path):
            found.append(_student(path, starter=starter))
            continue
        students = sorted(p for p in path.iterdir() if p.is_dir() and not _hidden(p))
        loose = sorted(p for p in path.iterdir() if p.is_file() and not _hidden(p))
        if not students and not loose:
            raise SubmissionError(f"{path}: empty folder: no submissions to grade")
        found.extend(_student(p, starter=starter) for p in students)
        # files next to the students' folders (a README, a zip) are reported, not run
        found.extend(
            Submission(p.stem, p, None, f"{p}: not a submission (put each student's files in a folder of their own)")
            for p in loose
            if p.suffix != ".py"
            and p.name.lower() not in ("readme", "readme.md", "readme.txt", ".ds_store")
        )
    return _unique(found)


def _unique(submissions: list[Submission]) -> list[Submission]:
    seen: dict[str, int] = {}
    unique = []
    for sub in submissions:
        name = sub.student
        if name in seen:
            seen[name] += 1
            name = f"{name}-{seen[sub.student]}"
        else:
            seen[name] = 1
        unique.append(sub if name == sub.student else Submission(name, sub.path, sub.controller, sub.error))
    return unique
