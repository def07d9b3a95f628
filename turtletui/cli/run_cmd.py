"""``turtletui run``: run controllers in the terminal app, or headless."""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import typer

from turtletui.cli.errors import fail
from turtletui.cli.plugin_manager import plugins_of
from turtletui.cli.ros_run import ros_python_option
from turtletui.cli.screen import require_screen

if TYPE_CHECKING:
    from turtletui.lessons.model import Lesson
    from turtletui.plugins.manager import Plugins
    from turtletui.worlds import WorldSpec

ROS_ARGS: list[str] = []
"""The ``--ros-args`` section of the command line, cut off before Typer parses."""


def run(
    controllers: list[str] = typer.Argument(
        None,
        help="Controller files (rclpy nodes) or names of controllers registered by plugins"
        " (see turtletui plugins). Default: the --lesson's reference node, else part6_wall_avoider,"
        " the course's Part 6 node.",
    ),
    headless: bool = typer.Option(False, "--headless", help="Run without the terminal app and print the log."),
    duration: float = typer.Option(60.0, "--duration", "-d", help="Simulated seconds to run."),
    seed: int = typer.Option(0, "--seed", help="Seed for everything random in the run."),
    realtime: bool = typer.Option(False, "--realtime", help="Run at wall-clock speed instead of lockstep."),
    record: str = typer.Option(
        None,
        "--record",
        metavar="PATH",
        help="Record every message, call and log line: run.jsonl (JSON Lines), run.mcap (MCAP for"
        " Foxglove, PlotJuggler, ros2 bag) or run/ (a rosbag2 folder for ros2 bag info|play).",
    ),
    foxglove: str = typer.Option(
        None,
        "--foxglove",
        metavar="[HOST:PORT]",
        help="Serve the run live to Foxglove or Lichtblick (default 127.0.0.1:8765; headless runs"
        " then run in real time). Needs: pip install 'turtletui[foxglove]'.",
    ),
    in_process: bool = typer.Option(
        False, "--in-process", help="Run the controllers in this process (trusted code only: no sandbox)."
    ),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="Print only the summary line."),
    plugin: list[Path] = typer.Option(None, "--plugin", help="Load a plugin file or folder (repeatable)."),
    lesson: str = typer.Option(None, "--lesson", help="Lesson to open in the app: an id (see turtletui lessons) or a file."),
    ascii_only: bool = typer.Option(False, "--ascii", help="Draw with plain ASCII and no colour."),
    pixels: str = typer.Option(
        "auto",
        "--pixels",
        help="How the app draws the arena: half (half blocks, any terminal), braille (finer trails),"
        " graphics (the real picture: Kitty, Sixel), or auto (the best the terminal shows).",
    ),
    distro: str = typer.Option(
        None,
        "--distro",
        metavar="NAME",
        help="The ROS 2 your nodes run as: humble, jazzy (turtlesim.msg), kilted or lyrical"
        " (turtlesim_msgs.msg). Default: $TURTLETUI_DISTRO, else the lesson's, else jazzy for files that"
        " import turtlesim.msg, else lyrical, the newest LTS. With --ros: the graph's own.",
    ),
    world: str = typer.Option(
        None,
        "--world",
        help="World to run in: a registered name (see turtletui plugins) or a .toml world file."
        " Default: the lesson's world, else turtlesim's empty arena.",
    ),
    ros: bool = typer.Option(
        False,
        "--ros",
        help="On a real ROS 2 graph: turtlesim as a real /turtlesim node, the files as ordinary ROS 2"
        " processes (the real rclpy), in real time; --duration is then wall seconds.",
    ),
    ros_python: str = ros_python_option(),
) -> None:
    """Run rclpy controller files against the simulated turtlesim.

    ROS arguments go last: turtletui run node.py --headless --ros-args -p speed:=2.0
    """
    if distro is not None:
        from turtletui.compat.distro import check_distro

        try:
            distro = check_distro(distro)
        except ValueError as err:
            fail(f"--distro: {err}")
    if ros_python is not None and not ros:
        fail("--ros-python goes with --ros")
    if ros:
        from turtletui.cli.ros_run import check_ros_options

        check_ros_options(record=record, foxglove=foxglove, in_process=in_process, distro=distro)
    if not headless:
        require_screen("run headless instead: turtletui run FILE.py --headless --duration 60")
        _run_app(controllers, plugins_of(plugin), lesson, ascii_only, seed, world, pixels, record, foxglove,
                 distro, ros_python if ros else None, ros)
        return
    from turtletui.api import run as run_controllers
    from turtletui.compat.ros_args import RosArgsError
    from turtletui.graph.logs import ERROR_SUFFIX, OUTPUT_SUFFIX
    from turtletui.runtime.loader import ControllerError
    from turtletui.runtime.resolve import resolve_controllers

    plugins = plugins_of(plugin)
    if not 0 < duration < 1e7:
        fail(f"--duration must be a positive number of seconds under 10,000,000, got {duration}")
    _check_pixels(pixels)
    _check_outputs(record, foxglove)
    # no distro yet: turtletui.api.run (the app: its session) lets the files' imports choose, and says so
    found, distro, world_spec = _lesson_distro_world(lesson, plugins, distro, world)
    specs = resolve_controllers(controllers or [demo_controller(found)], plugins=plugins)
    sim_world = None if world_spec is None else world_spec.build(seed)

    said: set[str] = set()
    """turtletui's own lines printed: a crash the log told is not told again."""

    def print_log(record) -> None:
        # As under ROS: a node's log lines go to stderr in rcutils' console
        # format, what a sandboxed controller prints goes to stdout as it is,
        # and what it writes to stderr to stderr.
        if quiet:
            return
        if record.node == "turtletui":
            said.add(record.msg)
        if record.node.endswith(OUTPUT_SUFFIX):
            sys.stdout.write(record.msg + "\n")
        elif record.node.endswith(ERROR_SUFFIX):
            sys.stderr.write(record.msg + "\n")
        else:
            sys.stderr.write(record.format() + "\n")

    if ros:
        from turtletui.cli.ros_run import run_headless

        def print_live(record) -> None:
            print_log(record)
            sys.stdout.flush()  # in real time beside other processes: no line held back

        result = run_headless(specs, duration, ros_python, ROS_ARGS, print_live, sim_world)
    else:
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
                world=sim_world,
                foxglove=foxglove,
                distro=distro,
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
        if crash.summary() not in said:  # (a crash the log told, as it happened, is not told twice)
            sys.stderr.write(crash.details() + "\n")
    sys.stdout.write(result.summary() + "\n")
    if result.interrupted:
        raise SystemExit(130)
    if result.crashes:
        raise SystemExit(1)


