"""Generate the files that let Gradescope, Classroom 50 or GitHub Classroom grade a
lesson in their own containers, one submission per container, with ``turtletui grade``.

Every bundle carries a wheel of the turtletui that wrote it (see
:mod:`turtletui.grading.wheel`) and installs it, with its dependencies from the
package index; an instructor may name a pip requirement instead.

- Gradescope (https://gradescope-autograders.readthedocs.io/en/latest/specs/): a
  zip with ``setup.sh`` (run once, as root, to build the Ubuntu 22.04 image with
  its Python 3.10) and ``run_autograder`` (run per submission from /autograder;
  the student's upload is in /autograder/submission). run_autograder always
  leaves /autograder/results/results.json: an upload that cannot be graded
  scores 0 with the reason, and grading that fails or outlives its time budget
  (set below the platform's timeout) leaves 0 with a message.
- Classroom 50: ``autograder.py`` for CLASSROOM/autograders/ASSIGNMENT/ (the
  runner calls it in the student's checkout and reads ./result.json), and a
  workflow that runs the same grading in any repository.
- GitHub Classroom (retired on 2026-08-28; for repositories still set up for
  it): ``.github/workflows/classroom.yml`` in the template repository, laid out
  like the workflow Classroom itself generated (workflow "Autograding Tests", job
  ``run-autograding-tests``), ending with classroom-resources/autograding-grading-reporter.

The templates are plain strings here, filled with :class:`string.Template`;
every value put in a shell command is quoted with :func:`shlex.quote`.
"""

from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path
from string import Template

from turtletui.errors import TurtletuiError
from turtletui.grading.reports import ReportError, write_text_atomic

GRADESCOPE_VENV = "/opt/turtletui"
GRADESCOPE_SOURCE = "/autograder/source"
GRADESCOPE_LESSONS = "/autograder/source/turtletui_lessons"
GRADESCOPE_TIME_LIMIT = 540
"""Seconds run_autograder lets grading take by default: below Gradescope's
default autograder timeout of 10 minutes, with time left to write the result."""
LESSONS_FOLDER = "turtletui_lessons"
"""Name of the copied lesson folder inside a Gradescope autograder."""
GITHUB_LESSONS = ".github/turtletui_lessons"
"""Where a custom lesson goes in a GitHub Classroom template repository."""
GITHUB_WHEELS = ".github/turtletui"
"""Where turtletui's wheel goes in a GitHub Classroom template repository."""
GITHUB_STEP_ID = "turtletui"
"""The grading step's id; the reporter reads its result from ``TURTLETUI_RESULTS``."""


class AutograderError(TurtletuiError, ValueError):
    """Autograder files that cannot be written; the message is one line."""


_SETUP_SH = Template("""\
#!/usr/bin/env bash
# Gradescope autograder setup for lesson $lesson_id, written by
# `turtletui autograder gradescope`. Gradescope runs it once, as root, while it
# builds the autograder image (Ubuntu 22.04 or newer: turtletui needs Python 3.10+).
set -euo pipefail

if ! python3 -c 'import sys, venv, ensurepip; sys.exit(sys.version_info < (3, 10))' 2>/dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends python3 python3-venv python3-pip
fi
python3 -c 'import sys; sys.exit(0 if sys.version_info >= (3, 10) else "turtletui needs Python 3.10 or newer: choose an Ubuntu 22.04 (or newer) base image")'

python3 -m venv $venv
$venv/bin/python -m pip install --upgrade pip
$venv/bin/python -m pip install $requirement
$venv/bin/turtletui --version
$lessons_setup""")

_LESSONS_SETUP = Template("""
# The lesson folder holds the hidden scenarios. turtletui grade runs as root and
# runs the student's controller as user nobody: only root may read the lessons.
chown -R root:root $lessons
chmod -R go-rwx $lessons
chmod 700 $lessons
""")

