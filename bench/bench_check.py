"""The app's check key against the CLI (no asserts: figures to read).

Run from the repository root:  python bench/bench_check.py [--lesson part6-closed-loop] [--repeats 3]

1. Baseline: ``turtletui grade FILE --lesson ID --same-user`` as a student
   runs it (default --jobs), whole command, results not kept between runs.
2. The app: ``k`` pressed in a running app (Textual's headless driver, the
   Part 6 controller running sandboxed at x1) until the score is shown,
   results not kept either. Target: no more than 1.5x the baseline.
Each figure is the median of the repeats, alternating the two so that both
see the same load.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

from bench_core import cpu_model  # noqa: E402

REFERENCE = ROOT / "plugins" / "reference" / "turtle_controller.py"


def cli_seconds(lesson: str, results: Path) -> float:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    started = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "turtletui", "grade", str(REFERENCE), "--lesson", lesson, "--same-user",
         "--quiet", "--format", "json", "--results", str(results)],
        check=True, env=env, stdout=subprocess.DEVNULL,
    )
    return time.perf_counter() - started


async def app_seconds(lesson: str, cache: Path) -> float:
    from turtletui.lessons.loader import find_lesson
    from turtletui.runtime.loader import ControllerSpec
    from turtletui.tui.app import TurtleApp

    os.environ["XDG_CACHE_HOME"] = str(cache)  # nothing kept from an earlier check
    app = TurtleApp([ControllerSpec("turtle_controller", path=REFERENCE)], lesson=find_lesson(lesson).path)
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause(1.0)  # the app and its controller are up
        panel = app.query_one("#lesson")
        started = time.perf_counter()
        await pilot.press("k")
        while "Score:" not in panel.source and "could not run" not in panel.source:
            await asyncio.sleep(0.02)
        elapsed = time.perf_counter() - started
        if "could not run" in panel.source:
            raise SystemExit(panel.source.splitlines()[2])
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lesson", default="part6-closed-loop")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    os.environ["XDG_DATA_HOME"] = tempfile.mkdtemp()  # the student's progress is not touched
    print(f"machine: {os.cpu_count()} CPUs, {cpu_model()}, Python {sys.version.split()[0]}")
    print(f"load:    {os.getloadavg()[0]:.2f} (1 min average, before)")
    cli, app = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(args.repeats):
            cli.append(cli_seconds(args.lesson, Path(tmp) / f"cli{i}"))
            app.append(asyncio.run(app_seconds(args.lesson, Path(tmp) / f"app{i}")))
    base, mine = statistics.median(cli), statistics.median(app)
    print(f"load:    {os.getloadavg()[0]:.2f} (1 min average, after)")
    print(f"lesson {args.lesson}, median of {args.repeats}")
    print(f"  turtletui grade (baseline)       {base:6.2f} s   ({', '.join(f'{t:.2f}' for t in cli)})")
    print(f"  k in the app                     {mine:6.2f} s   ({', '.join(f'{t:.2f}' for t in app)})")
    print(f"  app / CLI                        {mine / base:6.2f}x   target <= 1.5x")


if __name__ == "__main__":
    main()
