"""Host a controller in this process: trusted code (reference plugins, tests).

The controller's own ``main()`` drives: its ``rclpy.spin`` (or ``spin_once``,
``spin_until_future_complete``, ``wait_for_service``, ``rate.sleep``) pumps
the shared simulation, so lockstep needs no threads and no copies.
"""

from __future__ import annotations

import itertools
import random
import sys
import threading
from collections.abc import Callable

from turtletui import compat
from turtletui.compat import context as compat_context
from turtletui.compat import logging as compat_logging
from turtletui.runtime.host import CallbackTracking, Depth, RunEnded
from turtletui.runtime.loader import (
    ControllerError,
    ControllerSpec,
    run_controller,
    seed_numpy,
    user_frames,
)
from turtletui.runtime.report import (
    CrashReport,
    crash_from_exception,
    exit_message,
    exited_in_callback,
    log_ended_early,
    log_exited,
    stop_turtles,
)
from turtletui.runtime.scheduler import CLOCK_READS_PER_STEP, CLOCK_STEP_NS
from turtletui.runtime.simulation import MAX_ROUNDS_PER_INSTANT, Simulation
from turtletui.runtime.virtual_time import simulated_time


class InProcessHost(CallbackTracking):
    """Implements turtletui.compat.context.Host over a Simulation in this process."""

    def __init__(self, sim: Simulation, owner: str, end_ns: int) -> None:
        self.sim = sim
        self.graph = sim.graph
        self.owner = owner
        self.end_ns = end_ns
        self.running = True
        """False once the run has ended (a plain attribute: every spin reads it)."""
        self._instant = -1
        self._rounds = 0
        self._reads_instant = -1
        self._reads = 0
        self.controller_thread = threading.get_ident()
        self._depth = Depth()
        self.call_numbers = itertools.count(1)

    @property
    def callback_depth(self) -> int:
        # Callbacks run on the controller's thread only (see _one_thread): a
        # plain counter (see CallbackTracking) costs less per delivery.
        return self._depth.n if threading.get_ident() == self.controller_thread else 0

    def _one_thread(self) -> None:
        """Only the thread that runs the controller may wait here: threads that
        take turns need a process of their own (the sandbox)."""
        if threading.get_ident() != self.controller_thread:
            raise RuntimeError(
                "a controller run in-process can spin and sleep on its main thread only; "
                "run it sandboxed (without --in-process) to use threads"
            )

    def clock_read(self) -> None:
        """A reading of a simulated clock: every CLOCK_READS_PER_STEP at one
        instant let CLOCK_STEP_NS pass (turtletui.runtime.scheduler)."""
        now = self.graph.now_ns
        if now != self._reads_instant:
            self._reads_instant, self._reads = now, 0
        self._reads += 1
        if self._reads >= CLOCK_READS_PER_STEP:
            self.sleep_until(now + CLOCK_STEP_NS)

    def spin(self, stop: Callable[[], bool]) -> None:
        """Run every callback as it becomes ready until ``stop()`` or the end."""
        self._one_thread()
        if self.running:
            self.sim.pump(None, self.end_ns, until=stop)
            self._check_end()

    def _limit(self, timeout_ns: int | None) -> int:
        if timeout_ns is None:
            return self.end_ns
        return min(self.graph.now_ns + max(timeout_ns, 0), self.end_ns)

    def _check_end(self, deadline_ns: int | None = None) -> None:
        """The run is over once time is at its end and the controller waits
        for a later moment (``deadline_ns``; None: for ever). A wait that ends
        at the last instant itself returns with the run still going, as in
        the sandbox: the timers due then fire, and code after the wait runs."""
        if self.graph.now_ns >= self.end_ns and (deadline_ns is None or deadline_ns > self.end_ns):
            self.running = False

    def _deadline(self, timeout_ns: int | None) -> int | None:
        return None if timeout_ns is None else self.graph.now_ns + max(timeout_ns, 0)

    def spin_once(self, timeout_ns: int | None, wake: Callable[[], bool] | None = None) -> bool:
        """Run one callback, waiting up to ``timeout_ns`` (``wake`` is for hosts
        with threads: here no other thread can hand a callback over)."""
        self._one_thread()
        if not self.running:
            return self.waited_after_end()
        deadline = self._deadline(timeout_ns)
        outcome = self.sim.pump(self.owner, self.end_ns if timeout_ns is None else self._limit(timeout_ns))
        if outcome != "own":
            self._check_end(deadline)
        return outcome == "own" or self.running

    def spin_until(self, done: Callable[[], bool], timeout_ns: int | None, *, callbacks: bool = True) -> bool:
        self._one_thread()
        now = self.graph.now_ns
        if now != self._instant:
            self._instant, self._rounds = now, 0
        self._rounds += 1
        if self._rounds > MAX_ROUNDS_PER_INSTANT:
            # A loop of waits that each finish at once (calls answered in the
            # same instant) must not stop the world: let time reach its next event.
            due = self.graph.next_due()
            self.sleep_until(self.end_ns if due is None else due)
        limit = self._limit(timeout_ns)
        deadline = self._deadline(timeout_ns)
        while not done():
            if not self.running or self.graph.now_ns >= limit:
                self._check_end(deadline)
                return False
            self.sim.pump(self.owner, limit, run_own=callbacks, until=done)
        return True

    def sleep_until(self, t_ns: int) -> bool:
        self._one_thread()
        if self.running:
            self.sim.pump(self.owner, min(t_ns, self.end_ns), run_own=False)
            self._check_end(t_ns)
        return self.running or self.waited_after_end()


def run_in_process(
    sim: Simulation, spec: ControllerSpec, end_ns: int, *, ros_args: list[str], seed: int
) -> CrashReport | None:
    """Load and run one controller until it returns or ``end_ns``; report a crash."""
    owner = f"inproc:{spec.name}"
    host = InProcessHost(sim, owner, end_ns)
    compat.install(sim.distro)
    compat_context.reset_default_context()
    compat_logging.reset_levels()
    compat_context.bind_host(host)
    saved_argv = sys.argv
    sys.argv = [spec.label, *ros_args]
    random.seed(seed)
    crash = None
    ended = False  # the program ended by itself, without an error
    try:
        if spec.factory is not None:
            from turtletui.runtime.loader import spin_nodes

            with simulated_time(host, clocks=not sim.realtime):
                spin_nodes(list(spec.factory()))
        else:
            with simulated_time(host, clocks=not sim.realtime):
                seed_numpy(seed)
                run_controller(spec)
    except RunEnded:
        pass  # a callback still waiting when the run ended: stopped, as with Ctrl-C
    except (ControllerError, KeyboardInterrupt):
        raise
    except SystemExit as exc:
        if exc.code not in (None, 0):
            crash = CrashReport(spec.label, sim.t, "exit", exit_message(exc.code), user_frames(exc.__traceback__, spec.path))
        elif exited_in_callback(exc) and sim.graph.now_ns < end_ns:
            log_exited(sim.graph, spec.label, sim.t, user_frames(exc.__traceback__, spec.path))
        else:
            ended = True
    except BaseException as exc:  # noqa: BLE001 - controller code may raise anything
        crash = crash_from_exception(spec, sim.t, exc)
    else:
        ended = True
    finally:
        sys.argv = saved_argv
        host.running = False
        if crash is not None:
            stop_turtles(sim, owner)
        elif ended and sim.graph.now_ns < end_ns:
            log_ended_early(sim.graph, spec.label, sim.t)
        sim.graph.remove_owner(owner)
        compat_context.get_default_context().try_shutdown()
        compat_context.bind_host(None)
    return crash
