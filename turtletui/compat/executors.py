"""``rclpy.executors``, deterministic on the host's simulated clock.

A SingleThreadedExecutor runs one callback at a time, in the order they
became ready. A MultiThreadedExecutor, in a sandboxed controller, spins in
``num_threads`` threads that take turns (turtletui.runtime.scheduler): while
one callback waits (a synchronous service call, a sleep, an event), another
may run, as far as callback groups allow. In-process there are no threads: a
callback that waits for a service's response runs the other ready callbacks
meanwhile, one at a time, under the same group rules.

As in rclpy, an exception in a callback a MultiThreadedExecutor runs beside
the thread that spins (another thread, or nested in a callback that waits)
does not end that thread or the waiting callback: spin() raises it in the
thread that spins, and the callbacks running then go on. rclpy raises it at
its next dispatch, so that callback runs too (and if none ever becomes ready,
it never raises); turtletui raises it when the thread that spins next has its
turn (once its own callback, if it runs one, returns), without waiting for
another callback to become ready.

A program may subclass them, as rclpy's docs tell a custom executor to: its
own ``spin_once`` (spin() and rclpy.spin() call it), taking work with
``wait_for_ready_callbacks`` and running each handler itself or in a thread
pool (ros2/examples' PriorityExecutor). Only then do spins go through those
methods one callback at a time; an executor that overrides none of them spins
as before, without the per-callback calls.
"""

from __future__ import annotations

import inspect
import threading
from collections.abc import Callable
from typing import Any, ClassVar

from turtletui.compat import dispatch
from turtletui.compat.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from turtletui.compat.context import Context, get_default_context
from turtletui.compat.dispatch import running_groups, spun_by_this_thread, start_task
from turtletui.compat.identity import as_rclpy
from turtletui.compat.rcl_error import RCLError
from turtletui.compat.task import Future, Task

_NS = 1_000_000_000

_CONTEXT_INVALID = (
    "the given context is not valid, either rcl_init() was not called or rcl_shutdown() was called."
)
"""rcl's reason for refusing a timer or a wait set on a context not (or no longer) initialized."""

DEFAULT_THREADS = 4
"""Threads of a MultiThreadedExecutor made without ``num_threads`` (rclpy
takes the machine's CPU count: fixed here, so runs repeat on any machine)."""


class ExternalShutdownException(Exception):
    """Raised by rclpy when the context is shut down while spinning."""


class ShutdownException(Exception):
    pass


class TimeoutException(Exception):
    pass


class ConditionReachedException(Exception):
    """Raised by ``wait_for_ready_callbacks`` when its condition holds (rclpy's)."""


class TimeoutObject:
    """A timeout that ``spin_until_future_complete`` shortens as it goes, as rclpy's:
    what a subclass's ``_spin_once_until_future_complete`` is given."""

    def __init__(self, timeout: float) -> None:
        self._timeout = timeout

    @property
    def timeout(self) -> float:
        return self._timeout

    @timeout.setter
    def timeout(self, timeout: float) -> None:
        self._timeout = timeout


async def await_or_execute(callback: Callable[..., Any], *args: Any) -> Any:
    """Await ``callback(*args)`` if it is an ``async def`` function, else call it (as rclpy's)."""
    if inspect.iscoroutinefunction(callback):
        return await callback(*args)
    return callback(*args)


def _seconds(timeout_sec: float | TimeoutObject | None) -> float | None:
    return timeout_sec.timeout if isinstance(timeout_sec, TimeoutObject) else timeout_sec


def _timeout_ns(timeout_sec: float | TimeoutObject | None) -> int | None:
    timeout_sec = _seconds(timeout_sec)
    if timeout_sec is None or timeout_sec < 0:
        return None
    return int(min(timeout_sec, 1e9) * _NS)


_TAKE_POINTS = ("_spin_once_impl", "wait_for_ready_callbacks", "_wait_for_ready_callbacks")
"""How rclpy's executors take a callback: a subclass that overrides one of them has
turtletui's executors take callbacks through them (see Executor.__init_subclass__)."""


