"""``rclpy.node.Node`` and its entities, backed by turtletui's graph."""

from __future__ import annotations

import warnings
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from turtletui.compat.callback_groups import (
    CallbackGroup,
    MutuallyExclusiveCallbackGroup,
    ReentrantCallbackGroup,
)
from turtletui.compat.context import Context, get_default_context
from turtletui.compat.destroyable import Destroyable
from turtletui.compat.dispatch import dispatcher
from turtletui.compat.distro import current_distro
from turtletui.compat.event_handler import attach_event_callbacks
from turtletui.compat.exceptions import (  # noqa: F401  (re-exported: rclpy.node users import them here)
    InvalidHandle,
    InvalidParameterTypeException,
    InvalidParameterValueException,
    NameValidationException,
    NotInitializedException,
    ParameterAlreadyDeclaredException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
    validate_full_topic_name,
    validate_namespace,
    validate_node_name,
    validate_topic_name,
)
from turtletui.compat.executors import (
    answers_can_run,
    busy_exclusive_group,
    nothing_spins,
    threads_that_can_help,
    wait_inside_callback,
)
from turtletui.compat.graph_info import (
    NodeNameNonExistentError,
    TopicEndpointInfo,
    TopicEndpointTypeEnum,
    endpoints_info,
)
from turtletui.compat.guard_condition import GuardCondition
from turtletui.compat.identity import as_rclpy
from turtletui.compat.logging import RcutilsLogger, get_logger
from turtletui.compat.logging_service import LoggingService
from turtletui.compat.matched_events import watch_matches
from turtletui.compat.matching import match_publisher, match_subscription, watch_mismatches
from turtletui.compat.message_info import MessageInfo, message_info_maker, takes_message_info
from turtletui.compat.names import RCL_EXPAND_AT, check_substitutions, unknown_substitution
from turtletui.compat.parameter import (
    ListParametersResult,
    Parameter,
    ParameterDescriptor,
    ParameterValue,
    SetParametersResult,
    apply_descriptor,
    list_parameter_names,
    parameter_value_to_python,
    type_matches,
)
from turtletui.compat.parameter_service import ParameterService
from turtletui.compat.qos import (
    QoSProfile,
    depth_of,
    incompatible_policy,
    profile_of,
    qos_profile_parameter_events,
    qos_profile_rosout_default,
    qos_profile_services_default,
)
from turtletui.compat.qos_overriding_options import declare_qos_parameters
from turtletui.compat.rcl_error import RCLError, topic_type_error
from turtletui.compat.serialization import deserialize_message, raw_callback
from turtletui.compat.service_introspection import (
    Introspection,
    ServiceIntrospectionState,
    client_gid,
    request_answered,
    request_received,
    request_sent,
)
from turtletui.compat.task import Future
from turtletui.compat.time import Clock, ClockType, Duration, clock_for
from turtletui.compat.time_source import TimeSource
from turtletui.compat.timer import (
    Rate,
    Timer,
    scheduled_period,
    timer_info_parameter,
    with_timer_info,
)
from turtletui.compat.type_description_service import TypeDescriptionService
from turtletui.compat.type_support import check_for_type_support
from turtletui.graph import core
from turtletui.graph.logs import WARN
from turtletui.interfaces import Message, copier, float32_rounder, interface_name
from turtletui.interfaces.rcl_interfaces import Log, ParameterEvent
from turtletui.interfaces.rcl_interfaces import Parameter as ParameterMsg
from turtletui.interfaces.service_msgs import ServiceEventInfo
from turtletui.messages import (
    LONG_TIMER_ADVICE,
    LONG_TIMER_SECONDS,
    LOST_REQUEST_ADVICE,
    RESPONSE_WAITS_ADVICE,
)

_NS = 1_000_000_000


def _no_call() -> None:
    """The call of a timer made with no callback."""


def _check_msg_type(msg_type: Any) -> None:
    """rclpy's check_is_valid_msg_type."""
    check_for_type_support(msg_type)
    if not issubclass(msg_type, Message):
        raise RuntimeError(
            f"The message type provided is not valid ({msg_type}), this might be a service or action"
        )


class Publisher(Destroyable):
    """Publishes messages of one type on one topic."""

    def __init__(self, node: Node, record: core.Publisher, qos_profile: QoSProfile | int) -> None:
        self._node = node
        self._record = record
        self.msg_type = record.topic.msg_type
        self.qos_profile = qos_profile
        self._publish = node._graph.publish
        self._copy = copier(self.msg_type)
        self._topic = record.topic
        self._destroyed = False  # read on every publish: an instance attribute is quicker
        self._topic_as_given = record.topic.name
        self._graph = node._graph
        self._told_undiscovered = False
        record.entity = self

    @property
    def topic_name(self) -> str:
        self._require_alive()
        return self._topic.name

    @property
    def topic(self) -> str:
        return self.topic_name

    def publish(self, msg: Any) -> None:
        """Send a copy of ``msg`` to every subscriber of the topic: as with a
        middleware that serialises, changing ``msg`` afterwards changes nothing sent."""
        if self._destroyed:
            self._require_alive()
        if type(msg) is bytes:  # serialized, as rclpy publishes bytes
            msg = deserialize_message(msg, self.msg_type)
        if type(msg) is not self.msg_type:
            raise TypeError(
                f"publish() on {self._topic.name} expects a {self._topic.type_name} message, got "
                + (_describe(msg))
            )
        record = self._record
        graph = self._graph
        if record.created_ns + graph.discovery_ns > graph.now_ns:  # not graph.known_to_others(record)
            self._tell_if_lost()
        self._publish(self._topic, msg, None, record, snapshot=self._copy)

    def _tell_if_lost(self) -> None:
        """Say once why a message reached no one in another process, if someone
        there would have had it but has not discovered this publisher yet."""
        if self._told_undiscovered:
            return
        graph, record = self._graph, self._record
        qos = self.qos_profile
        if any(
            not incompatible_policy(qos, sub.qos) and not graph.matched(record, sub) for sub in self._topic.subscriptions
        ):
            self._told_undiscovered = True
            node = self._node.get_fully_qualified_name()
            graph.log("turtletui", WARN, _UNDISCOVERED.format(node=node, topic=self._topic.name))

    def get_subscription_count(self) -> int:
        """The subscriptions this publisher matches (QoS compatible, discovered)."""
        self._require_alive()
        graph, record = self._graph, self._record
        qos = self.qos_profile
        return sum(
            1 for sub in self._topic.subscriptions if not incompatible_policy(qos, sub.qos) and graph.matched(record, sub)
        )

    def wait_for_all_acked(self, timeout: Duration = Duration(seconds=-1)) -> bool:
        self._require_alive()
        return True

    def destroy(self) -> None:
        self._node._release_entity(self, self._node._graph.remove_endpoint)


_UNDISCOVERED = (
    "{node} published on {topic} before the subscribers had discovered it, so no one got that message: "
    "ROS 2 nodes take a moment to discover each other, here and on a real robot. Publish from a timer, "
    "or wait until publisher.get_subscription_count() > 0 before the first message."
)

_RESPONSE_WAITS = (
    "{node}: spin_until_future_complete() inside a callback waited its whole timeout for {service}'s "
    "response, which is handled in the callback's own mutually exclusive group (the node's default, "
    "if you gave none) only after the callback returns; meanwhile the node handled nothing else. "
    + RESPONSE_WAITS_ADVICE
)

_UNDISCOVERED_SERVICE = (
    "{node} called {service} before it had discovered the service's server, so the request was lost "
    "and will never be answered: ROS 2 nodes take a moment to discover each other, here and on a real "
    "robot. " + LOST_REQUEST_ADVICE
)

