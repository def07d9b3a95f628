"""The /turtlesim node: turtlesim's topics, services, action and parameters over a World."""

from __future__ import annotations

import functools
import struct
from array import array
from collections.abc import Callable
from typing import Any

from turtletui.graph.core import (
    NS_PER_S,
    ActionServer,
    GoalHandle,
    Graph,
    Publisher,
    Service,
    Subscription,
)
from turtletui.graph.logs import ERROR, INFO, WARN
from turtletui.graph.qos import SENSOR_DATA, SENSOR_DATA_DEPTH
from turtletui.graph.simulated_node import SimulatedNode
from turtletui.interfaces import fields_getter
from turtletui.interfaces.builtin_interfaces import Time
from turtletui.interfaces.geometry_msgs import Twist
from turtletui.interfaces.rcl_interfaces import (
    IntegerRange,
    ParameterDescriptor,
    ParameterType,
)
from turtletui.interfaces.sensor_msgs import LaserScan
from turtletui.interfaces.std_msgs import Header
from turtletui.interfaces.std_srvs import Empty
from turtletui.interfaces.turtlesim import (
    Color,
    Kill,
    Pose,
    RotateAbsolute,
    SetPen,
    Spawn,
    TeleportAbsolute,
    TeleportRelative,
)
from turtletui.sim import (
    ARENA_SIZE,
    DT,
    Event,
    Killed,
    ObstacleHit,
    RotationFeedback,
    RotationFinished,
    SimError,
    Spawned,
    WallHit,
    Warning_,
    World,
)
from turtletui.sim.obstacles import RayCaster

QOS_DEPTH = 7
"""turtlesim's topics: keep last 7, reliable (qos.hpp)."""

_TWIST_VELOCITIES = fields_getter(Twist, "linear.x", "linear.y", "angular.z")
"""What turtlesim reads of a velocity command."""
_F32 = struct.Struct("5f")
_F32_pack = _F32.pack
_F32_unpack = _F32.unpack
PARAMETERS = ("background_r", "background_g", "background_b", "holonomic")
"""The parameters turtlesim declares (besides what every rclcpp node declares: turtletui.graph.simulated_node)."""
_ROTATION_ENDINGS = {"succeeded": "Rotation goal completed successfully", "canceled": "Rotation goal canceled"}
"""What turtle.cpp logs (INFO) when a rotate_absolute goal ends; an abort has its own warning."""


def _descriptors() -> dict[str, ParameterDescriptor]:
    """turtle_frame.cpp's parameter descriptors."""
    colour = {"r": "Red", "g": "Green", "b": "Blue"}
    descriptors = {
        f"background_{c}": ParameterDescriptor(
            name=f"background_{c}",
            type=ParameterType.PARAMETER_INTEGER,
            description=f"{word} channel of the background color",
            integer_range=[IntegerRange(from_value=0, to_value=255, step=1)],
        )
        for c, word in colour.items()
    }
    descriptors["holonomic"] = ParameterDescriptor(
        name="holonomic", type=ParameterType.PARAMETER_BOOL, description="If true, then turtles will be holonomic"
    )
    return descriptors


def parameter_problem(name: str, value: Any, node: str = "/turtlesim") -> str | None:
    """Why turtlesim refuses to set ``name`` to ``value`` (None: it accepts it).

    The colours are integers with turtlesim's descriptor range 0..255,
    ``holonomic`` is a bool: the types and ranges ``ros2 param set`` and
    ``--ros-args -p`` are held to.
    """
    if name not in PARAMETERS:
        return f"parameter '{name}' is not declared by {node}"
    if name == "holonomic":
        if not isinstance(value, bool):
            return f"parameter 'holonomic' must be a bool, got {value!r}"
    elif isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 255:
        return f"parameter '{name}' must be an integer in 0..255, got {value!r}"
    return None


@functools.cache
def _packer(count: int) -> struct.Struct:
    return struct.Struct(f"{count}f")


def _float32(*values: float) -> tuple[float, ...]:
    """Round to float32 as the Pose message does on the wire."""
    packer = _packer(len(values))
    try:
        return packer.unpack(packer.pack(*values))
    except OverflowError:
        big = 3.4028234663852886e38
        return packer.unpack(packer.pack(*(min(max(v, -big), big) for v in values)))


class _TurtleEndpoints:
    __slots__ = ("pose", "color", "scan", "cmd_vel", "services", "action")

    def __init__(self) -> None:
        self.pose: Publisher | None = None
        self.color: Publisher | None = None
        self.scan: Publisher | None = None
        self.cmd_vel: Subscription | None = None
        self.services: list[Service] = []
        self.action: ActionServer | None = None


