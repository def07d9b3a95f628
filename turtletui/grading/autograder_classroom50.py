"""Generate a Classroom 50 autograder for a lesson: ``autograder.py`` for the
assignment's folder CLASSROOM/autograders/ASSIGNMENT/ in the teacher's
classroom50 repository, turtletui's wheel beside it, and a GitHub Actions
workflow that runs the same grading in any repository.

The contract (foundation50/classroom50 wiki, "Advanced Autograding"): the
runner calls autograder.py in the student's checkout with CLASSROOM,
ASSIGNMENT, SUBMISSION_TAG, COMMIT_URL, RELEASE_URL, REVIEW_URL set, and reads
./result.json; a non-zero exit is an infrastructure error. autograder.py
always writes result.json and exits 0.
"""

from __future__ import annotations

from pathlib import Path
from string import Template

from turtletui.grading.autograder import (
    GRADESCOPE_TIME_LIMIT,
    LESSONS_FOLDER,
    AutograderError,
    _check_lesson_id,
    _copy_lessons,
    _install_source,
    _refuse_existing,
    _write,
)

_AUTOGRADER = Template('''\
"""Classroom 50 autograder for turtletui lesson $lesson_id, written by
`turtletui autograder classroom50`. The runner calls it in the student's checkout
and reads ./result.json (schema classroom50/result/v1). It installs turtletui
from the wheel next to it, grades the checkout sandboxed, and always leaves a
result.json."""

import datetime
import json
import os
import secrets
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REQUIREMENT = $requirement
LESSON = $lesson
LESSONS = $lessons
EXECUTABLE = $executable
TIME_LIMIT = $time_limit


def fallback(message):
    """A result of 0 that says why, for when grading could not finish."""
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    result = {"schema": "classroom50/result/v1", "datetime": now, "graded_at": now}
    for field, variable in (("classroom", "CLASSROOM"), ("assignment", "ASSIGNMENT"),
                            ("submission", "SUBMISSION_TAG"), ("commit", "COMMIT_URL"),
                            ("release", "RELEASE_URL"), ("review", "REVIEW_URL")):
        if os.environ.get(variable):
            result[field] = os.environ[variable]
    if "commit" in result:
        result.setdefault("review", result["commit"])
    result.update({"score": 0, "max-score": 0, "tests": [
        {"test-name": "grading", "passed": False, "score": 0, "max-score": 0, "message": message}]})
    Path("result.json").write_text(json.dumps(result, indent=2))


def main():
    target = str(HERE / REQUIREMENT) if REQUIREMENT.endswith(".whl") else REQUIREMENT
    if subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", target]).returncode != 0:
        fallback("turtletui could not be installed; ask your instructor.")
        return 0
    # Results are kept outside the checkout, signed with a key made for this job.
    env = dict(os.environ, TURTLETUI_RESULTS_KEY=secrets.token_hex(32))
    work = tempfile.mkdtemp(prefix="turtletui-")
    command = [sys.executable, "-m", "turtletui", "grade", ".", "--lesson", LESSON,
               "--format", "classroom50", "--output", "result.json", "--results", work]
    if LESSONS:
        command += ["--lessons", str(HERE / LESSONS)]
    if EXECUTABLE:
        command += ["--executable", EXECUTABLE]
    try:
        graded = subprocess.run(command, env=env, stderr=subprocess.PIPE, text=True, timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        fallback(f"Grading took longer than {TIME_LIMIT} seconds and was stopped.")
        return 0
    sys.stderr.write(graded.stderr)
    if graded.returncode != 0 or not Path("result.json").is_file():
        last = (graded.stderr.strip().splitlines() or ["no result"])[-1]
        fallback(f"The autograder could not grade this submission: {last}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
''')

