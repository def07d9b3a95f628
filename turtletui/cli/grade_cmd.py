"""``turtletui grade SUBMISSION... --lesson ID``: grade a class, reproducibly.

Exit status: 0 when grading completed (whatever the scores), 1 when a score is
below ``--fail-under``, 2 for bad input (unknown lesson, missing path,
unwritable output), 3 for an internal error, 130 when interrupted (finished
results are kept; rerun to resume).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import typer

from turtletui.cli.errors import fail

EXIT_BELOW = 1
EXIT_INTERNAL = 3
EXIT_INTERRUPTED = 130

_FORMAT_HELP = "table (default), json, junit, gradescope, csv or github."


def grade(
    submissions: list[Path] = typer.Argument(
        ..., metavar="SUBMISSION", help="A controller file, a student's folder, or a class folder of them."
    ),
    lesson_id: str = typer.Option(..., "--lesson", metavar="ID", help="The lesson to grade against (id or file)."),
    fmt: str = typer.Option("table", "--format", metavar="FORMAT", help=_FORMAT_HELP),
    output: Path = typer.Option(None, "--output", "-o", metavar="PATH", help="Write the report here (atomically)."),
    results: Path = typer.Option(
        None,
        "--results",
        metavar="DIR",
        help="Keep each student's result and recordings here (default: turtletui-grades/LESSON).",
    ),
    jobs: int = typer.Option(
        0, "--jobs", "-j", min=0, metavar="N", show_default=False, help="Scenario runs in parallel (default: one per CPU)."
    ),
    force: bool = typer.Option(False, "--force", help="Regrade submissions whose results are kept."),
    fail_under: float = typer.Option(
        None, "--fail-under", metavar="SCORE", help="Exit 1 if any submission scores fewer points."
    ),
    folder: list[Path] = typer.Option(
        None, "--lessons", "--folder", metavar="DIR", help="Also look for lessons in this folder (repeatable)."
    ),
    plugin: list[Path] = typer.Option(
        None, "--plugin", metavar="PATH", help="Also load this plugin file or folder (repeatable)."
    ),
    recording_format: str = typer.Option(
        "mcap",
        "--recording-format",
        metavar="FORMAT",
        help="How failed runs are kept for turtletui replay: mcap (also opens in Foxglove,"
        " PlotJuggler and ros2 bag) or jsonl (JSON Lines).",
    ),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress lines on stderr."),
    same_user: bool = typer.Option(
        False,
        "--same-user",
        help="Run student code as this user even when it is root (only in a throwaway container).",
    ),
) -> None:
    """Grade submissions against a lesson's scenarios and checks."""
    from turtletui.grading.reports import FORMATS

    if fmt not in FORMATS:
        fail(f"--format {fmt!r}: choose one of {', '.join(FORMATS)}")
    from turtletui.grading.engine import RECORDING_FORMATS

    if recording_format not in RECORDING_FORMATS:
        fail(f"--recording-format {recording_format!r}: choose {' or '.join(RECORDING_FORMATS)}")
    try:
        _check_output(output)
        report = _grade(
            submissions,
            lesson_id,
            fmt,
            results,
            jobs,
            force,
            folder or [],
            plugin or [],
            quiet,
            same_user,
            recording_format,
        )
        _write(report, fmt, output)
    except KeyboardInterrupt:
        sys.stderr.write("turtletui: interrupted: finished results are kept; run the same command to resume\n")
        raise SystemExit(EXIT_INTERRUPTED) from None
    except (ValueError, OSError) as err:
        fail(str(err).splitlines()[0] if str(err) else type(err).__name__)
    except Exception as err:  # a bug in turtletui: one line, and the details in a file
        where = _save_traceback()
        sys.stderr.write(f"turtletui: internal error: {type(err).__name__}: {err} (details in {where})\n")
        raise SystemExit(EXIT_INTERNAL) from None
    if fail_under is not None and any(s.score < fail_under for s in report.submissions):
        raise SystemExit(EXIT_BELOW)