class TurtlesimNode:
    """Adapts the physics onto the graph exactly where ROS 2 turtlesim puts it.

    When the world has a LiDAR (not in turtlesim), every turtle also publishes
    sensor_msgs/LaserScan on ``/<name>/scan`` in frame ``<name>``, on the
    ticks the LiDAR's rate gives, best effort as LiDAR drivers publish; the
    rays are cast only for turtles whose scan someone receives (a subscription
    or a tap), while the noise and dropped beams are drawn for every turtle,
    so a subscription joining late cannot change the values.
    """

    NAME = "turtlesim"

    def __init__(self, graph: Graph, world: World | None = None, *, name: str = NAME) -> None:
        """The node's type descriptions name turtlesim's types as the graph's
        distro does (``graph.type_description_names``)."""
        self.graph = graph
        self.name = name
        """The node's name: turtlesim's own, or what ``-r __node:=NAME`` made it."""
        self.world = world if world is not None else World(spawn_turtle1=False)
        own = _descriptors()
        values = (*self.world.background, self.world.holonomic)
        self._ros = SimulatedNode(
            graph, name, "sim",
            parameters=[(p, value, own[p]) for p, value in zip(PARAMETERS, values, strict=True)],
            on_set=self._apply_parameter,
        )
        """What rclcpp gives the node: /rosout, /parameter_events, the parameter services ..."""
        self.node = self._ros.node
        self._turtles: dict[str, _TurtleEndpoints] = {}
        self._poses: dict[str, Any] = {}
        """The Pose message last published for each turtle."""
        self._goals: dict[int, GoalHandle] = {}
        self._pose_plan: list[tuple[Any, str, Publisher, Publisher]] = []
        self._colour_heard = False
        self._plan_version = -1
        """The graph version ``_pose_plan`` and ``_colour_heard`` were worked out for (see ``_plan``)."""
        self._plan_turtles: list | None = None
        self.event_sinks: list[Callable[[Event], None]] = []
        """Called with every event of the world as it is handled (e.g. the app
        marks wall hits on the arena)."""
        lidar = self.world.lidar
        self._scan_period = lidar.period_ticks(DT) if lidar is not None else 0
        self._scan_angles = lidar.angles() if lidar is not None else None
        self._caster = RayCaster(self.world.obstacles) if lidar is not None else None
        self._log(INFO, f"Starting turtlesim with node name {self.node.fqn}")
        node = self.node
        graph.add_service(node, "/clear", Empty, self._clear)
        graph.add_service(node, "/reset", Empty, self._reset)
        graph.add_service(node, "/spawn", Spawn, self._spawn)
        graph.add_service(node, "/kill", Kill, self._kill)
        self.timer = graph.add_timer(node, round(DT * NS_PER_S), self._update)
        if not self.world.turtles:
            self.world.reset()
        # A world built with turtles still holds their Spawned events: handling
        # those adds the endpoints (and logs the spawn, as turtlesim does).
        pending = {event.turtle for event in self.world.events if isinstance(event, Spawned)}
        for name in self.world.turtles:
            if name not in pending:
                self._add_turtle(name)
        self._handle_events()

    # -- the 16 ms update timer ---------------------------------------------
    def _update(self) -> None:
        world = self.world
        graph = self.graph
        # checked here, not in _plan: a call less on every tick
        if graph.version != self._plan_version or world.turtles_in_order is not self._plan_turtles:
            self._plan()
        sense = self._colour_heard or graph.record_everything
        if not world.step(sense_color=sense):
            return
        if world.events:
            self._handle_events()
            if graph.version != self._plan_version or world.turtles_in_order is not self._plan_turtles:
                self._plan()
        publish = graph.publish
        trusted_pose = Pose._trusted
        poses = self._poses
        for turtle, name, pose, colour in self._pose_plan:
            vx, vy = turtle.vx, turtle.vy
            speed = (vx * vx + vy * vy) ** 0.5
            try:
                fields = _F32_unpack(_F32_pack(turtle.x, turtle.y, turtle.theta, speed, turtle.wz))
            except OverflowError:
                fields = _float32(turtle.x, turtle.y, turtle.theta, speed, turtle.wz)
            msg = poses[name] = trusted_pose(*fields)
            # young=False: the trace sees every pose; QoS mismatches still mute
            publish(pose.topic, msg, None, pose, young=False, fresh=True)
            if sense:
                publish(colour.topic, Color._trusted(*turtle.color), None, colour, young=False, fresh=True)
        if self._scan_period and world.ticks % self._scan_period == 0:
            self._publish_scans()

    def _plan(self) -> None:
        """What each tick publishes for whom, worked out again only when the
        graph or the turtles changed: (turtle, name, pose publisher, colour
        publisher) in update order, and whether anyone hears a colour sensor."""
        turtles = self._turtles
        self._pose_plan = [
            (turtle, turtle.name, ends.pose, ends.color)
            for turtle in self.world.turtles_in_order
            if (ends := turtles.get(turtle.name)) is not None
        ]
        self._colour_heard = any(ends.color and ends.color.topic.subscriptions for ends in turtles.values())
        self._plan_version = self.graph.version
        self._plan_turtles = self.world.turtles_in_order

    def _publish_scans(self) -> None:
        world, graph = self.world, self.graph
        lidar = world.lidar
        order = world.turtles_in_order
        noise = failed = None
        if lidar.noise_std > 0.0:
            noise = world.rng.normal(0.0, lidar.noise_std, (len(order), lidar.samples))
        if lidar.dropout > 0.0:
            failed = world.rng.random((len(order), lidar.samples)) < lidar.dropout
        sec, nanosec = divmod(graph.stamp_ns, NS_PER_S)
        angle_min, angle_max, increment, scan_time, range_min, range_max = _float32(
            lidar.angle_min,
            lidar.last_angle,
            lidar.angle_increment,
            self._scan_period * DT,
            lidar.range_min,
            lidar.range_max,
        )
        for i, turtle in enumerate(order):
            publisher = self._turtles[turtle.name].scan
            topic = publisher.topic
            if not (topic.subscriptions or graph.taps):
                continue
            ranges = lidar.scan(
                self._caster,
                turtle.x,
                turtle.y,
                turtle.theta,
                None if noise is None else noise[i],
                self._scan_angles,
                None if failed is None else failed[i],
            )
            msg = LaserScan(
                header=Header(stamp=Time(sec=sec, nanosec=nanosec), frame_id=turtle.name),
                angle_min=angle_min,
                angle_max=angle_max,
                angle_increment=increment,
                time_increment=0.0,
                scan_time=scan_time,
                range_min=range_min,
                range_max=range_max,
                ranges=array("f", ranges.tobytes()),
            )
            graph.publish(topic, msg, None, publisher, young=False)

    def published(self, turtle: str, pose: Any) -> bool:
        """Whether ``pose`` is the message this node last published for
        ``turtle``: a controller may publish a Pose on the same topic, as in
        ROS, but a trajectory is the turtle's own."""
        return self._poses.get(turtle) is pose

    # -- parameters -----------------------------------------------------------
    def set_parameter(self, name: str, value: Any) -> str | None:
        """Set one of turtlesim's parameters; returns a reason if refused."""
        return self._ros.set_parameter(name, value)

    def _apply_parameter(self, name: str, value: Any) -> str | None:
        problem = parameter_problem(name, value, self.node.fqn)
        if problem is not None:
            return problem
        if name == "holonomic":
            self.world.holonomic = value
        else:
            params = {**self.node.parameters, name: value}
            self.world.set_background((params["background_r"], params["background_g"], params["background_b"]))
        return None

    def stop_type_description_service(self) -> None:
        """What ``-p start_type_description_service:=false`` does: no ``~/get_type_description``."""
        self._ros.stop_type_description_service()

    # -- services ---------------------------------------------------------------
    def _clear(self, request: Any, respond) -> None:
        self._log(INFO, "Clearing turtlesim.")
        self.world.clear()
        self._handle_events()
        respond(Empty.Response())

    def _reset(self, request: Any, respond) -> None:
        self._log(INFO, "Resetting turtlesim.")
        self.world.reset()
        self._handle_events()
        respond(Empty.Response())

    def _spawn(self, request: Any, respond) -> None:
        name = ""
        try:
            name = self.world.spawn(request.x, request.y, request.theta, request.name)
        except SimError as err:
            self._log(ERROR, str(err))
        self._handle_events()
        respond(Spawn.Response(name=name))

    def _kill(self, request: Any, respond) -> None:
        try:
            self.world.kill(request.name)
        except SimError as err:
            self._log(ERROR, str(err))
        self._handle_events()
        respond(Kill.Response())

    def _turtle_service(self, turtle: str, srv_type: type, apply):
        def handler(request: Any, respond) -> None:
            try:
                apply(turtle, request)
            except SimError as err:
                self._log(ERROR, str(err))
            self._handle_events()
            respond(srv_type.Response())

        return handler

    # -- per-turtle endpoints -----------------------------------------------------
    def _add_turtle(self, name: str) -> None:
        graph, node, world = self.graph, self.node, self.world
        ends = _TurtleEndpoints()
        ends.pose = graph.add_publisher(node, f"/{name}/pose", Pose, QOS_DEPTH)
        ends.color = graph.add_publisher(node, f"/{name}/color_sensor", Color, QOS_DEPTH)
        if world.lidar is not None:
            ends.scan = graph.add_publisher(node, f"/{name}/scan", LaserScan, SENSOR_DATA_DEPTH, qos=SENSOR_DATA)

        def on_cmd_vel(velocities: tuple[float, float, float]) -> None:
            if name in world.turtles:
                world.command_velocity(name, *velocities)
                if world.events:
                    self._handle_events()

        # The subscription keeps only what turtlesim reads of each Twist: a
        # publisher then need not copy the whole message (Graph.publish's snapshot).
        ends.cmd_vel = graph.add_subscription(
            node,
            f"/{name}/cmd_vel",
            Twist,
            QOS_DEPTH,
            on_cmd_vel,
            copy=_TWIST_VELOCITIES,
        )
        services = {
            "set_pen": (SetPen, lambda t, r: world.set_pen(t, r.r, r.g, r.b, r.width, r.off)),
            "teleport_absolute": (
                TeleportAbsolute,
                lambda t, r: world.teleport_absolute(t, r.x, r.y, r.theta),
            ),
            "teleport_relative": (
                TeleportRelative,
                lambda t, r: world.teleport_relative(t, r.linear, r.angular),
            ),
        }
        for short, (srv_type, apply) in services.items():
            handler = self._turtle_service(name, srv_type, apply)
            ends.services.append(graph.add_service(node, f"/{name}/{short}", srv_type, handler))
        ends.action = graph.add_action_server(
            node, f"/{name}/rotate_absolute", RotateAbsolute, lambda handle: self._on_goal(name, handle)
        )
        self._turtles[name] = ends

    def _remove_turtle(self, name: str) -> None:
        ends = self._turtles.pop(name, None)
        if ends is None:
            return
        graph = self.graph
        for endpoint in (ends.pose, ends.color, ends.scan, ends.cmd_vel):
            if endpoint is not None:
                graph.remove_endpoint(endpoint)
        for service in ends.services:
            graph.remove_service(service)
        if ends.action is not None:
            graph.remove_action_server(ends.action)

    # -- rotate_absolute ------------------------------------------------------------
    def _on_goal(self, turtle: str, handle: GoalHandle) -> None:
        if turtle not in self.world.turtles:
            handle.finish("aborted", RotateAbsolute.Result())
            return
        goal = self.world.start_rotation(turtle, handle.goal.theta)
        self._handle_events()
        self._goals[id(goal)] = handle
        handle.on_cancel = lambda: self.world.cancel_rotation(goal)

    # -- events -----------------------------------------------------------------------
    def _handle_events(self) -> None:
        for event in self.world.take_events():
            for sink in self.event_sinks:
                sink(event)
            if isinstance(event, WallHit):
                # turtle.cpp prints its canvas position, whose y axis points down.
                canvas_y = ARENA_SIZE - event.y
                self._log(WARN, f"Oh no! I hit the wall! (Clamping from [x={event.x:f}, y={canvas_y:f}])")
            elif isinstance(event, ObstacleHit):
                self._log(WARN, f"Oh no! I hit an obstacle! (Blocked at [x={event.x:f}, y={event.y:f}])")
            elif isinstance(event, RotationFeedback):
                handle = self._goals.get(id(event.goal))
                if handle is not None:
                    handle.publish_feedback(RotateAbsolute.Feedback(remaining=_float32(event.remaining, 0, 0, 0, 0)[0]))
            elif isinstance(event, RotationFinished):
                handle = self._goals.pop(id(event.goal), None)
                if event.status in _ROTATION_ENDINGS:
                    self._log(INFO, _ROTATION_ENDINGS[event.status])
                if handle is not None:
                    delta = _float32(event.delta, 0, 0, 0, 0)[0]
                    handle.finish(event.status, RotateAbsolute.Result(delta=delta))
            elif isinstance(event, Spawned):
                self._log(
                    INFO,
                    f"Spawning turtle [{event.turtle}] at x=[{event.x:f}], y=[{event.y:f}],"
                    f" theta=[{event.theta:f}]",
                )
                self._add_turtle(event.turtle)
            elif isinstance(event, Killed):
                self._remove_turtle(event.turtle)
            elif isinstance(event, Warning_):
                self._log(WARN, event.text)

    def _log(self, level: int, msg: str) -> None:
        self.graph.log(self.name, level, msg)
