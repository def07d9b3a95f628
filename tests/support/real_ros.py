"""The real ROS 2 that tests compare with and run against (marker ``realros``).

It is ``$TURTLETUI_ROS_PYTHON`` when set (a ROS installation's python), else
the throwaway ROS 2 of scripts/real_ros_env.py: the Kilted wheels (rclpy, Fast
DDS, the common messages) and turtlesim's interfaces, built on first use
(about 4 minutes) outside the repository and reused while its inputs are
unchanged. A test that needs it fails, saying why, when it cannot be had: it
is never skipped into a green run. Without it: ``pytest -m 'not realros'``.
"""

from __future__ import annotations

import fcntl
import functools
import os
import random
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

ENV_SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "real_ros_env.py"
BUILD_TIMEOUT = 3600.0


@functools.cache
def _built() -> tuple[str | None, str]:
    proc = subprocess.run(
        [sys.executable, str(ENV_SCRIPT)], capture_output=True, text=True, timeout=BUILD_TIMEOUT
    )
    if proc.returncode == 0 and proc.stdout.strip():
        return str(Path(proc.stdout.strip().splitlines()[-1]) / "ros-python"), ""
    return None, (proc.stderr.strip().splitlines() or ["no output"])[-1]


def ros_python() -> str:
    """The real ROS 2's python: a launcher that sets up its libraries, then runs python."""
    explicit = os.environ.get("TURTLETUI_ROS_PYTHON")
    if explicit:
        return explicit
    found, problem = _built()
    if found is None:
        pytest.fail(
            f"no real ROS 2 for the realros tests: `python3 scripts/real_ros_env.py` failed ({problem});"
            " set TURTLETUI_ROS_PYTHON to a ROS 2 python, or deselect them: pytest -m 'not realros'",
            pytrace=False,
        )
    return found


DOMAINS = range(1, 102)
"""ROS domain ids the tests take (0 is everyone's default; ROS 2 advises 0-101)."""
_LOCKS = Path(tempfile.gettempdir()) / f"turtletui-test-ros-domains-{os.getuid()}"
_used: set[int] = set()


@contextmanager
def own_domain() -> Iterator[int]:
    """A ROS domain id no other test process on this machine holds meanwhile
    (pytest-xdist's workers, another run of the suite): held by a file lock
    for the ``with`` block, released when it ends or the process dies. One
    this process used before is taken again only when all are, so that no test
    meets the participants an earlier one left behind."""
    _LOCKS.mkdir(exist_ok=True)
    ids = list(DOMAINS)
    random.SystemRandom().shuffle(ids)
    ids.sort(key=lambda n: n in _used)  # unused first, in random order
    for domain in ids:
        fd = os.open(_LOCKS / f"{domain}.lock", os.O_CREAT | os.O_RDWR, 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        _used.add(domain)
        try:
            yield domain
        finally:
            os.close(fd)  # releases the lock
        return
    raise RuntimeError(f"every ROS domain id in {DOMAINS} is held by another test process ({_LOCKS})")


def run_real(args: list[str], *, cwd: Path, timeout: float = 120.0, env: dict | None = None) -> subprocess.CompletedProcess:
    """Run the real ROS 2's python with ``args`` (text output captured)."""
    return subprocess.run([ros_python(), *args], cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env)


BRIDGE_SCRIPTS = Path(__file__).resolve().parents[1] / "bridge"
"""The ROS 2 programs the bridge tests run beside turtletui (ros_probe.py...)."""


def run_ros_script(ros_python: str, script: str, *args: str, timeout: float = 120.0) -> subprocess.CompletedProcess:
    """Run one of tests/bridge's scripts with the real rclpy (another ROS 2 process)."""
    return subprocess.run(
        [ros_python, str(BRIDGE_SCRIPTS / script), *args], capture_output=True, text=True, timeout=timeout
    )
