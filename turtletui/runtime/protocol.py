"""The messages between the simulator and a sandboxed controller.

Every exchange the parent sends a :class:`Tick` (the new simulated time and
what arrived for the child's nodes), or :class:`End`; the child answers with
a :class:`Report` of what its nodes did since the last one. Each message is
a NamedTuple: on the wire, an array of its fields in order.

- Parent to child: ``marshal`` (:func:`encode_tick`, :func:`decode_from_parent`);
  the child trusts its parent.
- Child to parent: JSON (:func:`encode_report`, :func:`decode_report`). The
  child runs untrusted code that may forge anything, so the parent decodes
  with the JSON scanner alone (no object hooks) and checks the count and type
  of every field, raising :class:`ProtocolError` that names the message and
  the field. What the fields mean (does the node exist, is this a Twist) is
  checked where they are applied (turtletui.runtime.sandbox_proxy).

Framing is turtletui.runtime.wire's. This module must not import numpy or
Textual (the child loads it).
"""

from __future__ import annotations

import json
import marshal
from collections.abc import Callable, Sequence
from typing import Any, NamedTuple

from turtletui.runtime.graph_mirror import GraphMirror, QosPolicies
from turtletui.runtime.wire import WireError

Values = list
"""A message as turtletui.interfaces.to_values gives it: its field values in order."""


class ProtocolError(WireError):
    """The child sent a reply that is not a :class:`Report` (the text says where)."""


# -- child to parent: graph changes ----------------------------------------------------------
# Nodes, publishers and subscriptions are named by the wire id the child gave them.


class DeclareNode(NamedTuple):
    wire_id: int
    name: str
    namespace: str


class RemoveNode(NamedTuple):
    wire_id: int


class DeclarePublisher(NamedTuple):
    wire_id: int
    node: int
    """The wire id of the node it belongs to (so in every record below)."""
    topic: str
    type_name: str
    depth: int
    qos: QosPolicies | None
    """What others see of its QoS; None for a bare depth."""


class DeclareSubscription(NamedTuple):
    wire_id: int
    node: int
    topic: str
    type_name: str
    depth: int
    label: str
    """Its callback's name (only ever shown, in a report of a slow controller)."""
    qos: QosPolicies | None
    message_info: bool = False
    """Whether its callback takes rclpy's MessageInfo: the parent sends its
    messages as :class:`StampedDelivery` records."""


class RemoveEndpoint(NamedTuple):
    """A publisher or subscription destroyed."""

    wire_id: int


class DeclareTimer(NamedTuple):
    """Told so that a report of a controller too slow for its timer can name it."""

    node: int
    period_ns: int
    label: str


class DeclareService(NamedTuple):
    node: int
    name: str
    type_name: str


class DeclareClient(NamedTuple):
    node: int
    name: str
    type_name: str


class DeclareActionClient(NamedTuple):
    node: int
    name: str
    type_name: str


class DeclareActionServer(NamedTuple):
    """The parent sends it goals (:class:`ServeGoal`); the child answers each
    with :class:`ServedGoalEvent` records."""

    node: int
    name: str
    type_name: str


REMOVABLE = ("service", "client", "action_client", "action_server")
"""What :class:`RemoveRecord` may remove."""


class RemoveRecord(NamedTuple):
    """A service, client, action client or action server destroyed."""

    kind: str
    """One of :data:`REMOVABLE`."""
    node: int
    name: str


class SetParameter(NamedTuple):
    """A node's parameter declared, set or undeclared (``remove``)."""

    node: int
    name: str
    value: Any
    """None, a bool, int, float or str, or a list of those."""
    remove: bool


GraphChange = (
    DeclareNode
    | RemoveNode
    | DeclarePublisher
    | DeclareSubscription
    | RemoveEndpoint
    | DeclareTimer
    | DeclareService
    | DeclareClient
    | DeclareActionClient
    | DeclareActionServer
    | RemoveRecord
    | SetParameter
)

# -- child to parent: traffic -----------------------------------------------------------------


class Log(NamedTuple):
    level: int
    node: str
    text: str
    in_callback: bool = True
    """Whether a callback the executor ran logged it (turtletui.graph.logs.LogRecord)."""
    call_step: int = 0
    """The number of the callback call that logged it (LogRecord.call, 0 outside
    any) less the previous Log's: a controller that logs one line per call sends
    the same Report bytes tick after tick, which the parent decodes once
    (SandboxHost._decode); GraphProxy adds the steps up again."""


