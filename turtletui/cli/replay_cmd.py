"""``turtletui replay RECORDING``: watch a recorded run again (a failed grading
scenario, or a ``turtletui run --record`` file), in the app or headless."""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from turtletui.cli.errors import fail
from turtletui.cli.screen import require_screen


def replay(
    recording: Path = typer.Argument(
        ..., metavar="RECORDING", help="A recording: run.jsonl, run.mcap or a rosbag2 folder."
    ),
    headless: bool = typer.Option(False, "--headless", help="Print the replayed log instead of opening the app."),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="Headless: print only the summary line."),
    ascii_only: bool = typer.Option(False, "--ascii", help="Draw with plain ASCII and no colour."),
    pixels: str = typer.Option("auto", "--pixels", help="half, braille, graphics or auto: as turtletui run."),
    png: Path = typer.Option(
        None, "--png", metavar="FILE", help="Draw the run's path as a PNG picture (an .svg name: SVG) instead."
    ),
) -> None:
    """Play a recorded run: the turtle drives the recorded path again."""
    from turtletui.runtime.replay import read_recording

    found = read_recording(recording)
    if png is not None:
        _picture(found, _world(found.header.get("world")), png)
        return
    if not headless:
        require_screen(f"replay headless instead: turtletui replay {recording} --headless")
    header = found.header
    if header:
        start = ", ".join(f"{v:.3f}" for v in found.start or ())
        where = f"lesson {header.get('lesson')}, scenario {header.get('scenario')}" if "lesson" in header else ""
        sys.stderr.write(f"replaying {recording} ({where}; start {start}; {found.duration:g} s)\n")
    world = _world(header.get("world"))
    if not headless:
        from turtletui.cli.run_cmd import _drawing

        drawing = _drawing(pixels, ascii_only)
        from turtletui.tui.app import TurtleApp

        TurtleApp(
            [],
            lesson=_lesson(header.get("lesson")),
            ascii=ascii_only,
            seed=int(header.get("seed", 0)),
            world=world,
            replay=found,
            pixels=drawing.pixels,
            graphics=drawing.graphics,
        ).run()
        return
    from turtletui.api import run
    from turtletui.runtime.replay import install_replay

    def print_log(record) -> None:
        if not quiet:
            sys.stdout.write(record.format() + "\n")

    try:
        result = run(
            [],
            duration=found.duration,
            seed=int(header.get("seed", 0)),
            setup=lambda sim: install_replay(sim, found),
            on_log=print_log,
            keep_calls=False,
            world=None if world is None else world.build(int(header.get("seed", 0))),
        )
    except BrokenPipeError:
        raise
    sys.stdout.write(result.summary() + "\n")


def _picture(found, world, out: Path) -> None:
    """Replay the recording (any format) headless and draw turtle1's path."""
    from turtletui.api import run
    from turtletui.grading.pictures import drawing_of, render_png, render_svg
    from turtletui.grading.reports import ReportError, write_text_atomic
    from turtletui.runtime.replay import install_replay

    seed = int(found.header.get("seed", 0))
    result = run(
        [],
        duration=found.duration,
        seed=seed,
        setup=lambda sim: install_replay(sim, found),
        keep_calls=False,
        keep_poses=True,
        world=None if world is None else world.build(seed),
    )
    poses = result.poses.get("turtle1", [])
    xy = [(x, y) for _, x, y, _ in poses]
    start = found.start or ((*xy[0], poses[0][3]) if poses else (5.544445, 5.544445, 0.0))
    drawing = drawing_of(xy, start, () if world is None else world.obstacles)
    try:
        if out.suffix.lower() == ".svg":
            write_text_atomic(out, render_svg(drawing))
        else:
            out.write_bytes(render_png(drawing))
    except (OSError, ReportError) as err:
        fail(f"cannot write {out}: {getattr(err, 'strerror', None) or err}")
    hits = len(drawing.hits)
    sys.stderr.write(f"wrote {out}: the path of turtle1, {hits} wall or obstacle hit{'' if hits == 1 else 's'} marked\n")


def _world(name: str | None):
    if name in (None, "empty"):
        return None
    from turtletui.worlds import WorldError, resolve_world

    try:
        return resolve_world(name)
    except WorldError as err:
        fail(f"{name}: {err}")


def _lesson(lesson_id):
    """The recorded run's lesson file, so the app shows its text and overlays; None if unknown."""
    if not isinstance(lesson_id, str):
        return None
    from turtletui.lessons.loader import LessonError, find_lesson

    try:
        return find_lesson(lesson_id).path
    except LessonError:
        return None
