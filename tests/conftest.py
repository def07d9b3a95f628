"""Fixtures for the whole suite."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest


def pytest_xdist_auto_num_workers(config: pytest.Config) -> int:
    """``-n auto``: one worker more than the CPUs this process may use. A good
    part of the suite's test time is waiting (real-time runs, DDS discovery,
    the browser), which the extra worker fills."""
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    return cpus + 1


@pytest.fixture(autouse=True)
def _private_data_home(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The grader's results key and other per-user data go to a temporary
    folder, never to the home of whoever runs the tests."""
    home = tmp_path_factory.mktemp("xdg-data")
    monkeypatch.setenv("XDG_DATA_HOME", str(home))
    monkeypatch.delenv("TURTLETUI_RESULTS_KEY", raising=False)
    return home


@pytest.fixture(autouse=True, scope="session")
def _course_distro() -> Iterator[None]:
    """The suite's controllers are the course's (``from turtlesim.msg import
    Pose``): they run as on Jazzy unless a test chooses a distro itself
    (tests/compat/test_distro.py tests the default). Session-wide, so that
    module-scoped fixtures that run controllers see it too."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("TURTLETUI_DISTRO", "jazzy")
        yield