class Publish(NamedTuple):
    topic: str
    values: Values
    publisher: int = 0
    """The wire id of the child's publisher that sent it."""
    young: bool = False
    """Whether no other process has discovered the publisher yet: the parent
    only keeps the message (the publisher is transient local)."""


class CallService(NamedTuple):
    call_id: int
    """The child's id for the call: the parent's :class:`ServiceResult` names it."""
    service: str
    values: Values


class SendGoal(NamedTuple):
    goal_id: int
    """The child's id for the goal: the parent's goal events name it."""
    action: str
    values: Values


class CancelGoal(NamedTuple):
    """The parent answers with a :class:`CancelAnswer`."""

    goal_id: int


# What the child's action servers do with the goals the parent sent them
# (:class:`ServeGoal`), named by the parent's goal id.


class AcceptServedGoal(NamedTuple):
    goal_id: int
    status: str
    """"accepted" or already "executing"."""


class RejectServedGoal(NamedTuple):
    goal_id: int


class ServedGoalStatus(NamedTuple):
    goal_id: int
    status: str
    """"executing" or "canceling"."""


class ServedGoalFeedback(NamedTuple):
    goal_id: int
    values: Values


class FinishServedGoal(NamedTuple):
    goal_id: int
    status: str
    """"succeeded", "aborted" or "canceled"."""
    values: Values


class AnswerServedCancel(NamedTuple):
    """The server decided on a :class:`ServeCancel`."""

    goal_id: int
    code: int
    """An action_msgs/srv/CancelGoal return code (0 to 3)."""
    canceling: bool


ServedGoalEvent = (
    AcceptServedGoal
    | RejectServedGoal
    | ServedGoalStatus
    | ServedGoalFeedback
    | FinishServedGoal
    | AnswerServedCancel
)


class ServiceResponse(NamedTuple):
    """The child's service answered a :class:`ServiceRequest`."""

    request_id: int
    values: Values


class Crash(NamedTuple):
    """Why the child's controller stopped, as the child saw it."""

    kind: str
    message: str
    frames: tuple[str, ...]
    """Traceback lines from the controller's own file."""


EXITED = "exited"
"""A Crash's kind for no crash: the program called ``sys.exit(0)`` in a
callback and ended cleanly (the parent notes where, as a clean end)."""


class Report(NamedTuple):
    """Child to parent, every exchange: what its nodes did since the last one."""

    changes: Sequence[GraphChange] = ()
    """Graph changes, in the order they were made."""
    logs: Sequence[Log] = ()
    publishes: Sequence[Publish] = ()
    calls: Sequence[CallService] = ()
    goals: Sequence[SendGoal] = ()
    cancels: Sequence[CancelGoal] = ()
    responses: Sequence[ServiceResponse] = ()
    served: Sequence[ServedGoalEvent] = ()
    """What the child's action servers did with their goals, in order."""
    logs_dropped: int = 0
    """Log records the child did not send (over its budget) so far."""
    wake_ns: int | None = None
    """When the child next has something to do (simulated ns); None: when something arrives."""
    done: bool = False
    """The controller ended: this is the last report."""
    crash: Crash | None = None
    """With ``done``: why it ended, if not normally."""


# -- parent to child --------------------------------------------------------------------------


class Delivery(NamedTuple):
    """A message for one of the child's subscriptions."""

    subscription: int
    values: Values


class StampedDelivery(NamedTuple):
    """A message for one of the child's subscriptions whose callback takes
    rclpy's MessageInfo: where it comes from, as well."""

    position: int
    """How many of the Tick's ``deliveries`` come before it: the child
    queues the two kinds in the order the parent's subscriptions had them."""
    subscription: int
    values: Values
    source_ns: int
    """When it was published, in simulated ns since start."""
    sequence: int | None
    """Its publisher's publication sequence number."""
    publisher_gid: bytes | None
    """Its publisher's GID, as the publisher's TopicEndpointInfo lists it."""


class ServiceResult(NamedTuple):
    """The answer to the child's :class:`CallService`."""

    call_id: int
    type_name: str
    """The response's interface (``pkg/srv/Name_Response``)."""
    values: Values


# What happened to the goals the child sent (:class:`SendGoal`), by its goal id.


class GoalAccepted(NamedTuple):
    goal_id: int
    server_goal_id: int
    """The goal's id on the server's side (what the client shows of it)."""
    status: str
    """"accepted" or "executing"."""


class GoalRejected(NamedTuple):
    goal_id: int


