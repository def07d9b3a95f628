"""pytest plugin: test your own rclpy node against the simulated turtlesim.

Installed with turtletui (entry point ``pytest11``), so in any project::

    def test_never_hits_the_wall(turtlesim_run):
        result = turtlesim_run("my_node.py", duration=30)
        assert result.ok, result.crashes
        assert result.wall_hits == 0
        t, x, y, theta = result.poses["turtle1"][-1]
        assert 2.0 < x < 9.0

``result`` is a turtletui.api.RunResult: ``poses`` (t, x, y, theta per pose),
``logs`` (records with .node, .level_name, .msg), ``service_calls``
(t, service, request, response), ``turtles`` (final pose, distance, wall hits).

Determinism needs no fixture: ``turtletui.testing.check_controller("my_node.py")``
in a test fails it (an AssertionError) with the first difference.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

import pytest

from turtletui.api import RunResult, run


@pytest.fixture
def turtlesim_run() -> Callable[..., RunResult]:
    """Run controller files for N simulated seconds (lockstep, sandboxed) and
    return the RunResult; pass ``in_process=True`` for trusted code."""

    def runner(
        *controllers: str | Path,
        duration: float = 10.0,
        ros_args: Sequence[str] = (),
        seed: int = 0,
        in_process: bool = False,
    ) -> RunResult:
        return run(
            list(controllers),
            duration=duration,
            ros_args=ros_args,
            seed=seed,
            sandbox=False if in_process else None,
            keep_poses=True,
        )

    return runner
