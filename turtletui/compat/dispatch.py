"""Node callbacks as rclpy's executors run them: under their callback group's
rules, and ``async def`` callbacks as tasks.

Every timer, subscription, service and client callback reaches the graph
through :func:`dispatcher`. A callback whose MutuallyExclusive group is busy
(another of its callbacks is running, in another executor thread or further
up this one's stack) waits, and runs as soon as the group is free. A callback
that returns a coroutine becomes a Task that goes on, in the same group, each
time the Future it awaits is done.

As in rclpy, an executor runs the callbacks of the nodes added to it only. A
node's callback that becomes ready while an executor without the node spins
(``rclpy.spin_once(other_node)``) waits, parked, until an executor with the
node spins; a subscription's messages wait in its queue meanwhile, up to its
depth. One ready queue serves the process: a thread whose executor takes a
callback of a node that another thread's executor spins right then hands it
over (``Executor._handed``), and that thread runs it, as each rclpy executor
waits on its own nodes' entities only.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from types import CoroutineType
from typing import Any

from turtletui.compat.callback_groups import CallbackGroup, MutuallyExclusiveCallbackGroup
from turtletui.compat.task import Task
from turtletui.graph.logs import WARN
from turtletui.messages import NEVER_SPUN_ADVICE

_running = threading.local()
"""The groups whose callbacks the calling thread is running, innermost last."""

_spinning_here = threading.local()
"""The executors the calling thread is inside a spin of, innermost last."""


def spun_by_this_thread() -> list[Any]:
    """The executors the calling thread is inside a spin of, innermost last."""
    stack = getattr(_spinning_here, "executors", None)
    if stack is None:
        stack = _spinning_here.executors = []
    return stack


def _spun_here() -> Any:
    """The executor the calling thread spins (innermost), or None."""
    stack = getattr(_spinning_here, "executors", None)
    return stack[-1] if stack else None


spinning_executors = 0
"""Executors spinning now, on any thread (turtletui.compat.executors counts
them). While at most one does, a node with a spinner is that executor's, and
a thread in a spin spins it: its callbacks run wherever taken, and the hot
paths skip the check of which executor the calling thread spins."""


class _Parks(threading.local):
    n = 0


_parks = _Parks()
"""Callbacks the calling thread parked or handed over (Parking.count)."""


NEVER_SPUN_GRACE_NS = 1_000_000_000
"""How long a callback of a node no executor has waits before turtletui says
so: a program may add the node to an executor a moment later (a thread that
starts rclpy.spin(node), an executor.add_node after some spin_once calls)."""


class Parking:
    """Callbacks of nodes no executor spun when they became ready (one per
    context), oldest first, and how many were ever parked: an executor's
    ``spin_once`` that took one goes on waiting for a callback of its own."""

    __slots__ = ("items", "told", "waiting")

    def __init__(self) -> None:
        self.items: list[tuple[Any, tuple]] = []
        """(node, ready-queue entry) pairs."""
        self.told: set[int] = set()
        """The ids of the nodes turtletui considered saying no executor ever spun."""
        self.waiting: list[Any] = []
        """The nodes whose note waits for its grace (NEVER_SPUN_GRACE_NS) to end."""

    @property
    def count(self) -> int:
        """How many callbacks the calling thread parked or handed over: an
        executor's ``spin_once`` whose callback did so goes on waiting."""
        return _parks.n

    def park(self, node: Any, item: tuple, *, tell: bool = True) -> None:
        """Keep ``item`` until an executor with ``node`` spins (once: a timer
        that fires again while it waits still runs once, as in rclpy); hand it
        to that executor if it spins now, on another thread. ``node`` may be
        an executor too: a task of its own waits until it spins (``tell``
        False: no note of a node no executor has)."""
        _parks.n += 1
        self._keep(node, item)
        if tell and node._executor is None and id(node) not in self.told:
            # ROS 2 says nothing: the node's callbacks just never run. Said
            # after a grace, and only if no executor has had the node by then.
            self.told.add(id(node))
            self.waiting.append(node)
            node._graph.soon(node._record, NEVER_SPUN_GRACE_NS, lambda: self._grace_over(node))

    def _keep(self, key: Any, item: tuple) -> None:
        """Keep ``item`` of ``key`` (a node, or an executor for its tasks): handed to
        the executor that spins it now (on another thread), else parked."""
        owner = _spinning_owner(key)
        items = self.items if owner is None else owner._handed
        callback = item[1]
        if all(entry[1][1] is not callback for entry in items):
            items.append((key, item))

    def unhand(self, executor: Any) -> None:
        """Park again what was handed to ``executor`` and is still waiting
        when it stops spinning (or hand it on, to where its node is spun now)."""
        handed, executor._handed = executor._handed, []
        for key, item in handed:
            self._keep(key, item)

    def _grace_over(self, node: Any) -> None:
        # not a callback of the executor spinning now: its spin_once goes on waiting
        _parks.n += 1
        if node in self.waiting:
            self.waiting.remove(node)
            self._tell(node)

    def tell_waiting(self) -> None:
        """Say, before the nodes go (the context shuts down), which nodes no
        executor ever had, whose grace has not ended yet."""
        waiting, self.waiting = self.waiting, []
        for node in waiting:
            self._tell(node)

    def _tell(self, node: Any) -> None:
        if node._executor is None and not node._destroyed:
            node._graph.log("turtletui", WARN, _NEVER_SPUN.format(node=node.get_fully_qualified_name()))

    def release(self, nodes: list[Any], ready: Any) -> None:
        """Queue the parked callbacks of ``nodes`` (and tasks of the executors among them)
        ahead of what else is ready, oldest first."""
        items = self.items
        if not items:
            return
        released = [item for node, item in items if node in nodes]
        if released:
            items[:] = [entry for entry in items if entry[0] not in nodes]
            ready.extendleft(reversed(released))