_RUN_AUTOGRADER = Template("""\
#!/usr/bin/env bash
# Gradescope runs this for every submission, as root, from /autograder. Written by
# `turtletui autograder gradescope` for lesson $lesson_id.
# It always leaves /autograder/results/results.json: Gradescope shows "the
# autograder failed" for a run without one.
set -uo pipefail

results=/autograder/results/results.json
mkdir -p /autograder/results
$lessons_guard
# A result of 0 with a message, for when grading itself could not finish.
fail() {
    local message="$$1"
    if ! MESSAGE="$$message" python3 -c 'import json, os, sys
json.dump({"score": 0.0, "output": os.environ["MESSAGE"], "visibility": "visible",
           "stdout_visibility": "hidden", "tests": []}, open(sys.argv[1], "w"))' "$$results"; then
        printf '{"score": 0.0, "output": "The autograder failed; ask your instructor.", "tests": []}' > "$$results"
    fi
}

# The student's code runs as user nobody: it must be able to read its own files.
chmod -R a+rX /autograder/submission 2>/dev/null
errors=$$(mktemp)
# The whole upload is one submission, whatever its layout (a file, a folder, a
# ROS 2 package, a workspace); turtletui grade finds the controller in it and
# writes results.json atomically, also for an upload it cannot grade.
timeout --signal=TERM --kill-after=20 $time_limit \\
    $venv/bin/turtletui grade /autograder/submission --lesson $lesson_arg$lessons_arg$executable_arg \\
    --format gradescope --hidden-tests $hidden --results "$$(mktemp -d)" \\
    --output "$$results" 2>"$$errors"
status=$$?
cat "$$errors" >&2
if [ "$$status" -eq 124 ] || [ "$$status" -eq 137 ]; then
    fail "Grading took longer than $time_limit seconds and was stopped: does your controller keep the simulation waiting? Your score is 0; resubmit, or ask your instructor."
elif [ "$$status" -ne 0 ] || [ ! -s "$$results" ]; then
    fail "The autograder could not grade this submission (exit status $$status): $$(tail -n 1 "$$errors" | cut -c1-500)"
fi
exit 0
""")

_LESSONS_GUARD = Template("""
# Again at every run, in case the image was rebuilt without setup.sh's chmod.
chmod -R go-rwx $lessons
""")

_README = Template("""\
turtletui autograder for Gradescope, lesson $lesson_id
$underline

1. Zip the files in this folder, not the folder itself (setup.sh and
   run_autograder must be at the root of the zip):

       cd $out_dir && zip -r ../turtletui-$lesson_id.zip .

2. In Gradescope, create a "Programming Assignment", open "Configure
   Autograder", choose an Ubuntu 22.04 (or newer) base image and upload the zip.
   Gradescope runs setup.sh once to build the image (it installs
   $requirement_text and its dependencies from PyPI), then run_autograder for
   each submission. Keep the autograder timeout above $time_limit seconds (the
   default, 10 minutes, is): run_autograder stops grading after $time_limit s and
   reports 0 with a message, instead of leaving no result.

3. Students upload their controller: one .py file, a folder, their ROS 2 package
   (e.g. my_robot_controller, with setup.py) or a workspace with src/. Each
   upload is graded in its own container with

       turtletui grade /autograder/submission --lesson $lesson_id --format gradescope$executable_arg

   which writes /autograder/results/results.json, naming the file and executable
   it graded. An upload that cannot be graded (empty, no controller, several
   possible ones) scores 0 with the reason. $hidden_text Failed
   runs come with a picture of the turtle's path. The grader's own log (stdout)
   is for you only.

4. Test it with "Test Autograder" and the lesson's reference controller before
   students submit.
$lessons_note""")

_HIDDEN_TEXT = {
    "summary": "Hidden scenarios show as one test (\"hidden scenarios: 2 of 3 passed\") without details, so students see their total.",
    "after_published": "Tests of hidden scenarios show once you publish grades; until then Gradescope hides the student's total.",
    "after_due_date": "Tests of hidden scenarios show after the due date; until then Gradescope hides the student's total.",
    "hidden": "Tests of hidden scenarios never show; Gradescope then hides the student's total.",
    "visible": "Tests of hidden scenarios show at once (their feedback has no measurements).",
}