class GoalStatus(NamedTuple):
    goal_id: int
    status: str
    """"executing" or "canceling"."""


class GoalFeedback(NamedTuple):
    goal_id: int
    values: Values


class GoalResult(NamedTuple):
    goal_id: int
    status: str
    """"succeeded", "aborted" or "canceled"."""
    values: Values


class CancelAnswer(NamedTuple):
    """The server's answer to the child's :class:`CancelGoal` (may come after the result)."""

    goal_id: int
    code: int
    canceling: bool


GoalEvent = GoalAccepted | GoalRejected | GoalStatus | GoalFeedback | GoalResult | CancelAnswer


# Goals for the child's own action servers (:class:`DeclareActionServer`),
# by the parent's goal id.


class ServeGoal(NamedTuple):
    goal_id: int
    action: str
    values: Values


class ServeCancel(NamedTuple):
    """A client asks to cancel the goal: the child answers with :class:`AnswerServedCancel`."""

    goal_id: int


ServerEvent = ServeGoal | ServeCancel


class ServiceRequest(NamedTuple):
    """A call of one of the child's services."""

    request_id: int
    service: str
    values: Values


class ParameterUpdate(NamedTuple):
    """``ros2 param set`` on one of the child's nodes (the parent checked the type)."""

    node: int
    name: str
    value: Any


class Tick(NamedTuple):
    """Parent to child, every exchange: the time now and what arrived."""

    now_ns: int
    deliveries: Sequence[Delivery] = ()
    results: Sequence[ServiceResult] = ()
    goal_events: Sequence[GoalEvent] = ()
    requests: Sequence[ServiceRequest] = ()
    parameters: Sequence[ParameterUpdate] = ()
    served: Sequence[ServerEvent] = ()
    """Goals and cancel requests for the child's action servers, in order."""
    graph: GraphMirror | None = None
    """The parent's graph, when it changed since the child last heard of it."""
    stamped: Sequence[StampedDelivery] = ()
    """Messages for the child's subscriptions that take MessageInfo (rare:
    kept apart so that ``deliveries`` cost nothing more)."""


class End(NamedTuple):
    """Parent to child: the run is over; send the last report."""


# -- parent to child: encoding ------------------------------------------------------------------
# marshal takes plain tuples only, not NamedTuples: each record goes as tuple(record).

_EVENT_TAGS: dict[type, str] = {
    GoalAccepted: "accepted",
    GoalRejected: "rejected",
    GoalStatus: "status",
    GoalFeedback: "feedback",
    GoalResult: "result",
    CancelAnswer: "cancel",
    ServeGoal: "goal",
    ServeCancel: "cancel",
}
_GOAL_EVENTS: dict[str, Callable[[Any], GoalEvent]] = {
    tag: cls._make for cls, tag in _EVENT_TAGS.items() if cls not in (ServeGoal, ServeCancel)
}
_SERVER_EVENTS: dict[str, Callable[[Any], ServerEvent]] = {"goal": ServeGoal._make, "cancel": ServeCancel._make}


_dumps = marshal.dumps


def encode_tick(tick: Tick) -> bytes:
    """The frame payload of ``tick``: a tuple of its fields, the records as
    plain tuples (empty ones as ``()``)."""
    now_ns, deliveries, results, goal_events, requests, parameters, served, graph, stamped = tick
    return _dumps((
        now_ns,
        tuple(map(tuple, deliveries)) if deliveries else (),
        tuple(map(tuple, results)) if results else (),
        _tagged(goal_events) if goal_events else (),
        tuple(map(tuple, requests)) if requests else (),
        tuple(map(tuple, parameters)) if parameters else (),
        _tagged(served) if served else (),
        None if graph is None else graph.to_wire(),
        tuple(map(tuple, stamped)) if stamped else (),
    ))


def _tagged(events: Sequence[Any]) -> tuple:
    return tuple([(_EVENT_TAGS[type(event)], tuple(event)) for event in events])


def encode_end() -> bytes:
    return marshal.dumps(None)


