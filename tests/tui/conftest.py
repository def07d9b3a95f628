"""The app keeps a student's progress under the XDG data folder: tests keep
theirs in a temporary one, never in the home folder of whoever runs them."""

from __future__ import annotations

import pytest


@pytest.fixture(autouse=True)
def _private_data_home(tmp_path_factory, monkeypatch) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path_factory.mktemp("data")))
