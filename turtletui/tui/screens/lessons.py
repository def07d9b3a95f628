"""The lesson switcher: every lesson turtletui found, with the student's
progress in each; Enter opens one in the lesson pane (and `k` checks it)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.screen import ModalScreen
from textual.widgets import OptionList, Static
from textual.widgets.option_list import Option

from turtletui.lessons.model import Lesson
from turtletui.tui.progress import LessonProgress


def progress_mark(entry: LessonProgress | None, ascii: bool = False) -> tuple[str, str]:
    """(mark, style) for a lesson: passed, tried (best score) or not checked yet."""
    if entry is None:
        return "  -  ", "dim"
    if entry.passed:
        return (" ok  " if ascii else "  ✓  "), "green"
    return f"{entry.best_score:g}/{entry.max_score:g}".center(5), "yellow"


class LessonScreen(ModalScreen["Lesson | None"]):
    """Pick a lesson; dismissed with it, or None."""

    BINDINGS = [Binding("escape,l,q", "dismiss(None)", "Close", show=False)]

    def __init__(self, lessons: Sequence[Lesson], progress: dict[str, LessonProgress],
                 current: Path | None, ascii: bool = False) -> None:
        super().__init__()
        self._lessons = list(lessons)
        self._progress = progress
        self._current = current
        self._ascii = ascii

    def compose(self) -> ComposeResult:
        with Vertical(id="lessons-box"):
            yield Static("Lessons  (Enter opens one, Esc closes; ✓ passed, n/m your best score)"
                         if not self._ascii else
                         "Lessons  (Enter opens one, Esc closes; ok passed, n/m your best score)",
                         id="lessons-title")
            yield OptionList(*(self._option(lesson) for lesson in self._lessons), id="lessons-list")

    def _option(self, lesson: Lesson) -> Option:
        mark, style = progress_mark(self._progress.get(lesson.id), self._ascii)
        part = "" if lesson.part is None else f"Part {lesson.part}: "
        label = Text(mark, style=style)
        label.append(f" {part}{lesson.title}", style="bold" if lesson.path == self._current else "")
        label.append(f"  {lesson.id}", style="dim")
        return Option(label, id=lesson.id)

    def on_mount(self) -> None:
        options = self.query_one(OptionList)
        current = next((i for i, lesson in enumerate(self._lessons) if lesson.path == self._current), 0)
        options.highlighted = current
        options.focus()

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        self.dismiss(next(lesson for lesson in self._lessons if lesson.id == event.option.id))
