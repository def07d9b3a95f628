"""Ctrl-C ends a run the way it ends a ROS node: with a summary, nothing left behind."""

import os
import queue
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest

import turtletui

REFERENCE = Path(__file__).resolve().parents[2] / "plugins" / "reference" / "turtle_controller.py"
READY = "Warning: Approaching wall detected!"
"""A line the Part 6 controller logs about 0.7 s into the run: it is running."""


def lines_of(stream) -> queue.Queue:
    """The lines ``stream`` yields, as they come (None at its end)."""
    lines: queue.Queue = queue.Queue()

    def pump() -> None:
        for line in stream:
            lines.put(line)
        lines.put(None)

    threading.Thread(target=pump, daemon=True).start()
    return lines


@pytest.mark.parametrize("where", ["in-process", "sandboxed"])
def test_ctrl_c_stops_a_real_time_run_with_a_summary(tmp_path: Path, where: str) -> None:
    record = tmp_path / "run.jsonl"
    args = [sys.executable, "-m", "turtletui", "run", "--headless", "--realtime", "--duration", "60"]
    args += ["--record", str(record)]
    if where == "sandboxed":
        args.append(str(REFERENCE))
    env = dict(os.environ, PYTHONPATH=str(Path(turtletui.__file__).resolve().parents[1]), PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        log = lines_of(proc.stderr)  # the nodes' log, on stderr as under ROS
        seen: list[str] = []
        while not seen or READY not in seen[-1]:
            # however slow the start on a busy machine: wait for the controller to run
            line = log.get(timeout=120)
            assert line is not None, seen
            seen.append(line)
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=120)
        rest = proc.stdout.read().splitlines()
        err = []
        while (line := log.get(timeout=30)) is not None:
            err.append(line)
        err = "".join(err)
    finally:
        proc.kill()
        proc.wait()
    assert proc.returncode == 130, err
    assert "Traceback" not in err
    summary = rest[-1]
    assert summary.startswith("sim time ") and "interrupted" in summary
    sim_time = float(summary.split()[2])
    assert 0.5 < sim_time < 60.0  # stopped by Ctrl-C, after the controller ran
    # The record is complete up to the interruption, and nothing is left behind.
    assert record.exists() and READY in record.read_text()
    assert not list(tmp_path.glob(".*.tmp"))
