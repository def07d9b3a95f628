"""``turtletui run``: run controllers headless (the terminal app arrives with issue 3)."""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from turtletui.cli.errors import fail

ROS_ARGS: list[str] = []
"""The ``--ros-args`` section of the command line, cut off before Typer parses."""


def run(
    controllers: list[str] = typer.Argument(
        None,
        help="Controller files (rclpy nodes) or names of controllers registered by plugins"
        " (see turtletui plugins). Default: part6_wall_avoider, the course's Part 6 node.",
    ),
    headless: bool = typer.Option(False, "--headless", help="Run without the terminal app and print the log."),
    duration: float = typer.Option(60.0, "--duration", "-d", help="Simulated seconds to run."),
    seed: int = typer.Option(0, "--seed", help="Seed for everything random in the run."),
    realtime: bool = typer.Option(False, "--realtime", help="Run at wall-clock speed instead of lockstep."),
    record: Path = typer.Option(None, "--record", help="Write every message, call and log line to FILE.jsonl."),
    in_process: bool = typer.Option(
        False, "--in-process", help="Run the controllers in this process (trusted code only: no sandbox)."
    ),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="Print only the summary line."),
    plugin: list[Path] = typer.Option(None, "--plugin", help="Load a plugin file or folder (repeatable)."),
    lesson: str = typer.Option(None, "--lesson", help="Lesson to open in the app: an id (see turtletui lessons) or a file."),
    ascii_only: bool = typer.Option(False, "--ascii", help="Draw with plain ASCII and no colour."),
) -> None:
    """Run rclpy controller files against the simulated turtlesim.

    ROS arguments go last: turtletui run node.py --headless --ros-args -p speed:=2.0
    """
    if not headless:
        if not sys.stdout.isatty() or not sys.stdin.isatty():
            fail(
                "no terminal to draw the app in; run headless instead: "
                "turtletui run FILE.py --headless --duration 60"
            )
        _run_app(controllers, plugin, lesson, ascii_only, seed)
        return
    from turtletui.api import run as run_controllers
    from turtletui.compat.ros_args import RosArgsError
    from turtletui.runtime.loader import ControllerError
    from turtletui.runtime.resolve import resolve_controllers

    try:
        specs = resolve_controllers(controllers or ["part6_wall_avoider"], plugins=plugin or ())
    except ControllerError as err:
        fail(str(err))
    if not duration > 0:
        fail(f"--duration must be a positive number of seconds, got {duration}")

    def print_log(record) -> None:
        if not quiet:
            sys.stdout.write(record.format() + "\n")

    try:
        result = run_controllers(
            specs,
            duration=duration,
            seed=seed,
            realtime=realtime,
            sandbox=False if in_process else None,
            ros_args=ROS_ARGS,
            record=record,
            on_log=print_log,
            keep_calls=False,
        )
    except (ControllerError, RosArgsError, ValueError) as err:
        fail(str(err))
    except BrokenPipeError:
        raise  # stdout closed (``| head``): Click exits quietly
    except OSError as err:
        fail(str(err))
    for crash in result.crashes:
        if crash.kind == "load":
            # A sandboxed file without main() or Node is bad input, as in-process.
            fail(crash.message)
        sys.stderr.write(crash.details() + "\n")
    sys.stdout.write(result.summary() + "\n")
    if result.interrupted:
        raise SystemExit(130)
    if result.crashes:
        raise SystemExit(1)


PART6_SAFE_BOX = (2.0, 2.0, 9.0, 9.0)
"""The Part 6 controller's safe zone (x, y from and to, metres), drawn on the arena."""


def _run_app(
    controllers: list[str] | None, plugins: list[Path] | None, lesson: str | None, ascii_only: bool, seed: int
) -> None:
    """The Textual app (imported only here: headless runs never load Textual)."""
    from turtletui.lessons.loader import LessonError, find_lesson
    from turtletui.runtime.loader import ControllerError
    from turtletui.runtime.resolve import resolve_controllers

    overlays: tuple = ()
    if not controllers:
        controllers = ["part6_wall_avoider"]
        overlays = (PART6_SAFE_BOX,)
        lesson = lesson or "part6-closed-loop"
    lesson_path = None
    if lesson is not None:
        try:
            lesson_path = find_lesson(lesson, plugins=plugins or ()).path
        except LessonError as err:
            fail(f"--lesson: {err}")
    try:
        specs = resolve_controllers(controllers, plugins=plugins or ())
    except ControllerError as err:
        fail(str(err))
    from turtletui.tui.app import TurtleApp

    TurtleApp(specs, lesson=lesson_path, ascii=ascii_only, ros_args=ROS_ARGS, seed=seed, overlays=overlays).run()
