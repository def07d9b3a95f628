"""Simulated time for controller code: sleeps, clocks and timed waits.

In lockstep, wall time means nothing to the simulation: a controller's main()
that does ``publish(); time.sleep(0.5)`` must let half a simulated second
pass, as it would let half a second of turtlesim pass on a real robot. While
the controller runs, ``time.sleep`` becomes a sleep in simulated time: time
advances, the node's own callbacks stay queued (as a sleeping thread would
leave them), and the rest of the world goes on.

In lockstep the clocks read simulated time too: ``time.time()``,
``time.monotonic()``, ``time.perf_counter()`` (and their ``_ns`` forms),
``time.localtime()`` and friends, and ``datetime.datetime.now()`` count from
the run's epoch, so a loop that drives "for 2 s of time.time()" drives for
2 s of the run, as on a robot. CPU-time clocks (``time.process_time``) stay
real: they measure the controller's own work. A sandboxed child (a process
that exists to run one controller) also makes ``select.select`` and the
pollers behind ``selectors`` (asyncio's too) wait in simulated time, in real
time runs too, letting the controller's other threads run.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from turtletui.runtime.scheduler import seconds_to_ns

_real_sleep = time.sleep

SELECT_STEP_NS = 10_000_000
"""How often a wait on real file descriptors looks at them again, in simulated
time: nothing in the simulation writes to them, so it cannot know when."""


def _simulated_sleep(host: Any):
    pid = os.getpid()

    def sleep(seconds: float) -> None:
        if os.getpid() != pid:
            # A process the controller forked has no simulated clock.
            _real_sleep(seconds)
            return
        if isinstance(seconds, bool) or not isinstance(seconds, (int, float)):
            raise TypeError(f"'{type(seconds).__name__}' object cannot be interpreted as an integer or float")
        if seconds < 0:
            raise ValueError("sleep length must be non-negative")
        if math.isnan(seconds):
            raise ValueError("Invalid value NaN (not a number)")
        # Once the run is over, this returns at once: the program is on its way
        # out (a callback still running is stopped: turtletui.runtime.host.RunEnded).
        host.sleep_until(host.graph.now_ns + seconds_to_ns(seconds))

    sleep.__doc__ = _real_sleep.__doc__
    return sleep


@contextmanager
def simulated_time(host: Any, *, clocks: bool) -> Iterator[None]:
    """Within the block, ``time.sleep`` sleeps in ``host``'s simulated time and,
    with ``clocks``, the clocks read it (see :func:`patch_clocks`)."""
    time.sleep = _simulated_sleep(host)
    undo = patch_clocks(host.graph, host.clock_read) if clocks else None
    try:
        yield
    finally:
        time.sleep = _real_sleep
        if undo is not None:
            undo()


def install_simulated_sleep(host: Any) -> None:
    """For a process that exists to run one controller (the sandbox child)."""
    time.sleep = _simulated_sleep(host)


# -- clocks -------------------------------------------------------------------------

_CLOCKS = (
    "time", "time_ns", "monotonic", "monotonic_ns", "perf_counter", "perf_counter_ns",
    "localtime", "gmtime", "ctime", "asctime", "strftime",
)


def patch_clocks(graph: Any, note: Callable[[], None]) -> Callable[[], None]:
    """Make time's wall and monotonic clocks and ``datetime.datetime.now()``
    read ``graph``'s simulated time from its epoch; ``note()`` is called at
    every reading (see :meth:`Scheduler.clock_read`). Returns what puts the
    real ones back."""
    import datetime
    import queue
    import threading

    saved = [(time, name, getattr(time, name)) for name in _CLOCKS]
    saved += [(threading, "_time", threading._time), (queue, "time", queue.time)]
    saved += [(datetime, "datetime", datetime.datetime)]
    real = {name: getattr(time, name) for name in _CLOCKS}

    def time_ns() -> int:
        note()
        return graph.epoch_ns + graph.now_ns

    def seconds() -> float:
        note()
        return (graph.epoch_ns + graph.now_ns) / 1e9

    def localtime(secs: float | None = None) -> time.struct_time:
        return real["localtime"](seconds() if secs is None else secs)

    def gmtime(secs: float | None = None) -> time.struct_time:
        return real["gmtime"](seconds() if secs is None else secs)

    def ctime(secs: float | None = None) -> str:
        return real["ctime"](seconds() if secs is None else secs)

    def asctime(t: Any = None) -> str:
        return real["asctime"](localtime() if t is None else t)

    def strftime(format: str, t: Any = None) -> str:
        return real["strftime"](format, localtime() if t is None else t)

    for function in (localtime, gmtime, ctime, asctime, strftime):
        function.__doc__ = real[function.__name__].__doc__
    # One clock for all: the run's. monotonic() and perf_counter() are
    # usually counted from some other origin; nothing may rely on which.
    time.time = time.monotonic = time.perf_counter = seconds
    time.time_ns = time.monotonic_ns = time.perf_counter_ns = time_ns
    time.localtime, time.gmtime, time.ctime = localtime, gmtime, ctime
    time.asctime, time.strftime = asctime, strftime
    # modules that bound time.monotonic when they were imported
    threading._time = seconds
    queue.time = seconds
    datetime.datetime = _simulated_datetime(datetime.datetime, seconds)

    def undo() -> None:
        for module, name, value in saved:
            setattr(module, name, value)

    return undo


class _RealInstances(type):
    """Metaclass of a stand-in class: a real instance is an instance of it."""

    _real: type

    def __instancecheck__(cls, obj: object) -> bool:
        return isinstance(obj, cls._real)

    def __subclasscheck__(cls, sub: type) -> bool:
        return issubclass(sub, cls._real)


def _simulated_datetime(real: type, seconds: Any) -> type:
    """``datetime.datetime`` whose ``now``, ``utcnow`` and ``today`` read ``seconds()``."""

    class datetime(real, metaclass=_RealInstances):  # type: ignore[misc, valid-type]
        __slots__ = ()
        _real = real

        @classmethod
        def now(cls, tz: Any = None) -> Any:
            return cls.fromtimestamp(seconds(), tz)

        @classmethod
        def utcnow(cls) -> Any:
            return cls.utcfromtimestamp(seconds())

        @classmethod
        def today(cls) -> Any:
            return cls.fromtimestamp(seconds())

        def __repr__(self) -> str:
            text = real.__repr__(self)  # "datetime(...)" for a subclass
            return text if text.startswith("datetime.") else f"datetime.{text}"

    datetime.__module__ = real.__module__
    datetime.__qualname__ = real.__qualname__
    datetime.__doc__ = real.__doc__
    return datetime


# -- waits on file descriptors (a sandboxed child) ---------------------------------


def install_simulated_select(host: Any) -> None:
    """Make ``select.select``, ``select.poll()``, ``select.epoll()`` and the
    ``selectors`` built on them wait in simulated time (see :func:`_waiting`)."""
    import select
    import selectors

    real_select = select.select
    real_poll = select.poll
    real_epoll = getattr(select, "epoll", None)

    def select_(rlist: Any, wlist: Any, xlist: Any, timeout: float | None = None) -> Any:
        if timeout is not None and timeout < 0:
            raise ValueError("timeout must be non-negative")
        watched = bool(rlist or wlist or xlist)

        def look() -> Any:
            found = real_select(rlist, wlist, xlist, 0)
            return found if any(found) else None

        found = _waiting(host, look, timeout, watched)
        return found if found is not None else ([], [], [])

    select_.__doc__ = real_select.__doc__
    select.select = select_
    selectors.SelectSelector._select = staticmethod(select_)
    select.poll = lambda: _Poller(host, real_poll(), 1_000_000)
    selectors.PollSelector._selector_cls = select.poll
    if real_epoll is not None:

        def epoll(sizehint: int = -1, flags: int = 0) -> _Poller:
            return _Poller(host, real_epoll(sizehint, flags), 1_000_000_000)

        select.epoll = epoll
        if hasattr(selectors, "EpollSelector"):
            selectors.EpollSelector._selector_cls = epoll


def _waiting(host: Any, look: Any, timeout: float | None, watched: bool) -> Any:
    """What ``look()`` finds now or, waiting in simulated time, within
    ``timeout`` seconds (None: until it finds something); None if nothing.

    Nothing in the simulation writes to a real file descriptor, so a wait
    with descriptors looks again every :data:`SELECT_STEP_NS`; one without
    (``select([], [], [], 1.9)``) is a sleep. After the run, a timed wait
    ends at once (as sleeps do) and a wait for ever is a real one."""
    found = look()
    if found is not None or timeout == 0:
        return found
    graph = host.graph
    deadline = None if timeout is None else graph.now_ns + seconds_to_ns(timeout)
    while True:
        if deadline is None and not host.running:
            return _wait_for_real(look)
        step = deadline
        if watched:
            step = graph.now_ns + SELECT_STEP_NS if deadline is None else min(deadline, graph.now_ns + SELECT_STEP_NS)
        host.scheduler.wait(None, step)
        found = look()
        if found is not None or (deadline is not None and graph.now_ns >= deadline):
            return found


def _wait_for_real(look: Any) -> Any:
    """Look until something is found, in real time (after the run)."""
    while (found := look()) is None:
        _real_sleep(0.01)
    return found


class _Poller:
    """A ``select.poll`` or ``select.epoll`` object whose ``poll`` waits in
    simulated time; ``unit`` is its timeout's unit in ns (ms for poll, s for
    epoll)."""

    def __init__(self, host: Any, real: Any, unit: int) -> None:
        self._host = host
        self._real = real
        self._unit = unit

    def poll(self, timeout: float | None = None, *args: Any) -> list:
        real = self._real
        if timeout is not None and timeout < 0:
            timeout = None  # both take a negative timeout as "no timeout"
        seconds = None if timeout is None else timeout * self._unit / 1e9

        def look() -> Any:
            return real.poll(0, *args) or None

        return _waiting(self._host, look, seconds, True) or []

    def __getattr__(self, name: str) -> Any:
        return getattr(self._real, name)

    def __enter__(self) -> _Poller:
        self._real.__enter__()
        return self

    def __exit__(self, *exc: object) -> None:
        self._real.__exit__(*exc)
