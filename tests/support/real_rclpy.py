"""The real rclpy for the tests that compare against it (marker ``real_rclpy``).

Its venv is built by scripts/real_rclpy_env.py (CI does that before the tests).
A test that needs it fails, with what to run, when it is missing: it is never
skipped into a green run. Without it: ``pytest -m 'not real_rclpy'``.
"""

from __future__ import annotations

import importlib.util
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _env_script():
    spec = importlib.util.spec_from_file_location("real_rclpy_env", ROOT / "scripts" / "real_rclpy_env.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def real_python() -> Path:
    """The python of the real rclpy's venv; a test failure saying how to build it if missing."""
    env = _env_script()
    found = env.find()
    if found is None or not found.exists():
        pytest.fail(
            f"the real rclpy is missing (no venv at {env.venv_dir()}): build it with "
            "`python scripts/real_rclpy_env.py`, or deselect these tests with -m 'not real_rclpy'",
            pytrace=False,
        )
    return found


def run_real(args: list[str], *, cwd: Path, timeout: float = 120.0, env: dict | None = None) -> subprocess.CompletedProcess:
    """Run the real rclpy's python with ``args`` (text output captured)."""
    return subprocess.run(
        [str(real_python()), *args], cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env
    )
