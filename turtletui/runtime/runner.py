"""Run a set of controllers against one simulation, start to end."""

from __future__ import annotations

import signal
import sys
import threading
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

from turtletui.graph.logs import ERROR
from turtletui.runtime.loader import ControllerError, ControllerSpec
from turtletui.runtime.report import CrashReport, log_crash
from turtletui.runtime.simulation import Simulation


@dataclass
class Outcome:
    """How the controllers ended: crash reports, and whether Ctrl-C cut the run short."""

    crashes: list[CrashReport] = field(default_factory=list)
    interrupted: bool = False


class _Interrupt:
    requested = False


@contextmanager
def _ctrl_c() -> Iterator[_Interrupt]:
    """Remember a Ctrl-C even if controller code catches the KeyboardInterrupt
    (the course's main() does), so the run stops as a ROS node would."""
    flag = _Interrupt()
    if threading.current_thread() is not threading.main_thread():
        yield flag
        return

    def on_sigint(signum: int, frame: Any) -> None:
        flag.requested = True
        raise KeyboardInterrupt

    previous_hook = sys.unraisablehook

    def quiet_interrupt(unraisable: Any) -> None:
        # A Ctrl-C that lands inside a finalizer (a Popen's __del__, say) cannot
        # propagate; Python would print it as "Exception ignored" with a
        # traceback. The flag already stops the run, so it needs no report.
        if flag.requested and isinstance(unraisable.exc_value, KeyboardInterrupt):
            return
        previous_hook(unraisable)

    previous = signal.signal(signal.SIGINT, on_sigint)
    sys.unraisablehook = quiet_interrupt
    try:
        yield flag
    finally:
        signal.signal(signal.SIGINT, previous)
        sys.unraisablehook = previous_hook


def run_controllers(
    sim: Simulation,
    specs: Sequence[ControllerSpec],
    end_ns: int,
    *,
    ros_args: list[str],
    seed: int,
    limits: Any = None,
    recipe: Any = None,
) -> Outcome:
    """Start the sandboxed controllers, let the in-process one (if any) drive
    through its own main(), then run the simulation to ``end_ns``. Every child
    process is closed, whatever happens. With ``recipe``
    (turtletui.runtime.replica.recipe_for) the one sandboxed controller takes
    the fast path."""
    inprocess = [s for s in specs if s.trusted]
    if len(inprocess) > 1:
        raise ControllerError("only one controller can run in-process at a time; run the others sandboxed")
    outcome = Outcome()
    hosts: list[Any] = []
    with _ctrl_c() as interrupt:
        try:
            sandboxed = [s for s in specs if not s.trusted]
            if sandboxed:
                from turtletui.runtime.sandbox import SandboxHost

                if recipe is not None:
                    from turtletui.runtime.fastpath import FastHost

                    (spec,) = sandboxed
                    hosts.append(FastHost.start(sim, spec, ros_args=ros_args, seed=seed, limits=limits, recipe=recipe))
                else:
                    for spec in sandboxed:
                        hosts.append(SandboxHost.start(sim, spec, ros_args=ros_args, seed=seed, limits=limits))
            for spec in inprocess:
                from turtletui.runtime.inprocess import run_in_process

                crash = run_in_process(sim, spec, end_ns, ros_args=ros_args, seed=seed)
                if crash is not None:
                    outcome.crashes.append(crash)
                    log_crash(sim.graph, crash)
            if not interrupt.requested and sim.graph.now_ns < end_ns:
                sim.run_until(end_ns)
        except KeyboardInterrupt:
            interrupt.requested = True
        finally:
            for host in hosts:
                crash = host.close()
                if crash is not None and not interrupt.requested:
                    outcome.crashes.append(crash)
        outcome.interrupted = interrupt.requested
    if outcome.interrupted:
        sim.graph.log("turtletui", ERROR, f"interrupted (Ctrl-C) at t={sim.t:.3f} s")
    return outcome
