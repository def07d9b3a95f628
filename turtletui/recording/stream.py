"""What a run looks like to ROS tools: the graph's events as CDR messages on channels.

Fed the events a recorder taps from the graph, a RosStream hands a sink
(an MCAP file, a Foxglove server) serialized messages on these channels:

- every topic of the run as it was published (``/turtle1/pose``,
  ``/turtle1/cmd_vel``, ``/turtle1/color_sensor``, ``/turtle1/scan``, the
  controllers' own topics);
- ``/rosout`` (rcl_interfaces/msg/Log): every log line;
- ``/tf`` (tf2_msgs/msg/TFMessage): ``world`` -> ``turtleN`` at each of
  turtlesim's poses, which have no header, so 3D views can place the turtles;
- ``/turtlesim/scene`` (visualization_msgs/msg/MarkerArray): arena, walls,
  obstacles, turtles and pen trails (turtletui.recording.scene);
- service calls on ``<service>/_request`` and ``<service>/_response``
  (turtlesim/msg/Spawn_Request and _Response: see turtletui.recording.schema
  for why ``msg/``), both at the time of the response;
- action goals on ``<action>/_goal`` (turtlesim/action/RotateAbsolute_Goal).

Log times are ROS time (the run's epoch plus simulated time).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection
from dataclasses import dataclass
from typing import Any, Protocol

from turtletui.graph.logs import LogRecord, to_log_message
from turtletui.interfaces import cdr, interface_name
from turtletui.interfaces.builtin_interfaces import Time
from turtletui.interfaces.geometry_msgs import Quaternion, Transform, TransformStamped, Vector3
from turtletui.interfaces.std_msgs import Header
from turtletui.interfaces.tf2_msgs import TFMessage
from turtletui.recording.qos import DEFAULT, LATCHED, ROSOUT, OfferedQos
from turtletui.recording.scene import FRAME, Scene
from turtletui.recording.schema import recorded_type_name

ROSOUT_TOPIC = "/rosout"
TF_TOPIC = "/tf"
SCENE_TOPIC = "/turtlesim/scene"
REQUEST_SUFFIX = "/_request"
RESPONSE_SUFFIX = "/_response"
GOAL_SUFFIX = "/_goal"
_NS_PER_S = 1_000_000_000
_SKIPPED = -1
"""The id of a channel left out of the recording."""

_TurtlesimCall = Callable[[Scene, str, Any, Any], None]


@dataclass(eq=False)
class Channel:
    """One topic of a recording: its type (the schema's name) and offered QoS."""

    topic: str
    type_name: str
    qos: list[OfferedQos]
    id: int = 0
    """Set by the sink."""
    count: int = 0
    """Messages written so far."""


class Sink(Protocol):
    """Where a stream's messages go."""

    def add_channel(self, channel: Channel) -> None:
        """A new channel (set ``channel.id``) before its first message."""

    def write(self, channel: Channel, log_time_ns: int, data: bytes) -> None:
        """One serialized message (CDR, header included)."""


class RosStream:
    """Turns tapped graph events into messages on a sink's channels.

    ``feed(t_ns, kind, payload)`` takes the kinds a recorder taps: "topic"
    (topic, msg), "pose" (topic, msg, turtle) for turtlesim's own poses,
    "service" (name, request, response), "goal" (action, goal), "log"
    (LogRecord) and "background" ((r, g, b), turtlesim's parameters).
    """

    def __init__(
        self,
        sink: Sink,
        *,
        epoch_ns: int,
        scene: Scene,
        topics: Collection[str] | None = None,
        type_name: Callable[[type], str] = interface_name,
    ) -> None:
        self._sink = sink
        self._type_name = type_name
        """How the run's distro names a type (the graph's type_name_of)."""
        self._epoch_ns = epoch_ns
        self._topics = None if topics is None else frozenset(topics)
        """Only these topics are written (``ros2 bag record TOPIC...``); None: every one."""
        self._channels: dict[str, Channel] = {}
        self.scene = scene
        self._last_ns = 0

    # -- channels ---------------------------------------------------------------------
    def channel(self, topic: str, type_name: str, offers: OfferedQos | list[OfferedQos] = DEFAULT) -> Channel:
        """The channel of ``topic``, made on first use with what its publishers
        offer (one offer, or each publisher's)."""
        found = self._channels.get(topic)
        if found is None:
            offers = [offers] if isinstance(offers, OfferedQos) else offers or [DEFAULT]
            found = self._channels[topic] = Channel(topic, type_name, offers)
            if self._topics is None or topic in self._topics:
                self._sink.add_channel(found)
            else:
                found.id = _SKIPPED
        return found

    def _write(self, channel: Channel, t_ns: int, msg: Any) -> None:
        if channel.id == _SKIPPED:
            return
        channel.count += 1
        self._sink.write(channel, self._epoch_ns + t_ns, cdr.serialize(msg))

    @property
    def channels(self) -> list[Channel]:
        """The channels written so far."""
        return [channel for channel in self._channels.values() if channel.id != _SKIPPED]

    # -- events --------------------------------------------------------------------------
    def feed(self, t_ns: int, kind: str, payload: Any) -> None:
        """One tapped event at simulated time ``t_ns``."""
        self._last_ns = t_ns
        if kind == "topic" or kind == "pose":
            topic, msg = payload[0], payload[1]
            channel = self._channels.get(topic.name)
            if channel is None:
                channel = self.channel(topic.name, topic.type_name, [OfferedQos.of(p.qos) for p in topic.publishers])
            self._write(channel, t_ns, msg)
            if kind == "pose":
                self._pose(t_ns, payload[2], msg)
        elif kind == "log":
            self._log(payload)
        elif kind == "service":
            self._service(t_ns, *payload)
        elif kind == "goal":
            name, goal = payload
            self._write(self.channel(name + GOAL_SUFFIX, self._type_name(type(goal))), t_ns, goal)
        elif kind == "background":
            self.scene.set_background(payload)
        if self.scene.due(t_ns):
            self._send_scene(t_ns)

    def finish(self) -> None:
        """Send the last scene if it changed since the last one sent."""
        if self.scene.due(self._last_ns + 3600 * _NS_PER_S):
            self._send_scene(self._last_ns)

    def _send_scene(self, t_ns: int) -> None:
        snapshot = self.scene.snapshot(t_ns, self._epoch_ns + t_ns)
        self._write(self.channel(SCENE_TOPIC, "visualization_msgs/msg/MarkerArray", LATCHED), t_ns, snapshot)

    def _pose(self, t_ns: int, turtle: str, pose: Any) -> None:
        self.scene.pose(turtle, pose.x, pose.y)
        sec, nanosec = divmod(self._epoch_ns + t_ns, _NS_PER_S)
        half = pose.theta / 2
        transform = TransformStamped._trusted(
            Header._trusted(Time._trusted(sec, nanosec), FRAME),
            turtle,
            Transform._trusted(
                Vector3._trusted(pose.x, pose.y, 0.0),
                Quaternion._trusted(0.0, 0.0, math.sin(half), math.cos(half)),
            ),
        )
        self._write(self.channel(TF_TOPIC, "tf2_msgs/msg/TFMessage"), t_ns, TFMessage._trusted([transform]))

    def _log(self, record: LogRecord) -> None:
        msg = to_log_message(record)
        channel = self.channel(ROSOUT_TOPIC, "rcl_interfaces/msg/Log", ROSOUT)
        if channel.id == _SKIPPED:
            return
        channel.count += 1
        self._sink.write(channel, record.stamp_ns, cdr.serialize(msg))

    def _service(self, t_ns: int, name: str, request: Any, response: Any) -> None:
        service_type = interface_name(request).removesuffix("_Request")  # turtletui's own name
        request_type = recorded_type_name(self._type_name(type(request)))
        self._write(self.channel(name + REQUEST_SUFFIX, request_type), t_ns, request)
        response_type = recorded_type_name(self._type_name(type(response)))
        self._write(self.channel(name + RESPONSE_SUFFIX, response_type), t_ns, response)
        # turtlesim's own services: /spawn, /kill, /clear, /reset, /<turtle>/set_pen
        short = name[1:] if name.count("/") == 1 else "set_pen" if name.count("/") == 2 else ""
        apply = _TURTLESIM_CALLS.get((short, service_type))
        if apply is not None and (short != "set_pen" or name.endswith("/set_pen")):
            apply(self.scene, name, request, response)


def _set_pen(scene: Scene, name: str, request: Any, response: Any) -> None:
    scene.set_pen(name[1:].rsplit("/", 1)[0], request.r, request.g, request.b, request.width, request.off)


def _spawned(scene: Scene, name: str, request: Any, response: Any) -> None:
    if response.name:
        scene.spawned(response.name)


_TURTLESIM_CALLS: dict[tuple[str, str], _TurtlesimCall] = {
    ("set_pen", "turtlesim/srv/SetPen"): _set_pen,
    ("spawn", "turtlesim/srv/Spawn"): _spawned,
    ("kill", "turtlesim/srv/Kill"): lambda scene, name, request, response: scene.killed(request.name),
    ("clear", "std_srvs/srv/Empty"): lambda scene, name, request, response: scene.cleared(),
    ("reset", "std_srvs/srv/Empty"): lambda scene, name, request, response: scene.reset(),
}
"""turtlesim's services that change what the scene shows, by (name, type)."""
