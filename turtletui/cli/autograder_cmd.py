"""``turtletui autograder gradescope|classroom50|github --lesson ID -o DIR``: write the
files that grade a lesson in Gradescope's, Classroom 50's or GitHub Classroom's own
containers, with a wheel of this turtletui to install there.

turtletui.lessons and turtletui.grading are imported inside the commands, so
``turtletui --help`` stays cheap.
"""

from __future__ import annotations

from pathlib import Path

import typer

from turtletui.cli.errors import fail

app = typer.Typer(
    name="autograder",
    help="Write an autograder that grades a lesson on Gradescope, Classroom 50 or GitHub Classroom.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)

_LESSON_HELP = "The lesson to grade: an id (see turtletui lessons) or a lesson file."
_LESSONS_HELP = "A folder of your own lessons; it is copied into the autograder."
_REQUIREMENT_HELP = (
    "What pip installs in the grading container instead of a wheel of this turtletui (built into the output)."
)
_EXECUTABLE_HELP = "The node to grade in a ROS 2 package upload, as ros2 run PKG NAME names it."
_FORCE_HELP = "Overwrite files that already exist."


def _lesson_and_source(lesson_id: str, lessons: Path | None) -> tuple[str, Path | None]:
    """The lesson's id and the lesson file or folder to copy into the autograder
    (None for a lesson that the installed turtletui bundles)."""
    from turtletui.lessons.loader import find_lesson
    from turtletui.plugins.bundled import lessons_dir

    found = find_lesson(lesson_id, [lessons] if lessons else ())
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


def _bundle(write, requirement: str | None, **arguments) -> list[Path]:
    """Call ``write`` (an autograder writer) with a wheel of this turtletui built
    for it, or with the ``requirement`` instead."""
    import tempfile

    with tempfile.TemporaryDirectory(prefix="turtletui-wheel-") as tmp:
        return write(turtletui_requirement=requirement, wheel=_wheel(requirement, Path(tmp)), **arguments)


def _wheel(requirement: str | None, into: Path) -> Path | None:
    """A wheel of this turtletui in ``into`` (None when a requirement replaces it);
    a one-line error when it cannot be built."""
    if requirement:
        return None
    from turtletui.grading.wheel import WheelError, build_wheel

    try:
        return build_wheel(into)
    except (WheelError, OSError) as err:
        fail(f"{err}; or name what to install with --requirement")


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
    executable: str = typer.Option(None, "--executable", metavar="NAME", help=_EXECUTABLE_HELP),
    hidden_tests: str = typer.Option(
        "summary", "--hidden-tests", metavar="HOW",
        help="summary (one test: students see their total), after_published, after_due_date, hidden or visible.",
    ),
    time_limit: int = typer.Option(
        540, "--time-limit", metavar="SECONDS", help="Stop grading after this long (below Gradescope's timeout)."
    ),
    requirement: str = typer.Option(None, "--requirement", metavar="SPEC", help=_REQUIREMENT_HELP),
    force: bool = typer.Option(False, "--force", help=_FORCE_HELP),
) -> None:
    """Write a Gradescope autograder (setup.sh, run_autograder, turtletui's wheel) for a lesson."""
    from turtletui.grading.autograder import write_gradescope_autograder

    found_id, source = _lesson_and_source(lesson_id, lessons)
    written = _bundle(
        write_gradescope_autograder, requirement, lesson_id=found_id, out_dir=output, lesson_source=source,
        executable=executable, hidden_tests=hidden_tests, time_limit=time_limit, force=force,
    )
    _report(
        written,
        f"Zip the files in {output} (not the folder) and upload the zip as the "
        f"assignment's autograder; see {output / 'README.txt'}.",
    )


@app.command("classroom50")
def classroom50(
    lesson_id: str = typer.Option(..., "--lesson", metavar="ID", help=_LESSON_HELP),
    output: Path = typer.Option(
        ..., "--output", "-o", metavar="DIR",
        help="The assignment's autograder folder (CLASSROOM/autograders/ASSIGNMENT in your classroom50 repository).",
    ),
    lessons: Path = typer.Option(None, "--lessons", metavar="DIR", help=_LESSONS_HELP),
    executable: str = typer.Option(None, "--executable", metavar="NAME", help=_EXECUTABLE_HELP),
    requirement: str = typer.Option(None, "--requirement", metavar="SPEC", help=_REQUIREMENT_HELP),
    force: bool = typer.Option(False, "--force", help=_FORCE_HELP),
) -> None:
    """Write a Classroom 50 autograder (autograder.py, turtletui's wheel, a workflow) for a lesson."""
    from turtletui.grading.autograder_classroom50 import write_classroom50_autograder

    found_id, source = _lesson_and_source(lesson_id, lessons)
    written = _bundle(
        write_classroom50_autograder, requirement, lesson_id=found_id, out_dir=output, lesson_source=source,
        executable=executable, force=force,
    )
    _report(written, f"Commit {output} to your classroom50 repository; see {output / 'README.txt'}.")


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
    executable: str = typer.Option(None, "--executable", metavar="NAME", help=_EXECUTABLE_HELP),
    requirement: str = typer.Option(None, "--requirement", metavar="SPEC", help=_REQUIREMENT_HELP),
    force: bool = typer.Option(False, "--force", help=_FORCE_HELP),
) -> None:
    """Write a GitHub Classroom workflow (GitHub Classroom was retired on 2026-08-28)."""
    from turtletui.grading.autograder import write_github_workflow

    found_id, source = _lesson_and_source(lesson_id, lessons)
    written = _bundle(
        write_github_workflow, requirement, lesson_id=found_id, out_dir=output, lesson_source=source,
        submission=submission, executable=executable, force=force,
    )
    _report(
        written,
        f"Commit them to the assignment's template repository ({output}). GitHub Classroom was "
        f"retired on 2026-08-28: for new courses, use turtletui autograder classroom50.",
    )
