"""The ``grade`` fixture of the lesson tests (helpers in tests/support/lessons.py)."""

from __future__ import annotations

import pytest
from support.lessons import Grader


@pytest.fixture(scope="session")
def grade() -> Grader:
    return Grader()
