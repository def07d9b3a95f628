"""The trusted side of a run: world, graph, turtlesim node and the loop that
moves time forward, in lockstep or in real time."""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from typing import Protocol

from turtletui.compat.distro import resolve_distro, type_description_names, type_namer
from turtletui.graph.core import DISCOVERY_NS, LOCKSTEP_EPOCH_NS, NS_PER_S, Graph, NodeRecord
from turtletui.graph.introspection import dangling_endpoints, mismatched_qos, mistyped_endpoints
from turtletui.graph.logs import WARN, LogRecord
from turtletui.graph.turtlesim_node import TurtlesimNode
from turtletui.sim import World

_real_sleep = time.sleep  # controllers may get a simulated time.sleep

TOPIC_CHECK_AFTER_NS = NS_PER_S
"""When to warn about controller topics nothing is connected to (likely typos)."""

_UNPACED_BUDGET = 0.002
"""Seconds an externally paced simulation waits for a sandboxed answer before
moving on (the answer is then picked up on a later step): keeps an app's
event loop responsive."""

MAX_ROUNDS_PER_INSTANT = 64
"""Waits a controller may finish at one simulated instant before its next wait
lets time move on: a real call takes wall time, so a loop of calls cannot
stop the world."""


class RemoteHost(Protocol):
    """A controller host in another process (turtletui.runtime.sandbox)."""

    owner: str
    wake_ns: int | None
    """When the host's own timers or sleeps next need it, in simulated ns."""

    def wants_exchange(self, now_ns: int) -> bool:
        """Whether it has messages to receive or a timer due now."""

    def exchange(self) -> bool:
        """Send what is queued for it, let it run, and publish what it sent
        back. Returns whether anything happened (in real time an answer may
        still be on its way)."""


class Simulation:
    """World + graph + /turtlesim, and the pump that runs them."""

    def __init__(
        self,
        *,
        world: World | None = None,
        realtime: bool = False,
        speed: float = 1.0,
        paced: bool = True,
        log_sinks: Sequence[Callable[[LogRecord], None]] = (),
        turtlesim_name: str = TurtlesimNode.NAME,
        distro: str | None = None,
    ) -> None:
        self.distro = resolve_distro(distro)
        """The ROS 2 distro controllers run as (turtletui.compat.distro)."""
        epoch = time.time_ns() if realtime else LOCKSTEP_EPOCH_NS
        self.graph = Graph(
            epoch_ns=epoch, type_name=type_namer(self.distro), type_description_names=type_description_names(self.distro)
        )
        self.graph.discovery_ns = DISCOVERY_NS
        self.graph.log_sinks.extend(log_sinks)
        self.world = world if world is not None else World(spawn_turtle1=False)
        self.turtlesim = TurtlesimNode(self.graph, self.world, name=turtlesim_name)
        self.remotes: list[RemoteHost] = []
        self._topic_check = self.graph.add_timer(self.turtlesim.node, TOPIC_CHECK_AFTER_NS, self._warn_of_endpoints)
        self.graph.on_node = self._node_made
        self.realtime = realtime
        self.speed = speed
        """Simulated seconds per wall second in real-time mode."""
        self.paced = paced
        """Real time: whether the pump sleeps until each step is due. An app
        that calls run_until from its own 16 ms timer paces it instead."""
        self._wall_origin: float | None = None
        self._sim_origin = 0

    @property
    def t(self) -> float:
        """Simulated seconds since start."""
        return self.graph.now_ns / NS_PER_S

    def _node_made(self, node: NodeRecord) -> None:
        """A controller's node (a reloaded one too): look at every endpoint a
        second from now, when its node has made its endpoints and discovery is over."""
        if node.owner == "sim":  # the simulator's own (turtlesim, ros2 tools, rosbag2)
            return
        self.graph.reset_timer(self._topic_check)

    def _warn_of_endpoints(self) -> None:
        """Say what ROS 2 would leave silent: topics nothing is at the other end
        of, endpoints whose types or QoS never match (each run of this once)."""
        self._topic_check.canceled = True
        graph = self.graph
        for warning in [*dangling_endpoints(graph), *mistyped_endpoints(graph), *mismatched_qos(graph)]:
            graph.log("turtletui", WARN, warning)

    def pump(
        self,
        own: str | None,
        limit_ns: int,
        *,
        run_own: bool = True,
        until: Callable[[], bool] | None = None,
    ) -> str:
        """Run callbacks, sandbox exchanges and timers up to ``limit_ns``.

        Returns "own" right after a callback owned by ``own`` ran, "until" as
        soon as ``until()`` holds, "limit" when nothing is left before the
        limit (time is then at ``limit_ns``). With ``run_own`` False, ``own``'s
        callbacks are held back and stay queued, as while a node sleeps.
        """
        graph = self.graph
        ready = graph.ready
        popleft = ready.popleft
        advance = graph.advance
        held: list | None = None
        remotes = self.remotes
        try:
            while True:
                while ready:
                    item = popleft()
                    if own is not None and item[0] == own:
                        if not run_own:
                            if held is None:
                                held = []
                            held.append(item)
                            continue
                        item[1]()
                        return "own"
                    item[1]()
                if until is not None and until():
                    return "until"
                if remotes or self.realtime:
                    if remotes and self._exchange():
                        continue
                    if not self._advance(limit_ns):
                        return "limit"
                elif not advance(limit_ns):
                    return "limit"  # lockstep alone: the next timer, or the limit
        finally:
            if held:
                ready.extendleft(reversed(held))

    def run_until(self, limit_ns: int) -> None:
        """Run everything (no in-process controller driving) up to ``limit_ns``."""
        self.pump(None, limit_ns)

    def _exchange(self) -> bool:
        now = self.graph.now_ns
        remotes = self.remotes
        if len(remotes) == 1:  # one sandboxed controller: most runs, every tick
            remote = remotes[0]
            return remote.wants_exchange(now) and remote.exchange()
        busy = [remote for remote in remotes if remote.wants_exchange(now)]
        progressed = False
        for remote in busy:
            if remote.exchange():
                progressed = True
        return progressed

    def _advance(self, limit_ns: int) -> bool:
        graph = self.graph
        due = graph.next_due()
        for remote in self.remotes:
            wake = remote.wake_ns
            if wake is not None and (due is None or wake < due):
                due = wake
        if due is None or due > limit_ns:
            if limit_ns > graph.now_ns:
                graph.now_ns = limit_ns
            return False
        if self.realtime and self.paced:
            self._wait_for(due)
        graph.advance(due)
        if graph.now_ns < due:
            graph.now_ns = due
        return True

    def wall_budget(self) -> float:
        """Real time: wall seconds until the next timer is due (0 if overdue)."""
        if not self.paced:
            return _UNPACED_BUDGET
        due = self.graph.next_due()
        if due is None or self._wall_origin is None:
            return 0.016
        target = self._wall_origin + (due - self._sim_origin) / NS_PER_S / self.speed
        return max(0.0, target - time.monotonic())

    def _wait_for(self, t_ns: int) -> None:
        now = time.monotonic()
        if self._wall_origin is None:
            self._wall_origin = now
            self._sim_origin = self.graph.now_ns
        target = self._wall_origin + (t_ns - self._sim_origin) / NS_PER_S / self.speed
        if target > now:
            _real_sleep(target - now)
