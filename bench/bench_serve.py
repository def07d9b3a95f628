"""First frame of ``turtletui serve`` in a real browser (no asserts: a table to read).

Run from the repository root (needs Debian's chromium at /usr/bin/chromium and
the test extra: playwright, pyte, pillow):

    python bench/bench_serve.py [--repeats 5]

What is measured: ``turtletui serve FILE --lesson part6-closed-loop`` (FILE
the Part 6 starter, sandboxed) runs on a free port; headless chromium is
started once. Each repeat opens a new page at 1280x800 (about 142x44 cells)
and times, from the moment the page is asked for:

- page loaded: the DOMContentLoaded event (the page and textual.js);
- first bytes: the app's first terminal output arriving over the WebSocket
  (textual-serve has started the app process);
- first frame: the page's terminal, replayed into pyte, shows the status line
  and the arena with its metre scale: the target, <= 3 s;
- editor shown: the editor pane shows the file (it opens right after).

Baseline, in the same process: the terminal app's first frame in a
pseudo-terminal at 120x40 (bench_app.first_frame: ``turtletui run``, the Part 6
reference controller and lesson), median of the same number of starts; the
ratio says what the browser, the WebSocket and the server add.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_app import first_frame  # noqa: E402
from bench_core import cpu_model  # noqa: E402
from support.browser import BrowserTerminal, chromium, served, shows_the_arena  # noqa: E402

from turtletui.plugins.bundled import lessons_dir  # noqa: E402

TARGET_S = 3.0


def browser_start(browser, url: str) -> dict[str, float]:
    """Seconds from asking for the page to each milestone, in a new page."""
    context = browser.new_context(viewport={"width": 1280, "height": 800})
    page = context.new_page()
    terminal = BrowserTerminal(page)
    try:
        asked = time.monotonic()
        page.goto(url, wait_until="domcontentloaded")
        loaded = time.monotonic()
        frame = terminal.wait_for(shows_the_arena, "the arena")
        editor = terminal.wait_for(lambda text: "part6_starter.py" in text, "the editor")
        return {
            "page loaded": loaded - asked,
            "first bytes": terminal.first_data - asked,
            "first frame": frame - asked,
            "editor shown": editor - asked,
        }
    finally:
        context.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=5, help="page starts (median; default 5)")
    args = parser.parse_args()

    def row(name: str, value: str, target: str = "") -> None:
        print(f"  {name:<44} {value:>16}   {target}", flush=True)

    print(f"machine: {platform.platform()}")
    print(f"cpu:     {cpu_model()} ({os.cpu_count()} cores)")
    print(f"python:  {sys.version.split()[0]} ({platform.python_implementation()})")
    print(f"runs:    {args.repeats} page starts at 1280x800, {args.repeats} terminal starts at 120x40 (median)\n")
    print(f"  {'figure':<44} {'value':>16}   target")

    terminal_frames = [f for f in (first_frame(120, 40)[0] for _ in range(args.repeats)) if f is not None]
    baseline = statistics.median(terminal_frames) if terminal_frames else None
    row("terminal first frame (baseline)", f"{baseline:.3f} s" if baseline else "failed", "< 1.5 s")

    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "part6_starter.py").write_bytes((lessons_dir() / "part6_starter.py").read_bytes())
        with chromium() as browser, served("part6_starter.py", "--lesson", "part6-closed-loop", cwd=Path(tmp)) as url:
            browser_start(browser, url)  # warm-up: the browser's caches, the first app's imports
            runs = [browser_start(browser, url) for _ in range(args.repeats)]
    for name in ("page loaded", "first bytes", "first frame", "editor shown"):
        values = [run[name] for run in runs]
        target = f"<= {TARGET_S:g} s" if name == "first frame" else ""
        row(f"browser {name}", f"{statistics.median(values):.3f} s", target)
        if name == "first frame":
            row(f"browser {name}, min / max", f"{min(values):.2f} / {max(values):.2f} s")
    frame = statistics.median(run["first frame"] for run in runs)
    if baseline:
        row("browser first frame / terminal first frame", f"{frame / baseline:.2f}x")


if __name__ == "__main__":
    main()