def _grade(submissions, lesson_id, fmt, results, jobs, force, folders, plugins, quiet, same_user, recording_format):
    from turtletui.grading.batch import ResultStore, default_jobs, grade_submissions, store_key
    from turtletui.grading.engine import prepare
    from turtletui.grading.integrity import PrivateCopies, check_runtime_readable, unprivileged_ids
    from turtletui.grading.reports import SINGLE_SUBMISSION_FORMATS
    from turtletui.grading.submissions import find_submissions
    from turtletui.lessons.loader import find_lesson
    from turtletui.runtime.sandbox import Limits

    lesson = find_lesson(lesson_id, folders, plugins)
    plan = prepare(lesson, plugins=plugins)
    found = find_submissions(list(submissions), starter=lesson.starter)
    if fmt in SINGLE_SUBMISSION_FORMATS and len(found) != 1:
        raise ValueError(
            f"--format {fmt} reports one submission (the platform grades one per container), got {len(found)}"
        )
    store = ResultStore(results or Path("turtletui-grades") / lesson.id, store_key(plan))
    limits = Limits()
    copies = None
    ids = None if same_user else unprivileged_ids()
    if ids is not None:
        check_runtime_readable()
        limits = Limits(run_as=ids)
        copies = PrivateCopies()
    total = len(found)
    finished = 0

    def progress(result, reused: bool) -> None:
        nonlocal finished
        finished += 1
        if quiet:
            return
        if result.error:
            status = f"error: {result.error}"
        else:
            status = f"{result.score:g}/{result.max_score:g}"
            status += " (kept from an earlier run)" if reused else f" in {result.execution_time:.1f} s"
        sys.stderr.write(f"[{finished}/{total}] {result.student}: {status}\n")

    try:
        return grade_submissions(
            plan,
            found,
            store=store,
            jobs=jobs or default_jobs(),
            force=force,
            limits=limits,
            plugins=plugins,
            on_result=progress,
            workdir=copies,
            recording_format=recording_format,
        )
    finally:
        if copies is not None:
            copies.close()


def _check_output(output: Path | None) -> None:
    """Refuse an output path that cannot be written before grading a class, not after."""
    if output is None:
        return
    if output.is_dir():
        raise ValueError(f"cannot write {output}: it is a folder")
    if not output.parent.is_dir():
        raise ValueError(f"cannot write {output}: {output.parent} is not a folder")
    if not os.access(output.parent, os.W_OK | os.X_OK):
        raise ValueError(f"cannot write {output}: permission denied")


def _write(report, fmt: str, output: Path | None) -> None:
    from turtletui.grading.reports import (
        github_output_line,
        print_table,
        render_report,
        write_report,
    )

    if output is not None:
        write_report(report, fmt, output)
    elif fmt == "table":
        print_table(report)
    else:
        sys.stdout.write(render_report(report, fmt).rstrip("\n") + "\n")
    github_output = os.environ.get("GITHUB_OUTPUT")
    if fmt == "github" and github_output:
        with open(github_output, "a", encoding="utf-8") as file:
            file.write(github_output_line(report) + "\n")


def _save_traceback() -> str:
    import tempfile
    import traceback

    fd, path = tempfile.mkstemp(prefix="turtletui-error-", suffix=".txt")
    with os.fdopen(fd, "w") as file:
        traceback.print_exc(file=file)
    return path


def checks(
    plugin: list[Path] = typer.Option(
        None, "--plugin", metavar="PATH", help="Also load this plugin file or folder (repeatable)."
    ),
) -> None:
    """List the checks a lesson can name, with their thresholds."""
    from turtletui.grading.engine import available_checks

    for name, check in sorted(available_checks(plugin or ()).items()):
        params = "?" if check.params is None else ", ".join(check.params) or "none"
        print(f"{name}\n    {check.description or '(no description)'}\n    thresholds: {params}")