def decode_from_parent(payload: bytes) -> Tick | End:
    """What :func:`encode_tick` or :func:`encode_end` made (the child trusts it)."""
    message = marshal.loads(payload)
    if message is None:
        return End()
    now_ns, deliveries, results, goal_events, requests, parameters, served, graph, stamped = message
    return Tick(
        now_ns,
        tuple(map(Delivery._make, deliveries)) if deliveries else (),
        tuple(map(ServiceResult._make, results)) if results else (),
        tuple([_GOAL_EVENTS[tag](fields) for tag, fields in goal_events]) if goal_events else (),
        tuple(map(ServiceRequest._make, requests)) if requests else (),
        tuple(map(ParameterUpdate._make, parameters)) if parameters else (),
        tuple([_SERVER_EVENTS[tag](fields) for tag, fields in served]) if served else (),
        None if graph is None else GraphMirror.from_wire(graph),
        tuple(map(StampedDelivery._make, stamped)) if stamped else (),
    )


# -- child to parent: encoding ------------------------------------------------------------------

_CHANGE_TAGS: dict[type, str] = {
    DeclareNode: "node",
    RemoveNode: "rmnode",
    DeclarePublisher: "pub",
    DeclareSubscription: "sub",
    RemoveEndpoint: "rm",
    DeclareTimer: "timer",
    DeclareService: "srv",
    DeclareClient: "client",
    DeclareActionClient: "aclient",
    DeclareActionServer: "asrv",
    RemoveRecord: "rmrecord",
    SetParameter: "param",
}
_SERVED_TAGS: dict[type, str] = {
    AcceptServedGoal: "accept",
    RejectServedGoal: "reject",
    ServedGoalStatus: "status",
    ServedGoalFeedback: "feedback",
    FinishServedGoal: "result",
    AnswerServedCancel: "cancel",
}


def _json_encoder() -> Callable[[Any], str]:
    """``json.dumps(obj, separators=(",", ":"), allow_nan=True)`` as one call
    of the C encoder built once: json.dumps builds one per call, and checks
    for circular references a Report (fresh lists of values) cannot have."""
    python = json.JSONEncoder(separators=(",", ":"), allow_nan=True, check_circular=False)
    make = json.encoder.c_make_encoder
    try:
        # (markers, default, encoder, indent, key separator, item separator, sort_keys, skipkeys, allow_nan)
        encode = make(None, python.default, json.encoder.encode_basestring_ascii, None, ":", ",", False, False, True)
    except TypeError:  # no C accelerator (None), or another signature than CPython 3.10-3.13's
        return python.encode
    join = "".join

    def dumps(obj: Any) -> str:
        return join(encode(obj, 0))

    return dumps


_ENCODE_JSON = _json_encoder()


def encode_report(report: Report) -> bytes:
    """The frame payload of ``report``: a JSON object with only what is not empty."""
    changes, logs, publishes, calls, goals, cancels, responses, served, logs_dropped, wake_ns, done, crash = report
    message: dict[str, Any] = {}
    if changes:
        message["decl"] = [[_CHANGE_TAGS[type(change)], *change] for change in changes]
    if logs:
        message["log"] = logs
    if publishes:
        message["pub"] = publishes
    if calls:
        message["call"] = calls
    if goals:
        message["goal"] = goals
    if cancels:
        message["cancel"] = cancels
    if responses:
        message["resp"] = responses
    if served:
        message["served"] = [[_SERVED_TAGS[type(event)], *event] for event in served]
    if logs_dropped:
        message["logs_dropped"] = logs_dropped
    if wake_ns is not None:
        message["wake"] = wake_ns
    if done:
        message["done"] = True
    if crash is not None:
        message["crash"] = crash
    return _ENCODE_JSON(message).encode()


# -- child to parent: decoding (untrusted) ------------------------------------------------------


class _Bad(Exception):
    """One field is not what it should be: ``expected`` says what it should be."""

    def __init__(self, expected: str) -> None:
        self.expected = expected


def _show(value: Any) -> str:
    text = repr(value)
    return f"{type(value).__name__} {text if len(text) <= 60 else text[:57] + '...'}"


_PLAIN_TYPES: dict[Callable[[Any], Any], type] = {}
"""The checks that only compare a field's type with one type, and that type."""


def _of_type(kind: type, expected: str) -> Callable[[Any], Any]:
    """The check of a field that must be of type ``kind`` (a bool is no int)."""

    def check(value: Any) -> Any:
        if type(value) is not kind:
            raise _Bad(expected)
        return value

    _PLAIN_TYPES[check] = kind
    return check


_int = _of_type(int, "an integer")
_str = _of_type(str, "a string")
_bool = _of_type(bool, "true or false")
_values = _of_type(list, "a list of field values")


def _removable(value: Any) -> str:
    if value not in REMOVABLE:
        raise _Bad(f"one of {', '.join(REMOVABLE)}")
    return value


