"""Issue 17's ratios side by side, from one run (no asserts: a table to read).

Run from the repository root:  python bench/bench_ratios.py [--repeats N]

1. The bare loop: Part 6's physics and decision in plain Python, measured here
   (bench_core.baseline_wall): the baseline every tick is compared with.
2. The marginal in-process tick of the Part 6 controller: a 600 s run less a
   1 s run, over the ticks between them (start-up and loading cancel out).
3. The marginal sandboxed tick, measured the same way: on the fast path
   (the child runs the controller against its own copy of the simulation,
   the parent replays; turtletui.runtime.fastpath), and in lockstep (a
   round trip per exchange, as the app's real-time runs still go).
   Beside them, the in-process tick while turtlesim publishes its colour
   sensor every tick, as it does while a run is recorded (no target: a
   recorded run should cost about what a plain one does).
4. One Part 6 submission graded by the whole ``turtletui grade`` command
   (--jobs 2, process start included): simulated seconds per wall second,
   on the fast path and (TURTLETUI_LOCKSTEP=1) in lockstep.

Each figure is the median of ``--repeats`` runs.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

from bench_core import as_installed, baseline_wall, cpu_model, median_of, ticks_for  # noqa: E402

from turtletui.api import run  # noqa: E402
from turtletui.runtime.loader import ControllerSpec  # noqa: E402
from turtletui.runtime.replica import LOCKSTEP_VAR  # noqa: E402
from turtletui.runtime.sandbox import Limits  # noqa: E402
from turtletui.runtime.simulation import Simulation  # noqa: E402

PART6 = ROOT / "plugins" / "reference" / "turtle_controller.py"
DISTRO = "jazzy"
"""The course's files import ``turtlesim.msg``: the distro that has it."""
LONG, SHORT = 600.0, 1.0
LESSON, LESSON_SECONDS = "part6-closed-loop", 540.0
"""The lesson graded, and the simulated seconds its runs add up to."""

IN_PROCESS_MAX, SANDBOXED_MAX, GRADING_MIN = 8.0, 2.0, 1000.0


def sense_colour(sim: Simulation) -> None:
    sim.graph.record_everything = True  # what a recording sets


def run_wall(duration: float, *, trusted: bool, sensed: bool = False, lockstep: bool = False) -> float:
    """Wall seconds of one ``api.run`` of Part 6, start-up included; a run
    whose controller failed would measure nothing, so it stops the bench."""
    controller = ControllerSpec("tc", PART6, trusted=trusted) if trusted else str(PART6)
    setup = sense_colour if sensed else None
    limits = Limits(lockstep=lockstep)
    started = time.perf_counter()
    result = run([controller], duration=duration, keep_calls=False, distro=DISTRO, setup=setup, limits=limits)
    wall = time.perf_counter() - started
    if not result.ok:
        sys.exit(f"bench_ratios: the Part 6 controller failed: {result.crashes[0].message}")
    return wall


def marginal_tick_us(repeats: int, *, trusted: bool, sensed: bool = False, lockstep: bool = False) -> float:
    """Microseconds per tick between a SHORT and a LONG run."""
    long = median_of(lambda: run_wall(LONG, trusted=trusted, sensed=sensed, lockstep=lockstep), repeats)
    short = median_of(lambda: run_wall(SHORT, trusted=trusted, sensed=sensed, lockstep=lockstep), repeats)
    return (long - short) / (ticks_for(LONG) - ticks_for(SHORT)) * 1e6


def grade_wall(submission: Path, results: Path, *, lockstep: bool = False) -> float:
    """Wall seconds of ``turtletui grade`` on one submission, as an instructor runs it."""
    same_user = ["--same-user"] if os.geteuid() == 0 else []
    command = [
        sys.executable, "-m", "turtletui", "grade", str(submission), "--lesson", LESSON,
        "-q", "--jobs", "2", "--force", "--results", str(results), *same_user,
    ]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    env.pop(LOCKSTEP_VAR, None)
    if lockstep:
        env[LOCKSTEP_VAR] = "1"
    started = time.perf_counter()
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
    return time.perf_counter() - started


def verdict(ok: bool) -> str:
    return "PASS" if ok else "MISS"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    repeats = parser.parse_args().repeats
    as_installed()
    print(f"machine: {platform.platform()}")
    print(f"cpu:     {cpu_model()} ({os.cpu_count()} cores), load {os.getloadavg()[0]:.1f}")
    print(f"python:  {sys.version.split()[0]} ({platform.python_implementation()})")
    print(f"repeats: {repeats} (median)\n")

    run_wall(SHORT, trusted=True)  # warm imports and caches
    ticks = ticks_for(LONG)
    bare_us = median_of(lambda: baseline_wall(ticks), repeats) / ticks * 1e6
    inproc_us = marginal_tick_us(repeats, trusted=True)
    sensed_us = marginal_tick_us(repeats, trusted=True, sensed=True)
    sandbox_us = marginal_tick_us(repeats, trusted=False)
    lockstep_us = marginal_tick_us(repeats, trusted=False, lockstep=True)
    with tempfile.TemporaryDirectory() as tmp:
        submission = Path(tmp) / "student" / "turtle_controller.py"
        submission.parent.mkdir()
        shutil.copy(PART6, submission)
        grade_s = median_of(lambda: grade_wall(submission, Path(tmp) / "results"), repeats)
        grade_lockstep_s = median_of(lambda: grade_wall(submission, Path(tmp) / "results", lockstep=True), repeats)
    grading_x = LESSON_SECONDS / grade_s

    rows = [
        ("bare loop (baseline)", f"{bare_us:.3f} us/tick", "", "", ""),
        ("in-process tick (marginal)", f"{inproc_us:.2f} us/tick", f"{inproc_us / bare_us:.1f}x bare",
         f"<= {IN_PROCESS_MAX:g}x", verdict(inproc_us / bare_us <= IN_PROCESS_MAX)),
        ("  the same, colour sensed (recorded)", f"{sensed_us:.2f} us/tick", f"{sensed_us / inproc_us:.2f}x in-process",
         "", ""),
        ("sandboxed tick (marginal, fast path)", f"{sandbox_us:.2f} us/tick", f"{sandbox_us / inproc_us:.1f}x in-process",
         f"<= {SANDBOXED_MAX:g}x", verdict(sandbox_us / inproc_us <= SANDBOXED_MAX)),
        ("  the same, lockstep", f"{lockstep_us:.2f} us/tick", f"{lockstep_us / inproc_us:.1f}x in-process", "", ""),
        (f"grade, one Part 6 ({LESSON_SECONDS:g} sim s)", f"{grade_s:.2f} s wall", f"{grading_x:,.0f}x real time",
         f">= {GRADING_MIN:g}x", verdict(grading_x >= GRADING_MIN)),
        ("  the same, lockstep", f"{grade_lockstep_s:.2f} s wall", f"{LESSON_SECONDS / grade_lockstep_s:,.0f}x real time",
         "", ""),
    ]
    print(f"  {'figure':<36} {'value':>16}  {'ratio':>22}  {'target':>8}")
    for name, value, ratio, target, mark in rows:
        print(f"  {name:<36} {value:>16}  {ratio:>22}  {target:>8}  {mark}")


if __name__ == "__main__":
    main()
