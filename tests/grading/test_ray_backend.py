"""`turtletui grade --backend ray`: each scenario run a Ray task, sandboxed as
in the local pool, with the same report, progress lines and results folder;
what is sent to the workers; and the errors of a missing Ray or a worker that
would grade differently."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from support.grading import (
    CRASH_WITH_POSE,
    HONEST,
    REPO,
    SYNTAX_ERROR,
    WALL_HITTER,
    grade_cli,
    make_class,
    one_line_error,
)
from typer.testing import CliRunner

from turtletui.cli import app
from turtletui.grading.bundles import BundleError, pack, unpack
from turtletui.grading.ray_backend import (
    LessonBundle,
    SubmissionBundle,
    WorkerMismatch,
    grade_remotely,
)
from turtletui.grading.store import KEY_ENV

KEY = "a secret of this grading"
HELPED = "from helpers import SPEED\n" + HONEST.replace("cmd.linear.x = 5.0", "cmd.linear.x = SPEED")
"""A controller that needs a file beside it: the workers must get the whole folder."""
PARRICIDE = HONEST.replace("    rclpy.init()\n", "    rclpy.init()\n    import os\n    os.kill(os.getppid(), 9)\n")
"""A controller that kills the process that runs it (a pool's or Ray's worker)."""


def comparable(text: str, folder: Path) -> dict:
    data = json.loads(text)
    for sub in data["submissions"]:
        sub.pop("execution_time")
        sub["recordings"] = [str(Path(r).relative_to(folder)) for r in sub["recordings"]]
    return data


def progress(stderr: str) -> list[str]:
    """The progress lines, without their wall times and their place in the
    order submissions finished ("[3/6] "), which runs side by side decide."""
    return sorted(re.sub(r"^\[\d+/\d+\] ", "", re.sub(r" \([0-9.]+ s of runs\)$", "", line)) for line in stderr.splitlines())


def test_a_local_ray_cluster_grades_exactly_as_the_local_pool(tmp_path: Path, lesson: Path):
    klass = make_class(
        tmp_path / "class",
        {"ann": HONEST, "ben": WALL_HITTER, "cat": CRASH_WITH_POSE, "dan": SYNTAX_ERROR, "eli": HELPED, "kim": PARRICIDE},
    )
    (klass / "eli" / "helpers.py").write_text("SPEED = 5.0\n")
    args = ["--lesson", str(lesson), "--same-user", "--format", "json"]
    local = grade_cli(klass, *args, "--results", tmp_path / "local", "-j", "2", env={KEY_ENV: KEY})
    assert local.exit_code == 0, local.stderr

    env = dict(os.environ, PYTHONPATH=str(REPO), **{KEY_ENV: KEY})
    env.pop("RAY_ADDRESS", None)
    ray = subprocess.run(
        [sys.executable, "-m", "turtletui", "grade", str(klass), *args, "--results", str(tmp_path / "ray"),
         "--backend", "ray", "--address", "local"],
        capture_output=True, text=True, env=env, timeout=300, cwd=tmp_path,
    )
    assert ray.returncode == 0, ray.stderr
    assert comparable(ray.stdout, tmp_path / "ray") == comparable(local.stdout, tmp_path / "local")
    scores = {s["student"]: s["score"] for s in json.loads(ray.stdout)["submissions"]}
    assert scores == {"ann": 3.0, "ben": 1.0, "cat": 0.0, "dan": 0.0, "eli": 3.0, "kim": 0.0}
    assert "the process grading this run was killed" in ray.stdout  # kim's, after Ray tried again
    # the same progress lines (Ray's own messages about the worker kim killed go to stderr too)
    assert set(progress(local.stderr)) <= set(progress(ray.stderr))
    assert len([line for line in ray.stderr.splitlines() if line.startswith("[")]) == 6
    # the driver saved each failed run's recording where the local pool does
    for student in ("ben", "cat"):
        recording = tmp_path / "ray" / "recordings" / student / "centre.mcap"
        assert recording.stat().st_size > 1000
    assert (tmp_path / "ray/recordings/ben/centre.mcap").read_bytes() == (
        tmp_path / "local/recordings/ben/centre.mcap"
    ).read_bytes()
    # and the results it signed make the same report again
    merged = CliRunner().invoke(app, ["grade", "merge", str(tmp_path / "ray"), "--format", "json"], env={KEY_ENV: KEY})
    assert merged.exit_code == 0, merged.stderr
    assert json.loads(merged.stdout) == json.loads(ray.stdout)


def test_without_ray_the_backend_is_a_one_line_error_naming_the_extra(
    tmp_path: Path, lesson: Path, monkeypatch: pytest.MonkeyPatch
):
    monkeypatch.setitem(sys.modules, "ray", None)  # import ray raises ImportError
    klass = make_class(tmp_path / "class", {"ann": HONEST})
    done = grade_cli(klass, "--lesson", lesson, "--results", tmp_path / "res", "--backend", "ray")
    assert "pip install 'turtletui[ray]'" in one_line_error(done)
    assert not list((tmp_path / "res").glob("*.json"))  # nothing was graded


def test_a_worker_with_another_turtletui_refuses_to_grade(tmp_path: Path):
    lesson = LessonBundle(files=pack([]), lesson="lesson/x.md", plugins=(), key="k", version="0.0.1")
    submission = SubmissionBundle(pack([]), str(tmp_path / "ann"), str(tmp_path))
    with pytest.raises(WorkerMismatch, match="the Ray workers have turtletui .*, the driver 0.0.1"):
        grade_remotely(lesson, submission, "ann", "ann/c.py", 0, False, "mcap", None, 3.0, "", None, True)


# -- what is sent ---------------------------------------------------------------------------


def test_a_student_folder_is_sent_with_its_source_and_without_build_output_or_links_out(tmp_path: Path):
    student = tmp_path / "ann"
    (student / "pkg" / "pkg").mkdir(parents=True)
    (student / "pkg" / "pkg" / "__init__.py").write_text("")
    (student / "pkg" / "pkg" / "node.py").write_text("print('hi')\n")
    (student / "data.csv").write_text("1,2\n")
    (student / "same.csv").symlink_to("data.csv")
    (student / "secret").symlink_to("/etc/passwd")
    for skipped in ("build", "install", "log", "__pycache__", ".git"):
        (student / skipped).mkdir()
        (student / skipped / "big.bin").write_bytes(b"x" * 1000)
    into = tmp_path / "unpacked"
    into.mkdir()
    unpack(pack([(student, "ann")]), into)
    files = sorted(str(p.relative_to(into)) for p in into.rglob("*"))
    assert files == ["ann", "ann/data.csv", "ann/pkg", "ann/pkg/pkg", "ann/pkg/pkg/__init__.py", "ann/pkg/pkg/node.py", "ann/same.csv"]
    assert (into / "ann" / "same.csv").is_symlink() and (into / "ann" / "same.csv").read_text() == "1,2\n"


def test_a_submission_too_big_to_send_is_refused_with_its_path(tmp_path: Path):
    (tmp_path / "ann").mkdir()
    (tmp_path / "ann" / "video.mp4").write_bytes(b"x" * 2048)
    with pytest.raises(BundleError, match=f"{tmp_path / 'ann'}: more than"):
        pack([(tmp_path / "ann", "ann")], limit=1024)
