"""``--ros`` for ``turtletui run`` and ``turtletui sim``: on a real ROS 2 graph (turtletui.bridge)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

import typer

from turtletui.cli.errors import fail

if TYPE_CHECKING:
    from turtletui.api import RunResult
    from turtletui.runtime.loader import ControllerSpec
    from turtletui.sim import World


def ros_python_option() -> Any:
    """``--ros-python PYTHON``, as run and sim take it."""
    return typer.Option(
        None,
        "--ros-python",
        metavar="PYTHON",
        help="With --ros: the python of the ROS 2 to use (default: a sourced ROS 2's;"
        " or set TURTLETUI_ROS_PYTHON).",
    )


def check_ros_options(
    *, record: str | None, foxglove: str | None, in_process: bool, distro: str | None = None
) -> None:
    """Options that mean nothing for processes on a real ROS 2 graph are refused."""
    if distro is not None:
        fail("--distro is not available with --ros: the ROS 2 that --ros joins is its own distro")
    if in_process:
        fail("--in-process and --ros do not go together: with --ros each file is its own ROS 2 process")
    if record is not None:
        fail("--record is not available with --ros: record the ROS 2 graph with ros2 bag record -a")
    if foxglove is not None:
        fail("--foxglove is not available with --ros: run foxglove_bridge on the ROS 2 graph instead")


def run_headless(
    specs: Sequence[ControllerSpec],
    duration: float,
    ros_python: str | None,
    ros_args: Sequence[str],
    on_log: Callable[[Any], None],
    world: World | None,
) -> RunResult:
    """Run the files as ROS 2 processes; a missing ROS 2 or a bad file is a clean exit."""
    from turtletui.bridge.process import RosUnavailable
    from turtletui.bridge.run import run_ros
    from turtletui.compat.ros_args import RosArgsError, parse_ros_args
    from turtletui.runtime.loader import ControllerError

    try:
        if ros_args:
            parse_ros_args(list(ros_args))
        return run_ros(specs, duration=duration, ros_python=ros_python, ros_args=ros_args, on_log=on_log, world=world)
    except (RosUnavailable, ControllerError, RosArgsError) as err:
        fail(str(err))


def connect_or_fail(ros_python: str | None, specs: Sequence[ControllerSpec] = ()) -> Any:
    """The twin, started before the app takes the screen: a missing ROS 2, or
    a controller that cannot run as a ROS 2 process, is one line."""
    from turtletui.bridge.process import RosUnavailable
    from turtletui.bridge.run import connect, ros_specs
    from turtletui.runtime.loader import ControllerError

    try:
        ros_specs(specs)
        return connect(ros_python)
    except (RosUnavailable, ControllerError) as err:
        fail(str(err))
