"""The ``turtletui`` command: thin Typer commands over turtletui's library API.

Importing this module must stay cheap (``turtletui --help`` in < 0.15 s): each
command imports what it needs when it runs, and nothing here imports Textual.
"""

from __future__ import annotations

import signal
import sys
from typing import Any

import typer
from typer.core import TyperGroup

from turtletui.cli import (
    autograder_cmd,
    grade_cmd,
    lessons_cmd,
    plugins_cmd,
    replay_cmd,
    run_cmd,
    serve_cmd,
    sim_cmd,
)
from turtletui.cli.errors import fail, internal_error
from turtletui.cli.merge_cmd import GradeCommand
from turtletui.errors import TurtletuiError

_CLICK_ENDS = (
    typer.Exit,
    typer.Abort,
    # ClickException: Click's own, or the one of the Click that newer Typers carry
    next(c for c in typer.BadParameter.__mro__ if c.__name__ == "ClickException"),
    KeyboardInterrupt,
    BrokenPipeError,
)
"""How a command may end that Click handles itself: --help and exits, usage
errors, Ctrl-C, a closed stdout (``| head``)."""

_USAGE_ERROR = next(c for c in typer.BadParameter.__mro__ if c.__name__ == "UsageError")


def usage_line(err: Any, argv: list[str]) -> str:
    """A usage error as one line naming the option and the value given
    (Click prints three lines, and for a bad number not the value)."""
    message = " ".join(err.format_message().split())
    where = f" (see {err.ctx.command_path} --help)" if getattr(err, "ctx", None) is not None else ""
    opts = list(getattr(getattr(err, "param", None), "opts", None) or [])
    if not message.startswith("Invalid value") or not opts or not opts[0].startswith("-"):
        return message + where
    value = None
    for i, word in enumerate(argv):
        name, eq, given = word.partition("=")
        if name in opts:
            value = given if eq else (argv[i + 1] if i + 1 < len(argv) else None)
    why = message.split(": ", 1)[-1].rstrip(".")
    got = "" if value is None or repr(value) in why else f" (got {value!r})"
    return f"{max(opts, key=len)}: {why[:1].lower()}{why[1:]}{got}{where}"


class _Commands(TyperGroup):
    """turtletui's commands: a TurtletuiError is a one-line error with exit
    status 2, anything else a bug reported as one (see cli.errors)."""

    def invoke(self, ctx: Any) -> Any:
        words = list(ctx.args)  # the subcommand's own words (the group takes them off as it runs)
        try:
            return super().invoke(ctx)
        except TurtletuiError as err:
            fail(" ".join(str(err).split()) or type(err).__name__)
        except _USAGE_ERROR as err:
            fail(usage_line(err, words))
        except _CLICK_ENDS:
            raise
        except Exception as err:  # noqa: BLE001 - a bug in turtletui: one line, the details in a file
            internal_error(err)


app = typer.Typer(
    cls=_Commands,
    name="turtletui",
    help="ROS 2's turtlesim in your terminal: run ordinary rclpy nodes against a simulated turtle.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)
app.command("run", context_settings={"allow_extra_args": False})(run_cmd.run)
app.command("sim")(sim_cmd.sim)
app.command("serve")(serve_cmd.serve)
app.command("plugins")(plugins_cmd.plugins)
app.command("lessons")(lessons_cmd.lessons)
app.command("lesson")(lessons_cmd.lesson)
app.command("new")(lessons_cmd.new)
app.command("grade", cls=GradeCommand)(grade_cmd.grade)  # and grade merge
app.command("checks")(grade_cmd.checks)
app.command("replay")(replay_cmd.replay)
app.add_typer(autograder_cmd.app, name="autograder")


def _print_version(value: bool) -> None:
    # An option callback: it runs while the line is parsed, before Click asks
    # for a command (a check in _root's body came too late: "Missing command").
    if value:
        from turtletui import __version__

        typer.echo(f"turtletui {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(
        False, "--version", help="Print the version and exit.", is_eager=True, callback=_print_version
    ),
) -> None:
    """ROS 2's turtlesim in your terminal."""


def split_ros_args(argv: list[str]) -> tuple[list[str], list[str]]:
    """Cut ``--ros-args ...`` off the command line: ROS's syntax is not Typer's."""
    if "--ros-args" in argv:
        i = argv.index("--ros-args")
        return argv[:i], argv[i:]
    return argv, []


def _interruptible() -> None:
    """Ctrl-C (SIGINT) ends a command even when it was started with SIGINT
    ignored, as a script's background job is: a ROS 2 node installs its own
    handler the same way, so turtlesim and rclpy nodes end on it regardless."""
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def main() -> None:
    """Console-script entry point."""
    _interruptible()
    argv, ros_args = split_ros_args(sys.argv[1:])
    run_cmd.ROS_ARGS[:] = sim_cmd.ROS_ARGS[:] = ros_args
    grade_cmd.OWN_PROCESS = True
    app(args=run_cmd.with_foxglove_default(argv), prog_name="turtletui")
