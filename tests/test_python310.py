"""turtletui installs on Gradescope's Ubuntu 22.04 image, whose Python is 3.10.

No 3.10 interpreter installs on the development machine (Debian 12 has 3.11;
uv's and deadsnakes' builds are not reachable), so the code is checked for the
language and library features it uses: vermin finds the minimum version each
construct needs (ruff's target-version py310 keeps the syntax honest too)."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import turtletui

PACKAGE = Path(turtletui.__file__).parent


def test_the_package_needs_nothing_newer_than_python_3_10():
    proc = subprocess.run(
        [
            shutil.which("vermin") or "vermin", "--no-tips", "--violations", "-t=3.10-", "--eval-annotations",
            "--backport", "typing_extensions",
            # tomllib is imported with a fallback to tomli (a 3.10 dependency)
            "--exclude", "tomllib",
            str(PACKAGE),
        ],
        capture_output=True,
        text=True,
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_the_metadata_promises_python_3_10():
    pyproject = (Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()  # CI installs a copy
    assert 'requires-python = ">=3.10"' in pyproject and 'target-version = "py310"' in pyproject
