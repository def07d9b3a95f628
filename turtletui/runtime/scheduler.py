"""Controller threads taking turns in simulated time (the sandboxed child).

A controller may spin its node in one thread and run its control loop in
another ("rclpy.spin in a thread, the loop in main"). Left to the operating
system, the order in which such threads reach the simulator changes from run
to run, and so does the trajectory. In a sandboxed child only one controller
thread runs at a time. It hands over where a thread would block: a sleep, a
wait on a lock, event, condition, semaphore or queue, a join, a spin with
nothing to do. The next to run is, of the threads that may go on, the one
that has waited longest (see :meth:`Scheduler._next`); when none may,
simulated time moves on to the earliest moment one of them waits for, and
the simulator says what happened meanwhile. The order depends only on what the threads do, so a run is the
same every time, whatever the machine does.

:func:`install` replaces ``threading``'s locks, the start of new threads,
``Thread.join`` and ``Thread.is_alive``, and ``queue.SimpleQueue`` for the
rest of the process: it is meant for a process that exists to run one
controller. Everything built on them (Condition, Event, Semaphore, Barrier,
Timer, queue.Queue, concurrent.futures) then takes turns too. A thread that
busy-waits for another without blocking never lets it run: threads take
turns only where they block.
"""

from __future__ import annotations

import _thread
import os
from collections import deque
from collections.abc import Callable
from time import monotonic as _monotonic
from time import sleep as _real_sleep
from typing import Any

_allocate_park = _thread.allocate_lock  # real locks: a parked thread sleeps in the kernel
_real_start_new_thread = _thread.start_new_thread

CLOCK_READS_PER_STEP = 100
"""Clock readings (or zero sleeps) at one simulated instant after which the
next lets :data:`CLOCK_STEP_NS` of simulated time pass: a loop that polls the
clock until some time has passed (``while time.time() < end: ...``) would
otherwise never see it pass, where on a robot each turn takes a little time."""
CLOCK_STEP_NS = 1_000_000

_forks = 0
"""How many times this process forked into a child: a scheduler notices it
was copied into a process the controller forked (which has none of its
threads and must never talk to the simulator)."""


def _count_fork() -> None:
    global _forks
    _forks += 1


os.register_at_fork(after_in_child=_count_fork)


def _always() -> bool:
    return True


class _Turn:
    """One controller thread as the scheduler sees it."""

    __slots__ = ("park", "ready", "deadline", "spinning", "on_threads", "result", "finished", "daemon", "ident")

    def __init__(self, daemon: bool = False) -> None:
        self.park = _allocate_park()
        self.park.acquire()  # taken: the thread sleeps on it until its turn comes
        self.ready: Callable[[], bool] | None = None
        self.deadline: int | None = None
        self.spinning = False
        self.on_threads = False
        """Its wait can end only by another controller thread (a lock, a join)."""
        self.ident = 0
        """The operating-system thread's ident (threading.get_ident())."""
        self.result = False
        self.finished = False
        self.daemon = daemon