_FIX_INSIDE = (
    "Use call_async() (await it in an async def callback, or add_done_callback()), or give the client "
    "(and the service) a callback group of its own (ReentrantCallbackGroup) and spin the node with a "
    "MultiThreadedExecutor."
)
_FIX_OUTSIDE = (
    "Spin the node in a thread first (threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()), "
    "or use call_async() with rclpy.spin_until_future_complete()."
)


def _as_sent(msg: Any) -> Any:
    """``msg`` as the middleware carries it to the other side: a copy of its own,
    float32 fields rounded, numpy and other subclass values plain."""
    copy = copier(type(msg))(msg)
    rounder = float32_rounder(type(msg))
    if rounder is not None:
        rounder(copy)
    return copy


def _describe(msg: Any) -> str:
    try:
        return interface_name(type(msg))
    except Exception:
        return f"{type(msg).__name__} {msg!r}"


class Subscription(Destroyable):
    """Calls ``callback(msg)`` for each message on a topic, with its own copy of
    it, or ``callback(msg, message_info)`` if it takes two arguments (see
    turtletui.compat.message_info)."""

    def __init__(self, node: Node, record: core.Subscription, callback: Callable, qos_profile: Any) -> None:
        self._node = node
        self._record = record
        self.msg_type = record.topic.msg_type
        self.callback = callback
        self.qos_profile = qos_profile
        self._topic_as_given = record.topic.name
        record.entity = self

    @property
    def topic_name(self) -> str:
        self._require_alive()
        return self._record.topic.name

    def get_publisher_count(self) -> int:
        """The publishers this subscription matches (QoS compatible, discovered)."""
        self._require_alive()
        record = self._record
        graph = self._node._graph
        qos = self.qos_profile
        return sum(
            1 for pub in record.topic.publishers if not incompatible_policy(pub.qos, qos) and graph.matched(pub, record)
        )

    def destroy(self) -> None:
        self._node._release_entity(self, self._node._graph.remove_endpoint)


class Client(Destroyable):
    """A service client: ``call_async(request)`` returns a Future of the response."""

    def __init__(self, node: Node, record: core.ServiceClient, callback_group: CallbackGroup, srv_name: str) -> None:
        self._node = node
        self._record = record
        self.srv_type = record.srv_type
        self.srv_name = srv_name
        """The name as given to create_client, as rclpy keeps it (service_name: resolved)."""
        self.callback_group = callback_group
        self._told_undiscovered = False
        self._told_response_waits = False
        self._sequence = 0
        self._pending_requests: dict[int, Future] = {}
        """The futures of calls sent and not yet answered, by sequence number (rclpy's)."""
        self._gid = client_gid(node.get_fully_qualified_name(), record.name, len(node._entities))
        self._introspection = Introspection(node, self.srv_type, record.name)

    @property
    def service_name(self) -> str:
        """The fully qualified name of the service (rcl's)."""
        return self._record.name

    def configure_introspection(
        self, clock: Any, service_event_qos_profile: QoSProfile, introspection_state: ServiceIntrospectionState
    ) -> None:
        """Publish this client's requests and responses on ``<service>/_service_event``."""
        self._require_alive()
        self._introspection.configure(clock, service_event_qos_profile, introspection_state)

    def call_async(self, request: Any) -> Future:
        """Send ``request``; the Future completes when the response arrives
        (handled in the client's callback group, as rclpy does)."""
        self._require_alive()
        if type(request) is not self.srv_type.Request:
            raise TypeError(
                f"call_async() on {self.service_name} expects a {self._record.type_name}.Request, got "
                + _describe(request)
            )
        request = _as_sent(request)  # the caller may change its request (the docs' self.req) and send it again
        future = Future()
        future._client = self
        host = self._node.context.host
        graph = host.graph
        self._sequence += 1
        sequence, gid, introspection = self._sequence, self._gid, self._introspection
        introspection.publish(ServiceEventInfo.REQUEST_SENT, gid, sequence, request=request)
        request_sent(request, gid, sequence)
        # As rclpy: the future leaves the pending requests in a done callback, a task
        # of the executor that takes the response, which runs before the program's own.
        self._pending_requests[sequence] = future
        future.add_done_callback(self.remove_pending_request)
        if self.service_name in graph.services and not graph.service_matched(self._record):
            self._tell_request_lost()  # and never answered, as in ROS 2
            return future
        node = self._node

        def take_response(response: Any) -> None:
            request_answered(request)
            introspection.publish(ServiceEventInfo.RESPONSE_RECEIVED, gid, sequence, response=response)
            if self._pending_requests.get(sequence) is not future:
                return  # removed (remove_pending_request, a cancel): rclpy drops the response
            # As rclpy's executor taking a response: the future's done callbacks become its tasks.
            future._set_executor(node.executor)
            future.set_result(response)

        run = dispatcher(host, self.callback_group, take_response, node=node)
        run.entity = self  # type: ignore[attr-defined]  # what Executor.wait_for_ready_callbacks names
        graph.call(self.service_name, request, run, host.owner)
        return future

    def get_pending_request(self, sequence_number: int) -> Future:
        """The future of the call numbered ``sequence_number``; KeyError if it is not pending."""
        return self._pending_requests[sequence_number]

    def remove_pending_request(self, future: Future) -> None:
        """Forget the call of ``future``: its response, if it comes, is dropped and
        its done callbacks never run (rclpy's)."""
        for sequence, pending in self._pending_requests.items():
            if pending is future:
                del self._pending_requests[sequence]
                break

    def _tell_request_lost(self) -> None:
        if not self._told_undiscovered:
            self._told_undiscovered = True
            node = self._node.get_fully_qualified_name()
            self._node._graph.log("turtletui", WARN, _UNDISCOVERED_SERVICE.format(node=node, service=self.service_name))

    def call(self, request: Any, timeout_sec: float | None = None) -> Any:
        """Call and wait for the response; TimeoutError after ``timeout_sec``.

        Where ROS 2 would wait for ever (nothing can deliver the response),
        raises RuntimeError saying why and what to do instead."""
        host = self._node.context.host
        inside = host.callback_depth > 0
        hang = self._why_call_hangs(inside)
        if hang:
            raise RuntimeError(
                f"{self.service_name}: Client.call() {hang}: in ROS 2 it would wait for ever. "
                + (_FIX_INSIDE if inside else _FIX_OUTSIDE)
            )
        future = self.call_async(request)
        timeout_ns = None if timeout_sec is None else int(min(max(timeout_sec, 0), 1e9) * _NS)
        if inside:
            wait_inside_callback(self._node, future.done, timeout_ns)
        else:
            host.spin_until(future.done, timeout_ns, callbacks=False)
        if not future.done():
            if timeout_sec is not None and host.running:
                raise TimeoutError()
            return None
        return future.result()

    def _why_call_hangs(self, inside: bool) -> str:
        """Why nothing could deliver the response of a synchronous call made
        now ("" if something can)."""
        if not inside:
            if nothing_spins(self._node):
                return "with nothing spinning the node waits for a response that nothing can deliver"
            return ""
        if not threads_that_can_help(self._node):
            return (
                "inside a callback would deadlock in ROS 2: the executor running your callback has one "
                "thread, busy waiting, so it cannot deliver the response"
            )
        if busy_exclusive_group(self.callback_group):
            return (
                "inside a callback would deadlock in ROS 2: the client is in the same mutually exclusive "
                "callback group as the callback that waits (the node's default group, if you gave none), "
                "so its response cannot be handled until that callback returns"
            )
        service = self._node._graph.services.get(self.service_name)
        if service is not None and busy_exclusive_group(getattr(service.handler, "group", None)):
            return (
                "inside a callback would deadlock in ROS 2: the service it calls is in the same mutually "
                "exclusive callback group as the callback that waits, so it cannot run until that returns"
            )
        return ""

    def _response_can_run(self) -> bool:
        """Whether, while the calling thread runs a callback, the response
        to a call (and the service's handler, if this controller serves it)
        could be handled: neither waits for a mutually exclusive group busy
        with that callback."""
        service = self._node._graph.services.get(self.service_name)
        return answers_can_run(self.callback_group, None if service is None else service.handler)

    def _tell_response_waits(self) -> None:
        """Say, once, that a wait inside a callback ran out its timeout because
        the response could not be handled before the callback returned."""
        if not self._told_response_waits:
            self._told_response_waits = True
            node = self._node.get_fully_qualified_name()
            self._node._graph.log("turtletui", WARN, _RESPONSE_WAITS.format(node=node, service=self.service_name))

    def service_is_ready(self) -> bool:
        """Whether the service's server exists and this client has discovered it."""
        self._require_alive()
        return self._node._graph.service_matched(self._record)

    def wait_for_service(self, timeout_sec: float | None = None) -> bool:
        """Wait (in simulated time) until the server exists and this client has
        discovered it, as a graph event wakes rclpy's wait; False on timeout."""
        graph = self._node._graph
        return wait_for_server(
            self._node.context.host, self._record, lambda: graph.services.get(self.service_name),
            self.service_is_ready, timeout_sec,
        )

    def destroy(self) -> None:
        self._introspection.destroy()
        self._node._release_entity(self, self._node._graph.remove_client)


