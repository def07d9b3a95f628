"""Run a lesson's checks on the controller the app is running, as ``turtletui
grade`` would, and describe the result in Markdown for the lesson pane.

Grading runs in a separate process (lockstep, sandboxed, one job), so the app
keeps its 16 ms loop while the scenarios run.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

RUNNING = "## Your checks\n\n*Running the lesson's scenarios...*\n"


def results_dir(lesson: Path) -> Path:
    """Where the app keeps check results and recordings: the user's cache, so
    that ``turtletui replay`` still finds them after the app is closed."""
    cache = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return cache / "turtletui" / "checks" / lesson.stem


def _short(path: str) -> str:
    home = str(Path.home())
    return "~" + path[len(home) :] if path.startswith(home + os.sep) else path


def grade_command(controller: Path, lesson: Path, results: Path) -> list[str]:
    """The ``turtletui grade`` command line for one controller file."""
    return [
        sys.executable,
        "-m",
        "turtletui",
        "grade",
        str(controller),
        "--lesson",
        str(lesson),
        "--format",
        "json",
        "--jobs",
        "1",
        "--quiet",
        "--results",
        str(results),
        # the student grades their own code, as their own user, as the app runs it
        "--same-user",
    ]


def describe(stdout: str, stderr: str, returncode: int) -> str:
    """Markdown for the lesson pane from what ``turtletui grade`` printed."""
    if returncode != 0:
        reason = (stderr.strip().splitlines() or [f"exit status {returncode}"])[-1]
        return f"## Your checks\n\n**The checks could not run:** {reason.removeprefix('turtletui: error: ')}\n"
    try:
        report = json.loads(stdout)
        submission = report["submissions"][0]
    except (ValueError, KeyError, IndexError, TypeError):
        return "## Your checks\n\n**The checks could not run:** the grader's answer was not readable.\n"
    score, top = submission["score"], submission["max_score"]
    lines = ["## Your checks", "", f"**Score: {score:g} / {top:g}**", ""]
    if submission.get("error"):
        lines += [f"**Not graded:** {submission['error']}", ""]
        return "\n".join(lines)
    by_check: dict[str, list[dict]] = {}
    for test in submission["tests"]:
        by_check.setdefault(test["check"], []).append(test)
    for check, tests in by_check.items():
        failed = [t for t in tests if t["status"] != "passed"]
        if not failed:
            lines.append(f"- ✓ `{check}`: passed in all {len(tests)} runs")
            continue
        where = ", ".join(t["scenario"] for t in failed)
        lines.append(f"- ✗ `{check}`: failed in {len(failed)} of {len(tests)} runs ({where})")
        # each line its own quoted paragraph: Markdown would run them together
        lines.append("\n  >\n".join(f"  > {line}" for line in (failed[0].get("output") or "").splitlines()))
    if submission.get("recordings"):
        lines += ["", "Watch a failed run again:", ""]
        lines += [f"- `turtletui replay {_short(path)}`" for path in submission["recordings"]]
    lines += ["", "Press `k` to run the checks again after you change your file."]
    return "\n".join(lines) + "\n"