_README_LESSONS = """
The lesson comes from turtletui_lessons/ in this folder (copied from
$source). setup.sh makes that folder readable by root only: the student's
code runs as user nobody and cannot read the hidden scenarios.
"""

_WORKFLOW = Template("""\
# GitHub Classroom autograding for turtletui lesson $lesson_id, written by
# `turtletui autograder github`. Put it in the assignment's template repository
# as .github/workflows/classroom.yml; Classroom runs it on every push.
# GitHub Classroom was retired on 2026-08-28: this is for repositories still set
# up for it. New courses: `turtletui autograder classroom50`.
#
# The layout follows the workflow GitHub Classroom generates itself: workflow
# "Autograding Tests", job run-autograding-tests, skipped for the Classroom bot.
# The last step is classroom-resources/autograding-grading-reporter. For each id
# in its `runners` input it reads the environment variable named after the id,
# upper-cased, plus "_RESULTS" (src/main.js of that action), decodes it from
# base64 and adds up the tests' scores (src/notify-classroom.js). The grading step
# (id "$step_id") sets that output: `turtletui grade --format github` appends
# result=<base64 JSON> to $$GITHUB_OUTPUT.
$lessons_note
name: Autograding Tests
"on":
  - push
  - repository_dispatch
  - workflow_dispatch
permissions:
  checks: write
  actions: read
  contents: read
jobs:
  run-autograding-tests:
    runs-on: ubuntu-latest
    if: github.actor != 'github-classroom[bot]'
    timeout-minutes: 30
    steps:
      - name: Checkout code
        uses: actions/checkout@v4
      - name: Set up Python
        uses: actions/setup-python@v5
        with:
          python-version: "3.12"
      - name: Install turtletui
        run: |
          python -m pip install --upgrade pip
          python -m pip install $requirement
      - name: Grade with turtletui
        id: $step_id
        # Results are kept outside the student's checkout and signed with a key
        # made for this job: nothing in the repository can pass for a result.
        run: |
          export TURTLETUI_RESULTS_KEY="$$(python -c 'import secrets; print(secrets.token_hex(32))')"
          turtletui grade $submission --lesson $lesson_arg$lessons_arg$executable_arg --format github --results "$$RUNNER_TEMP/turtletui-grades" --output "$$RUNNER_TEMP/turtletui-result.txt"
      - name: Autograding Reporter
        # Report even when the grading step failed: the output carries the score.
        if: $${{ !cancelled() }}
        uses: classroom-resources/autograding-grading-reporter@v1
        env:
          $env_name: "$${{ steps.$step_id.outputs.result }}"
        with:
          runners: $step_id
""")

_WORKFLOW_LESSONS = """#
# The lesson comes from .github/turtletui_lessons/ in this repository. Students can
# read it, hidden scenarios included: a student's repository is theirs. Grade on
# Gradescope when the hidden scenarios must stay secret.
"""


# -- helpers --------------------------------------------------------------------------


def _check_lesson_id(lesson_id: str) -> None:
    from turtletui.lessons.loader import ID_PATTERN

    if not ID_PATTERN.fullmatch(lesson_id):
        raise AutograderError(
            f"{lesson_id!r} is not a lesson id (lowercase letters, digits and '-')"
        )


def _check_requirement(requirement: str) -> None:
    if not requirement.strip() or any(ord(c) < 32 for c in requirement):
        raise AutograderError(f"{requirement!r} is not a pip requirement for turtletui")


def _refuse_existing(paths: list[Path], force: bool) -> None:
    if force:
        return
    for path in paths:
        if path.exists():
            raise AutograderError(f"{path} already exists; use --force to overwrite it")


def _lesson_files(source: Path) -> list[tuple[Path, Path]]:
    """(file to copy, path relative to the lesson folder) for a lesson file or folder."""
    if source.is_file():
        return [(source, Path(source.name))]
    if not source.is_dir():
        raise AutograderError(f"{source}: no such lesson file or folder")
    files = []
    for path in sorted(source.rglob("*")):
        relative = path.relative_to(source)
        if any(part.startswith(".") or part == "__pycache__" for part in relative.parts):
            continue
        if path.is_file():
            files.append((path, relative))
    return files