def _ours(cls: type, names: tuple[str, ...]) -> bool:
    """Whether every one of ``names`` on ``cls`` is this module's (not a subclass's own)."""
    return all(getattr(getattr(cls, name, None), "__module__", None) == __name__ for name in names)


class Executor:
    """Runs the callbacks of the nodes added to it."""

    _runs_callbacks: ClassVar[bool] = False
    """Whether the class runs callbacks itself (SingleThreadedExecutor, MultiThreadedExecutor):
    a subclass of Executor must define spin_once, as in rclpy."""
    _takes_itself: ClassVar[bool] = False
    """Whether spin_once may run a callback straight off the host (no subclass
    overrides how a callback is taken: _TAKE_POINTS)."""
    _spins_itself: ClassVar[bool] = False
    """Whether spin() may run callbacks straight off the host (as _takes_itself, and spin_once is ours)."""
    _waits_itself: ClassVar[bool] = False
    """Whether spin_until_future_complete may (as _takes_itself, and
    _spin_once_until_future_complete is ours)."""

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls._takes_itself = cls._runs_callbacks and _ours(cls, _TAKE_POINTS)
        cls._spins_itself = cls._takes_itself and _ours(cls, ("spin_once",))
        cls._waits_itself = cls._takes_itself and _ours(cls, ("_spin_once_until_future_complete",))

    def __init__(self, *, context: Context | None = None) -> None:
        self._context = context or get_default_context()
        if not self._context._ok:
            # rclpy's executor makes a guard condition, which needs an initialized context
            raise RuntimeError("Context must be initialized a GuardCondition can be created")
        self._nodes: list[Any] = []
        self._spinning = 0
        """Threads inside this executor's spin calls now."""
        self._is_shutdown = False
        self._failures: list[Exception] = []
        """Errors of callbacks run beside the thread that spins, for spin() to
        raise there, oldest first (MultiThreadedExecutor)."""
        # wait_for_ready_callbacks' generator, reused while its arguments stay the same (rclpy's)
        self._cb_iter: Any = None
        self._last_args: tuple | None = None
        self._last_kwargs: dict | None = None
        self._handed: list[tuple[Any, tuple]] = []
        """Callbacks of this executor's nodes (or its tasks) that another
        thread's executor took while this one spins: its own thread runs them
        (turtletui.compat.dispatch.Parking)."""

    @property
    def context(self) -> Context:
        return self._context

    def add_node(self, node: Any) -> bool:
        if node in self._nodes:
            return False
        self._nodes.append(node)
        node._spinners += self._spinning
        node.executor = self
        if self._spinning:
            self._release_parked()
        return True

    def remove_node(self, node: Any) -> None:
        if node in self._nodes:
            self._nodes.remove(node)
            node._spinners -= self._spinning

    def _release_parked(self) -> None:
        """Queue the callbacks of this executor's nodes that waited for it (turtletui.compat.dispatch)."""
        host = self._context._host
        if host is not None:
            self._context.parking.release([*self._nodes, self], host.graph.ready)
            self._take_handed()

    def _take_handed(self) -> None:
        """Queue, ahead of what else is ready, the callbacks another thread's executor handed over."""
        handed = self._handed
        if handed:
            self._handed = []
            self._context._host.graph.ready.extendleft([item for _, item in reversed(handed)])

    def _was_handed(self) -> bool:
        return bool(self._handed)

    def get_nodes(self) -> list[Any]:
        return list(self._nodes)

    def wake(self) -> None:
        """rclpy's executor triggers its guard condition so that a wait in progress takes in
        new nodes and entities; it runs no callback and ends no wait. turtletui's waits see
        new entities as they are made, so there is nothing to do."""

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop spinning and forget the nodes."""
        self._is_shutdown = True
        for node in self._nodes:
            node._spinners -= self._spinning
        self._nodes.clear()
        self._cb_iter = self._last_args = self._last_kwargs = None
        return True

    def __enter__(self) -> Executor:
        return self

    def __exit__(self, exc_type: Any, exc_val: Any, exc_tb: Any) -> None:
        self.shutdown()

    def create_task(self, callback: Callable | Any, *args: Any, **kwargs: Any) -> Task:
        """Run ``callback(*args)`` (or a coroutine) soon, as a Task of this executor."""
        return start_task(
            self._context.host, ReentrantCallbackGroup(), callback, args, kwargs, now=False, executor=self
        )

    def create_future(self) -> Future:
        """A Future whose done callbacks this executor runs."""
        return Future(executor=self)

    def _guard(self, what: str) -> Any:
        host = self._context.host
        if host.callback_depth:
            raise RuntimeError(
                f"{what} was called inside a callback: in ROS 2 this deadlocks, because the "
                "executor is busy running your callback and cannot deliver anything else. "
                "Use call_async() with add_done_callback(), or do the waiting in main()."
            )
        return host

    def _stopped(self) -> bool:
        # Context.ok() inline: spin checks this each time the ready callbacks
        # run out, once a tick.
        if self._is_shutdown or self._failures:
            return True
        context = self._context
        host = context._host
        return not (context._ok and host is not None and host.running)

    def _fail(self, error: Exception) -> None:
        """Keep a callback's error for spin() to raise; the first few only (a
        timer that raises every time while a callback waits long would keep
        every traceback and its frames)."""
        if len(self._failures) < _FAILURES_KEPT:
            self._failures.append(error)

    def _raise_failure(self) -> None:
        """Raise the oldest error of a callback run beside the thread that spins (if any)."""
        if self._failures:
            raise self._failures.pop(0)

    def spin(self) -> None:
        if not self._spins_itself:
            # rclpy's: the executor's own spin_once (a subclass's), until shutdown
            while self._context.ok() and not self._is_shutdown:
                self.spin_once()
            return
        host = self._guard("spin()")
        if not self._stopped():
            self._run(host, lambda: self._spin_host(host, self._stopped))
        self._raise_failure()

    def _spin_host(self, host: Any, stop: Callable[[], bool]) -> None:
        """``host.spin(stop)``, taking in what other threads' executors hand over meanwhile."""

        def stop_or_handed() -> bool:
            return stop() or bool(self._handed)

        while True:
            self._take_handed()
            host.spin(stop_or_handed)
            if not self._handed or stop():
                return

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """Run one callback: a custom executor (a subclass of Executor) defines it,
        taking work with :meth:`wait_for_ready_callbacks`, as in rclpy."""
        raise NotImplementedError()

    def _run_one(self, host: Any, timeout_ns: int | None) -> None:
        """Run one callback of this executor's nodes (the first ready), waiting
        up to ``timeout_ns``. Another node's callback the host took meanwhile
        waits parked (or goes to the executor spinning it on another thread),
        and the wait goes on (rclpy's wait set never wakes for it); one that
        another thread's executor handed over runs here."""
        parking = self._context.parking
        graph = host.graph
        deadline = None if timeout_ns is None else graph.now_ns + max(timeout_ns, 0)
        while True:
            self._take_handed()
            parked = parking.count
            ran = host.spin_once(None if deadline is None else max(deadline - graph.now_ns, 0), self._was_handed)
            if self._stopped():
                return
            if parking.count == parked and (ran or not self._handed):
                return

    def spin_until_future_complete(self, future: Future, timeout_sec: float | None = None) -> None:
        if not self._waits_itself:
            self._spin_steps_until(future, timeout_sec)
            return
        failures = self._failures

        def settled() -> bool:
            # As rclpy: a cancelled future is not done(), but ends the wait too.
            return future.done() or future.cancelled() or bool(failures)

        timeout_ns = _timeout_ns(timeout_sec)
        host = self._context.host
        client = getattr(future, "_client", None)  # a service call's (not a task's, nor another kind of future's)
        if host is not None and host.callback_depth and self._spins_again(client, timeout_sec):
            # rclpy spins the executor again, inside the callback: what other
            # callback groups have ready runs meanwhile, and a timeout ends the wait
            if not self._stopped():
                self._spin_until(host, settled, timeout_ns)
                if not future.done() and client is not None and host.running and not client._response_can_run():
                    client._tell_response_waits()  # ROS 2 says nothing
            self._raise_failure()
            return
        host = self._guard("spin_until_future_complete()")
        if not self._stopped():
            self._run(host, lambda: self._spin_until(host, settled, timeout_ns))
        self._raise_failure()

    def _spin_until(self, host: Any, settled: Callable[[], bool], timeout_ns: int | None) -> None:
        """``host.spin_until(settled, timeout_ns)``, taking in what other threads' executors hand over meanwhile."""

        def settled_or_handed() -> bool:
            return settled() or bool(self._handed)

        graph = host.graph
        deadline = None if timeout_ns is None else graph.now_ns + max(timeout_ns, 0)
        while True:
            self._take_handed()
            host.spin_until(settled_or_handed, None if deadline is None else max(deadline - graph.now_ns, 0))
            if settled() or not self._handed or self._stopped():
                return
            if deadline is not None and graph.now_ns >= deadline:
                return

    def _spins_again(self, client: Any, timeout_sec: float | None) -> bool:
        """Whether a wait for a future inside a callback this (single-threaded)
        executor runs ends in ROS 2: at its timeout, or when what completes the
        future (the response to ``client``'s call) is in a callback group free
        to run. Else rclpy would wait for ever, and turtletui says why instead (_guard)."""
        spun = spun_by_this_thread()
        if not spun or spun[-1] is not self or isinstance(self, MultiThreadedExecutor):
            return False
        if timeout_sec is not None and timeout_sec >= 0:
            return True
        return client is not None and client._response_can_run()

    def _spin_steps_until(self, future: Future, timeout_sec: float | None) -> None:
        """rclpy's spin_until_future_complete: ``_spin_once_until_future_complete``
        (a subclass's, or one that takes work through a subclass's methods) until
        the future is done, the executor or context shuts down, or the timeout
        passes (on the run's time, which rclpy reads from time.monotonic)."""
        future.add_done_callback(lambda _future: self.wake())
        context = self._context

        def going() -> bool:
            return context.ok() and not future.done() and not future.cancelled() and not self._is_shutdown

        if timeout_sec is None or timeout_sec < 0:
            while going():
                self._spin_once_until_future_complete(future, timeout_sec)
            return
        graph = context.host.graph
        end = graph.now_ns + int(timeout_sec * _NS)
        left = TimeoutObject(timeout_sec)
        while going():
            self._spin_once_until_future_complete(future, left)
            now = graph.now_ns
            if now >= end:
                return
            left.timeout = (end - now) / _NS

    def spin_once_until_future_complete(self, future: Future, timeout_sec: float | TimeoutObject | None = None) -> None:
        """Run one callback, unless ``future`` is done: a custom executor defines it."""
        raise NotImplementedError()

    def _spin_once_until_future_complete(
        self, future: Future, timeout_sec: float | TimeoutObject | None = None
    ) -> None:
        raise NotImplementedError()

    def wait_for_ready_callbacks(self, *args: Any, **kwargs: Any) -> tuple[Task, Any, Any]:
        """The next callback ready to run, as ``(handler, entity, node)``: calling
        ``handler`` (a Task) runs it and keeps its error. ``entity`` is the timer,
        subscription, service or guard condition (None for a task of
        create_task, and for a client's response), ``node`` its node. Arguments
        go to ``_wait_for_ready_callbacks``: ``timeout_sec`` (TimeoutException
        when it passes), ``nodes``, ``condition``. As rclpy's."""
        while True:
            if self._cb_iter is None or self._last_args != args or self._last_kwargs != kwargs:
                self._last_args = args
                self._last_kwargs = kwargs
                self._cb_iter = self._wait_for_ready_callbacks(*args, **kwargs)
            try:
                return next(self._cb_iter)
            except StopIteration:
                self._cb_iter = None

    def _wait_for_ready_callbacks(
        self,
        timeout_sec: float | TimeoutObject | None = None,
        nodes: list[Any] | None = None,
        condition: Callable[[], bool] = lambda: False,
    ) -> Any:
        """Yield the callbacks of the executor's nodes (or of ``nodes``) and its
        tasks that are ready, waiting up to ``timeout_sec`` for one.

        The host runs what becomes ready; a callback of these nodes, with none
        of them spun (this thread counts as spinning no executor meanwhile),
        waits parked (turtletui.compat.dispatch.Parking) and is taken from there.
        Raises ShutdownException (the executor shut down), ExternalShutdownException
        (the context did), TimeoutException, or ConditionReachedException."""
        timeout_ns = _timeout_ns(timeout_sec)
        host = self._guard("wait_for_ready_callbacks()")
        graph = host.graph
        context = self._context
        deadline = None if timeout_ns is None else graph.now_ns + timeout_ns
        yielded = False
        while not yielded and not self._is_shutdown and not condition():
            chosen = self.get_nodes() if nodes is None else nodes
            work = self._parked_work(chosen)
            if not work:
                self._wait_for_work(host, deadline)
                if self._is_shutdown:
                    raise ShutdownException()
                if not context._ok:
                    raise ExternalShutdownException()
                work = self._parked_work(chosen)
            for key, item in work:
                if self._unpark(key, item):
                    yielded = True
                    yield self._handler(key, item)
            if not yielded and deadline is not None and graph.now_ns >= deadline and host.running:
                raise TimeoutException()
        if self._is_shutdown:
            raise ShutdownException()
        if condition():
            raise ConditionReachedException()

    def _parked_work(self, nodes: list[Any]) -> list[tuple[Any, tuple]]:
        """The parked callbacks of ``nodes`` and this executor's tasks, oldest first."""
        return [(key, item) for key, item in self._context.parking.items if key is self or key in nodes]

    def _unpark(self, key: Any, item: tuple) -> bool:
        """Take ``item`` out of the parked callbacks; False if something else took it meanwhile."""
        items = self._context.parking.items
        for index, entry in enumerate(items):
            if entry[0] is key and entry[1] is item:
                del items[index]
                return True
        return False

    def _wait_for_work(self, host: Any, deadline: int | None) -> None:
        """Let the host run what becomes ready, up to ``deadline``, until one callback of
        this host ran: this thread counts as inside a spin of no node, so a callback
        of this executor's nodes waits parked."""
        spun = spun_by_this_thread()
        spun.append(_NO_EXECUTOR)
        try:
            host.spin_once(None if deadline is None else max(deadline - host.graph.now_ns, 0))
        finally:
            spun.pop()

    def _handler(self, key: Any, item: tuple) -> tuple[Task, Any, Any]:
        """``(handler, entity, node)`` for a parked ``item``: a task of this
        executor's is its own handler, as in rclpy."""
        call = item[1]
        task = getattr(call, "task", None)
        if key is self and task is not None:
            handler, entity, node = task, None, None
        else:

            def run() -> None:
                # a callback runs here as in a thread that spins nothing: not parked again
                spun = spun_by_this_thread()
                if not spun:
                    call()
                    return
                saved = spun[:]
                spun.clear()
                try:
                    call()
                finally:
                    spun[:] = saved

            handler, node = Task(run, executor=self), key
            entity = _entity_of(key, item) if key is not self else None
            if key is self:
                node = None
        handler._raises = False
        return handler, entity, node

    def _run(self, host: Any, spin: Callable[[], Any]) -> None:
        """Run ``spin`` (which runs callbacks on the calling thread) as this executor."""
        with self._counted():
            spin()

    def _counted(self) -> _Spinning:
        return _Spinning(self)


