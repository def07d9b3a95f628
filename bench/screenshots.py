"""SVG screenshots of the app for the README: docs/app-120x40.svg, docs/app-80x24.svg
and docs/app-ascii-80x24.svg.

Run from the repository root:  python bench/screenshots.py [--seconds 3]

Each runs the default ``turtletui run`` app headless (Textual's run_test):
the Part 6 reference controller ``part6_wall_avoider`` sandboxed, the Part 6
lesson and the safe-box overlay, with seed 0. The app's clock is a fake one
that advances exactly 16 ms per tick and stops at --seconds (default 3), so
every shot shows the simulation at exactly t = 3.000 s whatever the machine's
speed (the clock starts once the controller is up, and the simulation waits
for every answer of the sandboxed controller, as in lockstep), and log
stamps use the fixed lockstep epoch instead of the wall clock.
"""

from __future__ import annotations

import argparse
import asyncio
import sys
import time
import types
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import turtletui.runtime.simulation as simulation  # noqa: E402
from turtletui.graph.core import LOCKSTEP_EPOCH_NS  # noqa: E402
from turtletui.runtime.resolve import resolve_controllers  # noqa: E402
from turtletui.tui.app import TICK_SECONDS, TurtleApp  # noqa: E402

DOCS = ROOT / "docs"
LESSON = ROOT / "lessons" / "part6_closed_loop.md"
SHOTS = (
    # file name, (columns, rows), ascii, key pressed before the shot
    ("app-120x40.svg", (120, 40), False, None),
    ("app-80x24.svg", (80, 24), False, "3"),
    ("app-ascii-80x24.svg", (80, 24), True, None),
)


class StepClock:
    """A monotonic clock that moves 16 ms per reading (one step per app tick)
    and stops at ``stop`` seconds: the simulation then stands still at exactly
    that simulated time while the app keeps drawing it."""

    def __init__(self, stop: float) -> None:
        self.start = self.now = 1000.0
        self.stop = self.start + stop
        self.running = False
        """Held until the controller has started (the app starts it after its first frame)."""

    def __call__(self) -> float:
        if self.running:
            self.now = min(self.now + TICK_SECONDS, self.stop)
        return self.now


async def shoot(filename: str, size: tuple[int, int], ascii_only: bool, key: str | None, seconds: float) -> Path:
    specs = resolve_controllers(["part6_wall_avoider"])
    clock = StepClock(seconds)
    app = TurtleApp(specs, lesson=LESSON, ascii=ascii_only, clock=clock)
    async with app.run_test(size=size) as pilot:
        for _ in range(200):
            if app.session is not None and all(slot.status != "starting" for slot in app.session.slots):
                break
            await pilot.pause(0.05)
        clock.running = True
        for _ in range(int(seconds * 20) + 200):  # the ticks take about `seconds` of wall time
            if clock.now >= clock.stop:
                break
            await pilot.pause(0.05)
        else:
            raise RuntimeError(f"{filename}: the app did not reach t = {seconds:g} s")
        await pilot.pause(0.2)  # a frame or two of the final state
        if key is not None:
            await pilot.press(key)
        await pilot.pause(0.3)
        app.save_screenshot(filename=filename, path=str(DOCS))
    return DOCS / filename


def fixed_epoch() -> None:
    """Log stamps are epoch + simulated time; a live simulation takes the epoch
    from the wall clock. Give it the lockstep epoch instead (this process only,
    and only the simulation module's view of ``time``)."""
    fake = types.SimpleNamespace(**{name: getattr(time, name) for name in dir(time) if not name.startswith("__")})
    fake.time_ns = lambda: LOCKSTEP_EPOCH_NS
    simulation.time = fake


def wait_for_the_controller() -> None:
    """The app waits at most 2 ms for the sandboxed controller's answer to each
    step (a slow answer is picked up later, as in ROS). On a busy machine that
    makes the controller late and the picture different; the shots wait for
    every answer instead, as lockstep does, so they show the same run anywhere."""
    simulation._UNPACED_BUDGET = 2.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seconds", type=float, default=3.0, help="simulated seconds to run before each shot")
    seconds = parser.parse_args().seconds
    DOCS.mkdir(exist_ok=True)
    fixed_epoch()
    wait_for_the_controller()
    for filename, size, ascii_only, key in SHOTS:
        path = asyncio.run(shoot(filename, size, ascii_only, key, seconds))
        print(f"{path.relative_to(ROOT)}  {path.stat().st_size / 1024:.0f} KB")


if __name__ == "__main__":
    main()
