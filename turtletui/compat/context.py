"""``rclpy.context``: the link between controller code and the host that runs it.

A *host* (turtletui.runtime) owns the graph and decides how time passes. It
binds itself with ``bind_host`` before the controller is loaded; ``rclpy.init``
then attaches the default context to it. Controller code never sees the host.
"""

from __future__ import annotations

import inspect
import weakref
from typing import TYPE_CHECKING, Any, Protocol

from turtletui.compat.dispatch import Parking
from turtletui.compat.identity import as_rclpy
from turtletui.compat.rcl_error import RCLError, UnknownROSArgsError
from turtletui.compat.ros_args import RosArgs, RosArgsError, UnknownRosArgs, parse_ros_args

if TYPE_CHECKING:
    from turtletui.graph.core import Graph


class Host(Protocol):
    """What the runtime offers the compat layer (see turtletui.runtime.host)."""

    graph: Graph
    owner: str
    callback_depth: int
    callback_counter: Any
    """Counts callbacks as they run: ``callback_counter.n`` is how deep the
    calling thread is (callback_depth), ``.call`` the number of the call it
    runs (0 outside any); turtletui.compat.dispatch keeps both."""
    call_numbers: Any
    """Numbers this host's callback calls, from 1 in every run: the lines one
    call logs carry its number (LogRecord.call)."""

    def spin(self, stop: Any) -> None:
        """Run this host's callbacks as they become ready until ``stop()``
        holds or the run ends (rclpy.spin)."""

    def spin_once(self, timeout_ns: int | None, wake: Any = None) -> bool:
        """Run callbacks of this host (advancing time as needed) until one ran,
        ``timeout_ns`` simulated ns passed or ``wake()`` holds. False when the
        run has ended, or (a host with threads) when none ran."""

    def spin_until(self, done: Any, timeout_ns: int | None) -> bool:
        """Spin until ``done()`` is true, the timeout passes or the run ends."""

    def sleep_until(self, t_ns: int) -> bool:
        """Let simulated time run to ``t_ns`` without running this host's callbacks."""

    @property
    def running(self) -> bool:
        """False once the run has ended (the context then shuts down)."""

    def waited_after_end(self) -> bool:
        """What a wait that returned because the run is over returns (False),
        unless the waiter is stopped (turtletui.runtime.host.RunEnded)."""


_current_host: Host | None = None
"""The host controllers in this process run under. Process-wide, neither passed
nor a contextvar: rclpy's API gives it no way in (``rclpy.init()``, ``Node()``
take no host), and the threads a controller starts (its own, a
MultiThreadedExecutor's) begin with an empty context, so they would not see a
contextvar the host set. A process runs one controller at a time."""


def bind_host(host: Host | None) -> None:
    """Make ``host`` the one that ``rclpy.init`` and new contexts attach to."""
    global _current_host
    _current_host = host


def current_host() -> Host:
    if _current_host is None:
        raise RuntimeError(
            "turtletui's rclpy only works inside a controller run by turtletui: "
            "use `turtletui run FILE` or turtletui.api.run()"
        )
    return _current_host


