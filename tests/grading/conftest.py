"""Fixtures of the batch-grading tests (the helpers are in tests/support/grading.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.grading import write_lesson


@pytest.fixture
def lesson(tmp_path: Path) -> Path:
    """The tiny lesson's file."""
    return write_lesson(tmp_path)