def _resolve_world(name: str, plugins: Plugins, what: str = "--world") -> WorldSpec:
    """The WorldSpec ``--world`` (or a lesson) names; a clean exit if there is none."""
    from turtletui.worlds import WorldError, resolve_world

    try:
        return resolve_world(name, plugins=plugins)
    except WorldError as err:
        fail(f"{what}: {err}")


def _run_app(
    controllers: list[str] | None,
    plugins: Plugins,
    lesson: str | None,
    ascii_only: bool,
    seed: int,
    world: str | None = None,
    pixels: str = "auto",
    record: str | None = None,
    foxglove: str | None = None,
    distro: str | None = None,
    ros_python: str | None = None,
    ros: bool = False,
) -> None:
    """The Textual app (imported only here: headless runs never load Textual)."""
    _check_outputs(record, foxglove)
    from turtletui.runtime.resolve import resolve_controllers

    # A lesson asked for opens beside the arena; the demo's own (no files) shows its log streaming.
    panel = "lesson" if lesson is not None else "log"
    if not controllers:
        lesson = lesson or "part6-closed-loop"
    found, distro, world_spec = _lesson_distro_world(lesson, plugins, distro, world)
    lesson_path = None if found is None else found.path
    specs = resolve_controllers(controllers or [demo_controller(found)], plugins=plugins)
    connection = None
    if ros:
        from turtletui.cli.ros_run import connect_or_fail

        connection = connect_or_fail(ros_python, specs)
    drawing = _drawing(pixels, ascii_only)
    from turtletui.tui.app import TurtleApp

    TurtleApp(
        specs,
        lesson=lesson_path,
        ascii=ascii_only,
        ros_args=ROS_ARGS,
        seed=seed,
        world=world_spec,
        pixels=drawing.pixels,
        graphics=drawing.graphics,
        record=record,
        foxglove=foxglove,
        distro=distro,
        ros=connection,
        panel=panel,
    ).run()