def _one_of(*allowed: str) -> Callable[[Any], str]:
    def check(value: Any) -> str:
        if value not in allowed or type(value) is not str:
            raise _Bad(f"one of {', '.join(allowed)}")
        return value

    return check


def _cancel_code(value: Any) -> int:
    if type(value) is not int or not 0 <= value <= 3:
        raise _Bad("a CancelGoal return code (0 to 3)")
    return value


def _qos(value: Any) -> QosPolicies | None:
    if value is None:
        return None
    try:
        return QosPolicies.parse(value)
    except ValueError:
        raise _Bad("null or QoS policies (reliability, durability, liveliness)") from None


def _is_scalar(value: Any) -> bool:
    return value is None or type(value) in (bool, int, float, str)


def _parameter_value(value: Any) -> Any:
    if _is_scalar(value) or (type(value) is list and all(map(_is_scalar, value))):
        return value
    raise _Bad("a value a ROS parameter can hold (a scalar or a list of them)")


def _frames(value: Any) -> tuple[str, ...]:
    if type(value) is not list or not all(type(line) is str for line in value):
        raise _Bad("a list of strings")
    return tuple(value)



_FIELDS: dict[type, tuple[Callable[[Any], Any], ...]] = {
    DeclareNode: (_int, _str, _str),
    RemoveNode: (_int,),
    DeclarePublisher: (_int, _int, _str, _str, _int, _qos),
    DeclareSubscription: (_int, _int, _str, _str, _int, _str, _qos, _bool),
    RemoveEndpoint: (_int,),
    DeclareTimer: (_int, _int, _str),
    DeclareService: (_int, _str, _str),
    DeclareClient: (_int, _str, _str),
    DeclareActionClient: (_int, _str, _str),
    DeclareActionServer: (_int, _str, _str),
    RemoveRecord: (_removable, _int, _str),
    SetParameter: (_int, _str, _parameter_value, _bool),
    Log: (_int, _str, _str, _bool, _int),
    Publish: (_str, _values, _int, _bool),
    CallService: (_int, _str, _values),
    SendGoal: (_int, _str, _values),
    CancelGoal: (_int,),
    ServiceResponse: (_int, _values),
    AcceptServedGoal: (_int, _one_of("accepted", "executing")),
    RejectServedGoal: (_int,),
    ServedGoalStatus: (_int, _one_of("executing", "canceling")),
    ServedGoalFeedback: (_int, _values),
    FinishServedGoal: (_int, _one_of("succeeded", "aborted", "canceled"), _values),
    AnswerServedCancel: (_int, _cancel_code, _bool),
    Crash: (_str, _str, _frames),
}
"""How each field of a record the child sends is checked (and converted), in field order."""


_PLAIN: dict[type, list[type]] = {
    cls: [_PLAIN_TYPES[check] for check in checks]
    for cls, checks in _FIELDS.items()
    if all(check in _PLAIN_TYPES for check in checks)
}
"""The records whose fields are all of one plain type each: checked at once by
comparing the types of their fields (the hot path: Publish, Log)."""


def _record(cls: type, fields: Any, key: str, index: int | None = None) -> Any:
    """The record ``cls`` from its fields (``key[index]`` in the report)."""
    if type(fields) is list and list(map(type, fields)) == _PLAIN.get(cls):
        return tuple.__new__(cls, fields)
    where = key if index is None else f"{key}[{index}]"
    checks = _FIELDS[cls]
    if type(fields) is not list:
        raise ProtocolError(f"{where}: a {cls.__name__} must be an array of its fields, got {_show(fields)}")
    if len(fields) != len(checks):
        raise ProtocolError(
            f"{where}: a {cls.__name__} has {len(checks)} fields ({', '.join(cls._fields)}), "
            f"got {len(fields)}: {_show(fields)}"
        )
    values = []
    for name, check, value in zip(cls._fields, checks, fields, strict=True):
        try:
            values.append(check(value))
        except _Bad as bad:
            raise ProtocolError(f"{where}: {cls.__name__}.{name} must be {bad.expected}, got {_show(value)}") from None
    return tuple.__new__(cls, values)


_CHANGES: dict[str, type] = {tag: cls for cls, tag in _CHANGE_TAGS.items()}


_SERVED: dict[str, type] = {tag: cls for cls, tag in _SERVED_TAGS.items()}