class Scheduler:
    """Gives the controller's threads turns; ``advance(wake_ns)`` lets the
    simulation run until ``wake_ns`` (None: until something arrives) and
    delivers what arrived, ``running()`` says whether the run goes on."""

    def __init__(self, graph: Any, advance: Callable[[int | None], Any], running: Callable[[], bool]) -> None:
        self.graph = graph
        self._advance_to = advance
        self._running = running
        self.current = _Turn()
        """The thread whose turn it is (at first the thread that made the scheduler)."""
        self._threads = [self.current]
        """Threads alive, in the order they started."""
        self._waiting: deque[_Turn] = deque()
        """Threads waiting for their turn, longest first."""
        self._clock_reads = 0
        self._forks = _forks
        self.current.ident = _thread.get_ident()
        self.deadlocked: Callable[[list[int]], None] | None = None
        """Called (with the idents of the threads, the caller's last) when every
        thread waits for ever on something only another could end: a deadlock,
        where under ROS the program hangs. Meant not to return (the child ends
        the run there); if it does, the waits end as at the run's end."""

    # -- waiting ------------------------------------------------------------
    def alone(self) -> bool:
        """Whether the controller has one thread (no one to hand over to)."""
        return len(self._threads) == 1 and self._forks == _forks

    def wait(
        self, ready: Callable[[], bool] | None, deadline: int | None, *, spinning: bool = False, on_threads: bool = False
    ) -> bool:
        """Let the calling thread wait until ``ready()`` holds (True), or until
        simulated time reaches ``deadline`` ns (False).

        Other threads run meanwhile; ``spinning`` says the thread waits for
        its node's callbacks, so time stops at the node's next timer too.
        ``on_threads`` says only another controller thread can make ``ready()``
        hold (a lock, a join): when every thread waits so for ever, that is a
        deadlock (:attr:`deadlocked`). Once the run is over, a timed wait ends
        at once (the clock jumps to its deadline), and so does a wait for ever
        that nothing else can end.
        """
        if self._forks != _forks:
            return self._wait_forked(ready, deadline)
        if len(self._threads) == 1:
            if on_threads and deadline is None and not (ready is not None and ready()):
                self._deadlock([self.current])
            return self._wait_alone(ready, deadline, spinning)
        me = self.current
        me.ready, me.deadline, me.spinning, me.on_threads = ready, deadline, spinning, on_threads
        self._waiting.append(me)
        self._hand_over(me)
        return me.result

    def _wait_alone(self, ready: Callable[[], bool] | None, deadline: int | None, spinning: bool) -> bool:
        """:meth:`wait` for a controller with one thread: no one to hand over to."""
        graph = self.graph
        while True:
            if ready is not None and ready():
                return True
            if deadline is not None and graph.now_ns >= deadline:
                return False
            if not self._running():
                self._after_the_end(deadline)
                return False
            wake = deadline
            if spinning:
                due = graph.next_due()
                if due is not None and (wake is None or due < wake):
                    wake = due
            self._advance(wake)

    def pause(self) -> None:
        """A zero sleep: the threads that may go on run first; every
        :data:`CLOCK_READS_PER_STEP` of them let a little time pass."""
        self.clock_read()
        self.wait(None, self.graph.now_ns)

    def poll(self) -> None:
        """Let the threads that may go on run, then ask the simulator what is
        due at this very instant (``spin_once(timeout_sec=0)``)."""
        self.wait(None, self.graph.now_ns)
        if self._forks == _forks and self._running():
            self._advance(self.graph.now_ns)

    def clock_read(self) -> bool:
        """Count a reading of the clock (see :data:`CLOCK_READS_PER_STEP`);
        whether it let time pass (waited)."""
        self._clock_reads += 1
        if self._clock_reads >= CLOCK_READS_PER_STEP:
            self._clock_reads = 0
            self.wait(None, self.graph.now_ns + CLOCK_STEP_NS)
            return True
        return False

    def _advance(self, wake: int | None) -> None:
        self._clock_reads = 0
        self._advance_to(wake)

    def _hand_over(self, me: _Turn | None) -> None:
        """Give the turn to the next thread that may go on (``me`` parks until
        its own turn comes back; None: the calling thread is ending)."""
        while True:
            turn = self._next()
            if turn is not None:
                break
            waiting = self._waiting
            if waiting and all(t.on_threads and t.deadline is None for t in waiting):
                self._deadlock([t for t in waiting if t is not me] + ([me] if me is not None else []))
            if not self._running():
                # The run is over and nothing can go on: the caller's wait
                # ends (False), or, if the caller is ending, the longest
                # waiting thread's, so that the program may end.
                if me is None and not self._waiting:
                    return
                turn = me if me is not None else self._waiting[0]
                self._waiting.remove(turn)
                turn.result = False
                break
            self._advance(self._wake())
        if turn is me:
            return
        self.current = turn
        turn.park.release()
        if me is not None:
            me.park.acquire()

    def _next(self) -> _Turn | None:
        """The thread to run next, taken from the queue with its wait's result;
        None if none may go on. A thread whose wait is over because something
        happened (callbacks to run, a lock released, an event set) goes before
        one whose time ran out at this instant: a timer and a sleep due at the
        same time run as in rclpy, whose Rate and sleeps are woken by the
        executor after the timers due then. Ties go to the longest waiting."""
        waiting = self._waiting
        for turn in waiting:
            ready = turn.ready
            if ready is not None and ready():
                turn.result = True
                waiting.remove(turn)
                return turn
        now = self.graph.now_ns
        running = self._running()
        for turn in waiting:
            deadline = turn.deadline
            if deadline is None:
                continue
            if now < deadline:
                if running:
                    continue
                self._after_the_end(deadline)
            turn.result = False
            waiting.remove(turn)
            return turn
        return None

    def _deadlock(self, turns: list[_Turn]) -> None:
        """Every thread in ``turns`` waits for ever on another: say so (:attr:`deadlocked`)."""
        if self.deadlocked is not None:
            self.deadlocked([turn.ident for turn in turns])

    def _after_the_end(self, deadline: int | None) -> None:
        """The run is over and the simulation gone: a timed wait passes at
        once, and the clock jumps to its end, so that a loop that waits for
        the clock to reach some time gets there and the program ends."""
        if deadline is not None and deadline > self.graph.now_ns:
            self.graph.now_ns = deadline

    def _wake(self) -> int | None:
        """When the simulation must come back: the earliest deadline of a
        waiting thread, or the next timer if one of them spins."""
        wake = None
        spinning = False
        for turn in self._waiting:
            deadline = turn.deadline
            if deadline is not None and (wake is None or deadline < wake):
                wake = deadline
            spinning = spinning or turn.spinning
        if spinning:
            due = self.graph.next_due()
            if due is not None and (wake is None or due < wake):
                wake = due
        return wake

    def _wait_forked(self, ready: Callable[[], bool] | None, deadline: int | None) -> bool:
        """In a process the controller forked: no simulator, so real time."""
        limit = None if deadline is None else _monotonic() + max(0, deadline - self.graph.now_ns) / 1e9
        while not (ready is not None and ready()):
            if limit is not None and _monotonic() >= limit:
                return False
            _real_sleep(0.001)
        return True

    # -- threads --------------------------------------------------------------
    def start_thread(self, function: Callable[..., Any], args: tuple, kwargs: dict | None = None) -> Callable[[], None]:
        """A new controller thread that will run ``function(*args, **kwargs)``
        when its turn comes (after the thread that starts it waits): returns
        what the new operating-system thread must run."""
        thread = getattr(function, "__self__", None)  # threading.Thread._bootstrap
        turn = _Turn(daemon=bool(getattr(thread, "daemon", False)))
        if thread is not None:
            thread._turtletui_turn = turn
        turn.ready = _always
        self._threads.append(turn)
        self._waiting.append(turn)

        def run() -> None:
            turn.ident = _thread.get_ident()
            turn.park.acquire()
            try:
                function(*args, **(kwargs or {}))
            finally:
                turn.finished = True
                self._threads.remove(turn)
                self._hand_over(None)

        return run

    def join_threads(self) -> None:
        """What Python does before it exits: run threading's exit hooks (a
        ThreadPoolExecutor stops its workers) and wait for every thread that
        is not a daemon."""
        if len(self._threads) == 1:
            return
        import threading

        for hook in reversed(list(getattr(threading, "_threading_atexits", ()))):
            hook()
        others = self._threads[1:]
        self.wait(lambda: all(t.finished or t.daemon for t in others), None, on_threads=True)