class _Spinning:
    """Counts the calling thread as spinning the executor while inside."""

    __slots__ = ("_executor",)

    def __init__(self, executor: Executor) -> None:
        self._executor = executor

    def __enter__(self) -> None:
        executor = self._executor
        if not executor._spinning:
            dispatch.spinning_executors += 1
        executor._spinning += 1
        for node in executor._nodes:
            node._spinners += 1
        spun_by_this_thread().append(executor)
        executor._release_parked()

    def __exit__(self, *exc: object) -> None:
        executor = self._executor
        executor._spinning -= 1
        if not executor._spinning:
            dispatch.spinning_executors -= 1
        for node in executor._nodes:
            node._spinners -= 1
        spun_by_this_thread().pop()
        if not executor._spinning and executor._handed:
            executor._context.parking.unhand(executor)


_NO_EXECUTOR = object()
"""What a thread waiting in wait_for_ready_callbacks spins: no executor, so every
callback it takes (of a node, or a task of an executor) waits parked for it."""


def _entity_of(node: Any, item: tuple) -> Any:
    """The timer, subscription, service, client or guard condition of ``node`` a parked ``item`` calls (or None)."""
    run = item[2] if len(item) > 2 else item[1]
    entity = getattr(run, "entity", None)  # a client's call
    if entity is not None:
        return entity
    for entity in getattr(node, "_entities", ()):
        record = getattr(entity, "_record", None)
        if record is not None and (
            getattr(record, "ready_item", None) is item
            or getattr(record, "callback", None) is run
            or getattr(record, "handler", None) is run
        ):
            return entity
        if getattr(entity, "_run", None) is run:
            return entity
    return None