_NEVER_SPUN = (
    "{node}: a callback of this node is ready, but no executor has this node, so in ROS 2 none of its "
    "callbacks (timers, subscriptions, services) run until one does. " + NEVER_SPUN_ADVICE
)


def _spinning_owner(key: Any) -> Any:
    """The executor that spins now and has ``key`` (a node), or is ``key``; None if none does."""
    spinners = getattr(key, "_spinners", None)
    if spinners is None:  # an executor, for its own tasks
        return key if key._spinning else None
    return key._executor if spinners else None


def _not_here(node: Any) -> bool:
    """Whether the calling thread spins an executor that does not have ``node``:
    the node's callback it took must wait for one that has (parked, or handed
    to the one spinning now on another thread). A host's own wait, outside
    any spin, runs it."""
    stack = getattr(_spinning_here, "executors", None)
    return bool(stack) and (not node._spinners or node._executor is not stack[-1])


def in_callback() -> bool:
    """Whether the calling thread is running a callback (an executor dispatched it)."""
    return bool(getattr(_running, "groups", None))


def current_call(host: Any) -> int:
    """The number of the callback call the calling thread is running (the
    innermost), 0 outside any: lines one call logs share it."""
    return host.callback_counter.call


def running_groups() -> list[CallbackGroup]:
    """The callback groups the calling thread is inside, innermost last."""
    stack = getattr(_running, "groups", None)
    if stack is None:
        stack = _running.groups = []
    return stack