def wait_for_server(
    host: Any, client: Any, server: Callable[[], Any], ready: Callable[[], bool], timeout_sec: float | None
) -> bool:
    """Wait (in simulated time) until ``server()`` (a service's or an action's
    server record) exists and ``client`` has discovered it (``ready()``), as a
    graph event wakes rclpy's wait; False on timeout."""
    graph = host.graph
    deadline = None if timeout_sec is None else graph.now_ns + int(timeout_sec * _NS)
    while not ready():
        if not host.running:
            # the program is on its way out (as sleeps, this returns at once): a
            # wait in a loop must not keep it waiting for a discovery that never
            # comes, nor loop for ever (`while not wait_for_service(1.0)` in a
            # callback is stopped as Ctrl-C stops it)
            return server() is not None or host.waited_after_end()
        left = None if deadline is None else deadline - graph.now_ns
        if left is not None and left <= 0:
            return False
        found = server()
        if found is None:
            host.spin_until(lambda: server() is not None, left, callbacks=False)
        else:  # found: discovered at a known instant, with or without other events before it
            at = graph.discovered_at(found, client) - graph.now_ns
            host.spin_until(ready, at if left is None else min(at, left), callbacks=False)
    return True


class Service(Destroyable):
    """A service server calling ``callback(request, response) -> response``."""

    def __init__(self, node: Node, record: core.Service, callback: Callable, srv_name: str) -> None:
        self._node = node
        self._record = record
        self.srv_type = record.srv_type
        self.srv_name = srv_name
        """The name as given to create_service, as rclpy keeps it (service_name: resolved)."""
        self.callback = callback
        self._introspection = Introspection(node, self.srv_type, record.name)

    @property
    def service_name(self) -> str:
        """The fully qualified name of the service (rcl's)."""
        return self._record.name

    def configure_introspection(
        self, clock: Any, service_event_qos_profile: QoSProfile, introspection_state: ServiceIntrospectionState
    ) -> None:
        """Publish the requests this service takes and its responses on ``<service>/_service_event``."""
        self._require_alive()
        self._introspection.configure(clock, service_event_qos_profile, introspection_state)

    def destroy(self) -> None:
        self._introspection.destroy()
        self._node._release_entity(self, self._node._graph.remove_service)


_NAME_ALONE = (
    "when declaring parameter named '{}', declaring a parameter only providing its name is deprecated. "
    "You have to either:\n"
    '\t- Pass a name and a default value different to "PARAMETER NOT SET" (and optionally a descriptor).\n'
    "\t- Pass a name and a parameter type.\n"
    "\t- Pass a name and a descriptor with `dynamic_typing=True"
)
"""rclpy's UserWarning for ``declare_parameter(name)`` (its text, unclosed backquote included)."""