class _RunsCallbacks(Executor):
    """What SingleThreadedExecutor and MultiThreadedExecutor share: spin_once and its kin,
    straight off the host unless a subclass changes how a callback is taken."""

    _runs_callbacks = True

    def spin_once(self, timeout_sec: float | None = None) -> None:
        if not self._takes_itself:
            self._spin_once_impl(timeout_sec)
            return
        # straight off the host (every spin_once of a program that subclasses nothing)
        if not self._context._ok:
            # rclpy makes a timer for the timeout, then a wait set: rcl refuses both after shutdown
            if timeout_sec is not None and timeout_sec > 0:
                raise RCLError(f"failed to create timer: {_CONTEXT_INVALID}, at /project/src/rcl/guard_condition.c:65")
            if not self._is_shutdown:
                raise RCLError(f"failed to initialize wait set: {_CONTEXT_INVALID}, at /project/src/rcl/wait.c:105")
            return
        host = self._guard("spin_once()")
        if not self._stopped():
            with self._counted():
                self._run_one(host, _timeout_ns(timeout_sec))
        self._raise_failure()

    def spin_once_until_future_complete(self, future: Future, timeout_sec: float | TimeoutObject | None = None) -> None:
        if not self._waits_itself:
            future.add_done_callback(lambda _future: self.wake())
        self._spin_once_until_future_complete(future, timeout_sec)

    def _spin_once_until_future_complete(
        self, future: Future, timeout_sec: float | TimeoutObject | None = None
    ) -> None:
        if self._takes_itself:
            if not future.done():
                _RunsCallbacks.spin_once(self, _seconds(timeout_sec))
            return
        self._spin_once_impl(timeout_sec, future.done)

    def _spin_once_impl(
        self, timeout_sec: float | TimeoutObject | None = None, wait_condition: Callable[[], bool] = lambda: False
    ) -> None:
        """rclpy's: one callback from wait_for_ready_callbacks, run here."""
        try:
            handler, _entity, _node = self.wait_for_ready_callbacks(timeout_sec, None, wait_condition)
        except (ShutdownException, TimeoutException, ConditionReachedException):
            pass
        else:
            handler()
            exception = handler.exception()
            if exception is not None:
                raise exception


