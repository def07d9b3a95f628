"""Run one rclpy program under either controller host: in this process, or
sandboxed in a child process (as students' files always run).

``tests/compat/conftest.py`` makes a ``controller_host`` fixture of it,
parametrised over both hosts. A test that shows a behaviour the sandbox does
not have yet is marked ``@pytest.mark.differs_in_sandbox("why")``: its
sandboxed case is then an expected failure, and a strict one, so the mark has
to go as soon as the sandbox behaves the same.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from turtletui.api import RunResult, run

HOSTS = ("in-process", "sandboxed")


@dataclass
class ControllerHost:
    """Runs controller source text under one host."""

    name: str
    folder: Path

    @property
    def sandboxed(self) -> bool:
        return self.name == "sandboxed"

    def write(self, source: str, filename: str = "controller.py") -> Path:
        return write_controller(self.folder, source, filename)

    def run(self, source: str, *, duration: float = 1.0, **options: Any) -> RunResult:
        """Run ``source`` (an rclpy file's text) for ``duration`` simulated
        seconds; ``options`` are turtletui.api.run's."""
        return run([self.write(source)], duration=duration, sandbox=self.sandboxed, **options)


def write_controller(folder: Path, source: str, filename: str) -> Path:
    """``source`` (an rclpy file's text, dedented) as ``folder/filename``."""
    path = folder / filename
    path.write_text(textwrap.dedent(source).lstrip(), encoding="utf-8")
    return path


def node_logs(result: RunResult, node: str) -> list[str]:
    """What the node called ``node`` logged, in order."""
    return [record.msg for record in result.logs if record.node == node]