class Lock:
    """``threading.Lock`` for controller threads that take turns: a thread
    that must wait for it lets the others run (in simulated time)."""

    __slots__ = ("_locked", "__weakref__")

    def __init__(self) -> None:
        self._locked = False

    def acquire(self, blocking: bool = True, timeout: float = -1) -> bool:
        if not blocking and timeout != -1:
            raise ValueError("can't specify a timeout for a non-blocking call")
        if timeout < 0 and timeout != -1:
            raise ValueError("timeout value must be a non-negative number")
        if not self._locked:
            self._locked = True
            return True
        if not blocking:
            return False
        scheduler = _scheduler
        if scheduler is None:
            raise RuntimeError("a turtletui lock was used with no scheduler")
        deadline = None if timeout == -1 else scheduler.graph.now_ns + seconds_to_ns(timeout)
        if scheduler.wait(self._free, deadline, on_threads=True):
            self._locked = True
            return True
        return False

    def _free(self) -> bool:
        return not self._locked

    def release(self) -> None:
        if not self._locked:
            raise RuntimeError("release unlocked lock")
        self._locked = False

    def locked(self) -> bool:
        return self._locked

    def __enter__(self) -> bool:
        return self.acquire()

    def __exit__(self, *exc: object) -> None:
        self.release()

    def _at_fork_reinit(self) -> None:
        self._locked = False

    acquire_lock = acquire
    release_lock = release
    locked_lock = locked

    def __repr__(self) -> str:
        return f"<{'locked' if self._locked else 'unlocked'} _thread.lock object at {id(self):#x}>"