class SingleThreadedExecutor(_RunsCallbacks):
    """Runs one callback at a time."""


class MultiThreadedExecutor(_RunsCallbacks):
    """Runs callbacks of different callback groups (or of a Reentrant one) at
    the same time, in ``num_threads`` threads taking turns (sandboxed)."""

    def __init__(self, num_threads: int | None = None, *, context: Context | None = None) -> None:
        super().__init__(context=context)
        if num_threads is not None and (isinstance(num_threads, bool) or not isinstance(num_threads, int)):
            raise TypeError(f"num_threads must be an int, got {num_threads!r}")
        if num_threads is not None and num_threads < 1:
            raise ValueError(f"num_threads must be at least 1, got {num_threads}")
        self._num_threads = num_threads or DEFAULT_THREADS
        self._left_running: list[threading.Thread] = []
        """Threads still running a callback when an error left spin()."""
        self._pool: Any = None
        self._futures: list[Any] = []
        """rclpy's: the handlers _spin_once_impl gave the pool, until they are done."""

    @property
    def _executor(self) -> Any:
        """rclpy's thread pool, which a subclass's spin_once may submit handlers to;
        made when first asked for (turtletui's own spins use threads of their own)."""
        if self._pool is None:
            from concurrent.futures import ThreadPoolExecutor

            self._pool = ThreadPoolExecutor(self._num_threads)
        return self._pool

    @_executor.setter
    def _executor(self, pool: Any) -> None:
        self._pool = pool

    def _spin_once_impl(
        self, timeout_sec: float | TimeoutObject | None = None, wait_condition: Callable[[], bool] = lambda: False
    ) -> None:
        """rclpy's: one callback from wait_for_ready_callbacks, given to the pool."""
        try:
            handler, _entity, _node = self.wait_for_ready_callbacks(timeout_sec, None, wait_condition)
        except (ExternalShutdownException, ShutdownException, TimeoutException, ConditionReachedException):
            pass
        else:
            self._executor.submit(handler)
            self._futures.append(handler)
            for future in self._futures[:]:
                if future.done():
                    self._futures.remove(future)
                    future.result()  # raise any exceptions

    def _run(self, host: Any, spin: Callable[[], Any]) -> None:
        """Run ``spin`` on the calling thread with ``num_threads - 1`` more
        threads running callbacks meanwhile (sandboxed; in-process there are
        none), until it returns. When a callback's error leaves it (raised on
        this thread, or by another, see _work), the callbacks the other
        threads are running go on, as in rclpy's thread pool: a later spin
        or shutdown() lets them finish."""
        if getattr(host, "scheduler", None) is None or self._num_threads < 2:
            super()._run(host, spin)
            return
        finished: list[bool] = []
        interrupted: list[KeyboardInterrupt] = []

        def stop() -> bool:
            return bool(finished) or self._stopped()

        workers = [
            threading.Thread(
                target=self._work, args=(host, stop, finished, interrupted), name=f"MultiThreadedExecutor-{n}", daemon=True
            )
            for n in range(1, self._num_threads)
        ]
        for worker in workers:
            worker.start()
        failed = False
        try:
            super()._run(host, spin)
        except Exception:
            failed = True
            raise
        finally:
            finished.append(True)
            if failed or self._failures:
                self._left_running.extend(workers)  # spin() raises at once, as rclpy's
            else:
                for worker in workers:
                    worker.join()
        if interrupted:
            raise interrupted[0]

    def _work(
        self, host: Any, stop: Callable[[], bool], finished: list[bool], interrupted: list[KeyboardInterrupt]
    ) -> None:
        with self._counted():
            try:
                self._spin_host(host, stop)
            except KeyboardInterrupt as interrupt:
                # the run's end stopping a callback here (turtletui.runtime.host.RunEnded):
                # the thread that spins gets it, as Ctrl-C goes to the main thread
                interrupted.append(interrupt)
                finished.append(True)
            except Exception as error:  # noqa: BLE001 - raised by spin() in the thread that spins
                # As rclpy's pool, which keeps a callback's error in its task for
                # spin() to raise: this thread is not the program's to end.
                self._fail(error)

    def shutdown(self, timeout_sec: float | None = None, *, wait_for_threads: bool = True) -> bool:
        """Stop spinning; with ``wait_for_threads``, wait (up to ``timeout_sec``)
        for the callbacks still running in this executor's threads, as rclpy
        waits for its pool (they run on after a callback's error left spin())."""
        done = super().shutdown(timeout_sec)
        if self._pool is not None:
            self._pool.shutdown(wait=wait_for_threads)
        me = threading.current_thread()
        left, self._left_running = self._left_running, []
        for worker in left:
            if wait_for_threads and worker is not me:
                worker.join(None if timeout_sec is None or timeout_sec < 0 else timeout_sec)
            done = done and not worker.is_alive()
        return done


