"""What happened to a controller: crash reports and stopping its turtles."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from turtletui.graph.logs import ERROR, INFO
from turtletui.messages import ENDED_EARLY_ADVICE, one_line

if TYPE_CHECKING:
    from turtletui.graph.core import Graph
    from turtletui.runtime.loader import ControllerSpec
    from turtletui.runtime.simulation import Simulation


@dataclass
class CrashReport:
    """A controller that stopped abnormally.

    ``kind`` is "exception", "exit", "timeout", "deadlock", "memory", "cpu", "killed",
    "slow" (too slow for real time) or "time" (over the run's time limit);
    ``frames`` are traceback lines from the controller's own file.
    """

    controller: str
    t: float
    kind: str
    message: str
    frames: list[str] = field(default_factory=list)

    def summary(self) -> str:
        """One line: who, when, what and where."""
        where = ""
        if self.frames:
            first = self.frames[-1].splitlines()[0].strip()
            where = f" ({first})"
        return f"controller {self.controller} {_VERB.get(self.kind, 'failed')} at t={self.t:.3f} s: {self.message}{where}"

    def details(self) -> str:
        return "\n".join([self.summary(), *self.frames])


_VERB = {
    "exception": "crashed",
    "exit": "exited",
    "timeout": "was stopped",
    "deadlock": "was stopped",
    "memory": "was stopped",
    "cpu": "was stopped",
    "slow": "was stopped",
    "time": "was stopped",
    "killed": "died",
}


def log_crash(graph: Graph, crash: CrashReport) -> None:
    """Log a crash as turtletui's ERROR lines: the summary, then the student's frames."""
    graph.log("turtletui", ERROR, crash.summary())
    for frame in crash.frames:
        for line in frame.splitlines():
            graph.log("turtletui", ERROR, line)


def log_ended_early(graph: Graph, label: str, t: float) -> None:
    """Note that controller ``label``'s program ended by itself at ``t``
    (seconds), before the run did: no error, but its nodes stopped with it (a
    main() that never spins, or returns at once), which alone explains a
    silent node."""
    graph.log("turtletui", INFO, f"{label} ended at t={t:.3f} s, before the run did, and its nodes stopped with it: {ENDED_EARLY_ADVICE}")


def log_exited(graph: Graph, label: str, t: float, frames: list[str]) -> None:
    """Note that controller ``label``'s program ended with ``sys.exit(0)`` (or
    ``sys.exit()``) in a callback at ``t`` (seconds): as under ROS, SystemExit
    goes out of rclpy.spin and the program ends with status 0, which is no
    crash; its nodes stopped with it. ``frames`` (CrashReport's) say where."""
    where = f" ({frames[-1].splitlines()[0].strip()})" if frames else ""
    graph.log("turtletui", INFO, f"{label} exited with status 0 at t={t:.3f} s{where}, before the run did: its nodes stopped with it")


def exited_in_callback(exc: BaseException) -> bool:
    """Whether SystemExit ``exc`` was raised inside a callback: its traceback
    goes through rclpy's spin (turtletui.compat), as a ``sys.exit()`` at the
    end of the program's own code does not."""
    import os

    compat = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "compat") + os.sep
    tb = exc.__traceback__
    while tb is not None:
        if tb.tb_frame.f_code.co_filename.startswith(compat):
            return True
        tb = tb.tb_next
    return False


def exit_message(code: object) -> str:
    """What ``sys.exit(code)`` with a failing ``code`` tells: the status
    ``python3 FILE`` exits with (1 for anything but a whole number, whose text
    Python prints), and that text."""
    if isinstance(code, int):
        return f"exited with status {int(code)}"
    return f"exited with status 1: {one_line(code)}"


def crash_from_exception(spec: ControllerSpec, t: float, exc: BaseException) -> CrashReport:
    from turtletui.runtime.loader import user_frames

    return CrashReport(spec.label, t, "exception", exception_message(exc), user_frames(exc.__traceback__, spec.path))


def exception_message(exc: BaseException) -> str:
    """``Type: text`` of an exception that ended a controller; an import of a
    name or module that is not there also says which was meant, as Python
    3.12 does ("Did you mean: 'Pose'?"), and not where turtletui keeps
    ROS's modules."""
    message = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
    if isinstance(exc, ImportError) and exc.name:
        message = _without_shim_path(message, exc)
        if "Did you mean" not in message:
            message += _meant(exc)
    return message


def _without_shim_path(message: str, exc: ImportError) -> str:
    from turtletui.compat import SHIM_PATH

    path = getattr(exc, "path", None)
    if path and str(path).startswith(SHIM_PATH):
        message = message.replace(f" ({path})", "")
    return message


def _meant(exc: ImportError) -> str:
    """". Did you mean: 'X'?" for the closest name the module (or package) has, or ""."""
    import difflib
    import pkgutil
    import re
    import sys

    assert exc.name is not None
    if isinstance(exc, ModuleNotFoundError):
        parent, _, wanted = exc.name.rpartition(".")
        package = sys.modules.get(parent) if parent else None
        if package is None or not hasattr(package, "__path__"):
            return ""
        names = [info.name for info in pkgutil.iter_modules(package.__path__)]
        prefix = f"{parent}."
    else:
        found = re.match(r"cannot import name '([^']+)'", str(exc))
        module = sys.modules.get(exc.name)
        if found is None or module is None:
            return ""
        wanted, names, prefix = found.group(1), [n for n in dir(module) if not n.startswith("_")], ""
    close = difflib.get_close_matches(wanted, names, n=1)
    return f". Did you mean: '{prefix}{close[0]}'?" if close else ""


def stop_turtles(sim: Simulation, owner: str) -> list[str]:
    """Stop every turtle whose cmd_vel ``owner`` ever published to (its controller
    ended). The stop is queued behind messages already on their way, so a
    command sent just before a crash does not start the turtle again."""
    names = [
        name
        for name in sim.world.turtles
        if owner in getattr(sim.graph.topics.get(f"/{name}/cmd_vel"), "publishers_made", ())
    ]

    def stop() -> None:
        for name in names:
            turtle = sim.world.turtles.get(name)
            if turtle is not None:
                turtle.vx = turtle.vy = turtle.wz = 0.0

    if names:
        sim.graph.ready.append(("sim", stop))
    return names
