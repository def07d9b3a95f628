"""The differential suite: each program in programs/ prints the same under
the real rclpy and under turtletui, sandboxed and in-process (issue 13).

The real rclpy's output of each program is computed once and compared with
both hosts: what the program printed (stdout), what its nodes logged
(stderr, rcutils' format, timestamps normalised) and its exit status.
Needs the real ROS 2 (marker realros; built on first use, see tests/support/real_ros.py).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from harness import Output, hosts_for, programs, run_real, run_turtletui
from support.real_ros import own_domain

pytestmark = pytest.mark.realros

PROGRAMS = programs()
_real: dict[str, Output] = {}


def real_output(program: Path, tmp_path: Path) -> Output:
    if program.name not in _real:
        with own_domain() as domain:
            _real[program.name] = run_real(program, tmp_path, domain)
    return _real[program.name]


def test_the_suite_has_its_programs():
    assert len(PROGRAMS) >= 25
    for program in PROGRAMS:
        text = program.read_text()
        assert text.startswith('"""'), f"{program.name}: say what it exercises in a docstring"
        assert 'if __name__ == "__main__":' in text, program.name


@pytest.mark.parametrize(
    ("program", "host"),
    [(program, host) for program in PROGRAMS for host in hosts_for(program)],
    ids=lambda value: value.stem if isinstance(value, Path) else value,
)
def test_turtletui_prints_what_the_real_rclpy_prints(program: Path, host: str, tmp_path: Path):
    real = real_output(program, tmp_path)
    assert real.returncode == 0, "the program fails under the real rclpy:\n" + "\n".join(real.stderr)
    assert real.stdout or real.stderr, "the program prints nothing to compare"
    ours = run_turtletui(program, tmp_path, host)
    assert ours.stdout == real.stdout
    assert ours.stderr == real.stderr
    assert ours.returncode == real.returncode
