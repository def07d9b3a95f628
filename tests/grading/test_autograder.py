"""Autograder generators (turtletui.grading.autograder): Gradescope and GitHub Classroom."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from turtletui.grading.autograder import (
    AutograderError,
    write_github_workflow,
    write_gradescope_autograder,
)

LESSON = "part6-closed-loop"
REQ = "turtletui==0.1.0"
BASH = shutil.which("bash")


def bash_syntax_ok(path: Path) -> None:
    if BASH is None:
        pytest.skip("no bash")
    proc = subprocess.run([BASH, "-n", str(path)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr


def custom_lessons(tmp_path: Path) -> Path:
    folder = tmp_path / "my lessons"
    folder.mkdir()
    (folder / "secret.md").write_text('+++\nid = "secret-maze"\ntitle = "Maze"\n+++\n# Maze\n')
    (folder / "__pycache__").mkdir()
    (folder / "__pycache__" / "x.pyc").write_bytes(b"\0")
    return folder


# -- gradescope -----------------------------------------------------------------------


def test_gradescope_writes_setup_run_autograder_and_readme(tmp_path: Path):
    out = tmp_path / "autograder"
    written = write_gradescope_autograder(LESSON, out, turtletui_requirement=REQ)
    assert sorted(p.name for p in written) == ["README.txt", "run_autograder", "setup.sh"]
    run, setup = out / "run_autograder", out / "setup.sh"
    assert os.access(run, os.X_OK) and os.access(setup, os.X_OK)
    assert run.read_text().startswith("#!/usr/bin/env bash\n")
    bash_syntax_ok(run)
    bash_syntax_ok(setup)
    setup_text, run_text = setup.read_text(), run.read_text()
    assert "python3-venv" in setup_text and "pip install turtletui==0.1.0" in setup_text
    assert "sys.version_info >= (3, 10)" in setup_text
    assert "/autograder/submission" in run_text
    assert re.search(
        r"turtletui grade /autograder/submission --lesson part6-closed-loop \\\n\s+--format gradescope "
        r"--hidden-tests summary --results \"\$\(mktemp -d\)\" \\\n\s+--output \"\$results\"",
        run_text,
    )
    assert "timeout --signal=TERM --kill-after=20 540" in run_text
    assert "--lessons" not in run_text
    readme = (out / "README.txt").read_text()
    assert "zip" in readme and "setup.sh" in readme


def test_gradescope_quotes_the_requirement_for_the_shell(tmp_path: Path):
    requirement = "turtletui @ https://example.org/turtletui-0.1.0-py3-none-any.whl; python_version>'3'"
    write_gradescope_autograder(LESSON, tmp_path, turtletui_requirement=requirement)
    setup = (tmp_path / "setup.sh").read_text()
    assert "pip install 'turtletui @ https://example.org/turtletui-0.1.0-py3-none-any.whl; " in setup
    bash_syntax_ok(tmp_path / "setup.sh")


def test_gradescope_copies_a_custom_lesson_folder_and_locks_it(tmp_path: Path):
    source = custom_lessons(tmp_path)
    out = tmp_path / "out"
    written = write_gradescope_autograder(
        "secret-maze", out, turtletui_requirement=REQ, lesson_source=source
    )
    assert out / "turtletui_lessons" / "secret.md" in written
    assert not (out / "turtletui_lessons" / "__pycache__").exists()
    run_text = (out / "run_autograder").read_text()
    setup_text = (out / "setup.sh").read_text()
    assert "--lesson secret-maze --lessons /autograder/source/turtletui_lessons" in run_text
    assert "chmod 700 /autograder/source/turtletui_lessons" in setup_text
    assert "chmod -R go-rwx /autograder/source/turtletui_lessons" in run_text
    bash_syntax_ok(out / "run_autograder")
    bash_syntax_ok(out / "setup.sh")


def test_gradescope_refuses_to_overwrite_unless_forced(tmp_path: Path):
    write_gradescope_autograder(LESSON, tmp_path, turtletui_requirement=REQ)
    (tmp_path / "setup.sh").write_text("mine")
    with pytest.raises(AutograderError) as err:
        write_gradescope_autograder(LESSON, tmp_path, turtletui_requirement=REQ)
    assert str(err.value) == f"{tmp_path / 'setup.sh'} already exists; use --force to overwrite it"
    assert (tmp_path / "setup.sh").read_text() == "mine"
    write_gradescope_autograder(LESSON, tmp_path, turtletui_requirement=REQ, force=True)
    assert (tmp_path / "setup.sh").read_text() != "mine"


def test_gradescope_refuses_before_writing_anything(tmp_path: Path):
    (tmp_path / "README.txt").write_text("mine")
    with pytest.raises(AutograderError, match="README.txt already exists"):
        write_gradescope_autograder(LESSON, tmp_path, turtletui_requirement=REQ)
    assert sorted(os.listdir(tmp_path)) == ["README.txt"]


def test_bad_ids_requirements_and_lesson_copies_are_one_line_errors(tmp_path: Path):
    with pytest.raises(AutograderError, match="not a lesson id"):
        write_gradescope_autograder("x; rm -rf /", tmp_path, turtletui_requirement=REQ)
    with pytest.raises(AutograderError, match="not a pip requirement"):
        write_gradescope_autograder(LESSON, tmp_path, turtletui_requirement="a\nb")
    source = custom_lessons(tmp_path)
    with pytest.raises(AutograderError, match="one contains the other"):
        write_gradescope_autograder(
            "secret-maze", source.parent, turtletui_requirement=REQ, lesson_source=source.parent
        )
    (tmp_path / "file").write_text("")
    with pytest.raises(AutograderError, match="is a file"):
        write_gradescope_autograder(LESSON, tmp_path / "file", turtletui_requirement=REQ)


def _fake_autograder(tmp_path: Path, turtletui_script: str) -> tuple[Path, str]:
    """run_autograder pointed at a fake /autograder tree and a fake turtletui."""
    write_gradescope_autograder(LESSON, tmp_path / "ag", turtletui_requirement=REQ, time_limit=10)
    script = (tmp_path / "ag" / "run_autograder").read_text()
    fake = tmp_path / "fake"
    (fake / "submission" / "upload").mkdir(parents=True)
    (fake / "submission" / "upload" / "controller.py").write_text("")
    bin_dir = fake / "venv" / "bin"
    bin_dir.mkdir(parents=True)
    (bin_dir / "turtletui").write_text("#!/usr/bin/env bash\n" + turtletui_script)
    (bin_dir / "turtletui").chmod(0o755)
    return fake, script.replace("/autograder", str(fake)).replace("/opt/turtletui", str(fake / "venv"))


def test_run_autograder_grades_the_whole_upload(tmp_path: Path):
    """Run the script against a fake /autograder tree: the upload is one submission."""
    if BASH is None:
        pytest.skip("no bash")
    fake, script = _fake_autograder(tmp_path, 'printf "%s\\n" "$@"; echo "{}" > "${@: -1}"\n')
    proc = subprocess.run([BASH, "-c", script], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    args = proc.stdout.splitlines()
    assert args[:2] == ["grade", str(fake / "submission")]
    assert args[args.index("--output") + 1] == str(fake / "results" / "results.json")


@pytest.mark.parametrize(
    ("behaviour", "words"),
    [
        ('echo "turtletui: internal error: boom" >&2; exit 3\n', "could not grade this submission (exit status 3): turtletui: internal error: boom"),
        ("exit 0\n", "could not grade this submission (exit status 0)"),
        ("sleep 60\n", "Grading took longer than 10 seconds"),
    ],
)
def test_run_autograder_always_leaves_a_result(tmp_path: Path, behaviour: str, words: str):
    """A grader that fails, writes nothing or outlives the time limit still leaves results.json."""
    if BASH is None:
        pytest.skip("no bash")
    fake, script = _fake_autograder(tmp_path, behaviour)
    stop = "timeout --signal=TERM --kill-after=20 10 "
    assert stop in script
    script = script.replace(stop, stop.replace(" 10 ", " 1 "))  # its 10 s limit, waited 1 s here
    proc = subprocess.run([BASH, "-c", script], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    data = json.loads((fake / "results" / "results.json").read_text())
    assert data["score"] == 0.0 and words in data["output"], data


# -- github ---------------------------------------------------------------------------


def load_workflow(path: Path) -> dict | None:
    try:
        import yaml
    except ImportError:
        return None
    return yaml.safe_load(path.read_text())


def test_github_workflow_grades_and_reports(tmp_path: Path):
    written = write_github_workflow(LESSON, tmp_path, turtletui_requirement=REQ)
    workflow = tmp_path / ".github" / "workflows" / "classroom.yml"
    assert written == [workflow]
    text = workflow.read_text()
    assert "\t" not in text
    data = load_workflow(workflow)
    if data is not None:
        job = data["jobs"]["run-autograding-tests"]
        steps = {step.get("id"): step for step in job["steps"]}
        grade = steps["turtletui"]
        assert "--format github" in grade["run"]
        reporter = job["steps"][-1]
        assert reporter["uses"] == "classroom-resources/autograding-grading-reporter@v1"
        assert reporter["with"]["runners"] == "turtletui"
        assert reporter["env"] == {"TURTLETUI_RESULTS": "${{ steps.turtletui.outputs.result }}"}
    # Textual checks hold with or without PyYAML.
    assert text.count("\n  run-autograding-tests:\n") == 1
    assert "uses: actions/checkout@v4" in text and "uses: actions/setup-python@v5" in text
    assert "python -m pip install turtletui==0.1.0" in text
    assert "turtletui grade . --lesson part6-closed-loop --format github" in text
    assert "        id: turtletui\n" in text
    assert "          runners: turtletui\n" in text
    assert 'TURTLETUI_RESULTS: "${{ steps.turtletui.outputs.result }}"' in text
    assert "uses: classroom-resources/autograding-grading-reporter@v1" in text
    for line in text.splitlines():
        assert len(line) - len(line.lstrip(" ")) in range(0, 13, 2), line


def test_github_workflow_with_a_custom_lesson_and_submission(tmp_path: Path):
    source = custom_lessons(tmp_path)
    out = tmp_path / "template"
    written = write_github_workflow(
        "secret-maze", out, turtletui_requirement=REQ, lesson_source=source,
        submission="src/my controller.py",
    )
    assert out / ".github" / "turtletui_lessons" / "secret.md" in written
    text = (out / ".github" / "workflows" / "classroom.yml").read_text()
    assert (
        "turtletui grade 'src/my controller.py' --lesson secret-maze "
        "--lessons .github/turtletui_lessons --format github" in text
    )
    assert "Students can" in text


def test_github_refuses_to_overwrite_unless_forced(tmp_path: Path):
    write_github_workflow(LESSON, tmp_path, turtletui_requirement=REQ)
    workflow = tmp_path / ".github" / "workflows" / "classroom.yml"
    workflow.write_text("mine")
    with pytest.raises(AutograderError, match=r"classroom.yml already exists; use --force"):
        write_github_workflow(LESSON, tmp_path, turtletui_requirement=REQ)
    assert workflow.read_text() == "mine"
    write_github_workflow(LESSON, tmp_path, turtletui_requirement=REQ, force=True)
    assert "Autograding Tests" in workflow.read_text()
