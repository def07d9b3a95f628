"""Make (or find) a throwaway virtual environment with the REAL rclpy, for tests.

The fidelity tests (tests/fidelity/, tests/interfaces/test_real_definitions.py)
run the same programs under ROS 2's own rclpy and under turtletui and compare
what they print. ROS 2 Kilted's rclpy, message packages and Fast DDS install
from the package index as ``ros-*`` wheels; they go into a venv of their own,
outside the repository, cached under a key of everything that goes into it
(the pinned packages and the Python version), so a second run costs nothing.
turtletui never depends on them.

    python scripts/real_rclpy_env.py          # build if needed; prints the venv's python
    python scripts/real_rclpy_env.py --check  # print it if built, else exit 1

The cache folder is ``$TURTLETUI_REAL_RCLPY_CACHE`` or
``~/.cache/turtletui/real-rclpy``; ``$TURTLETUI_REAL_RCLPY`` names a python
to use instead (e.g. a ROS installation's, after sourcing its setup file).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

PACKAGES = (
    "ros-rclpy==9.1.2",
    "ros-rmw-fastrtps-cpp==9.3.3",
    "ros-geometry-msgs==5.5.1",
    "ros-std-msgs==5.5.1",
    "ros-std-srvs==5.5.1",
    "ros-sensor-msgs==5.5.1",
    "ros-nav-msgs==5.5.1",
)
"""What the venv holds: Kilted's rclpy 9.1 with Fast DDS and the message
packages the fidelity programs import (example_interfaces and tf2_msgs have
no wheels on the index)."""

OVERRIDE_VAR = "TURTLETUI_REAL_RCLPY"
CACHE_VAR = "TURTLETUI_REAL_RCLPY_CACHE"


def cache_key() -> str:
    """A short hash of the packages and the Python that the venv is made of."""
    text = "\n".join([*PACKAGES, sys.version.split()[0], sys.platform])
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def venv_dir() -> Path:
    """Where the venv for this key lives (built or not)."""
    base = os.environ.get(CACHE_VAR) or Path.home() / ".cache" / "turtletui" / "real-rclpy"
    return Path(base) / cache_key()


def _python(folder: Path) -> Path:
    return folder / "bin" / "python"


def find() -> Path | None:
    """The real rclpy's python if it is there (the override or a finished build), else None."""
    override = os.environ.get(OVERRIDE_VAR)
    if override:
        return Path(override)
    folder = venv_dir()
    if (folder / ".complete").exists():
        return _python(folder)
    return None


def build(quiet: bool = False) -> Path:
    """Build the venv if it is not there yet; returns its python. Builds into a
    temporary folder and renames it, so an interrupted build leaves nothing half made."""
    found = find()
    if found is not None:
        return found
    folder = venv_dir()
    folder.parent.mkdir(parents=True, exist_ok=True)
    partial = folder.with_name(f"{folder.name}.partial-{os.getpid()}")
    shutil.rmtree(partial, ignore_errors=True)
    start = time.monotonic()
    try:
        subprocess.run([sys.executable, "-m", "venv", str(partial)], check=True)
        pip = [str(_python(partial)), "-m", "pip", "install", "--disable-pip-version-check"]
        subprocess.run([*pip, "-q", *PACKAGES], check=True)
        (partial / ".complete").write_text("\n".join(PACKAGES) + "\n")
        try:
            partial.rename(folder)
        except OSError:  # another build finished first: use that one
            shutil.rmtree(partial, ignore_errors=True)
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise
    if not quiet:
        print(f"built {folder} in {time.monotonic() - start:.0f} s", file=sys.stderr)
    # A venv's python is a link to the interpreter: scripts run it by this path.
    return _python(folder)


def main() -> None:
    if "--check" in sys.argv[1:]:
        found = find()
        if found is None:
            sys.exit(f"no real rclpy venv at {venv_dir()}: run python scripts/real_rclpy_env.py")
        print(found)
        return
    try:
        print(build())
    except subprocess.CalledProcessError as err:
        sys.exit(f"building the real rclpy venv failed: {err}")


if __name__ == "__main__":
    main()
