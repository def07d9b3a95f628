"""Run one rclpy program under the real rclpy and under turtletui, and normalise what it printed.

A program is an ordinary rclpy file with ``main()`` that ends by itself.
Under the real rclpy it runs as ``python program.py`` in the venv of
scripts/real_ros_env.py (Fast DDS, localhost only, a domain of its own).
Under turtletui it runs as ``turtletui run program.py --headless`` in the
sandbox (the host students use) or ``--in-process``. Both write what the
program prints to stdout and its nodes' log lines to stderr, as rclpy does.

Normalising removes what differs between any two runs of the same program:
log timestamps, addresses, and what turtletui adds around a run (the
simulator's own log lines, the summary line).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from support.real_ros import ros_python

PROGRAMS = Path(__file__).with_name("programs")
HOSTS = ("sandboxed", "in-process")
DURATION = "30"
"""Simulated seconds a turtletui run may last; programs end long before."""

_STAMP = re.compile(r"^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[\d+\.\d{9}\] ")
_ADDRESS = re.compile(r"0x[0-9a-fA-F]+")
_SUMMARY = re.compile(r"^sim time [\d.]+ s, wall time [\d.]+ s, distance .*$")
_TURTLETUI_NODES = ("[turtlesim]: ", "[turtletui]: ")


@dataclass(frozen=True)
class Output:
    """What a program printed (stdout) and logged (stderr), normalised, and its exit status."""

    stdout: list[str]
    stderr: list[str]
    returncode: int


_NEVER_RETRIEVED = "The following exception was never retrieved: "
_RCLPY_WARNING = re.compile(r"^\S*/site-packages/rclpy/\S+:\d+: \w+Warning: ")


def _lines(text: str) -> list[str]:
    out = []
    skip_source_line = False
    for line in text.splitlines():
        if skip_source_line and line.startswith("  "):
            skip_source_line = False
            continue
        skip_source_line = False
        if line.startswith(_NEVER_RETRIEVED):
            continue  # rclpy's notice, when a Future is collected, of a task that failed at shutdown: timing noise
        if _RCLPY_WARNING.match(line):
            # rclpy's own internals warning about themselves (e.g. "Failed to fini
            # rosout publisher" after a refused node name): not the program's output
            skip_source_line = True
            continue
        out.append(_ADDRESS.sub("0xADDR", _STAMP.sub(r"[\1] [TIME] ", line)))
    return out


def run_real(program: Path, cwd: Path, domain: int) -> Output:
    """The program under the real rclpy (Fast DDS)."""
    env = {
        **os.environ,
        "ROS_DOMAIN_ID": str(domain),
        "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
        "RCUTILS_COLORIZED_OUTPUT": "0",
        "PYTHONDONTWRITEBYTECODE": "1",
    }
    env.pop("PYTHONPATH", None)
    done = subprocess.run(
        [ros_python(), str(program)], cwd=cwd, env=env, capture_output=True, text=True, timeout=120
    )
    return Output(_lines(done.stdout), _lines(done.stderr), done.returncode)


def run_turtletui(program: Path, cwd: Path, host: str) -> Output:
    """The program under turtletui, sandboxed or in-process; turtletui's own
    lines (the simulator's log, the summary) are left out."""
    args = [sys.executable, "-m", "turtletui", "run", str(program), "--headless", "--duration", DURATION]
    if host == "in-process":
        args.append("--in-process")
    # as a student runs it: the program's imports choose the distro (the tests' Jazzy does not)
    env = {key: value for key, value in os.environ.items() if key != "TURTLETUI_DISTRO"}
    done = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=300)
    stdout = [line for line in _lines(done.stdout) if not _SUMMARY.match(line)]
    stderr = [line for line in _lines(done.stderr) if not any(node in line for node in _TURTLETUI_NODES)]
    return Output(stdout, stderr, done.returncode)


def programs() -> list[Path]:
    """Every program of the suite, by name (``_*.py`` are modules they share)."""
    return sorted(p for p in PROGRAMS.glob("*.py") if not p.name.startswith("_"))


SANDBOXED_ONLY = "Sandboxed only:"
"""What a program's docstring says when it needs threads, which only the
sandbox runs (in-process, a controller's threads are refused)."""


def hosts_for(program: Path) -> tuple[str, ...]:
    """The turtletui hosts a program is compared in."""
    head = program.read_text().split('"""')[1]
    return ("sandboxed",) if SANDBOXED_ONLY in " ".join(head.split()) else HOSTS
