"""Grading speed: `turtletui grade` as an instructor runs it (no asserts: figures to read).

Run from the repository root:  python bench/bench_grade.py [--class-size 30] [--jobs 2] [--repeats 5]

1. One Part 6 submission (the lesson's 8 runs, 540 simulated seconds): wall
   time of the whole command, process start included (target < 2 s).
2. A class of Part 6 submissions (a mix of right and wrong controllers) with
   --jobs N (target: 30 submissions in < 45 s with --jobs 2 on 2 cores).
3. The same class again: every result is kept, so the rerun only checks them.
Baseline in the same process: one plain 60 s sandboxed run (turtletui run --headless).
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

from bench_core import as_installed, cpu_model  # noqa: E402

REFERENCE = ROOT / "plugins" / "reference" / "turtle_controller.py"
WRONG = ROOT / "tests" / "lessons" / "solutions" / "part6"
MIX = [REFERENCE, *sorted(WRONG.glob("*.py"))]


def turtletui(*args: str) -> float:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    started = time.perf_counter()
    subprocess.run([sys.executable, "-m", "turtletui", *args], check=True, env=env, stdout=subprocess.DEVNULL)
    return time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--class-size", type=int, default=30)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--repeats", type=int, default=5, help="times one submission is graded (median shown)")
    args = parser.parse_args()
    as_installed()
    same_user = ["--same-user"] if os.geteuid() == 0 else []
    print(f"machine: {os.cpu_count()} CPUs, {cpu_model()}, Python {sys.version.split()[0]}")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        one = work / "one" / "turtle_controller.py"
        one.parent.mkdir()
        shutil.copy(REFERENCE, one)
        baseline = turtletui("run", str(one), "--headless", "--quiet", "--duration", "60")
        print(f"baseline: one 60 s sandboxed run, whole command      {baseline:6.2f} s")
        for jobs in (1, args.jobs):
            times = sorted(
                turtletui(
                    "grade", str(one), "--lesson", "part6-closed-loop", "-q", "--jobs", str(jobs), "--force",
                    "--results", str(work / f"results-one-{jobs}"), *same_user,
                )
                for _ in range(args.repeats)
            )
            seconds = statistics.median(times)
            print(
                f"one Part 6 submission, --jobs {jobs}:                  {seconds:6.2f} s"
                f"  ({seconds / baseline:.1f}x the baseline; target < 2 s)"
                f"  median of {len(times)}, {times[0]:.2f}-{times[-1]:.2f} s"
            )
        klass = work / "class"
        for i in range(args.class_size):
            student = klass / f"student{i:02d}"
            student.mkdir(parents=True)
            shutil.copy(MIX[i % len(MIX)], student / "controller.py")
        results = work / "results-class"
        command = ["grade", str(klass), "--lesson", "part6-closed-loop", "-q", "--results", str(results), *same_user]
        for jobs in (1, args.jobs):
            seconds = turtletui(*command, "--jobs", str(jobs), "--force")
            print(
                f"class of {args.class_size}, --jobs {jobs}:                        {seconds:6.2f} s"
                f"  ({seconds / args.class_size:.2f} s per submission; target < 45 s for 30)"
            )
        again = turtletui(*command, "--jobs", str(args.jobs))
        print(f"the same class again (results kept):           {again:6.2f} s")


if __name__ == "__main__":
    main()
