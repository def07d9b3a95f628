"""Fixtures for the tests that need a real ROS 2 (marker ``realros``).

The ROS 2 python is tests/support/real_ros.py's: ``$TURTLETUI_ROS_PYTHON``,
or the environment ``scripts/real_ros_env.py`` builds on first use. Without
one these tests fail, saying why; ``pytest -m "not realros"`` deselects them.

Every test runs on a ROS domain of its own, with discovery kept on this
machine, so parallel runs and other people's ROS 2 never meet it.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from support import real_ros


@pytest.fixture(scope="session")
def ros_python() -> str:
    return real_ros.ros_python()


@pytest.fixture
def ros_domain(monkeypatch: pytest.MonkeyPatch) -> Iterator[str]:
    """A ROS domain of this test's own (no test running meanwhile, in this
    process or another, has it), discovery on this machine only."""
    with real_ros.own_domain() as domain:
        monkeypatch.setenv("ROS_DOMAIN_ID", str(domain))
        monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
        yield str(domain)

