"""Core performance figures of turtletui (no asserts: a table to read).

Run from the repository root:  python bench/bench_core.py [--repeats N]
Each figure is the median of a few repeats.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from turtletui.api import run  # noqa: E402
from turtletui.runtime.loader import ControllerSpec  # noqa: E402
from turtletui.sim.constants import DT  # noqa: E402

PART6 = ROOT / "plugins" / "reference" / "turtle_controller.py"


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.lower().startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def as_installed() -> None:
    """Byte-compile the package, as pip does when it installs it: an editable
    checkout (or PYTHONDONTWRITEBYTECODE) would otherwise make every process a
    run starts (the grader, its workers, fork servers) compile turtletui from
    source, about 0.15 s each, which no installed copy pays."""
    import compileall

    compileall.compile_dir(ROOT / "turtletui", quiet=1)


def median_of(fn, repeats: int) -> float:
    return statistics.median(fn() for _ in range(repeats))


def ticks_for(duration: float) -> int:
    return int(round(duration / DT))


def inprocess_wall(duration: float) -> float:
    spec = ControllerSpec("tc", PART6, trusted=True)
    result = run([spec], duration=duration, keep_calls=False, distro="jazzy")
    return result.wall_time


def sandboxed_wall(duration: float) -> float:
    started = time.perf_counter()
    run([str(PART6)], duration=duration, keep_calls=False, distro="jazzy")
    return time.perf_counter() - started


def baseline_wall(ticks: int) -> float:
    """A bare loop: the same physics and the same Part 6 decision, no middleware."""
    x = y = 5.544444561004639
    theta = 0.0
    v = w = 0.0
    dt = DT
    cos, sin = math.cos, math.sin
    started = time.perf_counter()
    for _ in range(ticks):
        theta += w * dt
        x += cos(theta) * v * dt
        y += sin(theta) * v * dt
        x = min(max(x, 0.0), 11.088889122009277)
        y = min(max(y, 0.0), 11.088889122009277)
        if x > 9.0 or x < 2.0 or y > 9.0 or y < 2.0:
            v, w = 1.0, 1.5
        else:
            v, w = 5.0, 0.0
    return time.perf_counter() - started


def subprocess_wall(code: str) -> tuple[float, str]:
    started = time.perf_counter()
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=False)
    return time.perf_counter() - started, out.stdout.strip()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeats", type=int, default=3)
    repeats = parser.parse_args().repeats
    as_installed()
    rows: list[tuple[str, str, str]] = []

    def row(name: str, value: str, target: str = "") -> None:
        rows.append((name, value, target))
        print(f"  {name:<44} {value:>16}   {target}", flush=True)

    print(f"machine: {platform.platform()}")
    print(f"cpu:     {cpu_model()} ({os.cpu_count()} cores)")
    print(f"python:  {sys.version.split()[0]} ({platform.python_implementation()})")
    print(f"repeats: {repeats} (median)\n")
    print(f"  {'figure':<44} {'value':>16}   target")

    # -- in-process lockstep ------------------------------------------------
    inprocess_wall(5)  # warm imports
    for duration in (600.0, 60.0):
        ticks = ticks_for(duration)
        wall = median_of(lambda d=duration: inprocess_wall(d), repeats)
        us = wall / ticks * 1e6
        tgt = ">= 3000x" if duration == 600 else ""
        row(f"in-process {duration:g} s: wall", f"{wall:.3f} s")
        row(f"in-process {duration:g} s: ticks/s", f"{ticks / wall:,.0f}")
        row(f"in-process {duration:g} s: us/tick", f"{us:.2f}", "<= 5.3" if duration == 600 else "")
        row(f"in-process {duration:g} s: real-time factor", f"{duration / wall:,.0f}x", tgt)
        if duration == 600:
            in_us = us
            base = median_of(lambda t=ticks: baseline_wall(t), repeats)
            base_us = base / ticks * 1e6
            row("bare-loop baseline: us/tick", f"{base_us:.3f}")
            row("in-process / bare loop", f"{in_us / base_us:,.0f}x")

    # -- sandboxed lockstep ---------------------------------------------------
    for duration in (60.0, 600.0):
        ticks = ticks_for(duration)
        reps = repeats if duration == 60 else max(1, min(repeats, 3))
        wall = median_of(lambda d=duration: sandboxed_wall(d), reps)
        row(f"sandboxed {duration:g} s: wall (incl. start)", f"{wall:.3f} s", "< 0.5 s" if duration == 60 else "")
        row(f"sandboxed {duration:g} s: real-time factor", f"{duration / wall:,.0f}x", ">= 300x")
        row(f"sandboxed {duration:g} s: round trip us/tick", f"{wall / ticks * 1e6:.1f}")

    # -- CLI start-up and headless imports ---------------------------------------
    help_code = 'from turtletui.cli import main; import sys; sys.argv=["turtletui","--help"]; main()'
    helps = [subprocess_wall(help_code)[0] for _ in range(5)]
    row("turtletui --help wall", f"{statistics.median(helps):.3f} s", "< 0.15 s")
    textual_code = (
        "import sys; from turtletui.api import run; "
        f"run([{str(PART6)!r}], duration=5, distro='jazzy'); print('textual' in sys.modules)"
    )
    row("textual imported by a headless run", subprocess_wall(textual_code)[1] or "?", "False")

    # -- memory -------------------------------------------------------------------------
    rss_code = (
        "import resource; from pathlib import Path; from turtletui.api import run; "
        "from turtletui.runtime.loader import ControllerSpec; "
        f"run([ControllerSpec('tc', Path({str(PART6)!r}), trusted=True)], duration=600, keep_calls=False, distro='jazzy'); "
        "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)"
    )
    out = subprocess_wall(rss_code)[1]
    try:
        kb = int(out.splitlines()[-1])
        # ru_maxrss is KiB on Linux, bytes on macOS
        mb = kb / 1024 if sys.platform != "darwin" else kb / 1024 / 1024
        row("peak RSS, 600 s in-process run", f"{mb:.1f} MB", "< 150 MB")
    except (ValueError, IndexError):
        row("peak RSS, 600 s in-process run", "failed", "< 150 MB")


if __name__ == "__main__":
    main()