def dispatcher(
    host: Any,
    group: CallbackGroup,
    callback: Callable,
    message_info: Callable[[Any], dict] | None = None,
    received: Callable[[Any], None] | None = None,
    *,
    node: Any = None,
    timer: list[Any] | None = None,
) -> Callable:
    """``callback`` as the graph should call it: counted as a callback (as
    host.wrap_callback counts, inline: this runs for every delivery), run
    under ``group``'s rules, a coroutine it returns run as a Task.

    ``message_info``, for a subscription callback that takes rclpy's
    MessageInfo: its queue holds ``(msg, MessageOrigin)`` pairs (the graph's
    ``stamped`` subscriptions) and ``message_info(origin)`` makes the second
    argument of each call. ``received(msg)``, if given, does to each message
    what the middleware does on its way (float32 fields rounded) before the
    callback has it. ``node``, the node the callback is of, waits parked
    while an executor without it spins (see the module's docstring).
    ``timer``, for a timer's callback, holds its graph record once made: a
    parked call is the timer's one ready call, so the timer, due again
    meanwhile, is not queued beside it (rcl's timer is ready or not)."""
    depth = host.callback_counter
    calls = host.call_numbers
    ready = host.graph.ready
    owner = host.owner
    # Every node's default group: its begin/end rules inline, a call less each.
    exclusive = type(group) is MutuallyExclusiveCallbackGroup
    parking: Parking | None = None if node is None else node.context.parking

    def run(*args: Any) -> Any:
        if parking is not None:
            if node._destroyed:
                # A destroyed node's callback (one that waited parked, or was queued) never
                # runs: rclpy's executor no longer has the node's entities.
                return None
            if (not node._spinners or spinning_executors > 1) and _not_here(node):
                if timer:
                    record = timer[0]
                    record.queued = True  # taken again (Timer.take) when released
                    parking.park(node, record.ready_item)
                else:
                    # with ``run`` beside the call, for Executor.wait_for_ready_callbacks to name its entity
                    parking.park(node, (owner, lambda: run(*args), run) if args else (owner, run))
                return None
        if exclusive and group._active_entity is None:
            group._active_entity = run
        elif exclusive or not group.beginning_execution(run):
            # A timer that fires again while it waits still runs once, as in rclpy.
            if args or all(item[1] is not run for item in group._deferred):
                group._deferred.append((owner, (lambda: run(*args)) if args else run))
            return None
        held = False
        try:
            stack = _running.groups
        except AttributeError:
            stack = running_groups()
        stack.append(group)
        try:
            depth.n += 1
            outer = depth.call
            depth.call = next(calls)
            try:
                result = callback(*args)
            finally:
                depth.n -= 1
                depth.call = outer
            if result is not None and isinstance(result, CoroutineType):
                # As rclpy: the task holds its group until the coroutine ends.
                held = True
                start_task(host, group, result, now=True, release=lambda _task: release(run), node=node)
                return None
            return result
        finally:
            stack.pop()
            if not held:
                if exclusive:
                    group._active_entity = None
                else:
                    group.ending_execution(run)
                if group._deferred:
                    release_deferred(run)

    def release(entity: Any) -> None:
        group.ending_execution(entity)
        if group._deferred:
            release_deferred(entity)

    def release_deferred(entity: Any) -> None:
        if group.can_execute(entity):
            waiting, group._deferred = group._deferred, []
            ready.extendleft(reversed(waiting))

    def delivery(sub: Any) -> Callable[[], None]:
        """What hands subscription ``sub``'s queued messages to the callback:
        turtletui.graph.core.Subscription.deliver and ``run`` in one (for
        add_subscription's ``delivery``), a frame less per message. As rclpy's
        executor takes one message of a subscription each time it runs it, a
        delivery hands over the oldest message only and, if more are queued,
        queues itself again behind what else is ready: ``spin_once()`` runs
        one message, and two busy subscriptions take turns. A message for a
        free MutuallyExclusive group, the usual case, takes ``run``'s steps
        written out here; any other goes through ``run``."""
        queue = sub.queue
        popleft = queue.popleft

        def take() -> Any:
            """The oldest (message, origin) pair; the subscription stays pending while more wait."""
            entry = popleft()
            if queue:
                ready.append(sub.ready_item)
            else:
                sub.pending = False
            if received is not None:
                received(entry[0])
            return entry

        if message_info is not None:

            def deliver_with_info() -> None:
                if not queue:
                    sub.pending = False
                    return
                if parking is not None and (not node._spinners or spinning_executors > 1) and _not_here(node):
                    parking.park(node, sub.ready_item)  # the messages wait in the queue
                    return
                msg, origin = take()
                run(msg, message_info(origin))

            return deliver_with_info

        def deliver() -> None:
            if not queue:
                sub.pending = False
                return
            if parking is not None and (not node._spinners or spinning_executors > 1) and _not_here(node):
                parking.park(node, sub.ready_item)  # the messages wait in the queue
                return
            msg = popleft()  # take()'s steps written out: a frame less per message
            if queue:
                ready.append(sub.ready_item)
            else:
                sub.pending = False
            if received is not None:
                received(msg)
            if not exclusive or group._active_entity is not None:
                run(msg)
                return
            group._active_entity = run
            held = False
            try:
                stack = _running.groups
            except AttributeError:
                stack = running_groups()
            stack.append(group)
            try:
                depth.n += 1
                outer = depth.call
                depth.call = next(calls)
                try:
                    result = callback(msg)
                finally:
                    depth.n -= 1
                    depth.call = outer
                if result is not None and isinstance(result, CoroutineType):
                    held = True
                    start_task(host, group, result, now=True, release=lambda _task: release(run), node=node)
            finally:
                stack.pop()
                if not held:
                    group._active_entity = None
                    if group._deferred:
                        release_deferred(run)

        return deliver

    run.label = callback_label(callback)  # type: ignore[attr-defined]
    run.group = group  # type: ignore[attr-defined]
    run.delivery = delivery  # type: ignore[attr-defined]
    return run


