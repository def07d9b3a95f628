"""Fixtures for the tests that need a real ROS 2 (marker ``realros``).

The ROS 2 python comes from ``$TURTLETUI_ROS_PYTHON`` or, failing that, from
the environment ``scripts/real_ros_env.py`` built (``.ci/run`` builds it
first). Without one these tests fail, saying how to get one; a developer
without it deselects them: ``pytest -m "not realros"``.

Every test runs on a ROS domain of its own, with discovery kept on this
machine, so parallel runs and other people's ROS 2 never meet it.
"""

from __future__ import annotations

import os
import random
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ENV_SCRIPT = REPO / "scripts" / "real_ros_env.py"
HERE = Path(__file__).resolve().parent


def _find_ros_python() -> str:
    explicit = os.environ.get("TURTLETUI_ROS_PYTHON")
    if explicit:
        return explicit
    found = subprocess.run(
        [sys.executable, str(ENV_SCRIPT), "--existing"], capture_output=True, text=True
    )
    if found.returncode == 0 and found.stdout.strip():
        return str(Path(found.stdout.strip()) / "ros-python")
    pytest.fail(
        "no real ROS 2 for the realros tests: build one with `python3 scripts/real_ros_env.py`"
        " (or set TURTLETUI_ROS_PYTHON to a ROS 2 python); without ROS 2, deselect them:"
        " pytest -m 'not realros'",
        pytrace=False,
    )


@pytest.fixture(scope="session")
def ros_python() -> str:
    return _find_ros_python()


_DOMAINS = iter(range(random.SystemRandom().randrange(99), 10**6))


@pytest.fixture
def ros_domain(monkeypatch: pytest.MonkeyPatch) -> str:
    """A ROS domain of this test's own (the next one: no two tests of a run
    share one), discovery on this machine only."""
    domain = str(next(_DOMAINS) % 99 + 1)
    monkeypatch.setenv("ROS_DOMAIN_ID", domain)
    monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    return domain


def run_ros_script(ros_python: str, script: str, *args: str, timeout: float = 120.0) -> subprocess.CompletedProcess:
    """Run one of this folder's scripts with the real rclpy (another ROS 2 process)."""
    return subprocess.run(
        [ros_python, str(HERE / script), *args], capture_output=True, text=True, timeout=timeout
    )
