"""``turtletui sim``: turtlesim alone, with no controller: the drop-in for
``ros2 run turtlesim turtlesim_node``, in the app (drive it with the keys and
the ros2 command line) or headless (real time, its log on stdout).

Both front ends run one Simulation in real time; with ``--ros`` a bridge
(turtletui.bridge) puts it on a real ROS 2 graph as the node /turtlesim, the
headless loop and the app staying as they are.
"""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from turtletui.cli.errors import fail
from turtletui.cli.plugin_manager import plugins_of
from turtletui.cli.ros_run import ros_python_option
from turtletui.cli.screen import require_screen

ROS_ARGS: list[str] = []
"""The ``--ros-args`` section of the command line, cut off before Typer parses."""


def sim(
    headless: bool = typer.Option(False, "--headless", help="Run without the app and print turtlesim's log."),
    duration: float = typer.Option(
        None, "--duration", "-d", help="Headless: wall-clock seconds to run (default: until Ctrl-C)."
    ),
    ascii_only: bool = typer.Option(False, "--ascii", help="Draw with plain ASCII and no colour."),
    pixels: str = typer.Option(
        "auto", "--pixels", help="How the app draws the arena: half, braille, graphics or auto (as turtletui run)."
    ),
    world: str = typer.Option(
        None,
        "--world",
        help="World to run in: a registered name (see turtletui plugins) or a .toml world file."
        " Default: turtlesim's empty arena.",
    ),
    seed: int = typer.Option(0, "--seed", help="Seed for everything random in the world."),
    record: str = typer.Option(
        None,
        "--record",
        metavar="PATH",
        help="Record every message, call and log line, as turtletui run does: run.jsonl, run.mcap or run/"
        " (a rosbag2 folder).",
    ),
    foxglove: str = typer.Option(
        None,
        "--foxglove",
        metavar="[HOST:PORT]",
        help="Serve it live to Foxglove or Lichtblick (default 127.0.0.1:8765), as turtletui run does.",
    ),
    plugin: list[Path] = typer.Option(None, "--plugin", help="Load a plugin file or folder (repeatable)."),
    ros: bool = typer.Option(
        False,
        "--ros",
        help="Be turtlesim on a real ROS 2 graph: the node /turtlesim with turtlesim_node's topics,"
        " services, action, parameters and log, for any ROS 2 program (needs a sourced ROS 2).",
    ),
    ros_python: str = ros_python_option(),
) -> None:
    """Run turtlesim alone, as ros2 run turtlesim turtlesim_node does.

    turtlesim's ROS arguments go last: turtletui sim --ros-args -p background_r:=0 -p holonomic:=true
    """
    # the same --world, --pixels, --record and --foxglove as run
    from turtletui.cli.run_cmd import _check_outputs, _drawing, _resolve_world
    from turtletui.compat.ros_args import RosArgsError
    from turtletui.runtime.turtlesim_args import parse_turtlesim_args

    try:
        args = parse_turtlesim_args(ROS_ARGS)
    except RosArgsError as err:
        fail(str(err))
    if duration is not None and not 0 < duration < 1e7:
        fail(f"--duration must be a positive number of seconds under 10,000,000, got {duration}")
    world_spec = None if world is None else _resolve_world(world, plugins_of(plugin))
    _check_outputs(record, foxglove)
    if ros_python is not None and not ros:
        fail("--ros-python goes with --ros")
    if ros:
        from turtletui.cli.ros_run import check_ros_options

        check_ros_options(record=record, foxglove=foxglove, in_process=False)
    if not headless:
        if duration is not None:
            fail("--duration is for --headless runs; the app runs until you quit it (q)")
        drawing = _drawing(pixels, ascii_only)
        require_screen("run headless instead: turtletui sim --headless")
        connection = _connect(ros, ros_python)
        from turtletui.tui.app import TurtleApp

        TurtleApp(
            [],
            ascii=ascii_only,
            seed=seed,
            world=world_spec,
            turtlesim=args,
            pixels=drawing.pixels,
            graphics=drawing.graphics,
            record=record,
            foxglove=foxglove,
            ros=connection,  # the session runs as the graph's distro
        ).run()
        return
    connection = _connect(ros, ros_python)
    from turtletui.graph.core import NS_PER_S
    from turtletui.runtime.outputs import run_outputs
    from turtletui.runtime.simulation import Simulation

    def print_log(record) -> None:
        # as turtlesim_node: rcutils writes log lines to stderr
        sys.stderr.write(record.format() + "\n")
        sys.stderr.flush()  # a live log: a pipe must not hold lines back

    limit_ns = round(duration * NS_PER_S) if duration is not None else 2**62
    started: list = []  # turtlesim's start lines: shown once a recording is open, and on /rosout with --ros
    show = args.log_filter(print_log)
    bridge = None
    try:  # from the first line turtlesim logs: Ctrl-C may come at any point after it
        simulation = Simulation(
            world=None if world_spec is None else world_spec.build(seed),
            realtime=True,
            log_sinks=[started.append],
            turtlesim_name=args.name,
            distro=_ros_distro(connection),
        )
        args.apply(simulation)
        sinks = simulation.graph.log_sinks
        sinks.remove(started.append)
        if connection is not None:
            from turtletui.bridge.run import attach

            bridge = attach(simulation, connection, earlier_logs=started, log_filter=args.log_filter)
            # other processes' lines (relayed from /rosout) are theirs to print
            show = bridge.local_only(show)
        sinks.append(show)
        with run_outputs(simulation, record, foxglove, earlier_logs=started):
            for line in started:
                show(line)
            simulation.run_until(limit_ns)
    except KeyboardInterrupt:
        pass  # Ctrl-C is how turtlesim_node ends; a recording is kept
    except BrokenPipeError:
        raise  # stdout closed (``| head``): Click exits quietly
    except (OSError, ValueError) as err:  # a Foxglove port in use, a recording that cannot be written
        fail(str(err))
    finally:
        if bridge is not None:
            bridge.close()
        elif connection is not None:
            connection.twin.close()


def _connect(ros: bool, ros_python: str | None):
    """The ROS 2 twin for --ros (None without), started first: a missing ROS 2 is one line."""
    if not ros:
        return None
    from turtletui.cli.ros_run import connect_or_fail

    return connect_or_fail(ros_python)


def _ros_distro(connection: object) -> str | None:
    """The distro of the real ROS 2 graph a run joins (``--ros``), else None (the default)."""
    if connection is None:
        return None
    from turtletui.bridge.run import distro_of

    return distro_of(connection)