def callback_label(callback: Callable) -> str:
    """A short name for a callback: the function's or method's name, or ""
    for a lambda or another callable object."""
    name = getattr(callback, "__name__", "")
    return name if isinstance(name, str) and name.isidentifier() else ""


def start_task(
    host: Any,
    group: CallbackGroup,
    handler: Any,
    args: tuple = (),
    kwargs: dict | None = None,
    *,
    now: bool,
    first: bool = False,
    release: Callable[[Task], None] | None = None,
    executor: Any = None,
    node: Any = None,
) -> Task:
    """Run ``handler`` (a coroutine, or a function called with ``args``) as a
    Task: its first step now or queued (``first``: ahead of the callbacks
    already ready), the next ones queued each time the Future it awaits is
    done. With ``release``, the caller holds ``group`` for the task and
    ``release(task)`` runs when it ends; else each step runs under
    ``group``'s rules.

    As rclpy's executor keeps its tasks to itself: a step of the task of
    ``node`` (an ``async def`` callback of it) waits parked while no executor
    with the node spins, and one of a task ``executor`` made (its
    create_task, a Future's done callback) while that executor does not spin."""
    task = Task(handler, args, kwargs, executor=executor)
    ready = host.graph.ready
    owner = host.owner
    if release is None:
        step = dispatcher(host, group, task)
    else:
        counted = host.wrap_callback(task)

        def step() -> None:
            _in_group(group, counted, host)

        task._add_done_hook(release)
    if node is not None or executor is not None:
        step = _bound(step, owner, node, executor)
        step.task = task  # type: ignore[attr-defined]  # what Executor.wait_for_ready_callbacks hands out
    task._resume = lambda: ready.append((owner, step))
    if now:
        step()
    elif first:
        ready.appendleft((owner, step))
    else:
        task._resume()
    return task


def _bound(step: Callable[[], None], owner: str, node: Any, executor: Any) -> Callable[[], None]:
    """``step``, parked or handed over (turtletui.compat.dispatch.Parking) when the
    executor spinning on the calling thread is not one with ``node`` (if given), or
    is not ``executor``."""
    if node is not None:
        key, parking = node, node.context.parking

        def elsewhere() -> bool:
            return _not_here(node)
    else:
        key, parking = executor, executor.context.parking

        def elsewhere() -> bool:
            return _spun_here() not in (None, executor)

    def bound() -> None:
        if elsewhere():
            parking.park(key, (owner, bound), tell=False)
            return
        step()

    return bound


def _in_group(group: CallbackGroup, step: Callable[[], Any], host: Any) -> None:
    """Run a task's step as inside a callback of ``group``."""
    stack = running_groups()
    stack.append(group)
    depth = host.callback_counter
    outer = depth.call
    depth.call = next(host.call_numbers)
    try:
        step()
    finally:
        stack.pop()
        depth.call = outer