class EventsExecutor(SingleThreadedExecutor):
    """``rclpy.experimental.EventsExecutor`` (Kilted on): callbacks one at a time, as the
    SingleThreadedExecutor runs them (turtletui's executors already wait on events)."""


def threads_that_can_help(node: Any) -> bool:
    """Whether, while the calling thread waits inside one of ``node``'s
    callbacks, an executor can still run the node's other callbacks."""
    executor = getattr(node, "executor", None)
    return isinstance(executor, MultiThreadedExecutor) and executor._spinning > 0


def nothing_spins(node: Any) -> bool:
    """Whether no executor spins ``node`` now, and no other thread of the
    controller could (ROS 2 would then wait for ever for its callbacks)."""
    executor = getattr(node, "executor", None)
    scheduler = getattr(node.context.host, "scheduler", None)
    return (executor is None or not executor._spinning) and (scheduler is None or scheduler.alone())


def wait_inside_callback(node: Any, done: Callable[[], bool], timeout_ns: int | None) -> bool:
    """Wait, inside a callback of ``node`` spun by a MultiThreadedExecutor,
    until ``done()`` (True) or the timeout (False). With threads (sandboxed)
    the executor's other threads run callbacks meanwhile; without (in-process)
    this thread runs them, one at a time, as far as their groups allow."""
    return wait_in_host(node.context.host, done, timeout_ns)


