"""Generate the files that let Gradescope or GitHub Classroom grade a lesson in their
own containers, one submission per container, with ``turtletui grade``.

- Gradescope (https://gradescope-autograders.readthedocs.io/en/latest/specs/): a
  zip with ``setup.sh`` (run once, as root, to build the Ubuntu image) and
  ``run_autograder`` (run per submission from /autograder; the student's upload
  is in /autograder/submission; /autograder/results/results.json is the result).
- GitHub Classroom: ``.github/workflows/classroom.yml`` in the template repository,
  laid out like the workflow Classroom itself generates (workflow "Autograding
  Tests", job ``run-autograding-tests``), ending with
  classroom-resources/autograding-grading-reporter.

The templates are plain strings here, filled with :class:`string.Template`;
every value put in a shell command is quoted with :func:`shlex.quote`.
"""

from __future__ import annotations

import shlex
import shutil
from pathlib import Path
from string import Template

from turtletui.grading.reports import ReportError, write_text_atomic

GRADESCOPE_VENV = "/opt/turtletui"
GRADESCOPE_LESSONS = "/autograder/source/turtletui_lessons"
LESSONS_FOLDER = "turtletui_lessons"
"""Name of the copied lesson folder inside a Gradescope autograder."""
GITHUB_LESSONS = ".github/turtletui_lessons"
"""Where a custom lesson goes in a GitHub Classroom template repository."""
GITHUB_STEP_ID = "turtletui"
"""The grading step's id; the reporter reads its result from ``TURTLETUI_RESULTS``."""


class AutograderError(ValueError):
    """Autograder files that cannot be written; the message is one line."""


_SETUP_SH = Template("""\
#!/usr/bin/env bash
# Gradescope autograder setup for lesson $lesson_id, written by
# `turtletui autograder gradescope`. Gradescope runs it once, as root, while it
# builds the autograder image (Ubuntu 22.04 or newer: turtletui needs Python 3.10+).
set -euo pipefail

export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends python3 python3-venv python3-pip

python3 -m venv $venv
$venv/bin/python -m pip install --upgrade pip
$venv/bin/python -m pip install $requirement
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
set -uo pipefail

submission=/autograder/submission
mkdir -p /autograder/results
$lessons_guard
# Gradescope puts the student's upload in /autograder/submission (a zip comes
# unpacked). A single folder inside it is the submission; a single Python file is
# graded as that file; anything else as the folder (turtletui grade finds the
# controller in it).
shopt -s nullglob dotglob
entries=("$$submission"/*)
if [ "$${#entries[@]}" -eq 1 ] && [ -d "$${entries[0]}" ]; then
    submission="$${entries[0]}"
fi
python_files=("$$submission"/*.py)
shopt -u dotglob
target="$$submission"
if [ "$${#python_files[@]}" -eq 1 ]; then
    target="$${python_files[0]}"
fi

# The student's code runs as user nobody: it must be able to read its own files.
chmod -R a+rX /autograder/submission

# Only the grader writes results.json: turtletui grade replaces it atomically.
exec $venv/bin/turtletui grade "$$target" --lesson $lesson_arg$lessons_arg \\
    --format gradescope --output /autograder/results/results.json
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
   $requirement_text), then run_autograder for each submission.

3. Students upload their controller (one .py file, or several files with the
   controller among them). Each submission is graded in its own container with

       turtletui grade /autograder/submission --lesson $lesson_id --format gradescope

   which writes /autograder/results/results.json. Tests of hidden scenarios are
   shown to students only once you publish the grades ("after_published"); the
   grader's own log (stdout) is for you only.

4. Test it with "Test Autograder" and the lesson's reference controller before
   students submit.
$lessons_note""")

_README_LESSONS = """
The lesson comes from turtletui_lessons/ in this folder (copied from
$source). setup.sh makes that folder readable by root only: the student's
code runs as user nobody and cannot read the hidden scenarios.
"""

