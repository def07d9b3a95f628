"""Run a lesson's checks on the controller the app is running, as ``turtletui
grade`` would, and describe the result in Markdown for the lesson pane.

Grading runs in another process (lockstep, sandboxed), so the app keeps its
16 ms loop while the scenarios run. That process is this module's
:func:`main`: it prints one JSON line per finished scenario run
(``{"run": {...}}``) and then the report (``{"report": {...}}``), so the app
shows progress as it goes.

It leaves one CPU to the app: with two CPUs it runs the scenarios one after
the other on the other CPU, without polling for the controller's answers (a
reader that polls takes the CPU its controller needs: on a busy two-core
machine the Part 6 checks took three to four times as long that way).
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from turtletui.grading.results import NOT_JUDGED
from turtletui.messages import plural

RUNNING = "## Your checks\n\n*Running the lesson's scenarios...*\n"


def results_dir(lesson: Path) -> Path:
    """Where the app keeps check results and recordings: the user's cache, so
    that ``turtletui replay`` still finds them after the app is closed."""
    cache = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return cache / "turtletui" / "checks" / lesson.stem


def _short(path: str) -> str:
    home = str(Path.home())
    return "~" + path[len(home) :] if path.startswith(home + os.sep) else path


def check_command(controller: Path, lesson: Path, results: Path) -> list[str]:
    """The command line of the check process for one controller file."""
    return [sys.executable, "-m", "turtletui.tui.lesson_checks", str(controller), str(lesson), str(results)]


# -- the check process ------------------------------------------------------------------

def main(argv: Sequence[str] | None = None) -> int:
    """Grade ``CONTROLLER LESSON RESULTS`` as ``turtletui grade --same-user``
    does (the student checks their own code, as their own user), printing
    progress and the report as JSON lines."""
    args = list(sys.argv[1:] if argv is None else argv)
    if len(args) != 3:
        _emit({"error": "usage: python -m turtletui.tui.lesson_checks CONTROLLER LESSON RESULTS"})
        return 2
    controller, lesson, results = map(Path, args)
    jobs = _leave_a_cpu_to_the_app()
    try:
        return _grade(controller, lesson, results, jobs)
    except KeyboardInterrupt:
        return 130


def _leave_a_cpu_to_the_app() -> int:
    """Scenario runs side by side: one per CPU but one. With one left, that
    CPU is this process's alone and nothing polls (see the module docstring)."""
    try:
        cpus = sorted(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return max(1, (os.cpu_count() or 1) - 1)
    if len(cpus) > 2:
        return len(cpus) - 1
    os.environ["TURTLETUI_SPIN_SECONDS"] = "0"  # read as each sandbox starts (wire.default_spin_seconds)
    try:
        os.sched_setaffinity(0, {cpus[-1]})
    except OSError:
        pass
    return 1


def _grade(controller: Path, lesson_path: Path, results: Path, jobs: int) -> int:
    from turtletui.grading.batch import ResultStore, grade_submissions, store_key
    from turtletui.grading.engine import GradingError, prepare
    from turtletui.grading.reports import render_json
    from turtletui.grading.submissions import SubmissionError, find_submissions
    from turtletui.lessons.loader import LessonError, load_lesson
    from turtletui.runtime.sandbox import Limits

    try:
        plan = prepare(load_lesson(lesson_path))
        found = find_submissions([controller], starter=plan.lesson.starter)
        store = ResultStore(results, store_key(plan))
    except (LessonError, GradingError, SubmissionError, OSError) as err:
        _emit({"error": " ".join(str(err).split())})
        return 2
    finished = 0

    def on_run(student: str, outcome) -> None:
        nonlocal finished
        finished += 1
        run = plan.runs[outcome.run_index]
        passed = all(test.status == "passed" for _, test in outcome.tests)
        _emit({"run": {"done": finished, "of": len(plan.runs), "scenario": run.label, "passed": passed}})

    report = grade_submissions(plan, found, store=store, jobs=jobs, limits=Limits(), on_run=on_run)
    _emit({"report": json.loads(render_json(report))})
    return 0


def _emit(event: dict) -> None:
    sys.stdout.write(json.dumps(event) + "\n")
    sys.stdout.flush()


# -- the app's side -------------------------------------------------------------------

async def stop(process) -> None:
    """Stop a check process (an asyncio subprocess) as Ctrl-C stops ``turtletui
    grade``: its sandboxed runs are closed on the way out; killed if it lingers."""
    import asyncio
    import signal

    try:
        process.send_signal(signal.SIGINT)
        await asyncio.wait_for(process.wait(), timeout=3.0)
    except ProcessLookupError:
        pass
    except asyncio.TimeoutError:
        process.kill()
        await process.wait()


@dataclass
class CheckProgress:
    """What the check process said so far, read line by line."""

    done: int = 0
    of: int = 0
    runs: list[tuple[str, bool]] = field(default_factory=list)
    """(scenario, passed) of every finished run, in order."""
    report: dict | None = None
    error: str | None = None
    other: list[str] = field(default_factory=list)
    """Lines that were not events (a warning, a traceback's last line)."""

    def feed(self, line: str) -> bool:
        """Take one line of the process's output; True if the progress changed."""
        line = line.strip()
        if not line:
            return False
        try:
            event = json.loads(line)
        except ValueError:
            event = None
        if not isinstance(event, dict):
            self.other.append(line)
            return False
        if isinstance(event.get("run"), dict):
            run = event["run"]
            self.done, self.of = int(run.get("done", 0)), int(run.get("of", 0))
            self.runs.append((str(run.get("scenario", "?")), bool(run.get("passed"))))
            return True
        if isinstance(event.get("report"), dict):
            self.report = event["report"]
        elif "error" in event:
            self.error = str(event["error"])
        return True

    def running(self) -> str:
        """Markdown for the pane while the checks run."""
        if not self.of:
            return RUNNING
        marks = " ".join(f"{'✓' if ok else '✗'} {name}" for name, ok in self.runs)
        return f"## Your checks\n\n*Running the lesson's scenarios: {self.done} of {self.of} done*\n\n{marks}\n"

    def result(self, returncode: int) -> str:
        """Markdown for the pane once the process ended."""
        if self.report is not None and returncode == 0:
            return describe_report(self.report)
        reason = self.error or (self.other[-1] if self.other else f"exit status {returncode}")
        return f"## Your checks\n\n**The checks could not run:** {reason.removeprefix('turtletui: error: ')}\n"


def graded_score(report: dict) -> tuple[str, float, float] | None:
    """(lesson id, score, max score) of a report's one graded submission, or
    None when it was not graded."""
    try:
        submission = report["submissions"][0]
        if submission.get("error"):
            return None
        return str(report["lesson"]), float(submission["score"]), float(submission["max_score"])
    except (KeyError, IndexError, TypeError, ValueError):
        return None


def _where(tests: list[dict]) -> str:
    return "; ".join(t["scenario"] for t in tests)


_UNREADABLE = "## Your checks\n\n**The checks could not run:** the grader's answer was not readable.\n"


def describe_report(report: dict) -> str:
    """Markdown for the lesson pane from a grade report (as JSON data)."""
    try:
        submission = report["submissions"][0]
        score, top = submission["score"], submission["max_score"]
        lines = ["## Your checks", "", f"**Score: {score:g} / {top:g}**", ""]
        if submission.get("error"):
            lines += [f"**Not graded:** {submission['error']}", ""]
            return "\n".join(lines)
        tests = submission["tests"]
    except (KeyError, IndexError, TypeError):
        return _UNREADABLE
    by_check: dict[str, list[dict]] = {}
    for test in tests:
        by_check.setdefault(test["check"], []).append(test)
    for check, group in by_check.items():
        failed = [t for t in group if t["status"] != "passed"]
        if not failed:
            lines.append(f"- ✓ `{check}`: passed in {'its only run' if len(group) == 1 else f'all {len(group)} runs'}")
            continue
        unjudged = [t for t in failed if str(t.get("output", "")).startswith(NOT_JUDGED)]
        judged = [t for t in failed if t not in unjudged]
        runs = plural(len(group), "run")
        if judged:
            line = f"- ✗ `{check}`: failed in {len(judged)} of {runs} ({_where(judged)})"
            if unjudged:
                line += f", not judged in {len(unjudged)} ({_where(unjudged)})"
        else:
            line = f"- – `{check}`: not judged in {len(unjudged)} of {runs} ({_where(unjudged)})"
        lines.append(line)
        # what a run where it failed measured, not why another was not judged;
        # each line its own quoted paragraph: Markdown would run them together
        first = (judged or unjudged)[0]
        lines.append("\n  >\n".join(f"  > {text}" for text in (first.get("output") or "").splitlines()))
    if submission.get("recordings"):
        lines += ["", "Watch a failed run again:", ""]
        lines += [f"- `turtletui replay {_short(path)}`" for path in submission["recordings"]]
    lines += ["", "Press `k` to run the checks again after you change your file."]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