def wait_in_host(host: Any, done: Callable[[], bool], timeout_ns: int | None) -> bool:
    """Wait until ``done()`` (True) or the timeout (False): inside a callback,
    as ``wait_inside_callback``; outside, while other threads run callbacks."""
    if not host.callback_depth or (getattr(host, "scheduler", None) is not None and not host.scheduler.alone()):
        return host.spin_until(done, timeout_ns, callbacks=False)
    return _run_others_while_waiting(host, done, timeout_ns)


def _run_others_while_waiting(host: Any, done: Callable[[], bool], timeout_ns: int | None) -> bool:
    """Wait inside a callback, running the other ready callbacks on this
    thread meanwhile (no other thread can). One of them that raises is, for
    the MultiThreadedExecutor this thread spins, a callback of another of its
    threads: its error waits for spin() to raise it, and this wait goes on."""
    spun = spun_by_this_thread()
    executor = spun[-1] if spun else None
    if not isinstance(executor, MultiThreadedExecutor):
        return host.spin_until(done, timeout_ns)
    deadline = None if timeout_ns is None else host.graph.now_ns + max(timeout_ns, 0)
    while True:
        left = None if deadline is None else max(deadline - host.graph.now_ns, 0)
        try:
            return host.spin_until(done, left)
        except Exception as error:  # noqa: BLE001 - raised by spin() in the thread that spins
            executor._fail(error)