def _copy_lessons(source: Path, dest: Path, force: bool) -> list[Path]:
    """Copy a lesson file or folder into ``dest`` and return the files written."""
    source_real, dest_real = source.resolve(), dest.resolve()
    if dest_real == source_real or source_real in dest_real.parents or (
        dest_real in source_real.parents
    ):
        raise AutograderError(
            f"cannot copy the lessons {source} into {dest}: one contains the other; "
            f"choose another output folder"
        )
    files = _lesson_files(source)
    _refuse_existing([dest / rel for _, rel in files], force)
    written = []
    for path, relative in files:
        target = dest / relative
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(path, target)
        except OSError as err:
            raise AutograderError(f"cannot copy {path} to {target}: {err.strerror or err}") from err
        written.append(target)
    return written


def _write(path: Path, text: str, mode: int = 0o644) -> Path:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text_atomic(path, text)
        path.chmod(mode)
    except ReportError as err:
        raise AutograderError(str(err)) from err
    except OSError as err:
        raise AutograderError(f"cannot write {path}: {err.strerror or err}") from err
    return path


# -- gradescope -----------------------------------------------------------------------


def _install_source(out_dir: Path, requirement: str | None, wheel: Path | None, force: bool) -> tuple[str, str, list[Path]]:
    """What pip installs (quoted for the shell, relative to the bundle), how the
    README names it, and the files copied for it (the wheel)."""
    if (requirement is None) == (wheel is None):
        raise AutograderError("name either a pip requirement or a wheel of turtletui to install")
    if requirement is not None:
        _check_requirement(requirement)
        return shlex.quote(requirement), requirement, []
    assert wheel is not None
    target = out_dir / wheel.name
    _refuse_existing([target], force)
    if target.resolve() != wheel.resolve():
        try:
            out_dir.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(wheel, target)
        except OSError as err:
            raise AutograderError(f"cannot copy {wheel} to {target}: {err.strerror or err}") from err
    return "", f"{wheel.name} (turtletui itself, in this folder)", [target]


def write_gradescope_autograder(
    lesson_id: str,
    out_dir: Path,
    *,
    turtletui_requirement: str | None = None,
    wheel: Path | None = None,
    lesson_source: Path | None = None,
    executable: str | None = None,
    hidden_tests: str = "summary",
    time_limit: int = GRADESCOPE_TIME_LIMIT,
    force: bool = False,
) -> list[Path]:
    """Write a Gradescope autograder for ``lesson_id`` into ``out_dir``: setup.sh,
    run_autograder (executable), README.txt, turtletui's ``wheel`` (or setup.sh
    installs ``turtletui_requirement``) and, for a lesson of the instructor's own,
    a copy of ``lesson_source`` (a lesson file or folder) in turtletui_lessons/.
    ``executable`` picks the node in a ROS package upload; ``hidden_tests`` says how
    hidden scenarios show; grading stops after ``time_limit`` seconds. Returns the
    files written. Existing files are an :class:`AutograderError` unless ``force``."""
    _check_lesson_id(lesson_id)
    if hidden_tests not in _HIDDEN_TEXT:
        raise AutograderError(f"hidden tests: {hidden_tests!r}; choose one of {', '.join(_HIDDEN_TEXT)}")
    if executable is not None and not re.fullmatch(r"[A-Za-z0-9_.\-/ ]+", executable):
        raise AutograderError(f"{executable!r} is not an executable's name")
    if not 10 <= time_limit <= 24 * 3600:
        raise AutograderError(f"time limit {time_limit} s: choose between 10 s and a day")
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise AutograderError(f"{out_dir} is a file; name a folder to write the autograder to")
    setup, run, readme = out_dir / "setup.sh", out_dir / "run_autograder", out_dir / "README.txt"
    _refuse_existing([setup, run, readme], force)

    lessons = shlex.quote(GRADESCOPE_LESSONS)
    custom = lesson_source is not None
    written = []
    if custom:
        _refuse_existing([out_dir / LESSONS_FOLDER / rel for _, rel in _lesson_files(Path(lesson_source))], force)
    requirement, requirement_text, copied = _install_source(out_dir, turtletui_requirement, wheel, force)
    written += copied
    if not requirement:
        requirement = shlex.quote(f"{GRADESCOPE_SOURCE}/{copied[0].name}")
    executable_arg = f" --executable {shlex.quote(executable)}" if executable else ""
    setup_text = _SETUP_SH.substitute(
        lesson_id=lesson_id,
        venv=GRADESCOPE_VENV,
        requirement=requirement,
        lessons_setup=_LESSONS_SETUP.substitute(lessons=lessons) if custom else "",
    )
    run_text = _RUN_AUTOGRADER.substitute(
        lesson_id=lesson_id,
        venv=GRADESCOPE_VENV,
        lesson_arg=shlex.quote(lesson_id),
        lessons_arg=f" --lessons {lessons}" if custom else "",
        executable_arg=executable_arg,
        hidden=hidden_tests,
        time_limit=time_limit,
        lessons_guard=_LESSONS_GUARD.substitute(lessons=lessons) if custom else "",
    )
    title = f"turtletui autograder for Gradescope, lesson {lesson_id}"
    readme_text = _README.substitute(
        lesson_id=lesson_id,
        underline="=" * len(title),
        out_dir=shlex.quote(str(out_dir)),
        requirement_text=requirement_text,
        time_limit=time_limit,
        executable_arg=executable_arg,
        hidden_text=_HIDDEN_TEXT[hidden_tests],
        lessons_note=Template(_README_LESSONS).substitute(source=lesson_source)
        if custom
        else "",
    )

    if custom:
        written += _copy_lessons(Path(lesson_source), out_dir / LESSONS_FOLDER, force)
    written.append(_write(setup, setup_text, 0o755))
    written.append(_write(run, run_text, 0o755))
    written.append(_write(readme, readme_text))
    return written


