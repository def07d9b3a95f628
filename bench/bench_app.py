"""Figures of the terminal app, measured in a real pseudo-terminal (no asserts: a table to read).

Run from the repository root:

    python bench/bench_app.py                          # quick: 20 s tick runs, 2 min memory run
    python bench/bench_app.py --seconds 60 --minutes 10  # the figures the targets are set for

What is measured (the app is the default ``turtletui run``: the Part 6
reference controller ``part6_wall_avoider`` in its sandbox, the Part 6 lesson
with its safe-box overlay, the arena in half blocks), each at 120x40 and 80x24
unless said otherwise. The machine's load average is printed before and after:
on a shared machine the tick figures say more about the neighbours than about
the app.

- first frame: ``python -m turtletui run`` is spawned on a new pty
  (TERM=xterm-256color); time from the spawn until the pty output, escape
  sequences removed, contains the status line text " t = ". Median of
  ``--repeats`` starts. Then 'q' is sent and the time to exit is noted too.
- tick period: a child on a new pty runs TurtleApp in-process (the same specs
  and lesson as ``turtletui run``) for ``--seconds``; the simulation ticks in
  the app's ticker thread; after a warm-up
  of WARMUP_SECONDS it clears ``app.tick_gaps`` and takes
  ``getrusage(RUSAGE_SELF)``; at the end it writes the mean gap, the p99 of
  |gap - 16 ms| and the CPU share (user+sys of the app process only: the
  sandboxed controller is another process and is not counted) to a JSON file.
  The parent keeps reading (and discarding) the pty output, as a terminal does.
- memory: the same in-process run at 120x40 for ``--minutes``; RSS from
  /proc/self/statm at minute 1 and at the end. The target (within 10 %) is set
  for minute 1 vs minute 10: use ``--minutes 10``; the quick default (2) only
  shows the trend.
"""

from __future__ import annotations

import argparse
import errno
import fcntl
import json
import os
import platform
import pty
import re
import select
import signal
import statistics
import struct
import sys
import tempfile
import termios
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_core import cpu_model  # noqa: E402

SIZES = ((120, 40), (80, 24))
WARMUP_SECONDS = 2.0
"""Start-up (imports, sandbox start, first layout) is left out of the tick figures."""

MARKER = " t = "
ANSI = re.compile(rb"\x1b(?:\[[0-?]*[ -/]*[@-~]|\][^\x07\x1b]*(?:\x07|\x1b\\)|P[^\x1b]*\x1b\\|[@-Z\\-_])")

CHILD = r"""
import json, os, resource, sys, time
params = json.loads(sys.argv[1])
sys.path.insert(0, params["root"])
from pathlib import Path
from turtletui.plugins.bundled import lessons_dir
from turtletui.runtime.resolve import resolve_controllers
from turtletui.tui.app import TICK_SECONDS, TurtleApp


class BenchApp(TurtleApp):
    CSS_PATH = str(Path(sys.modules[TurtleApp.__module__].__file__).with_name(TurtleApp.CSS_PATH))

    def on_ready(self):  # timers need the running app (TurtleApp has no on_ready of its own)
        self.set_timer(params["warmup"], warm)
        if params["seconds"] > 60:
            self.set_timer(60.0, minute)
        self.set_timer(params["warmup"] + params["seconds"], finish)

specs = resolve_controllers(["part6_wall_avoider"])
lesson = lessons_dir() / "part6_closed_loop.md"
app = BenchApp(specs, lesson=lesson)
page = os.sysconf("SC_PAGE_SIZE")
stats = {}

def rss_mb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * page / 2**20

def cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime

def warm():
    app.tick_gaps.clear()
    stats["cpu0"], stats["wall0"], stats["t0"] = cpu(), time.monotonic(), app.session.t

def minute():
    stats["rss_minute1_mb"] = rss_mb()

def finish():
    gaps = sorted(app.tick_gaps)
    dev = sorted(abs(g - TICK_SECONDS) for g in gaps)
    wall = time.monotonic() - stats["wall0"]
    stats.update(
        ticks=len(gaps),
        mean_ms=sum(gaps) / len(gaps) * 1e3 if gaps else float("nan"),
        p99_dev_ms=dev[min(len(dev) - 1, int(0.99 * len(dev)))] * 1e3 if dev else float("nan"),
        max_gap_ms=gaps[-1] * 1e3 if gaps else float("nan"),
        cpu_pct=(cpu() - stats["cpu0"]) / wall * 100,
        sim_per_wall=(app.session.t - stats["t0"]) / wall,
        rss_end_mb=rss_mb(),
        status=app._status().strip(),
    )
    with open(params["out"], "w") as f:
        json.dump(stats, f)
    app.exit()

app.run()
"""