def busy_exclusive_group(group: Any) -> bool:
    """Whether ``group`` is a mutually exclusive group the calling thread is
    running a callback of (nothing else of it can run until that returns)."""
    return isinstance(group, MutuallyExclusiveCallbackGroup) and group in running_groups()


def answers_can_run(client_group: Any, server_handler: Any) -> bool:
    """Whether, while the calling thread runs a callback, a client's answers
    (taken in ``client_group``) and, if this controller serves the request,
    its server's handler could run: neither waits for a mutually exclusive
    group busy with that callback."""
    if busy_exclusive_group(client_group):
        return False
    return server_handler is None or not busy_exclusive_group(getattr(server_handler, "group", None))


_FAILURES_KEPT = 16
"""Errors of callbacks an executor keeps for spin() to raise (it raises the first)."""


_global_executor: Executor | None = None


def get_global_executor() -> Executor:
    global _global_executor
    context = get_default_context()
    # rclpy drops its global executor at shutdown; making another needs rclpy.init() again
    if _global_executor is None or _global_executor.context is not context or not context._ok:
        _global_executor = SingleThreadedExecutor()
    return _global_executor

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy(
    "rclpy.executors",
    Executor,
    SingleThreadedExecutor,
    MultiThreadedExecutor,
    ExternalShutdownException,
    ShutdownException,
    TimeoutException,
    ConditionReachedException,
    TimeoutObject,
)
as_rclpy("rclpy.experimental.events_executor", EventsExecutor)