def _tagged_records(kinds: dict[str, type], what: str) -> Callable[[Any, str], tuple]:
    """The decoder of an array of records of several kinds, each ``[tag, fields...]``."""

    def one(entry: Any, key: str, index: int) -> Any:
        if type(entry) is not list or not entry:
            raise ProtocolError(f"{key}[{index}]: a {what} must be an array [kind, fields...], got {_show(entry)}")
        cls = kinds.get(entry[0]) if type(entry[0]) is str else None
        if cls is None:
            raise ProtocolError(f"{key}[{index}]: unknown {what} {_show(entry[0])} (known: {', '.join(kinds)})")
        return _record(cls, entry[1:], key, index)

    def decode(entries: Any, key: str) -> tuple:
        if type(entries) is not list:
            raise ProtocolError(f"{key}: must be an array of {what}s, got {_show(entries)}")
        return tuple([one(entry, key, i) for i, entry in enumerate(entries)])

    return decode


def _records(cls: type) -> Callable[[Any, str], tuple]:
    plain = _PLAIN.get(cls)
    new = tuple.__new__

    def decode(entries: Any, key: str) -> tuple:
        if type(entries) is not list:
            raise ProtocolError(f"{key}: must be an array of {cls.__name__} records, got {_show(entries)}")
        records = []
        for index, fields in enumerate(entries):
            if type(fields) is list and list(map(type, fields)) == plain:
                records.append(new(cls, fields))  # the usual case, checked at once
            else:
                records.append(_record(cls, fields, key, index))
        return tuple(records)

    return decode


def _scalar(check: Callable[[Any], Any], nullable: bool = False) -> Callable[[Any, str], Any]:
    def decode(value: Any, key: str) -> Any:
        if nullable and value is None:
            return None
        try:
            return check(value)
        except _Bad as bad:
            raise ProtocolError(f"{key}: must be {bad.expected}{' or null' if nullable else ''}, got {_show(value)}") from None

    return decode


def _logs_dropped(value: Any, key: str) -> int:
    if type(value) is not int or value < 0:
        raise ProtocolError(f"{key}: must be a count (an integer >= 0), got {_show(value)}")
    return value


def _crash(value: Any, key: str) -> Crash | None:
    return None if value is None else _record(Crash, value, key)


_REPORT_ENTRIES: dict[str, tuple[int, Callable[[Any, str], Any]]] = {
    key: (Report._fields.index(field), decode)
    for key, field, decode in (
        ("decl", "changes", _tagged_records(_CHANGES, "graph change")),
        ("log", "logs", _records(Log)),
        ("pub", "publishes", _records(Publish)),
        ("call", "calls", _records(CallService)),
        ("goal", "goals", _records(SendGoal)),
        ("cancel", "cancels", _records(CancelGoal)),
        ("resp", "responses", _records(ServiceResponse)),
        ("served", "served", _tagged_records(_SERVED, "served-goal event")),
        ("logs_dropped", "logs_dropped", _logs_dropped),
        ("wake", "wake_ns", _scalar(_int, nullable=True)),
        ("done", "done", _scalar(_bool)),
        ("crash", "crash", _crash),
    )
}
"""The report's JSON keys: the place in a Report each fills and how it is decoded."""
_EMPTY_REPORT = list(Report())

_SCAN = json.JSONDecoder().scan_once
"""What json.loads does past its checks for encodings and white space: the
child sends UTF-8 without white space, and anything else is malformed."""


def decode_report(payload: bytes) -> Report:
    """The child's :class:`Report`. Raises WireError for what is not JSON (the
    text starts "sent a malformed reply") and ProtocolError for JSON that is not
    a report (the text names the entry, the record and the field)."""
    try:
        text = payload.decode()
        reply, end = _SCAN(text, 0)
    except StopIteration as stop:
        raise WireError(f"sent a malformed reply (no JSON value at char {stop.value})") from None
    except ValueError as err:  # also UnicodeDecodeError
        raise WireError(f"sent a malformed reply ({err})") from None
    except RecursionError:
        raise WireError("sent a malformed reply (nested too deeply)") from None
    if end != len(text):
        raise WireError(f"sent a malformed reply (more after the JSON value at char {end})")
    if type(reply) is not dict:
        raise WireError("sent a malformed reply (not an object)")
    fields = _EMPTY_REPORT.copy()
    entries = _REPORT_ENTRIES
    for key, value in reply.items():
        entry = entries.get(key)
        if entry is None:
            raise ProtocolError(f"unknown report entry {key[:60]!r} (known: {', '.join(entries)})")
        place, decode = entry
        fields[place] = decode(value, key)
    return tuple.__new__(Report, fields)
