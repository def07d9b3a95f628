"""Ctrl-C ends a run the way it ends a ROS node: promptly, with a summary, nothing left behind."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import turtletui

REFERENCE = Path(__file__).resolve().parents[2] / "plugins" / "reference" / "turtle_controller.py"


@pytest.mark.parametrize("where", ["in-process", "sandboxed"])
def test_ctrl_c_stops_a_real_time_run_with_a_summary(tmp_path: Path, where: str) -> None:
    record = tmp_path / "run.jsonl"
    args = [sys.executable, "-m", "turtletui", "run", "--headless", "--realtime", "--duration", "60"]
    args += ["--record", str(record), "-q"]
    if where == "sandboxed":
        args.append(str(REFERENCE))
    env = dict(os.environ, PYTHONPATH=str(Path(turtletui.__file__).resolve().parents[1]))
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    time.sleep(1.5)
    started = time.monotonic()
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=10)
    assert time.monotonic() - started < 3.0
    assert proc.returncode == 130, err
    assert "Traceback" not in err
    [summary] = out.splitlines()
    assert summary.startswith("sim time ") and "interrupted" in summary
    sim_time = float(summary.split()[2])
    assert 0.5 < sim_time < 5.0
    # The record is complete up to the interruption, and nothing is left behind.
    assert record.exists() and record.stat().st_size > 0
    assert not list(tmp_path.glob(".*.tmp"))
