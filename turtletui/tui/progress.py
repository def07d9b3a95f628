"""Which lessons a student passed, kept per user across runs of the app.

One JSON file, ``$XDG_DATA_HOME/turtletui/progress.json`` (by default
``~/.local/share/turtletui/progress.json``), written atomically after every
check. A file that cannot be read (damaged, edited by hand, another
version's) is never fatal: :attr:`Progress.warning` says so in one line and
the app starts from no progress; the next check writes a good file again.
"""

from __future__ import annotations

import json
import os
import time
from dataclasses import asdict, dataclass
from pathlib import Path

from turtletui.grading.reports import ReportError, write_text_atomic

VERSION = 1


def progress_file() -> Path:
    """Where progress is kept for this user."""
    data = Path(os.environ.get("XDG_DATA_HOME") or Path.home() / ".local" / "share")
    return data / "turtletui" / "progress.json"


@dataclass(frozen=True)
class LessonProgress:
    """How a student did in one lesson's checks."""

    passed: bool
    """Every check passed in some check so far (a later failure keeps it)."""
    best_score: float
    max_score: float
    checks: int
    """Times the student ran the lesson's checks."""
    last_checked: float
    """Unix time of the last check."""


class Progress:
    """The student's progress, read once and written after each check."""

    def __init__(self, path: Path | None = None) -> None:
        self.path = path or progress_file()
        self.warning: str | None = None
        """One line saying why the stored progress could not be read or written."""
        self.lessons: dict[str, LessonProgress] = self._read()

    def get(self, lesson_id: str) -> LessonProgress | None:
        return self.lessons.get(lesson_id)

    def record(self, lesson_id: str, score: float, max_score: float) -> LessonProgress:
        """A check of ``lesson_id`` scored ``score`` of ``max_score``: keep it
        (and write the file; a failure to write is a warning, not an error)."""
        before = self.lessons.get(lesson_id)
        passed = max_score > 0 and score >= max_score
        entry = LessonProgress(
            passed=passed or (before is not None and before.passed),
            best_score=max(score, before.best_score if before else score),
            max_score=max_score,
            checks=(before.checks if before else 0) + 1,
            last_checked=time.time(),
        )
        self.lessons[lesson_id] = entry
        self._write()
        return entry

    def _read(self) -> dict[str, LessonProgress]:
        try:
            text = self.path.read_text(encoding="utf-8")
        except FileNotFoundError:
            return {}
        except OSError as err:
            self.warning = f"{self.path}: cannot read your progress ({err.strerror or err}); starting afresh"
            return {}
        except UnicodeDecodeError:
            text = ""  # not UTF-8: reported below as unreadable JSON
        try:
            data = json.loads(text)
            if data.get("version") != VERSION:
                raise ValueError(f"version {data.get('version')!r}")
            return {str(lesson): _entry(values) for lesson, values in data["lessons"].items()}
        except (ValueError, KeyError, TypeError, AttributeError) as err:
            self.warning = f"{self.path}: your progress could not be read ({_reason(err)}); starting afresh"
            return {}

    def _write(self) -> None:
        data = {"version": VERSION, "lessons": {k: asdict(v) for k, v in sorted(self.lessons.items())}}
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            write_text_atomic(self.path, json.dumps(data, indent=1) + "\n")
        except (OSError, ReportError) as err:
            self.warning = f"your progress could not be saved: {' '.join(str(err).split())}"


def _entry(values: dict) -> LessonProgress:
    entry = LessonProgress(
        passed=bool(values["passed"]),
        best_score=float(values["best_score"]),
        max_score=float(values["max_score"]),
        checks=int(values["checks"]),
        last_checked=float(values["last_checked"]),
    )
    if type(values["passed"]) is not bool:
        raise ValueError(f"passed is {values['passed']!r}")
    return entry


def _reason(err: Exception) -> str:
    if isinstance(err, KeyError):
        return f"missing {err}"
    return " ".join(str(err).split())[:120] or type(err).__name__
