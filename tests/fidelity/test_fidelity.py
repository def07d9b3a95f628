"""The differential suite: each program in programs/ prints the same under
the real rclpy and under turtletui, sandboxed and in-process (issue 13).

The real rclpy's output of each program is computed once and compared with
both hosts: what the program printed (stdout), what its nodes logged
(stderr, rcutils' format, timestamps normalised) and its exit status.
Needs the real ROS 2 (marker realros; built on first use, see tests/support/real_ros.py).
"""

from __future__ import annotations

import dataclasses
import fcntl
import json
import os
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from harness import Output, hosts_for, programs, run_real, run_turtletui
from support.real_ros import own_domain, ros_python

pytestmark = pytest.mark.realros

PROGRAMS = programs()
REAL_AT_ONCE = 4
"""Real runs side by side: each mostly waits for Fast DDS's discovery."""


def _run_real_into(program: Path, shared: Path) -> None:
    """Write the real rclpy's output of ``program`` to ``shared``/<name>.json."""
    folder = shared / program.stem
    folder.mkdir(exist_ok=True)
    try:
        with own_domain() as domain:
            output = run_real(program, folder, domain)
    except Exception as err:  # noqa: BLE001 - said by the test waiting for it
        output = Output([], [f"the real run failed: {type(err).__name__}: {err}"], -1)
    partial = folder / "output.json"
    partial.write_text(json.dumps(dataclasses.asdict(output)))
    os.replace(partial, shared / f"{program.stem}.json")


@pytest.fixture(scope="session")
def real_output(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Callable[[Path], Output]]:
    """The real rclpy's output of a program. The first test process (of
    pytest-xdist's workers) to ask runs every program, a few at a time in the
    background, and shares the outputs through files with the others."""
    base = tmp_path_factory.getbasetemp()
    shared = (base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / "fidelity-real"
    shared.mkdir(exist_ok=True)
    with open(shared / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        first = not (shared / ".started").exists()
        (shared / ".started").touch()
    if first:
        ros_python()  # built (once) before the runs start
        pool = ThreadPoolExecutor(REAL_AT_ONCE, thread_name_prefix="real-rclpy")
        for program in PROGRAMS:
            pool.submit(_run_real_into, program, shared)
        pool.shutdown(wait=False)  # the process waits for the runs before it exits

    def get(program: Path) -> Output:
        path = shared / f"{program.stem}.json"
        deadline = time.monotonic() + 900
        while not path.exists():
            if time.monotonic() > deadline:
                pytest.fail(f"no real output of {program.name} after 15 minutes")
            time.sleep(0.05)
        return Output(**json.loads(path.read_text()))

    yield get


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
def test_turtletui_prints_what_the_real_rclpy_prints(
    program: Path, host: str, tmp_path: Path, real_output: Callable[[Path], Output]
):
    real = real_output(program)
    assert real.returncode == 0, "the program fails under the real rclpy:\n" + "\n".join(real.stderr)
    assert real.stdout or real.stderr, "the program prints nothing to compare"
    ours = run_turtletui(program, tmp_path, host)
    assert ours.stdout == real.stdout
    assert ours.stderr == real.stderr
    assert ours.returncode == real.returncode