_WORKFLOW = Template("""\
# Grades lesson $lesson_id with turtletui on every push, as Classroom 50's runner
# would, and keeps result.json (classroom50/result/v1) as an artifact. Written by
# `turtletui autograder classroom50`. Classroom 50 itself needs only the folder's
# autograder.py: use this workflow to try the autograder in the template
# repository, or to grade a repository outside Classroom 50 (with the folder
# copied to .classroom50/ there).
name: turtletui autograding
"on":
  - push
  - workflow_dispatch
permissions:
  contents: read
jobs:
  grade:
    runs-on: ubuntu-latest
    timeout-minutes: 20
    steps:
      - name: Checkout code
        uses: actions/checkout@v4
      - name: Set up Python
        uses: actions/setup-python@v5
        with:
          python-version: "3.12"
      - name: Grade with turtletui
        env:
          CLASSROOM: local
          ASSIGNMENT: $lesson_id
          SUBMISSION_TAG: "submit/$${{ github.sha }}"
          COMMIT_URL: "$${{ github.server_url }}/$${{ github.repository }}/commit/$${{ github.sha }}"
          RELEASE_URL: "$${{ github.server_url }}/$${{ github.repository }}/actions/runs/$${{ github.run_id }}"
        run: python .classroom50/autograder.py
      - name: Keep result.json
        if: $${{ !cancelled() }}
        uses: actions/upload-artifact@v4
        with:
          name: result
          path: result.json
""")

_README = Template("""\
turtletui autograder for Classroom 50, lesson $lesson_id
$underline

1. Put this folder's files in your classroom50 repository as
   CLASSROOM/autograders/ASSIGNMENT/ (autograder.py, $wheel_text and, for a
   lesson of your own, turtletui_lessons/). Classroom 50's runner calls
   autograder.py in each student's checkout and reads the result.json it writes
   (schema classroom50/result/v1; points are whole numbers there: each check's
   points are spread over its scenario runs as whole points).

2. Students push their controller: a .py file, a folder, their ROS 2 package or
   a workspace with src/. The result names the file and executable graded; an
   upload that cannot be graded scores 0 with the reason.

3. turtletui-autograding.yml is a GitHub Actions workflow that runs the same
   grading on every push and keeps result.json as an artifact: copy it to
   .github/workflows/ and this folder to .classroom50/ in a repository to try the
   autograder there, or to grade outside Classroom 50.

Students can read what the runner fetches (the autograder and the lesson):
grade on Gradescope when hidden scenarios must stay secret.
""")


def write_classroom50_autograder(
    lesson_id: str,
    out_dir: Path,
    *,
    turtletui_requirement: str | None = None,
    wheel: Path | None = None,
    lesson_source: Path | None = None,
    executable: str | None = None,
    time_limit: int = GRADESCOPE_TIME_LIMIT,
    force: bool = False,
) -> list[Path]:
    """Write a Classroom 50 autograder for ``lesson_id`` into ``out_dir`` (the
    assignment's autograders folder): autograder.py, turtletui's ``wheel`` (or
    ``turtletui_requirement``), turtletui-autograding.yml, README.txt and, for a
    lesson of the instructor's own, turtletui_lessons/. Returns the files written;
    existing files are an :class:`AutograderError` unless ``force``."""
    _check_lesson_id(lesson_id)
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise AutograderError(f"{out_dir} is a file; name a folder to write the autograder to")
    script, workflow, readme = (
        out_dir / "autograder.py", out_dir / "turtletui-autograding.yml", out_dir / "README.txt"
    )
    _refuse_existing([script, workflow, readme], force)
    _, requirement_text, copied = _install_source(out_dir, turtletui_requirement, wheel, force)
    requirement = copied[0].name if copied else str(turtletui_requirement)
    written = list(copied)
    if lesson_source is not None:
        written += _copy_lessons(Path(lesson_source), out_dir / LESSONS_FOLDER, force)
    code = _AUTOGRADER.substitute(
        lesson_id=lesson_id,
        requirement=repr(requirement),
        lesson=repr(lesson_id),
        lessons=repr(LESSONS_FOLDER if lesson_source is not None else ""),
        executable=repr(executable or ""),
        time_limit=int(time_limit),
    )
    written.append(_write(script, code))
    written.append(_write(workflow, _WORKFLOW.substitute(lesson_id=lesson_id)))
    title = f"turtletui autograder for Classroom 50, lesson {lesson_id}"
    written.append(
        _write(readme, _README.substitute(lesson_id=lesson_id, underline="=" * len(title), wheel_text=requirement_text))
    )
    return written
