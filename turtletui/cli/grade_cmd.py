"""``turtletui grade SUBMISSION... --lesson ID``: grade a class, reproducibly.

Exit status: 0 when grading completed (whatever the scores), 1 when a score is
below ``--fail-under``, 2 for bad input (unknown lesson, missing path,
unwritable output), 3 for an internal error (see cli.errors), 130 when
interrupted (finished results are kept; rerun to resume).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

import typer

from turtletui.cli.errors import fail
from turtletui.cli.plugin_manager import plugins_of
from turtletui.errors import UsageError

BACKENDS = ("local", "ray")
OWN_PROCESS = False
"""The command runs in a process of its own (the console script sets it; a
test's CliRunner does not): it starts no children but its runs', so after
each run graded in it every other child is killed (see grade_submissions)."""
EXIT_BELOW = 1
EXIT_INTERRUPTED = 130

_FORMAT_HELP = (
    "table (default), json, junit, gradescope, prairielearn, classroom50, canvas (with --roster), moodle, csv,"
    " or github (for GitHub Classroom, retired 2026-08-28)."
)


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
        0, "--jobs", "-j", min=0, metavar="N", show_default=False, help="Scenario runs in parallel (default, or 0: one per CPU)."
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
    time_limit: float = typer.Option(
        None,
        "--time-limit",
        metavar="SECONDS",
        help="Wall-clock seconds all the runs of one submission may take (default: the lesson's, else 300).",
    ),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress lines on stderr."),
    same_user: bool = typer.Option(
        False,
        "--same-user",
        help="Run student code as this user even when it is root (only in a throwaway container).",
    ),
    executable: str = typer.Option(
        None,
        "--executable",
        metavar="NAME",
        help="The node to grade in a ROS 2 package (as ros2 run PKG NAME names it) or the file in a folder.",
    ),
    roster: Path = typer.Option(
        None, "--roster", metavar="CSV", help="canvas, moodle: the class list exported from the LMS."
    ),
    hidden_tests: str = typer.Option(
        "summary",
        "--hidden-tests",
        metavar="HOW",
        help="gradescope: summary (one test, the student sees their total) or a visibility for each:"
        " after_published, after_due_date, hidden, visible.",
    ),
    shard: str = typer.Option(
        None,
        "--shard",
        metavar="K/N",
        help="Grade part K of N of the class (one of N machines); turtletui grade merge puts the parts together.",
    ),
    backend: str = typer.Option(
        "local",
        "--backend",
        metavar="NAME",
        help="Where the runs run: local (this machine) or ray (a Ray cluster, with the extra turtletui[ray]).",
    ),
    address: str = typer.Option(
        None,
        "--address",
        metavar="ADDR",
        help="ray: the cluster, as Ray names it (auto, local, ray://HOST:10001;"
        " default: $RAY_ADDRESS, else one on this machine, else a new one).",
    ),
    distro: str = typer.Option(
        None,
        "--distro",
        metavar="NAME",
        help="The ROS 2 submissions run as: humble, jazzy (turtlesim.msg), kilted or lyrical"
        " (turtlesim_msgs.msg). Default: $TURTLETUI_DISTRO, else the lesson's, else lyrical.",
    ),
) -> None:
    """Grade submissions against a lesson's scenarios and checks.

    turtletui grade merge DIR... writes one report from the results folders
    of a class graded in parts (--shard K/N); see turtletui grade merge --help.
    """
    from turtletui.grading.reports import SINGLE_SUBMISSION_FORMATS, ReportOptions

    check_report_options(fmt, roster, hidden_tests)
    if distro is not None:
        from turtletui.compat.distro import check_distro

        try:
            distro = check_distro(distro)
        except ValueError as err:
            fail(f"--distro: {err}")
    from turtletui.grading.engine import RECORDING_FORMATS

    if recording_format not in RECORDING_FORMATS:
        fail(f"--recording-format {recording_format!r}: choose {' or '.join(RECORDING_FORMATS)}")
    if time_limit is not None and not time_limit > 0:
        fail(f"--time-limit must be a positive number of seconds, got {time_limit:g}")
    if backend not in BACKENDS:
        fail(f"--backend {backend!r}: choose {' or '.join(BACKENDS)}")
    if address is not None and backend != "ray":
        fail("--address is the Ray cluster's: give it with --backend ray")
    if shard is not None and fmt in SINGLE_SUBMISSION_FORMATS:
        fail(f"--shard splits a class; --format {fmt} grades one submission")
    try:
        options = ReportOptions(roster=read_roster_option(roster), hidden=hidden_tests)
        check_output(output)
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
            executable,
            time_limit,
            shard,
            backend,
            address,
            distro,
        )
        write_output(report, fmt, output, options)
    except KeyboardInterrupt:
        sys.stderr.write("turtletui: interrupted: finished results are kept; run the same command to resume\n")
        raise SystemExit(EXIT_INTERRUPTED) from None
    exit_if_below(report, fail_under)


def exit_if_below(report: Any, fail_under: float | None) -> None:
    """Exit 1, saying who, if any submission of ``report`` scored under ``fail_under``."""
    if fail_under is None:
        return
    below = [s for s in report.submissions if s.score < fail_under]
    if below:
        named = ", ".join(f"{s.student or s.submission} ({s.score:g})" for s in below[:10])
        more = f" and {len(below) - 10} more" if len(below) > 10 else ""
        sys.stderr.write(f"turtletui: {len(below)} scored under --fail-under {fail_under:g}: {named}{more}\n")
        raise SystemExit(EXIT_BELOW)


def check_report_options(fmt: str, roster: Path | None, hidden_tests: str) -> None:
    """A one-line error and exit 2 for --format, --roster and --hidden-tests
    that name nothing or do not go together."""
    from turtletui.grading.reports import FORMATS, HIDDEN_CHOICES, ROSTER_FORMATS

    if fmt not in FORMATS:
        fail(f"--format {fmt!r}: choose one of {', '.join(FORMATS)}")
    if hidden_tests not in HIDDEN_CHOICES:
        fail(f"--hidden-tests {hidden_tests!r}: choose one of {', '.join(HIDDEN_CHOICES)}")
    if fmt == "canvas" and roster is None:
        fail("--format canvas needs --roster EXPORT.csv: the gradebook exported from Canvas")
    if roster is not None and fmt not in ROSTER_FORMATS:
        fail(f"--roster is for --format {' or '.join(ROSTER_FORMATS)}, not {fmt}")


def read_roster_option(path: Path | None):
    """The class list of ``--roster`` (None without it)."""
    if path is None:
        return None
    from turtletui.grading.formats.roster import read_roster

    return read_roster(path)


def _grade(
    submissions,
    lesson_id,
    fmt,
    results,
    jobs,
    force,
    folders,
    plugins,
    quiet,
    same_user,
    recording_format,
    executable,
    time_limit,
    shard_text,
    backend_name,
    address,
    distro,
):
    from contextlib import nullcontext
    from dataclasses import replace

    from turtletui.grading.batch import grade_submissions
    from turtletui.grading.engine import prepare
    from turtletui.grading.integrity import PrivateCopies, check_runtime_readable, unprivileged_ids
    from turtletui.grading.reports import SINGLE_SUBMISSION_FORMATS
    from turtletui.grading.shards import (
        WHOLE_CLASS,
        grading_conditions,
        parse_shard,
        part_of,
        write_manifest,
    )
    from turtletui.grading.store import ResultStore, checkout_of, store_key
    from turtletui.grading.submissions import find_submissions
    from turtletui.lessons.loader import find_lesson
    from turtletui.runtime import container
    from turtletui.runtime.sandbox import Limits

    plugins = plugins_of(plugins)
    shard = parse_shard(shard_text) if shard_text else WHOLE_CLASS
    lesson = find_lesson(lesson_id, folders, plugins)
    plan = prepare(lesson, plugins=plugins, distro=distro)
    single = fmt in SINGLE_SUBMISSION_FORMATS
    found = find_submissions(
        list(submissions),
        starter=lesson.starter_path,
        executable=executable,
        default_executable=lesson.executable,
        single=single,
    )
    if single and len(found) != 1:
        raise UsageError(
            f"--format {fmt} reports one submission (the platform grades one per container), got {len(found)}"
        )
    limits = Limits()
    if backend_name == "local":
        # Runs side by side fit the container's CPUs and memory (a run that could
        # use more than the container has would get the whole container killed).
        jobs = container.fitting_jobs(jobs or container.available_cpus())
        limits = replace(limits, memory_bytes=container.run_memory(jobs, limits.memory_bytes))
    # Stored results inside a submission, or inside the checkout a submission
    # named here comes from, could have been written by the student: never reused.
    named = [checkout_of(path) for path in submissions if path.is_file() or path in {s.path for s in found}]
    store = ResultStore(
        results or Path("turtletui-grades") / lesson.id,
        store_key(plan, plugins=plugins, limits=(limits, time_limit)),  # a new --time-limit grades again
        untrusted=[*named, *(s.path for s in found)],
    )
    write_manifest(store, plan, found, shard, grading_conditions(plan, limits, time_limit))
    everyone = len(found)
    found = part_of(found, shard)
    if shard != WHOLE_CLASS and not quiet:
        sys.stderr.write(f"part {shard} of the class: {len(found)} of {everyone} students\n")
    copies = None
    # on Ray, each worker decides whom student code runs as, and copies it
    ids = None if same_user or backend_name == "ray" else unprivileged_ids()
    if ids is not None:
        check_runtime_readable()
        limits = replace(limits, run_as=ids)
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
            # its runs' wall seconds added up: with --jobs, more than the command's own
            status += " (kept from an earlier run)" if reused else f" ({result.execution_time:.1f} s of runs)"
        sys.stderr.write(f"[{finished}/{total}] {result.student}: {status}\n")

    def slow(student: str, text: str) -> None:
        # no count: the counter numbers submissions as they end, and this one has not
        sys.stderr.write(f"{' ' * len(f'[{total}/{total}]')} {student}: {text}\n")

    cluster = nullcontext()
    if backend_name == "ray":
        from turtletui.grading.ray_backend import RayBackend

        cluster = RayBackend(address, plugins=plugins, same_user=same_user, jobs=jobs)
    try:
        with cluster as backend:
            return grade_submissions(
                plan,
                found,
                store=store,
                jobs=jobs,
                force=force,
                limits=limits,
                plugins=plugins,
                on_result=progress,
                workdir=copies,
                recording_format=recording_format,
                time_limit=time_limit,
                on_progress=None if quiet else slow,
                sole_parent=OWN_PROCESS and backend is None,
                backend=backend,
            )
    finally:
        if copies is not None:
            copies.close()


def check_output(output: Path | None) -> None:
    """Refuse an output path that cannot be written before grading a class, not after."""
    if output is None:
        return
    if output.is_dir():
        raise UsageError(f"cannot write {output}: it is a folder")
    if not output.parent.is_dir():
        raise UsageError(f"cannot write {output}: {output.parent} is not a folder")
    if not os.access(output.parent, os.W_OK | os.X_OK):
        raise UsageError(f"cannot write {output}: permission denied")
    from turtletui.files import cannot_write_in

    why = cannot_write_in(output.parent)
    if why is not None:
        raise UsageError(f"cannot write {output}: {why}")


def write_output(report, fmt: str, output: Path | None, options) -> None:
    """The report in ``fmt`` to ``output`` (atomically), or to the terminal."""
    from turtletui.grading.reports import (
        github_output_line,
        print_table,
        render_report,
        write_report,
    )

    if output is not None:
        write_report(report, fmt, output, options)
    elif fmt == "table":
        print_table(report)
    else:
        sys.stdout.write(render_report(report, fmt, options).rstrip("\n") + "\n")
    for warning in options.warnings:
        sys.stderr.write(f"turtletui: warning: {warning}\n")
    github_output = os.environ.get("GITHUB_OUTPUT")
    if fmt == "github" and github_output:
        try:
            with open(github_output, "a", encoding="utf-8") as file:
                file.write(github_output_line(report) + "\n")
        except OSError as err:
            fail(f"cannot write GITHUB_OUTPUT {github_output}: {err.strerror or err}")


def checks(
    plugin: list[Path] = typer.Option(
        None, "--plugin", metavar="PATH", help="Also load this plugin file or folder (repeatable)."
    ),
) -> None:
    """List the checks a lesson can name, with their thresholds."""
    import shutil
    import textwrap

    from turtletui.grading.engine import available_checks

    width = max(shutil.get_terminal_size().columns, 40)
    for name, check in sorted(available_checks(plugins_of(plugin)).items()):
        params = "?" if check.params is None else ", ".join(check.params) or "none"
        print(name)
        for text in (check.description or "(no description)", f"thresholds: {params}"):
            print(textwrap.fill(text, width, initial_indent="    ", subsequent_indent="    "))