def demo_controller(lesson: Lesson | None) -> str:
    """What runs when no file is given: the lesson's reference node (what the
    lesson's node does), else the course's Part 6 node."""
    return (lesson.reference if lesson is not None else None) or "part6_wall_avoider"


def _lesson_distro_world(lesson: str | None, plugins: Plugins, distro: str | None, world: str | None):
    """The lesson (``--lesson``: an id or a file), the distro (``--distro``,
    else ``$TURTLETUI_DISTRO``, else the lesson's; None when none of them
    says) and the world (``--world``, else the lesson's) of a run."""
    from turtletui.compat.distro import choose_distro
    from turtletui.lessons.loader import LessonError, find_lesson

    found = None
    if lesson is not None:
        try:
            found = find_lesson(lesson, plugins=plugins)
        except LessonError as err:
            fail(f"--lesson: {err}")
    try:
        # no file paths: with nothing chosen, the files choose as the run starts (api.run, the app)
        distro, _ = choose_distro(distro, None if found is None else found.distro)
    except ValueError as err:
        fail(str(err))
    what = "--world"
    if found is not None and world is None and found.world != "empty":
        world, what = found.world, f"lesson {found.id}: world"
    world_spec = None if world is None else _resolve_world(world, plugins, what)
    return found, distro, world_spec


def _check_pixels(pixels: str) -> None:
    """--pixels names a way of drawing, also where nothing is drawn (headless)."""
    from turtletui.tui.terminal import PIXEL_CHOICES  # no Textual

    if pixels not in PIXEL_CHOICES:
        fail(f"--pixels: expected one of {', '.join(PIXEL_CHOICES)}, got {pixels!r}")


def _drawing(pixels: str, ascii_only: bool):
    """How the app draws the arena in this terminal (asked before Textual takes it over)."""
    from turtletui.tui.terminal import TerminalError, choose_drawing

    try:
        return choose_drawing(pixels, ascii=ascii_only)
    except TerminalError as err:
        fail(f"--pixels: {err}")


def _check_outputs(record: str | None, foxglove: str | None) -> None:
    """A bad --record path or --foxglove address is an error before the app starts."""
    from turtletui.runtime.recorder import check_record_path

    try:
        if record is not None:
            check_record_path(record)
        if foxglove is not None:
            from turtletui.recording.foxglove import parse_address

            parse_address(foxglove)
    except (OSError, ValueError) as err:
        fail(str(err))


FOXGLOVE_DEFAULT = "127.0.0.1:8765"
_ADDRESS = re.compile(r"(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9.-]+)?:?\d{1,5}")


def with_foxglove_default(argv: list[str]) -> list[str]:
    """``--foxglove`` with no address gets the default: Click options cannot
    take an optional value, so a bare flag is completed before parsing."""
    out: list[str] = []
    for i, arg in enumerate(argv):
        out.append(arg)
        if arg == "--foxglove":
            following = argv[i + 1] if i + 1 < len(argv) else None
            if following is None or not _ADDRESS.fullmatch(following):
                out.append(FOXGLOVE_DEFAULT)
    return out