class Context:
    """Shared state of the nodes of one program, as ``rclpy.context.Context``."""

    inits = 0
    """How many contexts were initialised in this process (rclpy.init calls):
    tells the loader whether a file's top-level code started ROS itself."""

    def __init__(self) -> None:
        self._host: Host | None = None
        self._ok = False
        self._nodes: list[Any] = []
        self._callbacks: list[Any] = []
        self._made = 0
        self.parking = Parking()
        """Callbacks of nodes that wait for an executor that has them (turtletui.compat.dispatch)."""
        self.qos_events: list[tuple[int, int, Any, str, Any, Any]] = []
        """QoS warnings waiting for an executor (turtletui.compat.matching)."""
        self.ros_args = RosArgs()
        self.told_no_clock = False
        """Whether a node was told why its use_sim_time clock stands still."""
        self.told_event_callbacks = False
        """Whether turtletui said which QoS event callbacks it never calls."""

    @property
    def host(self) -> Host:
        if self._host is None:
            return current_host()
        return self._host

    def init(self, args: list[str] | None = None, *, initialize_logging: bool = True, domain_id: int | None = None) -> None:
        if self._ok:
            raise RuntimeError("Context.init() must only be called once")
        import sys

        try:
            ros_args = parse_ros_args(sys.argv if args is None else list(args))
        except UnknownRosArgs as err:
            raise UnknownROSArgsError(str(err.unknown)) from None
        except RosArgsError as err:
            from turtletui.compat.logging import get_logger

            get_logger("rcl").error("Failed to parse global arguments")
            raise RCLError(f"failed to initialize rcl: {err.rcl or err}") from None
        self._host = current_host()
        Context.inits += 1
        self.ros_args = ros_args
        self._ok = True

    def ok(self) -> bool:
        return self._ok and self._host is not None and self._host.running

    def shutdown(self) -> None:
        if not self._ok:
            raise RuntimeError("Context must be initialized before it can be shutdown")
        self._shutdown()

    def try_shutdown(self) -> None:
        if self._ok:
            self._shutdown()

    def _shutdown(self) -> None:
        self._ok = False
        self.parking.tell_waiting()  # the note of a node no executor had, before it goes
        # As rclpy's Context._cleanup: the nodes go first, then the on_shutdown callbacks run
        # (one that uses a node finds it destroyed).
        for node in list(self._nodes):
            node.destroy_node()
        callbacks, self._callbacks = self._callbacks, []
        for entry in callbacks:
            # rclpy keeps a method as a WeakMethod and calls what calling the entry gives:
            # a plain function runs as entry(), and whatever it returns, unless None, is called too
            callback = entry()
            if callback is not None:
                callback()

    def on_shutdown(self, callback: Any) -> None:
        """Call ``callback`` when this context shuts down (at once if it has already)."""
        if not callable(callback):
            # rclpy's own error, its text never formatted: str() shows the tuple
            raise TypeError("callback should be a callable, got {}", type(callback))
        if self._host is not None and not self._ok:
            callback()  # initialized once and shut down since: rclpy calls it now
            return
        self._callbacks.append(weakref.WeakMethod(callback) if inspect.ismethod(callback) else callback)

    def get_domain_id(self) -> int:
        return 0

    def track_node(self, node: Any) -> None:
        self._nodes.append(node)
        self._made += 1
        node._order = self._made

    def node_order(self, node: Any) -> int:
        """When ``node`` was made, among this context's nodes."""
        return getattr(node, "_order", 0)

    def flush_qos_events(self) -> None:
        """Log the QoS warnings waiting, as an executor runs event callbacks."""
        events, self.qos_events = sorted(self.qos_events, key=lambda e: e[:2]), []
        for done, (_, _, logger, text, callback, status) in enumerate(events, 1):
            if callback is None:
                logger.warning(text)
                continue
            try:
                callback(status)  # the program's incompatible_qos callback
            except BaseException:
                # Each handler is a callback of its own in rclpy: the ones after
                # this one still run, at the executor's next turn.
                left = events[done:]
                if left:
                    if not self.qos_events:
                        host = self.host
                        host.graph.ready.append((host.owner, self.flush_qos_events))
                    self.qos_events[:0] = left
                raise

    def untrack_node(self, node: Any) -> None:
        if node in self._nodes:
            self._nodes.remove(node)


_default_context: Context | None = Context()


def get_default_context(*, shutting_down: bool = False) -> Context:
    """The default context; ``shutting_down=True`` also forgets it, so that the next call
    makes a fresh one (what rclpy.shutdown() does, letting rclpy.init() run again)."""
    global _default_context
    if _default_context is None:
        _default_context = Context()
    context = _default_context
    if shutting_down:
        _default_context = None
    return context


def reset_default_context() -> Context:
    """Start a fresh default context (a host calls this before loading a controller)."""
    global _default_context
    _default_context = Context()
    return _default_context

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.context", Context)
