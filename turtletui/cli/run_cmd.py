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
        fail("the terminal app is not available yet in this version; add --headless to run without it")
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
