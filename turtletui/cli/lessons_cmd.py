"""``turtletui lessons``, ``turtletui lesson ID`` and ``turtletui new --lesson ID FILE``.

turtletui.lessons is imported inside the commands, so ``turtletui --help`` stays cheap.
"""

from __future__ import annotations

import shlex
from pathlib import Path

import typer

from turtletui.cli.errors import fail
from turtletui.cli.plugin_manager import plugins_of

_FOLDER_HELP = "Also look for lessons in this folder (every *.md but README.md; repeatable)."
_PLUGIN_HELP = "Also load this plugin file, or every .py in this folder (repeatable)."


def lessons(
    as_json: bool = typer.Option(
        False, "--json", help="Print a JSON list of objects, one per lesson."
    ),
    folder: list[Path] = typer.Option(None, "--folder", metavar="DIR", help=_FOLDER_HELP),
    plugin: list[Path] = typer.Option(None, "--plugin", metavar="PATH", help=_PLUGIN_HELP),
) -> None:
    """List the lessons turtletui found (bundled, from plugins, from --folder)."""
    from turtletui.grading.engine import available_checks, validate
    from turtletui.lessons.loader import discover_lessons

    plugins = plugins_of(plugin)
    found = discover_lessons(folder or (), plugins)
    # a misspelt check or world is found now, not when a class is graded
    known = available_checks(plugins)
    for item in found:
        validate(item, plugins=plugins, checks=known)
    if as_json:
        import json

        rows = [
            {
                "id": lesson.id,
                "title": lesson.title,
                "part": lesson.part,
                "path": str(lesson.path),
                "objectives": list(lesson.objectives),
                "starter": None if lesson.starter_path is None else str(lesson.starter_path),
                "reference": lesson.reference,
                "world": lesson.world,
                "scenarios": [s.name for s in lesson.scenarios],
            }
            for lesson in found
        ]
        print(json.dumps(rows, indent=2))
        return
    if not found:
        print("No lessons found.")
        return
    id_width = max(len("ID"), *(len(lesson.id) for lesson in found))
    import shutil
    import textwrap

    indent = " " * (id_width + 8)
    width = max(shutil.get_terminal_size().columns, len(indent) + 20)
    print(f"{'ID':<{id_width}}  PART  TITLE")
    for lesson in found:
        part = "-" if lesson.part is None else str(lesson.part)
        head = f"{lesson.id:<{id_width}}  {part:>4}  "
        print(textwrap.fill(lesson.title, width, initial_indent=head, subsequent_indent=indent))


def _find(lesson_id: str, folder: list[Path] | None, plugin: list[Path] | None):
    """The lesson named by id or path (a LessonError if there is none)."""
    from turtletui.lessons.loader import find_lesson

    return find_lesson(lesson_id, folder or (), plugins_of(plugin))


def lesson(
    lesson_id: str = typer.Argument(
        ..., metavar="ID", help="A lesson id (see turtletui lessons) or a lesson file."
    ),
    folder: list[Path] = typer.Option(None, "--folder", metavar="DIR", help=_FOLDER_HELP),
    plugin: list[Path] = typer.Option(None, "--plugin", metavar="PATH", help=_PLUGIN_HELP),
) -> None:
    """Show a lesson in the terminal."""
    found = _find(lesson_id, folder, plugin)
    heading = found.title if found.part is None else f"Part {found.part}: {found.title}"
    objectives = "".join(f"- {line}\n" for line in found.objectives)
    starter = (
        f"\nStart from the skeleton: `turtletui new --lesson {found.id} FILE.py`\n"
        if found.starter
        else ""
    )
    try:
        from rich.console import Console
        from rich.markdown import Markdown
    except ImportError:  # rich comes with Textual, but the lesson is plain text too
        print(heading)
        print("=" * len(heading))
        if objectives:
            print(f"\nYou will:\n{objectives}", end="")
        print(starter)
        print(found.body)
        return
    console = Console()
    console.print(heading, style="bold", markup=False, highlight=False)
    if objectives:
        console.print(Markdown(f"You will:\n\n{objectives}"))
    if starter:
        console.print(Markdown(starter))
    console.print()
    console.print(Markdown(found.body))


def new(
    file: Path = typer.Argument(..., metavar="FILE", help="Where to write the starter code."),
    lesson_id: str = typer.Option(
        ..., "--lesson", metavar="ID", help="The lesson whose starter to write."
    ),
    force: bool = typer.Option(False, "--force", help="Overwrite FILE if it exists."),
    folder: list[Path] = typer.Option(None, "--folder", metavar="DIR", help=_FOLDER_HELP),
    plugin: list[Path] = typer.Option(None, "--plugin", metavar="PATH", help=_PLUGIN_HELP),
) -> None:
    """Write a lesson's starter file to FILE, ready to edit and run."""
    found = _find(lesson_id, folder, plugin)
    if found.starter_path is None:
        fail(f"lesson {found.id!r} has no starter file")
    if file.exists() and not force:
        fail(f"{file} already exists; use --force to overwrite it")
    if file.is_dir():
        fail(f"{file} is a folder; name the file to write")
    from turtletui.lessons.starter import starter_for

    # `run --lesson` finds bundled lessons by id; one from --folder or a plugin by its file
    lesson_arg = str(found.path) if folder or plugin else found.id
    try:
        file.write_bytes(starter_for(found, file, lesson_arg))
    except OSError as err:
        parent = file.parent
        why = f"{parent} is not a folder" if not parent.is_dir() else (err.strerror or str(err)).lower()
        fail(f"cannot write {file}: {why}")
    print(f"Wrote {file} (starter of lesson {found.id}). Run it: "
          f"turtletui run {shlex.quote(str(file))} --lesson {shlex.quote(lesson_arg)}")
