"""What a recording notes of a run as it happens: cheap, and trusted.

A tap on the graph keeps (time, kind, payload) for every message, service
call, goal and log line, as the JSON Lines recorder does, and marks
turtlesim's own poses ("pose": a controller may publish a Pose on the same
topic, as in ROS, but /tf and the scene follow the turtle) and changes of
turtlesim's background parameters ("background"). Serializing waits for a
flush (turtletui.recording.stream).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from turtletui.graph.logs import LogRecord
from turtletui.interfaces.turtlesim import Pose
from turtletui.recording.scene import Scene


class RunTap:
    """Taps ``sim``'s graph (a turtletui.runtime.simulation.Simulation) until ``detach``."""

    def __init__(self, sim: Any, earlier_logs: Iterable[LogRecord] = (), *, everything: bool = True) -> None:
        self.graph = sim.graph
        self._world = sim.world
        self._turtlesim = sim.turtlesim
        self._background = self._world.background
        self.events: list[tuple[int, str, Any]] = [(round(record.t * 1e9), "log", record) for record in earlier_logs]
        self.everything = everything
        """Whether turtlesim should publish its colour sensor even with no subscriber."""
        self.graph.taps.append(self._tap)
        if everything:
            self.graph.record_everything = True

    def scene(self) -> Scene:
        """A scene of the world as it is now (before the events to come)."""
        world = self._world
        return Scene(tuple(world.obstacles), world.background, list(world.turtles))

    def _tap(self, kind: str, payload: Any) -> None:
        events = self.events
        now = self.graph.now_ns
        if kind == "topic":
            msg = payload[1]
            if msg.__class__ is Pose:
                name = payload[0].name
                turtle = name[1:-5]
                if name.endswith("/pose") and self._turtlesim.published(turtle, msg):
                    kind, payload = "pose", (payload[0], msg, turtle)
                    background = self._world.background
                    if background != self._background:
                        self._background = background
                        events.append((now, "background", background))
        events.append((now, kind, payload))

    def take(self) -> list[tuple[int, str, Any]]:
        """The events noted since the last take."""
        events, self.events = self.events, []
        return events

    def detach(self) -> None:
        graph = self.graph
        if self._tap in graph.taps:
            graph.taps.remove(self._tap)
            # another recording (a bag, the live view) may still want everything
            graph.record_everything = any(
                isinstance(owner, RunTap) and owner.everything
                for owner in (getattr(tap, "__self__", None) for tap in graph.taps)
            )
