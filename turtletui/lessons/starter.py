"""A lesson's starter file as a student's own file gets it (``turtletui new``,
``turtletui serve``): where the starter's text names itself ("Run it with:
turtletui run part5_starter.py"), it names the student's file, and the
command to run it opens the lesson too, so that ``k`` has something to check."""

from __future__ import annotations

import shlex
from pathlib import Path

from turtletui.lessons.model import Lesson


def starter_for(lesson: Lesson, file: Path, lesson_arg: str) -> bytes:
    """The bytes to write to ``file``: ``lesson``'s starter, naming ``file``
    and running it with ``--lesson lesson_arg``. A starter that is not UTF-8
    text is copied as it is. ``lesson.starter_path`` must be set."""
    source = lesson.starter_path
    data = source.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return data
    name = shlex.quote(file.name)
    text = text.replace(f"turtletui run {source.name}", f"turtletui run {name} --lesson {shlex.quote(lesson_arg)}")
    return text.replace(source.name, name).encode("utf-8")
