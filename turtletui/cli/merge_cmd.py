"""``turtletui grade merge DIR...``: one report from the results folders of a
class graded in parts (``turtletui grade ... --shard K/N`` on N machines).

Exit status: 0 when the report is written, 1 when a score is below
``--fail-under``, 2 for folders that cannot be merged (a signature that does
not hold, parts graded differently, a part given twice) and for students
without a result (unless ``--allow-missing``), 3 for an internal error.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import typer
from typer.core import TyperCommand

from turtletui.cli.errors import fail
from turtletui.cli.grade_cmd import (
    check_output,
    check_report_options,
    exit_if_below,
    read_roster_option,
    write_output,
)


def merge(
    folders: list[Path] = typer.Argument(
        ..., metavar="DIR", help="The --results folder of each part (each holds a class.manifest)."
    ),
    fmt: str = typer.Option("table", "--format", metavar="FORMAT", help="As turtletui grade's --format."),
    output: Path = typer.Option(None, "--output", "-o", metavar="PATH", help="Write the report here (atomically)."),
    allow_missing: bool = typer.Option(
        False, "--allow-missing", help="Write the report without the students that have no result (they are named on stderr)."
    ),
    fail_under: float = typer.Option(
        None, "--fail-under", metavar="SCORE", help="Exit 1 if any submission scores fewer points."
    ),
    roster: Path = typer.Option(
        None, "--roster", metavar="CSV", help="canvas, moodle: the class list exported from the LMS."
    ),
    hidden_tests: str = typer.Option(
        "summary", "--hidden-tests", metavar="HOW", help="gradescope: as turtletui grade's --hidden-tests."
    ),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="No summary line on stderr."),
) -> None:
    """Write one report from the results of a class graded in parts, as one
    machine grading it all would write it. Every part and the merge share the
    results key ($TURTLETUI_RESULTS_KEY)."""
    from turtletui.grading.merge import merge_results
    from turtletui.grading.reports import ReportOptions

    check_report_options(fmt, roster, hidden_tests)
    try:
        options = ReportOptions(roster=read_roster_option(roster), hidden=hidden_tests)
        check_output(output)
        merged = merge_results(folders)
        if merged.missing and not allow_missing:
            fail(f"{merged.missing_line()}; merge every part's folder, or --allow-missing for a report without them")
        write_output(merged.report, fmt, output, options)
    except (ValueError, OSError) as err:
        fail(str(err).splitlines()[0] if str(err) else type(err).__name__)
    if merged.missing:
        sys.stderr.write(f"turtletui: warning: {merged.missing_line()}\n")
    if not quiet:
        parts = ", ".join(str(part.manifest.shard) for part in sorted(merged.parts, key=lambda p: p.manifest.shard.index))
        students = len(merged.parts[0].manifest.members)
        sys.stderr.write(
            f"merged part{'s' if len(merged.parts) != 1 else ''} {parts}: "
            f"{len(merged.report.submissions)} of {students} students\n"
        )
    exit_if_below(merged.report, fail_under)


class GradeCommand(TyperCommand):
    """``turtletui grade``, whose first argument ``merge`` names its
    subcommand instead (write ``./merge`` to grade a folder called merge)."""

    def make_context(
        self, info_name: str | None, args: list[str], parent: Any = None, **extra: Any
    ) -> Any:
        if args[:1] == ["merge"]:
            if "--lesson" in args:
                fail("grade merge puts results folders together and takes no --lesson; to grade a folder named merge, write ./merge")
            command = typer.main.get_command(_merge_app)
            return command.make_context(f"{info_name} merge", args[1:], parent=parent, **extra)
        return super().make_context(info_name, args, parent=parent, **extra)


_merge_app = typer.Typer(add_completion=False, pretty_exceptions_enable=False, rich_markup_mode=None)
_merge_app.command("merge")(merge)