_WORKFLOW = Template("""\
# GitHub Classroom autograding for turtletui lesson $lesson_id, written by
# `turtletui autograder github`. Put it in the assignment's template repository
# as .github/workflows/classroom.yml; Classroom runs it on every push.
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
        run: |
          turtletui grade $submission --lesson $lesson_arg$lessons_arg --format github --output "$$RUNNER_TEMP/turtletui-result.txt"
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


def write_gradescope_autograder(
    lesson_id: str,
    out_dir: Path,
    *,
    turtletui_requirement: str,
    lesson_source: Path | None = None,
    force: bool = False,
) -> list[Path]:
    """Write a Gradescope autograder for ``lesson_id`` into ``out_dir``: setup.sh,
    run_autograder (executable), README.txt and, for a lesson of the instructor's
    own, a copy of ``lesson_source`` (a lesson file or folder) in turtletui_lessons/.
    Returns the files written. Existing files are an :class:`AutograderError`
    unless ``force``."""
    _check_lesson_id(lesson_id)
    _check_requirement(turtletui_requirement)
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise AutograderError(f"{out_dir} is a file; name a folder to write the autograder to")
    setup, run, readme = out_dir / "setup.sh", out_dir / "run_autograder", out_dir / "README.txt"
    _refuse_existing([setup, run, readme], force)

    lessons = shlex.quote(GRADESCOPE_LESSONS)
    custom = lesson_source is not None
    setup_text = _SETUP_SH.substitute(
        lesson_id=lesson_id,
        venv=GRADESCOPE_VENV,
        requirement=shlex.quote(turtletui_requirement),
        lessons_setup=_LESSONS_SETUP.substitute(lessons=lessons) if custom else "",
    )
    run_text = _RUN_AUTOGRADER.substitute(
        lesson_id=lesson_id,
        venv=GRADESCOPE_VENV,
        lesson_arg=shlex.quote(lesson_id),
        lessons_arg=f" --lessons {lessons}" if custom else "",
        lessons_guard=_LESSONS_GUARD.substitute(lessons=lessons) if custom else "",
    )
    title = f"turtletui autograder for Gradescope, lesson {lesson_id}"
    readme_text = _README.substitute(
        lesson_id=lesson_id,
        underline="=" * len(title),
        out_dir=shlex.quote(str(out_dir)),
        requirement_text=turtletui_requirement,
        lessons_note=Template(_README_LESSONS).substitute(source=lesson_source)
        if custom
        else "",
    )

    written = []
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
    turtletui_requirement: str,
    lesson_source: Path | None = None,
    submission: str = ".",
    force: bool = False,
) -> list[Path]:
    """Write ``.github/workflows/classroom.yml`` into ``out_dir`` (the template
    repository) to grade ``lesson_id`` on GitHub Classroom; ``submission`` is the
    path graded inside a student's repository (the whole repository by default).
    A lesson of the instructor's own is copied to ``.github/turtletui_lessons``.
    Returns the files written. Existing files are an :class:`AutograderError`
    unless ``force``."""
    _check_lesson_id(lesson_id)
    _check_requirement(turtletui_requirement)
    if not submission.strip() or any(ord(c) < 32 for c in submission):
        raise AutograderError(f"{submission!r} is not a path to grade")
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise AutograderError(f"{out_dir} is a file; name the template repository's folder")
    workflow = out_dir / ".github" / "workflows" / "classroom.yml"
    _refuse_existing([workflow], force)

    custom = lesson_source is not None
    text = _WORKFLOW.substitute(
        lesson_id=lesson_id,
        step_id=GITHUB_STEP_ID,
        env_name=f"{GITHUB_STEP_ID.upper()}_RESULTS",
        requirement=shlex.quote(turtletui_requirement),
        submission=shlex.quote(submission),
        lesson_arg=shlex.quote(lesson_id),
        lessons_arg=f" --lessons {shlex.quote(GITHUB_LESSONS)}" if custom else "",
        lessons_note=_WORKFLOW_LESSONS if custom else "",
    )
    written = []
    if custom:
        written += _copy_lessons(Path(lesson_source), out_dir / GITHUB_LESSONS, force)
    written.append(_write(workflow, text))
    return written