def load_average() -> str:
    return ", ".join(f"{load:.2f}" for load in os.getloadavg())


def spawn(argv: list[str], cols: int, rows: int) -> tuple[int, int]:
    """Fork a child on a new pty of cols x rows running argv; (pid, master fd)."""
    pid, fd = pty.fork()
    if pid == 0:  # the child: its stdin/stdout/stderr are the pty
        try:
            fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))
            env = dict(os.environ, TERM="xterm-256color", COLUMNS=str(cols), LINES=str(rows))
            env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(ROOT), env.get("PYTHONPATH")]))
            env.pop("NO_COLOR", None)
            os.chdir(ROOT)
            os.execve(sys.executable, argv, env)
        finally:
            os._exit(127)
    return pid, fd


def read_some(fd: int, timeout: float) -> bytes | None:
    """Bytes from the pty (b'' if none came in time), None once the child closed it."""
    ready, _, _ = select.select([fd], [], [], max(timeout, 0.0))
    if not ready:
        return b""
    try:
        return os.read(fd, 65536) or None
    except OSError as err:  # EIO: the slave side is closed
        if err.errno == errno.EIO:
            return None
        raise


def reap(pid: int, fd: int, deadline: float) -> float | None:
    """Drain the pty until the child exits (killing it at the deadline); its exit time."""
    while time.monotonic() < deadline:
        if read_some(fd, 0.05) is None:
            break
        done, _ = os.waitpid(pid, os.WNOHANG)
        if done:
            break
    exited = time.monotonic()
    done, _ = os.waitpid(pid, os.WNOHANG)
    if not done:
        if time.monotonic() >= deadline:
            os.kill(pid, signal.SIGTERM)
            exited = None
        os.waitpid(pid, 0)
    os.close(fd)
    return exited


def first_frame(cols: int, rows: int) -> tuple[float | None, float | None]:
    """(seconds to the first frame, seconds from 'q' to exit) of ``python -m turtletui run``."""
    started = time.monotonic()
    pid, fd = spawn([sys.executable, "-m", "turtletui", "run"], cols, rows)
    seen = b""
    frame = None
    deadline = started + 20.0
    while time.monotonic() < deadline:
        chunk = read_some(fd, deadline - time.monotonic())
        if chunk is None:
            break
        seen += chunk
        if MARKER.encode() in ANSI.sub(b"", seen[-65536:]):
            frame = time.monotonic() - started
            break
    if frame is None:
        reap(pid, fd, time.monotonic())
        return None, None
    # Let it run a moment (the 'q' of a real user is not instant), then quit.
    until = time.monotonic() + 1.0
    while time.monotonic() < until and read_some(fd, 0.05) is not None:
        pass
    asked = time.monotonic()
    os.write(fd, b"q")
    exited = reap(pid, fd, asked + 10.0)
    return frame, (exited - asked if exited is not None else None)


