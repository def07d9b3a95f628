"""The ``controller_host`` fixture: every test using it runs under both hosts."""

from __future__ import annotations

import pytest
from support.hosts import HOSTS, ControllerHost


@pytest.fixture(params=HOSTS)
def controller_host(request: pytest.FixtureRequest, tmp_path) -> ControllerHost:
    mark = request.node.get_closest_marker("differs_in_sandbox")
    if mark is not None and request.param == "sandboxed":
        reason = mark.args[0] if mark.args else "the sandbox does not behave so yet"
        request.applymarker(pytest.mark.xfail(strict=True, reason=reason))
    return ControllerHost(request.param, tmp_path)