class Node(Destroyable):
    """A ROS 2 node: the base class of every controller."""

    PARAM_REL_TOL = 1e-6

    def __init__(
        self,
        node_name: str,
        *,
        context: Context | None = None,
        cli_args: list[str] | None = None,
        namespace: str | None = None,
        use_global_arguments: bool = True,
        enable_rosout: bool = True,
        rosout_qos_profile: QoSProfile | int = qos_profile_rosout_default,
        start_parameter_services: bool = True,
        parameter_overrides: list[Parameter] | None = None,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        enable_logger_service: bool = False,
    ) -> None:
        self._context = context or get_default_context()
        if not self._context.ok():
            raise NotInitializedException("cannot create node")
        if not isinstance(node_name, str):
            raise TypeError(f"node_name must be a str, got {node_name!r}")
        validate_node_name(node_name)
        from turtletui.compat.ros_args import parse_ros_args

        ros_args = self._context.ros_args
        local = parse_ros_args(["--ros-args", *cli_args]) if cli_args else None
        remaps: dict[str, str] = {}  # rcl tries the node's own rules first, then the global ones
        for rules in (local, ros_args if use_global_arguments else None):
            if rules is not None:
                for source, target in rules.remaps_for(node_name).items():
                    remaps.setdefault(source, target)
        node_name = remaps.pop("__node", remaps.pop("__name", node_name))
        namespace = remaps.pop("__ns", namespace or "")
        if namespace and not namespace.startswith("/"):
            namespace = "/" + namespace
        if namespace:
            validate_namespace(namespace)
        # parameter files name the node as it ends up (after -r __node/__ns)
        fqn = f"{namespace.rstrip('/')}/{node_name}"
        overrides: dict[str, Any] = {}
        if use_global_arguments:
            overrides.update(ros_args.params_for(fqn))
        if local is not None:
            overrides.update(local.params_for(fqn))
        self._overrides = overrides
        for param in parameter_overrides or ():
            self._overrides.setdefault(param.name, param.value)
        self._allow_undeclared = allow_undeclared_parameters
        self._remaps: dict[str, str] = {}
        """Remap rules as rcl applies them: both sides expanded for this node (``chatter``
        is ``/ns/chatter`` here), compared with a name once it is expanded."""
        host = self._context.host
        self._graph = host.graph
        self._record = host.graph.add_node(
            node_name, namespace, host.owner, parameter_setter=self._set_from_outside
        )
        watch_mismatches(host.graph)
        self._remaps = {self._expand(source): self._expand(target) for source, target in remaps.items()}
        self._parameters: dict[str, Parameter] = {}
        self._descriptors: dict[str, ParameterDescriptor] = {}
        self._on_set: list[Callable] = []
        self._pre_set: list[Callable] = []
        """Pre-set parameters callbacks (Iron on): they may change the list being set."""
        self._post_set: list[Callable] = []
        """Post-set parameters callbacks (Iron on): told what was set."""
        self._entities: list[Any] = []
        self._executor: Any = None
        """The executor the node was last added to (rclpy's ``node.executor``)."""
        self._told_long_timer = False
        """Whether turtletui asked if this node's long timer meant milliseconds."""
        self._spinners = 0
        """Spins in progress of executors that have this node (one per thread
        inside one): while none, an executor without it parks its callbacks."""
        self._default_callback_group = MutuallyExclusiveCallbackGroup()
        self._rate_group = ReentrantCallbackGroup()
        """Where the timers of the node's rates run, as rclpy's (never busy: a rate can always tick)."""
        self._callback_groups: list[CallbackGroup] = [self._default_callback_group]
        self._logger = get_logger(f"{namespace.strip('/').replace('/', '.')}.{node_name}".lstrip("."))
        self._clock = clock_for(self._context, ClockType.ROS_TIME)
        self._context.track_node(self)
        # What rcl and rclpy give every node: /rosout, /parameter_events, use_sim_time ...
        if enable_rosout:
            self._graph.add_publisher(
                self._record, "/rosout", Log, depth_of(rosout_qos_profile), qos=rosout_qos_profile
            )
        self._parameter_event_publisher: Publisher | None = self.create_publisher(
            ParameterEvent, "/parameter_events", qos_profile_parameter_events
        )
        self._parameter_event_publisher._told_undiscovered = True  # rclpy's own: no note blames the student
        if automatically_declare_parameters_from_overrides:
            for name, value in self._overrides.items():
                self.declare_parameter(name, value, ignore_override=True)
        self._time_source = TimeSource(node=self)
        self._time_source.attach_clock(self._clock)
        if start_parameter_services:
            ParameterService(self)
        if enable_logger_service:
            self._logger_service = LoggingService(self)
        if current_distro() != "humble":  # rclpy's TypeDescriptionService, Iron on
            self._type_description_service = TypeDescriptionService(self)

    # -- identity ---------------------------------------------------------------
    @property
    def context(self) -> Context:
        return self._context

    @property
    def executor(self) -> Any:
        return self._executor

    @executor.setter
    def executor(self, value: Any) -> None:
        """As rclpy: a node is in one executor at a time; joining another leaves the first."""
        current = self._executor
        if current is value:
            return
        if current is not None:
            current.remove_node(self)
        self._executor = value
        if value is not None:
            value.add_node(self)

    @property
    def default_callback_group(self) -> CallbackGroup:
        """The group of callbacks created without one: mutually exclusive, as in rclpy."""
        return self._default_callback_group

    @property
    def callback_groups(self) -> list[CallbackGroup]:
        return list(self._callback_groups)

    def add_callback_group(self, callback_group: CallbackGroup) -> None:
        if callback_group not in self._callback_groups:
            self._callback_groups.append(callback_group)

    # -- the node's entities, as rclpy's properties list them (created first, first) --
    def _made(self, kind: type) -> Iterator[Any]:
        yield from [e for e in self._entities if isinstance(e, kind)]

    @property
    def publishers(self) -> Iterator[Publisher]:
        """The publishers made on this node (/parameter_events' too, as rclpy's)."""
        return self._made(Publisher)

    @property
    def subscriptions(self) -> Iterator[Subscription]:
        return self._made(Subscription)

    @property
    def clients(self) -> Iterator[Client]:
        return self._made(Client)

    @property
    def services(self) -> Iterator[Service]:
        """The services made on this node (its parameter services too, as rclpy's)."""
        return self._made(Service)

    @property
    def timers(self) -> Iterator[Timer]:
        """The timers made on this node (those of its rates too, as rclpy's)."""
        return self._made(Timer)

    @property
    def guards(self) -> Iterator[GuardCondition]:
        return self._made(GuardCondition)

    def _group(self, callback_group: CallbackGroup | None) -> CallbackGroup:
        """The group an entity's callbacks run in (the node's default if None)."""
        if callback_group is None:
            return self._default_callback_group
        if not isinstance(callback_group, CallbackGroup):
            raise TypeError(
                "callback_group must be a MutuallyExclusiveCallbackGroup or a ReentrantCallbackGroup, "
                f"got {callback_group!r}"
            )
        self.add_callback_group(callback_group)
        return callback_group

    def _qos_event(
        self, entity: Any, text: str, callback: Callable[[Any], None] | None = None, status: Any = None
    ) -> None:
        """Log ``text`` as rclpy's default QoS event callback of ``entity``
        does, or call the program's own ``callback`` with ``status``: when an
        executor next runs the node's callbacks, a node's events in the order
        of its entities, nodes in the order they were made."""
        events = self._context.qos_events
        if not events:
            host = self._context.host
            host.graph.ready.append((host.owner, self._context.flush_qos_events))
        order = (self._context.node_order(self), self._entities.index(entity))
        events.append((*order, self._logger, text, callback, status))

    def get_name(self) -> str:
        self._require_alive()
        return self._record.name

    def get_namespace(self) -> str:
        self._require_alive()
        return self._record.namespace or "/"

    def get_fully_qualified_name(self) -> str:
        self._require_alive()
        return self._record.fqn

    def get_logger(self) -> RcutilsLogger:
        return self._logger

    def get_clock(self) -> Clock:
        return self._clock

    # -- names ----------------------------------------------------------------
    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """Expand ``~``, relative names and (unless ``only_expand``) remappings, as rcl does."""
        return self._resolve_name(topic, only_expand, is_service=False)

    def resolve_service_name(self, service: str, *, only_expand: bool = False) -> str:
        """A service name with ``~``, relative names and (unless ``only_expand``) remappings resolved, as rcl does."""
        return self._resolve_name(service, only_expand, is_service=True)

    def _resolve_name(self, name: Any, only_expand: bool, *, is_service: bool) -> str:
        """What rclpy's resolve_*_name do (rcl_node_resolve_name): a name rcl
        cannot resolve is an RCLError with rcl's text, not the exception that
        creating an entity of that name raises."""
        self._require_alive()
        if name is None:
            raise RCLError(f"failed to resolve name: input_topic_name argument is null, {RCL_EXPAND_AT}60")
        if not isinstance(name, str):
            raise TypeError(
                "rclpy_resolve_name(): incompatible function arguments. The following argument types are supported:\n"
                "    1. (arg0: rclpy::Node, arg1: str, arg2: bool, arg3: bool) -> str\n\n"
                f"Invoked with: <rclpy._rclpy_pybind11.Node object at {id(self):#x}>, {name!r}, {only_expand!r}, {is_service!r}"
            )
        try:
            validate_topic_name(name, is_service=is_service)
        except NameValidationException as err:
            raise RCLError(f"failed to resolve name: {err._error_msg}, {RCL_EXPAND_AT}73") from None
        unknown = unknown_substitution(name)
        if unknown is not None:
            raise RCLError(f"failed to resolve name: unknown substitution: {unknown}, {RCL_EXPAND_AT}164")
        expanded = self._expand(name)
        try:
            validate_full_topic_name(expanded, is_service=is_service)
        except NameValidationException as err:
            raise RCLError(
                f"failed to resolve name: {err._error_msg}, at /project/src/rcl/node_resolve_name.c:102"
            ) from None
        return expanded if only_expand else self._remaps.get(expanded, expanded)

    def _expand_topic_name(self, topic: str, *, is_service: bool = False) -> str:
        """``topic`` as a fully qualified name, not remapped (what graph queries use). A name
        rcl cannot expand is a ValueError with rcl's text, as rclpy's expand_topic_name raises."""
        if isinstance(topic, str):
            try:
                validate_topic_name(topic)
            except NameValidationException as err:
                raise ValueError(f"topic name '{topic}' is invalid: {err._error_msg}, {RCL_EXPAND_AT}73") from None
            check_substitutions(topic)
        return self._resolve(topic, is_service, only_expand=True)

    def _resolve(self, topic: str, is_service: bool = False, *, only_expand: bool = False) -> str:
        self._require_alive()
        if topic is None:
            raise RCLError("failed to validate name: topic_name argument is null")  # rcl's, for pybind11's NULL
        if not isinstance(topic, str):
            raise TypeError(f"a topic or service name must be a str, got {topic!r}")
        validate_topic_name(topic, is_service=is_service)
        name = self._expand(topic)
        if not only_expand:
            name = self._remaps.get(name, name)
        validate_full_topic_name(name, is_service=is_service)
        return name

    def _expand(self, topic: str) -> str:
        record = self._record
        check_substitutions(topic)
        if topic.startswith("~"):
            topic = record.fqn + topic[1:]
        if "{" in topic:
            namespace = record.namespace or "/"
            topic = topic.replace("{node}", record.name).replace("{ns}", namespace).replace("{namespace}", namespace)
        if topic.startswith("/"):
            return topic
        return f"{record.namespace.rstrip('/')}/{topic}"

    # -- entities ---------------------------------------------------------------
    def create_publisher(
        self,
        msg_type: Any,
        topic: str,
        qos_profile: QoSProfile | int,
        *,
        callback_group: Any = None,
        event_callbacks: Any = None,
        qos_overriding_options: Any = None,
        publisher_class: type[Publisher] = Publisher,
    ) -> Publisher:
        self._require_alive()
        qos_profile = profile_of(qos_profile)  # rclpy's order: the QoS, the name, the type
        # rclpy resolves the name (rcl's RCLError for a bad one) only to declare the QoS
        # parameters; otherwise making the entity names what is wrong with it
        name = self.resolve_topic_name(topic) if qos_overriding_options is not None else self._resolve(topic)
        if qos_overriding_options is not None:
            declare_qos_parameters("publisher", self, name, qos_profile, qos_overriding_options)
        _check_msg_type(msg_type)
        depth = depth_of(qos_profile)
        try:
            record = self._graph.add_publisher(self._record, name, msg_type, depth, qos=qos_profile)
        except core.TopicTypeConflict as err:
            raise topic_type_error("publisher", err.name, err.type_name) from None
        publisher = publisher_class(self, record, qos_profile)
        publisher._topic_as_given = topic
        self._entities.append(publisher)
        attach_event_callbacks(self, publisher, event_callbacks, "publisher")
        match_publisher(self, publisher)
        watch_matches(self, publisher)
        return publisher

    def create_subscription(
        self,
        msg_type: Any,
        topic: str,
        callback: Callable[[Any], None] | Callable[[Any, MessageInfo], None],
        qos_profile: QoSProfile | int,
        *,
        callback_group: Any = None,
        event_callbacks: Any = None,
        qos_overriding_options: Any = None,
        raw: bool = False,
        content_filter_options: Any = None,
    ) -> Subscription:
        self._require_alive()
        qos_profile = profile_of(qos_profile)  # rclpy's order: the QoS, the name, the type
        # rclpy resolves the name (rcl's RCLError for a bad one) only to declare the QoS
        # parameters; otherwise making the entity names what is wrong with it
        name = self.resolve_topic_name(topic) if qos_overriding_options is not None else self._resolve(topic)
        if qos_overriding_options is not None:
            declare_qos_parameters("subscription", self, name, qos_profile, qos_overriding_options)
        _check_msg_type(msg_type)
        depth = depth_of(qos_profile)
        host = self._context.host
        with_info = takes_message_info(callback)  # after the name's checks, as rclpy
        info = message_info_maker(self._graph) if with_info else None
        delivered = raw_callback(callback, with_info) if raw else callback
        run = dispatcher(host, self._group(callback_group), delivered, info, float32_rounder(msg_type), node=self)
        try:
            record = self._graph.add_subscription(
                self._record,
                name,
                msg_type,
                depth,
                run,
                qos=qos_profile,
                copy=copier(msg_type),
                delivery=run.delivery,
                stamped=with_info,
            )
        except core.TopicTypeConflict as err:
            raise topic_type_error("subscription", err.name, err.type_name) from None
        subscription = Subscription(self, record, callback, qos_profile)
        subscription._topic_as_given = topic
        self._entities.append(subscription)
        attach_event_callbacks(self, subscription, event_callbacks, "subscription")
        match_subscription(self, subscription)
        watch_matches(self, subscription)
        return subscription

    def create_timer(
        self,
        timer_period_sec: float,
        callback: Callable[[], None],
        callback_group: Any = None,
        clock: Clock | None = None,
        autostart: bool = True,
    ) -> Timer:
        # rclpy's conversion, with its errors ("fast", None, nan, inf) and its truncation
        period_ns = int(float(timer_period_sec) * _NS)
        if period_ns < 0:
            raise RCLError("failed to create timer: timer period must be non-negative")
        given = callback
        if clock is not None and not isinstance(clock, Clock):
            raise TypeError(f"create_timer() needs an rclpy.clock.Clock as clock, got {clock!r}")
        if period_ns >= LONG_TIMER_SECONDS * _NS and not self._told_long_timer:
            self._told_long_timer = True
            period = f"{period_ns / _NS:g}"
            self._graph.log(
                "turtletui",
                WARN,
                f"{self.get_fully_qualified_name()}: a timer with a period of {period} s first fires {period} s "
                f"after it is made. {LONG_TIMER_ADVICE}",
            )
        group = self._group(callback_group)
        made: list[Timer] = []
        record_of: list[Any] = []
        record = self._graph.add_timer(
            self._record,
            scheduled_period(period_ns),  # a period of 0 is ready at every spin in rcl
            self._timer_run(given, group, made, record_of),
            # rclpy lets a destroyed node make a timer; no executor calls it
            autostart=autostart and not self._destroyed,
        )
        record_of.append(record)
        timer = Timer(self, record, self._clock if clock is None else clock, period_ns)
        timer._callback = given
        made.append(timer)
        timer.callback_group = group
        self._entities.append(timer)
        return timer

    def _timer_run(self, callback: Any, group: Any, timer: list[Timer], record: list[Any]) -> Callable:
        """What the graph calls for a timer (``timer[0]``, ``record[0]`` once made) whose callback is ``callback``."""
        if not callback:
            callback = _no_call  # rclpy's executor skips a timer whose callback is None
        info_parameter = timer_info_parameter(callback) if callable(callback) else None
        if info_parameter is not None:
            callback = with_timer_info(callback, info_parameter, timer)
        # a callback that is not callable fails when called, as in rclpy
        return dispatcher(self._context.host, group, callback, node=self, timer=record)

    def create_guard_condition(
        self, callback: Callable[[], Any] | None, callback_group: CallbackGroup | None = None
    ) -> GuardCondition:
        """A condition ``trigger()`` sets; the executor spinning this node then runs ``callback``."""
        self._require_alive()
        group = self._group(callback_group)
        run = dispatcher(self._context.host, group, callback, node=self) if callback is not None else None
        guard = GuardCondition(self, callback, group, run)
        self._entities.append(guard)
        return guard

    def create_rate(self, frequency: float, clock: Clock | None = None) -> Rate:
        return Rate(self, frequency, clock)

    def create_client(
        self,
        srv_type: Any,
        srv_name: str,
        *,
        qos_profile: QoSProfile = qos_profile_services_default,
        callback_group: Any = None,
    ) -> Client:
        self._require_alive()
        _check_srv_type(srv_type)
        record = self._graph.add_client(self._record, self._resolve(srv_name, True), srv_type)
        client = Client(self, record, self._group(callback_group), srv_name)
        self._entities.append(client)
        return client

    def create_service(
        self,
        srv_type: Any,
        srv_name: str,
        callback: Callable[[Any, Any], Any],
        *,
        qos_profile: QoSProfile = qos_profile_services_default,
        callback_group: Any = None,
    ) -> Service:
        self._require_alive()
        _check_srv_type(srv_type)
        host = self._context.host
        name = self._resolve(srv_name, True)

        made: list[Service] = []

        def handler(request: Any, respond: Callable[[Any], None]) -> None:
            gid, sequence = request_received(request)
            introspection = made[0]._introspection
            introspection.publish(ServiceEventInfo.REQUEST_RECEIVED, gid, sequence, request=request)
            response = callback(request, srv_type.Response())
            if type(response) is not srv_type.Response:
                raise TypeError(
                    f"service {name}: the callback must return a {interface_name(srv_type)}.Response, "
                    f"got {response!r}"
                )
            introspection.publish(ServiceEventInfo.RESPONSE_SENT, gid, sequence, response=response)
            respond(_as_sent(response))  # the server may keep its response and change it

        handler.__name__ = getattr(callback, "__name__", "handler")
        record = self._graph.add_service(
            self._record, name, srv_type, dispatcher(host, self._group(callback_group), handler, node=self)
        )
        service = Service(self, record, callback, srv_name)
        made.append(service)
        self._entities.append(service)
        return service

    # -- destruction ---------------------------------------------------------------
    # As in rclpy: True when the entity was this node's and is destroyed now,
    # False otherwise (another node's, or destroyed already); using it after
    # raises InvalidHandle.
    def destroy_publisher(self, publisher: Publisher) -> bool:
        return self._destroy_entity(publisher, self._graph.remove_endpoint)

    def destroy_subscription(self, subscription: Subscription) -> bool:
        return self._destroy_entity(subscription, self._graph.remove_endpoint)

    def destroy_timer(self, timer: Timer) -> bool:
        return self._destroy_entity(timer, self._graph.cancel_timer)

    def destroy_client(self, client: Client) -> bool:
        return self._destroy_entity(client, self._graph.remove_client)

    def destroy_service(self, service: Service) -> bool:
        return self._destroy_entity(service, self._graph.remove_service)

    def destroy_guard_condition(self, guard: GuardCondition) -> bool:
        if guard not in self._entities:
            return False
        self._entities.remove(guard)
        guard._destroyed = True
        return True

    def destroy_rate(self, rate: Rate) -> bool:
        """Destroy ``rate`` and its timer; False (as rclpy) when the timer was already gone."""
        destroyed = self.destroy_timer(rate._timer)
        rate.destroy()
        return destroyed

    def _destroy_entity(self, entity: Any, remove: Callable[[Any], Any]) -> bool:
        if entity not in self._entities:
            return False
        self._entities.remove(entity)
        self._release_entity(entity, remove)
        return True

    def _release_entity(self, entity: Any, remove: Callable[[Any], Any]) -> None:
        """What ``entity.destroy()`` does in rclpy (a ``with`` block's end too): the entity
        leaves the graph but stays in the node's lists until ``node.destroy_*()`` takes it out."""
        if not entity._destroyed:
            remove(entity._record)
            entity._destroyed = True

    def __exit__(self, *exc_info: object) -> None:
        """Leaving ``with Node(...) as node:`` destroys the node, as in rclpy."""
        self.destroy_node()

    def destroy_node(self) -> None:
        """Remove the node and all its entities from the graph."""
        if self._destroyed:
            return
        self._destroyed = True
        self._parameter_event_publisher = None
        self._graph.remove_node(self._record)
        for entity in self._entities:
            entity._destroyed = True
        self._entities.clear()
        self._context.untrack_node(self)

    # -- graph queries ----------------------------------------------------------------
    # Names are expanded but not remapped, as rclpy's queries do (except the
    # *_info_by_topic ones, which remap too).
    def count_publishers(self, topic_name: str) -> int:
        self._require_alive()
        return self._graph.count_publishers(self._expand_topic_name(topic_name))

    def count_subscribers(self, topic_name: str) -> int:
        self._require_alive()
        return self._graph.count_subscribers(self._expand_topic_name(topic_name))

    def count_clients(self, service_name: str) -> int:
        self._require_alive()
        return self._graph.count_clients(self._expand_topic_name(service_name, is_service=True))

    def count_services(self, service_name: str) -> int:
        self._require_alive()
        return self._graph.count_services(self._expand_topic_name(service_name, is_service=True))

    def get_publishers_info_by_topic(self, topic_name: str, no_mangle: bool = False) -> list[TopicEndpointInfo]:
        """A TopicEndpointInfo per publisher on the topic."""
        name = self._info_topic_name(topic_name, no_mangle)
        return endpoints_info(self._graph.publishers_of(name), TopicEndpointTypeEnum.PUBLISHER)

    def get_subscriptions_info_by_topic(
        self, topic_name: str, no_mangle: bool = False
    ) -> list[TopicEndpointInfo]:
        """A TopicEndpointInfo per subscription of the topic."""
        name = self._info_topic_name(topic_name, no_mangle)
        return endpoints_info(self._graph.subscriptions_of(name), TopicEndpointTypeEnum.SUBSCRIPTION)

    def _info_topic_name(self, topic_name: str, no_mangle: bool) -> str:
        self._require_alive()
        if no_mangle:
            return topic_name
        name = self._expand_topic_name(topic_name)
        return self._remaps.get(name, name)

    def get_topic_names_and_types(self, no_demangle: bool = False) -> list[tuple[str, list[str]]]:
        self._require_alive()
        return self._graph.topic_names_and_types()

    def get_service_names_and_types(self) -> list[tuple[str, list[str]]]:
        self._require_alive()
        return self._graph.service_names_and_types()

    def get_node_names(self) -> list[str]:
        return [name for name, _ in self.get_node_names_and_namespaces()]

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        self._require_alive()
        return self._graph.node_names_and_namespaces()

    def get_node_names_and_namespaces_with_enclaves(self) -> list[tuple[str, str, str]]:
        return [(name, namespace, "/") for name, namespace in self.get_node_names_and_namespaces()]

    def get_fully_qualified_node_names(self) -> list[str]:
        return [
            f"{namespace.rstrip('/')}/{name}" for name, namespace in self.get_node_names_and_namespaces()
        ]

    def wait_for_node(self, fully_qualified_node_name: str, timeout: float) -> bool:
        """Wait (in simulated time) until the node is in the graph; False on timeout
        (at once for a timeout of 0 or less, as rclpy's loop never looks then)."""
        if not fully_qualified_node_name.startswith("/"):
            fully_qualified_node_name = f"/{fully_qualified_node_name}"

        def found() -> bool:
            return fully_qualified_node_name in self.get_fully_qualified_node_names()

        if timeout <= 0:
            return False
        if found():
            return True
        return self._context.host.spin_until(found, int(timeout * _NS), callbacks=False)

    def get_publisher_names_and_types_by_node(
        self, node_name: str, node_namespace: str, no_demangle: bool = False
    ) -> list[tuple[str, list[str]]]:
        return self._names_and_types_by_node(node_name, node_namespace, "publishers", "publisher")

    def get_subscriber_names_and_types_by_node(
        self, node_name: str, node_namespace: str, no_demangle: bool = False
    ) -> list[tuple[str, list[str]]]:
        return self._names_and_types_by_node(node_name, node_namespace, "subscriptions", "subscriber")

    def get_service_names_and_types_by_node(
        self, node_name: str, node_namespace: str
    ) -> list[tuple[str, list[str]]]:
        return self._names_and_types_by_node(node_name, node_namespace, "services", "service")

    def get_client_names_and_types_by_node(
        self, node_name: str, node_namespace: str
    ) -> list[tuple[str, list[str]]]:
        return self._names_and_types_by_node(node_name, node_namespace, "clients", "client")

    def _names_and_types_by_node(
        self, node_name: str, node_namespace: str, kind: core.EndpointKind, noun: str
    ) -> list[tuple[str, list[str]]]:
        self._require_alive()
        record = self._graph.find_node(node_name, node_namespace)
        if record is None:
            # rclpy's text, which rcl leaves without the node's name
            raise NodeNameNonExistentError(f"cannot get {noun} names and types for nonexistent node: error not set")
        return self._graph.names_and_types_by_node(record, kind)

    # -- parameters ----------------------------------------------------------------
    def declare_parameter(
        self,
        name: str,
        value: Any = None,
        descriptor: ParameterDescriptor | None = None,
        ignore_override: bool = False,
    ) -> Parameter:
        """Declare a parameter; a ``--ros-args -p`` override of the same type wins.
        A name alone (no value, no descriptor) is deprecated in rclpy: it warns
        and declares a dynamically typed parameter."""
        if value is None and descriptor is None:
            return self.declare_parameters("", [(name,)], ignore_override)[0]
        entry = (name, value, ParameterDescriptor() if descriptor is None else descriptor)
        return self.declare_parameters("", [entry], ignore_override)[0]

    def declare_parameters(
        self, namespace: str, parameters: Sequence[tuple], ignore_override: bool = False
    ) -> list[Parameter]:
        """Declare each ``(name,)``, ``(name, value)`` or ``(name, value, descriptor)``
        under ``namespace``, after checking every entry as rclpy does (its
        TypeErrors and ValueErrors, and its UserWarning for a name alone)."""
        checked = []
        for index, entry in enumerate(parameters):
            if len(entry) < 1 or len(entry) > 3:
                raise TypeError(
                    f"Invalid parameter tuple length at index {index} in parameters list: {entry}; "
                    "expecting length between 1 and 3"
                )
            name = entry[0]
            if not isinstance(name, str):
                raise TypeError(f"First element {name} at index {index} in parameters list is not a str.")
            if namespace:
                name = f"{namespace}.{name}"
            value = entry[1] if len(entry) > 1 else None
            descriptor = entry[2] if len(entry) > 2 else ParameterDescriptor()
            if not isinstance(descriptor, ParameterDescriptor):
                raise TypeError(
                    f"Third element {descriptor} at index {index} in parameters list is not a ParameterDescriptor."
                )
            if len(entry) == 1:
                warnings.warn(_NAME_ALONE.format(name), UserWarning, stacklevel=2)
                descriptor.dynamic_typing = True
            if isinstance(value, Parameter.Type):
                if value is Parameter.Type.NOT_SET:
                    raise ValueError(f"Cannot declare parameter {{{name}}} as statically typed of type NOT_SET")
                if descriptor.dynamic_typing:
                    raise ValueError(
                        f"When declaring parameter {{{name}}} passing a descriptor with`dynamic_typing=True` "
                        "is not allowed when the parameter type is provided"
                    )
            elif not descriptor.dynamic_typing:
                inferred = value.type if isinstance(value, ParameterValue) else None
                if inferred is None:
                    inferred = Parameter.Type.from_parameter_value(value).value
                if inferred == Parameter.Type.NOT_SET.value:
                    raise ValueError(
                        "Cannot declare a statically typed parameter with default value of type PARAMETER_NOT_SET"
                    )
            checked.append((name, value, descriptor))
        return [self._declare_one(name, value, descriptor, ignore_override) for name, value, descriptor in checked]

    def _declare_one(
        self, name: str, value: Any, descriptor: ParameterDescriptor, ignore_override: bool
    ) -> Parameter:
        self._require_alive()
        if name in self._parameters:
            raise ParameterAlreadyDeclaredException([name])
        if isinstance(value, ParameterValue):
            value = parameter_value_to_python(value)
        if isinstance(value, Parameter.Type):
            expected, value = value, None
        else:
            expected = Parameter.Type.from_parameter_value(value)
        if not ignore_override and name in self._overrides:
            override = self._overrides[name]
            if (
                expected is not Parameter.Type.NOT_SET
                and not descriptor.dynamic_typing
                and override is not None  # not set (``[]`` in YAML): rclpy declares it so
                and not type_matches(expected, override)
            ):
                raise InvalidParameterTypeException(Parameter(name, value=override), expected)
            value = override
        typed = not descriptor.dynamic_typing and expected is not Parameter.Type.NOT_SET
        # typed: an empty list given for an array type keeps that type
        parameter = Parameter(name, expected if typed and expected.check(value) else None, value)
        if not descriptor.dynamic_typing:
            descriptor.type = expected.value
        result = apply_descriptor(
            parameter, descriptor, declared=False, rel_tol=self.PARAM_REL_TOL, check_read_only=False
        )
        if not result.successful:
            raise InvalidParameterValueException(name, value, result.reason)
        result = self._run_on_set([parameter])  # as rclpy's declare: on-set, not pre-set
        if not result.successful:
            raise InvalidParameterValueException(name, value, result.reason)
        self._parameters[name] = parameter
        self._descriptors[name] = descriptor
        self._graph.set_parameter(self._record, name, value)
        self._publish_parameter_event(new=[parameter])
        self._run_post_set([parameter])
        return parameter

    def undeclare_parameter(self, name: str) -> None:
        self._require_alive()
        if name not in self._parameters:
            raise ParameterNotDeclaredException(name)
        if self._descriptors[name].read_only:
            raise ParameterImmutableException(name)
        del self._parameters[name]
        del self._descriptors[name]
        self._graph.set_parameter(self._record, name, None, remove=True)

    def has_parameter(self, name: str) -> bool:
        return name in self._parameters

    def get_parameter(self, name: str) -> Parameter:
        """The parameter; a statically typed one declared without a value is uninitialized."""
        if name in self._parameters:
            parameter = self._parameters[name]
            descriptor = self._descriptors.get(name)
            if parameter.type_ is not Parameter.Type.NOT_SET or descriptor is None or descriptor.dynamic_typing:
                return parameter
            raise ParameterUninitializedException(name)
        if self._allow_undeclared:
            return Parameter(name, Parameter.Type.NOT_SET, None)
        raise ParameterNotDeclaredException(name)

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None) -> Parameter:
        """The parameter, or ``alternative_value`` if it is undeclared or has no value yet."""
        if alternative_value is None:
            alternative_value = Parameter(name, Parameter.Type.NOT_SET)
        parameter = self._parameters.get(name)
        if parameter is None or parameter.type_ is Parameter.Type.NOT_SET:
            return alternative_value
        return parameter

    def get_parameters(self, names: list[str]) -> list[Parameter]:
        if not all(isinstance(name, str) for name in names):
            raise TypeError("All names must be instances of type str")
        return [self.get_parameter(name) for name in names]

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        start = f"{prefix}." if prefix else ""
        return {n[len(start):]: p for n, p in self._parameters.items() if n.startswith(start)}

    def add_pre_set_parameters_callback(self, callback: Callable[[list[Parameter]], list[Parameter]]) -> None:
        """A callback that may change the list of parameters set_parameters is setting
        (not run by declare_parameter); the newest runs first, as in rclpy."""
        self._pre_set.insert(0, callback)

    def add_on_set_parameters_callback(self, callback: Callable[[list[Parameter]], SetParametersResult]) -> None:
        """A callback that accepts or refuses parameters before they are set or declared;
        the newest runs first and the first refusal wins, as in rclpy."""
        _check_callable(callback)
        self._on_set.insert(0, callback)

    def add_post_set_parameters_callback(self, callback: Callable[[list[Parameter]], None]) -> None:
        """A callback told which parameters were set or declared; the newest runs first."""
        _check_callable(callback)
        self._post_set.insert(0, callback)

    def remove_pre_set_parameters_callback(self, callback: Callable) -> None:
        self._pre_set.remove(callback)

    def remove_on_set_parameters_callback(self, callback: Callable) -> None:
        self._on_set.remove(callback)

    def remove_post_set_parameters_callback(self, callback: Callable) -> None:
        self._post_set.remove(callback)

    def _run_on_set(self, parameters: list[Parameter]) -> SetParametersResult:
        """rclpy's on-set callbacks: the first that refuses decides."""
        for callback in self._on_set:
            result = callback(parameters)
            if not isinstance(result, SetParametersResult):
                warnings.warn("Callback returned an invalid type, it should return SetParameterResult.", stacklevel=2)
                return SetParametersResult(successful=False, reason="Callback returned an invalid type")
            if not result.successful:
                return result
        return SetParametersResult(successful=True)

    def _run_post_set(self, parameters: list[Parameter]) -> None:
        for callback in self._post_set:
            callback(parameters)

    def set_parameters(self, parameter_list: list[Parameter]) -> list[SetParametersResult]:
        """Set parameters one by one; each gets its own result."""
        return [self._set_parameters([parameter]) for parameter in parameter_list]

    def _set_from_outside(self, name: str, value: Any) -> str | None:
        """``ros2 param set``: why the node refused, or None."""
        try:
            result = self.set_parameters([Parameter(name, value=value)])[0]
        except (ParameterNotDeclaredException, InvalidParameterTypeException) as err:
            return str(err)
        return None if result.successful else (result.reason or "the node refused it")

    def set_parameters_atomically(self, parameter_list: list[Parameter]) -> SetParametersResult:
        return self._set_parameters(parameter_list)

    def _set_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        """rclpy 9's _set_parameters_atomically: all or none; a NOT_SET value
        undeclares a dynamically typed parameter."""
        self._require_alive()
        if self._pre_set:
            parameters = [parameter for callback in self._pre_set for parameter in callback(parameters)]
            if not parameters:
                return SetParametersResult(
                    successful=False,
                    reason="parameter list cannot be empty, this might be due to "
                    "pre_set_parameters_callback modifying the original parameters list.",
                )
        if not all(isinstance(parameter, Parameter) for parameter in parameters):
            raise TypeError(f"parameter must be instance of type '{Parameter!r}'")
        undeclared = [p.name for p in parameters if p.name not in self._parameters]
        if undeclared and not self._allow_undeclared:
            # rclpy 9 names all but the first: its check's any() consumed that one
            raise ParameterNotDeclaredException(undeclared[1:])
        for parameter in parameters:
            descriptor = self._descriptors.get(parameter.name)
            if descriptor is not None:
                result = apply_descriptor(
                    parameter, descriptor, declared=parameter.name in self._parameters, rel_tol=self.PARAM_REL_TOL
                )
                if not result.successful:
                    return result
        result = self._run_on_set(parameters)
        if not result.successful:
            return result
        new, changed, deleted = [], [], []
        for parameter in parameters:
            if parameter.type_ is Parameter.Type.NOT_SET:
                deleted.append(parameter)
                self._parameters.pop(parameter.name, None)
                self._descriptors.pop(parameter.name, None)
                self._graph.set_parameter(self._record, parameter.name, None, remove=True)
                continue
            self._descriptors.setdefault(parameter.name, ParameterDescriptor(dynamic_typing=True))
            known = self._parameters.get(parameter.name)
            (new if known is None or known.type_ is Parameter.Type.NOT_SET else changed).append(parameter)
            self._parameters[parameter.name] = parameter
            self._graph.set_parameter(self._record, parameter.name, parameter.value)
        self._publish_parameter_event(new=new, changed=changed, deleted=deleted)
        self._run_post_set(parameters)
        return SetParametersResult(successful=True)

    def set_descriptor(
        self, name: str, descriptor: ParameterDescriptor, alternative_value: ParameterValue | None = None
    ) -> ParameterValue:
        """A new descriptor for a declared parameter; its value stays if it complies, else
        ``alternative_value`` is tried (rclpy's Node.set_descriptor, with its exceptions)."""
        if not self.has_parameter(name):
            if not self._allow_undeclared:
                raise ParameterNotDeclaredException(name)
            return self.get_parameter(name).get_parameter_value()
        if self.describe_parameter(name).read_only:
            raise ParameterImmutableException(name)
        current = self.get_parameter(name)
        alternative = (
            current
            if alternative_value is None
            else Parameter.from_parameter_msg(ParameterMsg(name=name, value=alternative_value))
        )
        if not self._apply_descriptor_and_set(current, descriptor).successful:
            result = self._apply_descriptor_and_set(alternative, descriptor)
            if not result.successful:
                raise InvalidParameterValueException(name, alternative.value, result.reason)
        self._descriptors[name] = descriptor
        return self.get_parameter(name).get_parameter_value()

    def _apply_descriptor_and_set(self, parameter: Parameter, descriptor: ParameterDescriptor) -> SetParametersResult:
        """rclpy's: the parameter is stored (no event, no callbacks) if the descriptor allows it."""
        result = apply_descriptor(
            parameter, descriptor, declared=True, rel_tol=self.PARAM_REL_TOL, check_read_only=False
        )
        if result.successful:
            self._parameters[parameter.name] = parameter
            self._graph.set_parameter(self._record, parameter.name, parameter.value)
        return result

    def _publish_parameter_event(
        self, *, new: Sequence[Parameter] = (), changed: Sequence[Parameter] = (), deleted: Sequence[Parameter] = ()
    ) -> None:
        """Tell /parameter_events what changed, as rclpy does after every
        successful declare or set (not after undeclare_parameter)."""
        publisher = self._parameter_event_publisher
        if publisher is None:
            return
        event = ParameterEvent(
            stamp=self._clock.now().to_msg(),
            node=self._record.fqn,
            new_parameters=[p.to_parameter_msg() for p in new],
            changed_parameters=[p.to_parameter_msg() for p in changed],
            deleted_parameters=[p.to_parameter_msg() for p in deleted],
        )
        publisher.publish(event)

    def describe_parameter(self, name: str) -> ParameterDescriptor:
        """The parameter's descriptor (its type filled in)."""
        if name in self._descriptors:
            return self._descriptors[name]
        if self._allow_undeclared:
            return ParameterDescriptor()
        raise ParameterNotDeclaredException(name)

    def describe_parameters(self, names: list[str]) -> list[ParameterDescriptor]:
        return [self.describe_parameter(name) for name in names]

    def get_parameter_type(self, name: str) -> int:
        """The parameter's type number (a ParameterType constant)."""
        if name in self._parameters:
            return self._parameters[name].type_.value
        if self._allow_undeclared:
            return Parameter.Type.NOT_SET
        raise ParameterNotDeclaredException(name)

    def get_parameter_types(self, names: list[str]) -> list[int]:
        if not all(isinstance(name, str) for name in names):
            raise TypeError("All names must be instances of type str")
        return [self.get_parameter_type(name) for name in names]

    def list_parameters(self, prefixes: list[str], depth: int) -> ListParametersResult:
        """The names of the parameters under ``prefixes`` (all if empty), at most
        ``depth`` levels deep (0: any), and their prefixes."""
        return list_parameter_names(list(self._parameters), prefixes, depth)


def _check_callable(callback: Any) -> None:
    if not callable(callback):
        # rclpy's, a format string it never formats: the TypeError's text is the tuple
        raise TypeError("Callback must be callable, got {}", type(callback))


def _check_srv_type(srv_type: Any) -> None:
    """rclpy's check_is_valid_srv_type."""
    check_for_type_support(srv_type)
    if not (hasattr(srv_type, "Request") and hasattr(srv_type, "Response")):
        raise RuntimeError(
            f"The service type provided is not valid ({srv_type}), this might be a message or action"
        )

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.node", Node)
as_rclpy("rclpy.publisher", Publisher)
as_rclpy("rclpy.subscription", Subscription)
as_rclpy("rclpy.client", Client)
as_rclpy("rclpy.service", Service)