def inprocess_run(cols: int, rows: int, seconds: float) -> dict | None:
    """Run TurtleApp for ``seconds`` after the warm-up in a child on a pty; its stats."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "stats.json"
        params = {"root": str(ROOT), "out": str(out), "seconds": seconds, "warmup": WARMUP_SECONDS}
        pid, fd = spawn([sys.executable, "-c", CHILD, json.dumps(params)], cols, rows)
        tail = b""
        deadline = time.monotonic() + WARMUP_SECONDS + seconds + 30.0
        while time.monotonic() < deadline:
            chunk = read_some(fd, 0.5)
            if chunk is None:
                break
            tail = (tail + chunk)[-4096:]  # kept for an error message only
        reap(pid, fd, time.monotonic() + 10.0)
        if not out.exists():
            text = ANSI.sub(b"", tail).decode("utf-8", "replace").strip()
            print(f"  (run at {cols}x{rows} wrote no stats; last output: {text[-300:]!r})", flush=True)
            return None
        return json.loads(out.read_text())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seconds", type=float, default=60.0, help="length of each tick run (default 60)")
    parser.add_argument("--minutes", type=float, default=2.0, help="length of the memory run (target: 10)")
    parser.add_argument("--repeats", type=int, default=3, help="first-frame starts per size (median)")
    args = parser.parse_args()

    def row(name: str, value: str, target: str = "") -> None:
        print(f"  {name:<44} {value:>16}   {target}", flush=True)

    print(f"machine: {platform.platform()}")
    print(f"cpu:     {cpu_model()} ({os.cpu_count()} cores)")
    print(f"python:  {sys.version.split()[0]} ({platform.python_implementation()})")
    print(f"load:    {load_average()} (1, 5, 15 min) at the start")
    print(
        f"runs:    first frame median of {args.repeats}; tick runs {args.seconds:g} s;"
        f" memory run {args.minutes:g} min (after a {WARMUP_SECONDS:g} s warm-up)\n"
    )
    print(f"  {'figure':<44} {'value':>16}   target")

    # -- first frame ------------------------------------------------------------------
    for cols, rows in SIZES:
        frames, exits = [], []
        for _ in range(args.repeats):
            frame, exit_s = first_frame(cols, rows)
            if frame is not None:
                frames.append(frame)
            if exit_s is not None:
                exits.append(exit_s)
        size = f"{cols}x{rows}"
        row(f"{size} first frame", f"{statistics.median(frames):.3f} s" if frames else "failed", "< 1.5 s")
        if len(frames) > 1:
            row(f"{size} first frame, min / max", f"{min(frames):.2f} / {max(frames):.2f} s")
        row(f"{size} 'q' to exit", f"{statistics.median(exits):.3f} s" if exits else "failed")

    # -- tick period and CPU ---------------------------------------------------------------
    def tick_rows(label: str, stats: dict | None) -> None:
        if stats is None:
            row(f"{label}: tick run", "failed")
            return
        row(f"{label}: ticks", f"{stats['ticks']}")
        row(f"{label}: mean tick period", f"{stats['mean_ms']:.3f} ms", "16.0 +- 0.2 ms")
        row(f"{label}: p99 |period - 16 ms|", f"{stats['p99_dev_ms']:.3f} ms", "<= 4 ms")
        row(f"{label}: longest gap", f"{stats['max_gap_ms']:.1f} ms")
        row(f"{label}: app CPU (one core)", f"{stats['cpu_pct']:.1f} %", "<= 25 %")
        row(f"{label}: sim s per wall s", f"{stats['sim_per_wall']:.3f}", "1.000")

    for cols, rows in SIZES:
        tick_rows(f"{cols}x{rows} {args.seconds:g} s", inprocess_run(cols, rows, args.seconds))

    # -- memory -----------------------------------------------------------------------------
    cols, rows = SIZES[0]
    label = f"{cols}x{rows} {args.minutes:g} min"
    stats = inprocess_run(cols, rows, args.minutes * 60.0)
    tick_rows(label, stats)
    if stats is not None:
        start = stats.get("rss_minute1_mb")
        end = stats["rss_end_mb"]
        if start is None:
            row(f"{label}: RSS at the end", f"{end:.1f} MB")
            row(f"{label}: RSS minute 1 vs end", "run <= 1 min", "within 10 %")
        else:
            row(f"{label}: RSS at minute 1", f"{start:.1f} MB")
            row(f"{label}: RSS at the end", f"{end:.1f} MB")
            row(f"{label}: RSS growth, minute 1 to end", f"{(end - start) / start * 100:+.1f} %", "within 10 %")
        print(f"\n  status line at the end: {stats['status']}")

    print(f"\n  load average at the end: {load_average()} (1, 5, 15 min)")
    print(
        "\nfirst frame: spawn of `python -m turtletui run` to the status line in the pty output."
        "\nmean tick period / p99: wall gaps between the app's 16 ms simulation ticks (app.tick_gaps)"
        " while it renders\n  at most 30 frames/s with the Part 6 controller sandboxed; the p99 is of"
        " |gap - 16 ms|."
        "\napp CPU: user+sys of the app process only (getrusage RUSAGE_SELF), per wall second, in %"
        " of one core;\n  the sandboxed controller process is not counted."
        "\nsim s per wall s: simulated time gained per wall second (1.000 = real time)."
        "\nRSS: resident set from /proc/self/statm; the target compares minute 1 with minute 10"
        " (--minutes 10)."
    )


if __name__ == "__main__":
    main()