def seconds_to_ns(seconds: float) -> int:
    """A timeout in seconds as simulated nanoseconds (capped: ``float('inf')``
    and huge values wait as long as a run can last)."""
    return int(min(seconds, 1e9) * 1_000_000_000)


_scheduler: Scheduler | None = None


def install(scheduler: Scheduler) -> None:
    """Make every thread the controller starts, and every lock and wait it
    uses, take turns under ``scheduler`` (for the rest of this process)."""
    global _scheduler
    import queue
    import threading

    _scheduler = scheduler

    def start_new_thread(function: Callable[..., Any], args: tuple, kwargs: dict | None = None) -> int:
        if scheduler._forks != _forks:
            return _real_start_new_thread(function, args, *([kwargs] if kwargs else []))
        return _real_start_new_thread(scheduler.start_thread(function, args, kwargs), ())

    def rlock(*args: Any, **kwargs: Any) -> Any:
        return threading._PyRLock(*args, **kwargs)  # built on _allocate_lock, so on Lock

    threading.Lock = threading._allocate_lock = Lock
    threading.RLock = rlock
    _thread.start_new_thread = start_new_thread
    if hasattr(threading, "_start_new_thread"):
        threading._start_new_thread = start_new_thread
    if hasattr(threading, "_start_joinable_thread"):  # Python 3.13
        real_joinable = threading._start_joinable_thread

        def start_joinable_thread(function: Callable[..., Any], handle: Any = None, daemon: bool = True) -> Any:
            if scheduler._forks != _forks:
                return real_joinable(function, handle=handle, daemon=daemon)
            return real_joinable(scheduler.start_thread(function, ()), handle=handle, daemon=daemon)

        threading._start_joinable_thread = start_joinable_thread
    _patch_thread(threading.Thread, scheduler)
    queue.SimpleQueue = queue._PySimpleQueue  # the C one blocks in C


def _patch_thread(cls: type, scheduler: Scheduler) -> None:
    real_join = cls.join
    real_is_alive = cls.is_alive

    def join(self: Any, timeout: float | None = None) -> None:
        turn = getattr(self, "_turtletui_turn", None)
        if turn is None or scheduler._forks != _forks:
            return real_join(self, timeout)
        if not self._started.is_set():
            raise RuntimeError("cannot join thread before it is started")
        if turn is scheduler.current:
            raise RuntimeError("cannot join current thread")
        deadline = None if timeout is None else scheduler.graph.now_ns + seconds_to_ns(max(timeout, 0))
        if scheduler.wait(lambda: turn.finished, deadline, on_threads=True):
            real_join(self)  # its operating-system thread is ending: at once
        return None

    def is_alive(self: Any) -> bool:
        turn = getattr(self, "_turtletui_turn", None)
        if turn is None or scheduler._forks != _forks:
            return real_is_alive(self)
        return self._started.is_set() and not turn.finished

    join.__doc__ = real_join.__doc__
    is_alive.__doc__ = real_is_alive.__doc__
    cls.join = join
    cls.is_alive = is_alive