# -- github classroom --------------------------------------------------------------------


def write_github_workflow(
    lesson_id: str,
    out_dir: Path,
    *,
    turtletui_requirement: str | None = None,
    wheel: Path | None = None,
    lesson_source: Path | None = None,
    submission: str = ".",
    executable: str | None = None,
    force: bool = False,
) -> list[Path]:
    """Write ``.github/workflows/classroom.yml`` into ``out_dir`` (the template
    repository) to grade ``lesson_id`` on GitHub Classroom (retired 2026-08-28);
    ``submission`` is the path graded inside a student's repository (the whole
    repository by default). turtletui's ``wheel`` goes to ``.github/turtletui/``
    (or the workflow installs ``turtletui_requirement``); a lesson of the
    instructor's own is copied to ``.github/turtletui_lessons``. Returns the
    files written. Existing files are an :class:`AutograderError` unless ``force``."""
    _check_lesson_id(lesson_id)
    if not submission.strip() or any(ord(c) < 32 for c in submission):
        raise AutograderError(f"{submission!r} is not a path to grade")
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise AutograderError(f"{out_dir} is a file; name the template repository's folder")
    workflow = out_dir / ".github" / "workflows" / "classroom.yml"
    _refuse_existing([workflow], force)
    requirement, _, copied = _install_source(out_dir / GITHUB_WHEELS, turtletui_requirement, wheel, force)
    if not requirement:
        requirement = shlex.quote(f"{GITHUB_WHEELS}/{copied[0].name}")

    custom = lesson_source is not None
    text = _WORKFLOW.substitute(
        lesson_id=lesson_id,
        step_id=GITHUB_STEP_ID,
        env_name=f"{GITHUB_STEP_ID.upper()}_RESULTS",
        requirement=requirement,
        submission=shlex.quote(submission),
        lesson_arg=shlex.quote(lesson_id),
        lessons_arg=f" --lessons {shlex.quote(GITHUB_LESSONS)}" if custom else "",
        executable_arg=f" --executable {shlex.quote(executable)}" if executable else "",
        lessons_note=_WORKFLOW_LESSONS if custom else "",
    )
    written = list(copied)
    if custom:
        written += _copy_lessons(Path(lesson_source), out_dir / GITHUB_LESSONS, force)
    written.append(_write(workflow, text))
    return written
