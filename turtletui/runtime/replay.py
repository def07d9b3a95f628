"""Play a recorded run again: what the controller published and called is fed,
at the recorded instants, into a fresh simulation that starts as the recorded
one did. The simulation is deterministic, so the turtle drives exactly the
recorded path, without the controller's code.

A recording is JSON Lines (turtletui.runtime.recorder), whose optional first
line is a header ``{"recording": 1, "start": [x, y, theta], "seed": ...,
"duration": ..., "world": ..., ...}`` that grading writes, or MCAP: a
``.mcap`` file or a rosbag2 folder (turtletui.recording), with that header
in its "turtletui" metadata record.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from turtletui.graph.core import NS_PER_S, TopicTypeConflict
from turtletui.graph.introspection import is_plumbing_topic
from turtletui.graph.logs import INFO
from turtletui.interfaces import from_dict, get_interface
from turtletui.recording.qos import DEFAULT, OfferedQos, adapted_offer
from turtletui.runtime.recorder import RecordingError
from turtletui.runtime.simulation import Simulation

__all__ = ["Recording", "RecordingError", "install_replay", "read_recording"]

_SIMULATOR_TOPIC_SUFFIXES = ("/pose", "/color_sensor", "/scan")


@dataclass
class Recording:
    """A recording's header and the controller's side of its events."""

    path: Path
    header: dict[str, Any] = field(default_factory=dict)
    inputs: list[dict[str, Any]] = field(default_factory=list)
    """Messages, service calls and goals the controllers sent, in order."""
    logs: list[dict[str, Any]] = field(default_factory=list)
    end: float = 0.0
    """Time of the last event, simulated seconds."""
    offers: dict[str, list[OfferedQos]] = field(default_factory=dict)
    """What each topic's recorded publishers offered (MCAP recordings only)."""

    @property
    def duration(self) -> float:
        return float(self.header.get("duration") or self.end)

    @property
    def start(self) -> tuple[float, float, float] | None:
        start = self.header.get("start")
        return None if start is None else (float(start[0]), float(start[1]), float(start[2]))


def _controller_input(event: dict[str, Any]) -> bool:
    if "topic" in event:
        return not event["topic"].endswith(_SIMULATOR_TOPIC_SUFFIXES) and not is_plumbing_topic(event["topic"])
    return "service" in event or "action" in event


def read_recording(path: str | Path) -> Recording:
    """Parse a recording; RecordingError names the line (or the MCAP file) of
    anything malformed."""
    path = Path(path)
    if path.suffix.lower() == ".mcap" or path.is_dir():
        return _read_mcap(path)
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except FileNotFoundError:
        raise RecordingError(f"{path}: no such recording") from None
    except (OSError, UnicodeDecodeError) as err:
        raise RecordingError(f"{path}: cannot read the recording ({err})") from None
    recording = Recording(path)
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            event = json.loads(line)
        except json.JSONDecodeError as err:
            raise RecordingError(f"{path}:{number}: not a JSON line ({err.msg})") from None
        if not isinstance(event, dict):
            raise RecordingError(f"{path}:{number}: expected a JSON object")
        if number == 1 and "recording" in event:
            recording.header = event
            continue
        t = event.get("t")
        if not isinstance(t, (int, float)) or t < 0:
            raise RecordingError(f"{path}:{number}: field 't' must be a time in seconds, got {t!r}")
        recording.end = max(recording.end, float(t))
        if "log" in event:
            recording.logs.append(event)
        elif _controller_input(event):
            _check_input(path, number, event)
            recording.inputs.append(event)
    return recording


def _read_mcap(path: Path) -> Recording:
    from turtletui.recording.read import McapReadError, read_mcap, recorded_offers

    try:
        header, events = read_mcap(path)
    except McapReadError as err:
        raise RecordingError(str(err)) from None
    recording = Recording(path, header=header, offers=recorded_offers(path))
    for event in events:
        recording.end = max(recording.end, event["t"])
        if "log" in event:
            recording.logs.append(event)
        elif _controller_input(event):
            where = f"{event.get('topic') or event.get('service') or event.get('action')} at t={event['t']:.3f} s"
            _check_input(path, where, event)
            recording.inputs.append(event)
    return recording


def _check_input(path: Path, number: int | str, event: dict[str, Any]) -> None:
    kind = "topic" if "topic" in event else "service" if "service" in event else "action"
    try:
        if kind == "topic":
            from_dict(get_interface(event["type"]), event["msg"])
    except (KeyError, TypeError, ValueError) as err:
        raise RecordingError(f"{path}:{number}: cannot replay this {kind} event ({err})") from None


def _simulator_type(graph: Any, event: dict[str, Any]) -> bool:
    """Whether a recorded topic event has the type the simulator uses on its topic."""
    topic = graph.topics.get(event.get("topic"))
    return topic is not None and topic.type_name == event.get("type")


def install_replay(sim: Simulation, recording: Recording) -> None:
    """Put the recorded start pose in place and schedule every recorded input.

    As ``ros2 bag play`` would, a ``rosbag2_player`` node publishes the
    recorded messages, from publishers it makes at the start with the QoS
    the recorded publishers offered (an MCAP recording says; a JSON Lines
    one does not: rclcpp's default then); its service calls and goals come
    from the same node."""
    from turtletui.graph.core import Graph
    from turtletui.recording.bag import PLAYER, rosbag2_node

    graph: Graph = sim.graph
    start = recording.start
    if start is not None and "turtle1" in sim.world.turtles:
        sim.world.place("turtle1", *start)
    node = rosbag2_node(graph, PLAYER, PLAYER)
    publishers: dict[tuple[str, str], Any] = {}
    for event in sorted(recording.inputs, key=lambda event: not _simulator_type(graph, event)):
        name = event.get("topic")
        key = (name, event.get("type"))
        if name is not None and key not in publishers:
            offer = adapted_offer(recording.offers.get(name, [])) or DEFAULT
            msg_type = get_interface(event["type"])
            try:
                publishers[key] = graph.add_publisher(node, name, msg_type, 10, qos=offer.policies())
            except TopicTypeConflict:
                # One player publishes one type per name (as one DDS participant):
                # the simulator's type comes first (sorted by _simulator_type), so
                # what is left reached none of the simulator's endpoints.
                publishers[key] = None
    graph.log("turtletui", INFO, f"replaying {recording.path.name}: {len(recording.inputs)} recorded inputs")

    def send(event: dict[str, Any]) -> Callable[[], None]:
        def fire() -> None:
            if "topic" in event:
                publisher = publishers[event["topic"], event["type"]]
                if publisher is not None:
                    graph.publish(publisher.topic, from_dict(publisher.topic.msg_type, event["msg"]), None, publisher)
            elif "service" in event:
                service = graph.services.get(event["service"])
                if service is not None:
                    request = from_dict(service.srv_type.Request, event["request"])
                    graph.call(event["service"], request, lambda response: None, PLAYER)
            else:
                server = graph.action_servers.get(event["action"])
                if server is not None:
                    goal = from_dict(server.action_type.Goal, event["goal"])
                    graph.send_goal(event["action"], goal, PLAYER, _ignore, _ignore, _ignore)

        return fire

    for event in recording.inputs:
        due = round(event["t"] * NS_PER_S)
        graph.call_later(node, max(due - graph.now_ns, 1), send(event))


def _ignore(*_: Any) -> None:
    return None
