"""The Gradescope autograder, run as Gradescope runs it: a private mount
namespace with its own /autograder (source, submission, results), an empty
/opt, a clean environment, as root; setup.sh installs turtletui's wheel and its
dependencies from PyPI, then run_autograder grades each upload."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest
from support.ros_package import write_package
from typer.testing import CliRunner

from turtletui.cli import app

HERE = Path(__file__).parent
REPO = HERE.parents[1]
REFERENCE = REPO / "plugins" / "reference" / "turtle_controller.py"


def _can_simulate() -> str | None:
    if os.geteuid() != 0:
        return "needs root (Gradescope runs the autograder as root)"
    if shutil.which("unshare") is None:
        return "needs unshare (util-linux)"
    if subprocess.run(["unshare", "-m", "true"], capture_output=True).returncode != 0:
        return "cannot make a mount namespace here"
    return None


pytestmark = pytest.mark.skipif(_can_simulate() is not None, reason=str(_can_simulate()))


def uploads(folder: Path) -> Path:
    reference = REFERENCE.read_text()
    (folder / "file").mkdir(parents=True)
    (folder / "file" / "turtle_controller.py").write_text(reference)
    (folder / "file" / "notes.txt").write_text("my notes\n")
    # the course's package, its node importing a module of its own package
    package = write_package(folder / "package", controller="from .utils import SAFE_HIGH  # noqa\n" + reference)
    (package.parent / ".DS_Store").write_bytes(b"\0\1")
    (folder / "bad").mkdir()
    (folder / "bad" / "turtle_controller.py").write_bytes(b"\x7fELF\0\0\0binary")
    (folder / "empty").mkdir()
    return folder


def test_gradescope_runs_the_bundle_for_files_packages_and_bad_uploads(tmp_path: Path):
    bundle = tmp_path / "bundle"
    made = CliRunner().invoke(
        app,
        ["autograder", "gradescope", "--lesson", "part6-closed-loop", "-o", str(bundle),
         "--executable", "turtle_controller"],
    )
    assert made.exit_code == 0, made.output
    assert list(bundle.glob("turtletui-*.whl"))
    out = tmp_path / "out"
    proc = subprocess.run(
        ["unshare", "-m", "--propagation", "private", "bash", str(HERE / "gradescope_simulation.sh"),
         str(bundle), str(uploads(tmp_path / "uploads")), str(out)],
        capture_output=True, text=True, timeout=1200,
    )
    setup_log = (out / "setup.log").read_text() if (out / "setup.log").exists() else ""
    assert proc.returncode == 0, proc.stderr + setup_log[-3000:]

    def results(name: str) -> dict:
        path = out / f"{name}.json"
        assert path.exists(), (out / f"{name}.log").read_text()[-3000:]
        return json.loads(path.read_text())

    file, package, bad, empty = (results(n) for n in ("file", "package", "bad", "empty"))
    for data in (file, package):
        assert data["score"] == 10.0, json.dumps(data)[:3000]
        assert all(t["visibility"] == "visible" for t in data["tests"])
        assert any(t["name"].startswith("hidden scenarios: ") for t in data["tests"])
        assert sum(t["max_score"] for t in data["tests"]) == pytest.approx(10.0)
    assert "Graded: turtle_controller.py." in file["output"]
    assert "my_robot_controller/turtle_controller.py (my_robot_controller turtle_controller: main())" in package["output"]
    assert bad["score"] == 0.0 and "could not be graded" in bad["output"] and "binary" in bad["output"]
    assert empty["score"] == 0.0 and "the upload is empty" in empty["output"]
