"""Finding a ROS 2 python and running the twin (``ros_node.py``) in it.

turtletui runs in its own environment (a venv with its own Python and numpy);
ROS 2 runs in another (a sourced /opt/ros/DISTRO, or a venv with the ROS 2
wheels). The twin is a child process of a python that imports the real
rclpy, so the two never have to share an interpreter. Which python:

1. ``--ros-python PATH`` or ``$TURTLETUI_ROS_PYTHON``, when given;
2. else turtletui's own python, when it finds an rclpy (a sourced ROS 2 of
   the same Python version);
3. else ``python3`` on the PATH outside turtletui's venv (a sourced ROS 2 with
   the system's Python).

The first that starts the twin is used; when none does, ``RosUnavailable``
says in one line how to source ROS 2.
"""

from __future__ import annotations

import importlib.util
import json
import os
import queue
import shutil
import subprocess
import sys
import threading
from collections import deque
from pathlib import Path
from typing import Any

TWIN_SCRIPT = Path(__file__).with_name("ros_node.py")
RUN_FILE_SCRIPT = Path(__file__).with_name("run_file.py")
ENV_PYTHON = "TURTLETUI_ROS_PYTHON"
START_TIMEOUT = 60.0
"""Wall seconds the twin may take to import rclpy and join the graph (a busy machine)."""

HOW_TO_SOURCE = (
    "source ROS 2 first (source /opt/ros/jazzy/setup.bash), or name a python that imports"
    f" rclpy with --ros-python PATH (or ${ENV_PYTHON})"
)


class RosUnavailable(Exception):
    """No real ROS 2 could be reached; the text says why and what to do, in one line."""


def candidate_pythons(explicit: str | None = None) -> list[str]:
    """The pythons to try, best first (see the module's docstring)."""
    explicit = explicit or os.environ.get(ENV_PYTHON) or None
    if explicit:
        found = shutil.which(explicit) or explicit
        if not Path(found).is_file():
            raise RosUnavailable(f"--ros-python {explicit}: no such program")
        return [found]
    candidates = []
    if importlib.util.find_spec("rclpy") is not None:
        candidates.append(sys.executable)
    venv_bin = str(Path(sys.prefix) / "bin")
    path = os.pathsep.join(p for p in os.environ.get("PATH", "").split(os.pathsep) if p and p != venv_bin)
    system = shutil.which("python3", path=path)
    if system and system not in candidates and Path(system).resolve() != Path(sys.executable).resolve():
        candidates.append(system)
    return candidates


class TwinProcess:
    """The twin's process: ``send`` a request, ``replies`` holds what it said."""

    def __init__(self, python: str, *, env: dict[str, str] | None = None) -> None:
        self.python = python
        self._proc = subprocess.Popen(
            [python, str(TWIN_SCRIPT)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            env=env,
            start_new_session=True,  # Ctrl-C reaches turtletui, which ends the twin itself
        )
        self.replies: queue.SimpleQueue[dict[str, Any] | None] = queue.SimpleQueue()
        """What the twin said, one dict a line; None once its output closed."""
        self.stderr_tail: deque[str] = deque(maxlen=20)
        self._write_lock = threading.Lock()
        self.alive = True
        threading.Thread(target=self._read_stdout, name="turtletui-ros-out", daemon=True).start()
        threading.Thread(target=self._read_stderr, name="turtletui-ros-err", daemon=True).start()

    def _read_stdout(self) -> None:
        for line in self._proc.stdout:
            try:
                self.replies.put(json.loads(line))
            except ValueError:
                self.stderr_tail.append(line.decode(errors="replace").rstrip())
        self.replies.put(None)

    def _read_stderr(self) -> None:
        for line in self._proc.stderr:
            self.stderr_tail.append(line.decode(errors="replace").rstrip())

    def wait_ready(self, timeout: float = START_TIMEOUT) -> dict[str, Any]:
        """The twin's first line: its ``ready`` report; RosUnavailable otherwise."""
        try:
            first = self.replies.get(timeout=timeout)
        except queue.Empty:
            self.close()
            raise RosUnavailable(f"{self.python}: the ROS 2 side did not start within {timeout:g} s") from None
        if first is None or first.get("op") != "ready":
            self.close()
            reason = first.get("error") if first else (self.last_error() or "it ended at once")
            raise RosUnavailable(f"{self.python}: {reason}")
        return first

    def last_error(self) -> str:
        lines = [line for line in self.stderr_tail if line.strip()]
        return lines[-1].strip() if lines else ""

    def send(self, request: dict[str, Any]) -> bool:
        """Write one request; False once the twin is gone."""
        if not self.alive:
            return False
        data = json.dumps(request, separators=(",", ":")).encode() + b"\n"
        try:
            with self._write_lock:
                self._proc.stdin.write(data)
                self._proc.stdin.flush()
        except (BrokenPipeError, OSError, ValueError):
            self.alive = False
        return self.alive

    def close(self, timeout: float = 3.0) -> None:
        """End the twin: its input closes (it leaves the graph), then it is killed if still there."""
        self.alive = False
        try:
            self._proc.stdin.close()
        except OSError:
            pass
        try:
            self._proc.wait(timeout)
        except subprocess.TimeoutExpired:
            self._proc.kill()
            self._proc.wait()


def start_twin(ros_python: str | None = None) -> tuple[TwinProcess, dict[str, Any]]:
    """The twin running in the first python that has a ROS 2, and its report."""
    reasons = []
    for python in candidate_pythons(ros_python):
        twin = TwinProcess(python)
        try:
            return twin, twin.wait_ready()
        except RosUnavailable as err:
            reasons.append(str(err))
    found = "; ".join(reasons) if reasons else "no python with rclpy found"
    raise RosUnavailable(f"no ROS 2 here ({found}): {HOW_TO_SOURCE}")
