"""``turtletui autograder gradescope|github --lesson ID -o DIR``: write the files that
grade a lesson in Gradescope's or GitHub Classroom's own containers.

turtletui.lessons and turtletui.grading are imported inside the commands, so
``turtletui --help`` stays cheap.
"""

from __future__ import annotations

from pathlib import Path

import typer

from turtletui.cli.errors import fail

app = typer.Typer(
    name="autograder",
    help="Write an autograder that grades a lesson on Gradescope or GitHub Classroom.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)

_LESSON_HELP = "The lesson to grade: an id (see turtletui lessons) or a lesson file."
_LESSONS_HELP = "A folder of your own lessons; it is copied into the autograder."
_REQUIREMENT_HELP = "What pip installs in the grading container (default: this turtletui version)."
_FORCE_HELP = "Overwrite files that already exist."


def _lesson_and_source(lesson_id: str, lessons: Path | None) -> tuple[str, Path | None]:
    """The lesson's id and the lesson file or folder to copy into the autograder
    (None for a lesson that the installed turtletui bundles); a one-line error and
    exit 2 for an unknown lesson."""
    from turtletui.lessons.loader import LessonError, find_lesson
    from turtletui.plugins.bundled import lessons_dir

    try:
        found = find_lesson(lesson_id, [lessons] if lessons else ())
    except LessonError as err:
        fail(str(err))
    path = found.path.resolve()
    bundled = lessons_dir()
    if bundled is not None and bundled.resolve() in path.parents:
        # The container's turtletui has it: a copy would be a second lesson with that id.
        return found.id, None
    if lessons is not None and lessons.resolve() in path.parents:
        return found.id, lessons
    # A lesson file named on the command line, or one a plugin registers: copy the
    # file, since the grading container installs turtletui only.
    return found.id, found.path


def _requirement(requirement: str | None) -> str:
    if requirement:
        return requirement
    from turtletui import __version__

    return f"turtletui=={__version__}"


def _report(written: list[Path], what: str) -> None:
    for path in written:
        print(f"wrote {path}")
    print(what)


@app.command("gradescope")
def gradescope(
    lesson_id: str = typer.Option(..., "--lesson", metavar="ID", help=_LESSON_HELP),
    output: Path = typer.Option(
        ..., "--output", "-o", metavar="DIR", help="Folder to write setup.sh and run_autograder to."
    ),
    lessons: Path = typer.Option(None, "--lessons", metavar="DIR", help=_LESSONS_HELP),
    requirement: str = typer.Option(None, "--requirement", metavar="SPEC", help=_REQUIREMENT_HELP),
    force: bool = typer.Option(False, "--force", help=_FORCE_HELP),
) -> None:
    """Write a Gradescope autograder (setup.sh, run_autograder) for a lesson."""
    from turtletui.grading.autograder import AutograderError, write_gradescope_autograder

    found_id, source = _lesson_and_source(lesson_id, lessons)
    try:
        written = write_gradescope_autograder(
            found_id,
            output,
            turtletui_requirement=_requirement(requirement),
            lesson_source=source,
            force=force,
        )
    except AutograderError as err:
        fail(str(err))
    _report(
        written,
        f"Zip the files in {output} (not the folder) and upload the zip as the "
        f"assignment's autograder; see {output / 'README.txt'}.",
    )


@app.command("github")
def github(
    lesson_id: str = typer.Option(..., "--lesson", metavar="ID", help=_LESSON_HELP),
    output: Path = typer.Option(
        ..., "--output", "-o", metavar="DIR", help="The assignment's template repository."
    ),
    lessons: Path = typer.Option(None, "--lessons", metavar="DIR", help=_LESSONS_HELP),
    submission: str = typer.Option(
        ".", "--submission", metavar="PATH",
        help="What to grade in a student's repository (default: all of it).",
    ),
    requirement: str = typer.Option(None, "--requirement", metavar="SPEC", help=_REQUIREMENT_HELP),
    force: bool = typer.Option(False, "--force", help=_FORCE_HELP),
) -> None:
    """Write a GitHub Classroom workflow (.github/workflows/classroom.yml) for a lesson."""
    from turtletui.grading.autograder import AutograderError, write_github_workflow

    found_id, source = _lesson_and_source(lesson_id, lessons)
    try:
        written = write_github_workflow(
            found_id,
            output,
            turtletui_requirement=_requirement(requirement),
            lesson_source=source,
            submission=submission,
            force=force,
        )
    except AutograderError as err:
        fail(str(err))
    _report(
        written,
        f"Commit them to the assignment's template repository ({output}); GitHub "
        f"Classroom grades every push.",
    )
