"""turtletui's side on a real ROS 2 graph: run by a ROS 2 python, not by turtletui.

``python3 ros_node.py`` (the python of a sourced ROS 2, or of a venv with the
ROS 2 wheels) imports the real rclpy and nothing of turtletui, so turtletui's
own Python, numpy and packages never meet ROS's. It talks to turtletui over
its standard input and output, one JSON object a line:

- turtletui says which nodes and endpoints its graph has (``node``, ``pub``,
  ``sub``, ``srv``, ``action``, ``remove``...): each gets a real twin here,
  with the same names, types and QoS (keep last N, reliable), so the DDS graph
  shows turtletui's /turtlesim as turtlesim_node would be shown;
- what turtletui's nodes publish and log (``publish``, ``log``, ``param``)
  goes out on the twins (logs on /rosout, parameters on /parameter_events);
- what arrives from other processes and machines comes back: messages on the
  twins' subscriptions (``message``), service calls (``request``), action
  goals and cancels (``goal``, ``cancel``), parameter sets (``param_set``),
  the other nodes with their endpoints (``graph``) and their log lines
  (``rosout``).

Messages travel as plain nested dicts (field name -> value). The first line
out is ``ready`` (with what was found) or ``error`` (one sentence, e.g. no
rclpy here); the process ends when its input closes.
"""

# No turtletui imports, and nothing newer than the oldest ROS 2 python (3.8).
from __future__ import annotations

import functools
import importlib
import json
import os
import queue
import sys
import threading

BRIDGE_NODE = "_turtletui_bridge"
"""The twin process's own node (hidden, as ROS hides names starting with _)."""

GRAPH_PERIOD = 0.5
"""Seconds between looks at the rest of the graph."""

INFRASTRUCTURE_TOPICS = ("/rosout", "/parameter_events")
PARAMETER_SERVICES = (
    "describe_parameters",
    "get_parameter_types",
    "get_parameters",
    "list_parameters",
    "set_parameters",
    "set_parameters_atomically",
    "get_type_description",
    "get_logger_levels",
    "set_logger_levels",
)

_out = sys.stdout.buffer
_write_lock = threading.Lock()


def send(obj: dict) -> None:
    line = json.dumps(obj, separators=(",", ":")).encode() + b"\n"
    with _write_lock:
        _out.write(line)
        _out.flush()


# -- messages <-> plain dicts ----------------------------------------------------------


def _is_message(value) -> bool:
    return hasattr(value, "get_fields_and_field_types") and hasattr(value, "SLOT_TYPES")


def to_plain(msg) -> dict:
    out = {}
    for name in msg.get_fields_and_field_types():
        out[name] = _plain_value(getattr(msg, name))
    return out


def _plain_value(value):
    if _is_message(value):
        return to_plain(value)
    if isinstance(value, bytes):
        return value[0] if len(value) == 1 else list(value)
    if isinstance(value, (list, tuple)):
        return [_plain_value(item) for item in value]
    tolist = getattr(value, "tolist", None)  # array.array, numpy arrays and scalars
    if tolist is not None:
        return tolist()
    return value


def _slot_class(slot):
    """The message class of a nested slot type (or of a sequence's elements)."""
    inner = getattr(slot, "value_type", slot)
    namespaces = getattr(inner, "namespaces", None)
    if not namespaces:
        return None
    module = importlib.import_module(".".join(namespaces))
    return getattr(module, inner.name)


def _is_octet(slot) -> bool:
    inner = getattr(slot, "value_type", slot)
    return getattr(inner, "typename", None) in ("octet", "byte")


def from_plain(cls, data: dict):
    msg = cls()
    fill(msg, data)
    return msg


def fill(msg, data: dict) -> None:
    names = list(msg.get_fields_and_field_types())
    slots = dict(zip(names, msg.SLOT_TYPES))  # noqa: B905 - runs on Python 3.8 too
    for name, value in data.items():
        slot = slots[name]
        if isinstance(value, dict):
            fill(getattr(msg, name), value)
            continue
        if isinstance(value, list):
            element = _slot_class(slot)
            if element is not None:
                value = [from_plain(element, item) for item in value]
            elif _is_octet(slot):
                value = [bytes((item,)) for item in value]
        elif _is_octet(slot) and isinstance(value, int):
            value = bytes((value,))
        setattr(msg, name, value)


# -- the twin -------------------------------------------------------------------------


class Twin:
    """The real nodes and endpoints mirroring turtletui's graph, and the look-outs."""

    def __init__(self, rclpy, turtlesim_package: str) -> None:
        from rclpy.executors import SingleThreadedExecutor

        self.rclpy = rclpy
        self.turtlesim_package = turtlesim_package
        self.executor = SingleThreadedExecutor()
        self.bridge = rclpy.create_node(BRIDGE_NODE, start_parameter_services=False)
        self.executor.add_node(self.bridge)
        self.inbox: queue.SimpleQueue = queue.SimpleQueue()
        self.wake = self.bridge.create_guard_condition(self._handle_inbox)
        self.nodes: dict = {}
        """turtletui's node id -> rclpy Node."""
        self.node_names: dict = {}
        self.endpoints: dict = {}
        """endpoint id -> (kind, rclpy object, topic or service name, node id)."""
        self.receivers: dict = {}
        """topic -> the subscription ids on it; the first one passes messages on."""
        self.own_gids: set = set()
        self.foreign_gids: set = set()
        self.calls: dict = {}
        self.clients: dict = {}
        self.action_clients: dict = {}
        self.client_goals: dict = {}
        self.goals: dict = {}
        self._ids = 0
        self._setting_from_turtletui = False
        self._last_graph = None
        self._doubles: set = set()
        from rcl_interfaces.msg import Log

        self.bridge.create_subscription(Log, "/rosout", self._on_rosout, _rosout_qos())
        from rcl_interfaces.msg import ParameterEvent

        self.bridge.create_subscription(ParameterEvent, "/parameter_events", self._on_parameter_event, 100)
        self._asked_parameters: set = set()
        self.bridge.create_timer(GRAPH_PERIOD, self._report_graph)

    # -- the inbox (turtletui's lines), handled in the executor's thread --------------
    def read_stdin(self) -> None:
        for line in sys.stdin.buffer:
            self.inbox.put(line)
            self.wake.trigger()
        self.inbox.put(None)
        self.wake.trigger()

    def _handle_inbox(self) -> None:
        while True:
            try:
                line = self.inbox.get_nowait()
            except queue.Empty:
                return
            if line is None:
                raise SystemExit(0)
            try:
                request = json.loads(line)
                getattr(self, "op_" + request.pop("op"))(**request)
            except (SystemExit, KeyboardInterrupt):
                raise
            except Exception as err:  # one bad request must not end the twin
                send({"op": "problem", "text": f"{type(err).__name__}: {err}"})

    # -- types ----------------------------------------------------------------------------
    def interface(self, type_name: str):
        package, kind, name = type_name.split("/")
        if package in ("turtlesim", "turtlesim_msgs"):
            package = self.turtlesim_package
        module = importlib.import_module(f"{package}.{kind}")
        return getattr(module, name)

    def type_name(self, real_type: str) -> str:
        """A real type name as turtletui names it (turtlesim_msgs -> turtlesim)."""
        package, _, rest = real_type.partition("/")
        return f"turtlesim/{rest}" if package == "turtlesim_msgs" else real_type

    # -- nodes ----------------------------------------------------------------------------
    def op_node(self, id: int, name: str, namespace: str, parameters: dict, descriptors: dict) -> None:
        node = self.rclpy.create_node(
            name, namespace=namespace or None, automatically_declare_parameters_from_overrides=False
        )
        for pname, value in parameters.items():
            if node.has_parameter(pname):
                continue  # what every node declares (use_sim_time, start_type_description_service)
            try:
                node.declare_parameter(pname, value, _descriptor(pname, value, descriptors.get(pname)))
            except Exception as err:  # a value ROS cannot hold: the node goes on without it
                send({"op": "problem", "text": f"{node.get_fully_qualified_name()}: parameter {pname}: {err}"})
        if hasattr(node, "add_post_set_parameters_callback"):
            node.add_post_set_parameters_callback(lambda params, node_id=id: self._parameters_set(node_id, params))
        else:  # Humble: the last callback before the set (rclpy checked the descriptors already)
            node.add_on_set_parameters_callback(lambda params, node_id=id: self._parameters_accepted(node_id, params))
        self.nodes[id] = node
        self.node_names[id] = node.get_fully_qualified_name()
        self.executor.add_node(node)

    def op_drop_node(self, id: int) -> None:
        for endpoint_id in [e for e, entry in self.endpoints.items() if entry[3] == id]:
            self.op_remove(endpoint_id)
        node = self.nodes.pop(id, None)
        self.node_names.pop(id, None)
        if node is not None:
            self.executor.remove_node(node)
            node.destroy_node()

    def op_param(self, node: int, name: str, value) -> None:
        from rclpy.parameter import Parameter

        self._setting_from_turtletui = True
        try:
            self.nodes[node].set_parameters([Parameter(name, value=value)])
        finally:
            self._setting_from_turtletui = False

    def _parameters_set(self, node_id: int, parameters) -> None:
        if self._setting_from_turtletui:
            return
        for parameter in parameters:
            send({"op": "param_set", "node": node_id, "name": parameter.name, "value": parameter.value})

    def _parameters_accepted(self, node_id: int, parameters):
        from rcl_interfaces.msg import SetParametersResult

        self._parameters_set(node_id, parameters)
        return SetParametersResult(successful=True)

    def op_log(self, node: int, level: int, msg: str) -> None:
        # One call site per severity: rclpy ties a call site to one severity.
        logger = self.nodes[node].get_logger()
        if level >= 50:
            logger.fatal(msg)
        elif level >= 40:
            logger.error(msg)
        elif level >= 30:
            logger.warning(msg)
        elif level >= 20:
            logger.info(msg)
        else:
            logger.debug(msg)

    # -- topics ---------------------------------------------------------------------------
    def op_pub(self, id: int, node: int, topic: str, type: str, depth: int) -> None:
        publisher = self.nodes[node].create_publisher(self.interface(type), topic, _qos(depth))
        self.endpoints[id] = ("pub", publisher, topic, node)
        self.own_gids.clear()  # worked out again from the graph when a message comes

    def op_publish(self, id: int, msg: dict) -> None:
        entry = self.endpoints.get(id)
        if entry is not None:
            publisher = entry[1]
            publisher.publish(from_plain(publisher.msg_type, msg))

    def op_sub(self, id: int, node: int, topic: str, type: str, depth: int) -> None:
        def receive(msg, info, id=id, topic=topic):
            receivers = self.receivers.get(topic)
            if not receivers or receivers[0] != id or self._own(topic, info):
                return
            send({"op": "message", "topic": topic, "msg": to_plain(msg)})

        if not _callbacks_take_message_info():  # Humble: no publisher to tell the twins' own apart
            receive = functools.partial(receive, info=None)

        subscription = self.nodes[node].create_subscription(self.interface(type), topic, receive, _qos(depth))
        self.endpoints[id] = ("sub", subscription, topic, node)
        self.receivers.setdefault(topic, []).append(id)

    def _own(self, topic: str, info) -> bool:
        """Whether a message came from one of the twins (turtletui delivered it already)."""
        if info is None:
            return False
        gid = info.get("publisher_gid") if isinstance(info, dict) else None
        data = bytes(gid["data"]) if gid else b""
        if data in self.own_gids:
            return True
        if data in self.foreign_gids:
            return False
        ours = set(self.node_names.values())
        for endpoint in self.bridge.get_publishers_info_by_topic(topic):
            key = bytes(endpoint.endpoint_gid)
            fqn = "/".join(p for p in (endpoint.node_namespace.rstrip("/"), endpoint.node_name) if p)
            if not fqn.startswith("/"):
                fqn = "/" + fqn
            (self.own_gids if fqn in ours else self.foreign_gids).add(key)
        return data in self.own_gids

    # -- services ---------------------------------------------------------------------------
    def op_srv(self, id: int, node: int, name: str, type: str) -> None:
        srv_type = self.interface(type)

        async def serve(request, response, name=name, srv_type=srv_type):
            future = self._future()
            call = self._next_id()
            self.calls[call] = (future, srv_type)
            send({"op": "request", "service": name, "call": call, "msg": to_plain(request)})
            return await future

        service = self.nodes[node].create_service(srv_type, name, serve)
        self.endpoints[id] = ("srv", service, name, node)

    def op_response(self, call: int, msg) -> None:
        future, srv_type = self.calls.pop(call, (None, None))
        if future is None:
            return
        future.set_result(from_plain(srv_type.Response, msg or {}))

    # -- actions ------------------------------------------------------------------------------
    def op_action(self, id: int, node: int, name: str, type: str) -> None:
        from rclpy.action import ActionServer, CancelResponse, GoalResponse

        action_type = self.interface(type)

        async def execute(goal_handle, name=name, action_type=action_type):
            goal = self._next_id()
            future = self._future()
            self.goals[goal] = (goal_handle, future, action_type)
            goal_handle.turtletui_goal = goal
            send({"op": "goal", "action": name, "goal": goal, "msg": to_plain(goal_handle.request)})
            status, result = await future
            if status == "succeeded":
                goal_handle.succeed()
            elif status == "canceled" and goal_handle.is_cancel_requested:
                goal_handle.canceled()
            else:
                goal_handle.abort()
            return from_plain(action_type.Result, result or {})

        def cancel(goal_handle):
            goal = getattr(goal_handle, "turtletui_goal", None)
            if goal is not None:
                send({"op": "cancel", "goal": goal})
            return CancelResponse.ACCEPT

        server = ActionServer(
            self.nodes[node], action_type, name, execute,
            goal_callback=lambda request: GoalResponse.ACCEPT, cancel_callback=cancel,
        )
        self.endpoints[id] = ("action", server, name, node)

    def op_feedback(self, goal: int, msg: dict) -> None:
        entry = self.goals.get(goal)
        if entry is not None:
            goal_handle, _, action_type = entry
            goal_handle.publish_feedback(from_plain(action_type.Feedback, msg))

    def op_result(self, goal: int, status: str, msg: dict) -> None:
        entry = self.goals.pop(goal, None)
        if entry is not None:
            entry[1].set_result((status, msg))

    # -- calls of other processes' services (ros2 service call in the app) -------------------
    def op_call(self, call: int, service: str, type: str, msg: dict) -> None:
        srv_type = self.interface(type)
        client = self.clients.get(service)
        if client is None:
            client = self.clients[service] = self.bridge.create_client(srv_type, service)

        def done(future, call=call):
            response = future.result()
            send({"op": "reply", "call": call, "msg": None if response is None else to_plain(response)})

        client.call_async(from_plain(srv_type.Request, msg)).add_done_callback(done)

    # -- goals for other processes' action servers (ros2 action send_goal in the app) ----------
    def op_send_goal(self, goal: int, action: str, type: str, msg: dict) -> None:
        from rclpy.action import ActionClient

        action_type = self.interface(type)
        client = self.action_clients.get(action)
        if client is None:
            client = self.action_clients[action] = ActionClient(self.bridge, action_type, action)

        def feedback(message, goal=goal):
            send({"op": "goal_feedback", "goal": goal, "msg": to_plain(message.feedback)})

        def finished(future, goal=goal):
            self.client_goals.pop(goal, None)
            outcome = future.result()
            status = {4: "succeeded", 5: "canceled"}.get(getattr(outcome, "status", 0), "aborted")
            result = to_plain(outcome.result) if outcome is not None else {}
            send({"op": "goal_done", "goal": goal, "status": status, "msg": result})

        def answered(future, goal=goal):
            handle = future.result()
            if handle is None or not handle.accepted:
                send({"op": "goal_done", "goal": goal, "status": "aborted", "msg": {}})
                return
            self.client_goals[goal] = handle
            handle.get_result_async().add_done_callback(finished)

        client.send_goal_async(from_plain(action_type.Goal, msg), feedback_callback=feedback).add_done_callback(answered)

    def op_cancel_goal(self, goal: int) -> None:
        handle = self.client_goals.get(goal)
        if handle is not None:
            handle.cancel_goal_async()

    # -- removal --------------------------------------------------------------------------------
    def op_remove(self, id: int) -> None:
        entry = self.endpoints.pop(id, None)
        if entry is None:
            return
        kind, thing, name, node_id = entry
        node = self.nodes.get(node_id)
        if kind == "sub":
            receivers = self.receivers.get(name, [])
            if id in receivers:
                receivers.remove(id)
        if node is None:
            return
        if kind == "pub":
            node.destroy_publisher(thing)
        elif kind == "sub":
            node.destroy_subscription(thing)
        elif kind == "srv":
            node.destroy_service(thing)
        elif kind == "action":
            thing.destroy()

    # -- the rest of the graph --------------------------------------------------------------------
    def _on_rosout(self, record) -> None:
        name = record.name
        if ("/" + name) in self.node_names.values() or name == BRIDGE_NODE:
            return
        if any(fqn.endswith("/" + name) for fqn in self.node_names.values()):
            return
        stamp = record.stamp.sec * 1_000_000_000 + record.stamp.nanosec
        send({"op": "rosout", "node": name, "level": int(record.level), "msg": record.msg, "stamp": stamp})

    def _report_graph(self) -> None:
        from rclpy.action import (
            get_action_client_names_and_types_by_node,
            get_action_server_names_and_types_by_node,
        )

        bridge = self.bridge
        ours = set(self.node_names.values())
        nodes = []
        everyone = bridge.get_node_names_and_namespaces()
        for fqn in sorted(ours):
            if fqn not in self._doubles and sum(_fqn(n, ns) == fqn for n, ns in everyone) > 1:
                self._doubles.add(fqn)
                send({"op": "problem", "text": (
                    f"another node named {fqn} is on this ROS 2 graph (ROS_DOMAIN_ID "
                    f"{os.environ.get('ROS_DOMAIN_ID', '0')}): both get the same commands; stop it, "
                    "or give this one another ROS_DOMAIN_ID")})
        for name, namespace in sorted(everyone):
            fqn = _fqn(name, namespace)
            if fqn in ours or name == BRIDGE_NODE:
                continue
            try:
                entry = {
                    "name": name,
                    "namespace": namespace if namespace != "/" else "",
                    "pub": self._endpoints(bridge.get_publisher_names_and_types_by_node(name, namespace)),
                    "sub": self._endpoints(bridge.get_subscriber_names_and_types_by_node(name, namespace)),
                    "srv": self._services(bridge.get_service_names_and_types_by_node(name, namespace)),
                    "cli": self._services(bridge.get_client_names_and_types_by_node(name, namespace)),
                    "asrv": self._endpoints(get_action_server_names_and_types_by_node(bridge, name, namespace)),
                    "acli": self._endpoints(get_action_client_names_and_types_by_node(bridge, name, namespace)),
                }
            except Exception:  # the node left while we looked: next time
                continue
            nodes.append(entry)
        if nodes != self._last_graph:
            self._last_graph = nodes
            send({"op": "graph", "nodes": nodes})
        present = set()
        for entry in nodes:
            fqn = _fqn(entry["name"], entry["namespace"])
            present.add(fqn)
            if fqn not in self._asked_parameters and [fqn + "/list_parameters", "rcl_interfaces/srv/ListParameters"] in [
                list(pair) for pair in self._all_services(entry)
            ]:
                self._asked_parameters.add(fqn)
                self._fetch_parameters(fqn)
        self._asked_parameters &= present

    def _all_services(self, entry) -> list:
        bridge = self.bridge
        try:
            return [[name, types[0]] for name, types in bridge.get_service_names_and_types_by_node(
                entry["name"], entry["namespace"] or "/") if types]
        except Exception:
            return []

    # -- other nodes' parameters (ros2 param list|get|dump in the app) ----------------------------
    def _fetch_parameters(self, fqn: str) -> None:
        from rcl_interfaces.srv import GetParameters, ListParameters

        lister = self.bridge.create_client(ListParameters, fqn + "/list_parameters")
        getter = self.bridge.create_client(GetParameters, fqn + "/get_parameters")

        def got(future, names):
            response = future.result()
            if response is not None:
                values = {n: _parameter_value(v) for n, v in zip(names, response.values)}  # noqa: B905
                send({"op": "params", "node": fqn, "values": values, "deleted": []})
            self.bridge.destroy_client(lister)
            self.bridge.destroy_client(getter)

        def listed(future):
            response = future.result()
            if response is None:
                return
            names = list(response.result.names)
            request = GetParameters.Request(names=names)
            getter.call_async(request).add_done_callback(lambda f: got(f, names))

        lister.call_async(ListParameters.Request()).add_done_callback(listed)

    def _on_parameter_event(self, event) -> None:
        fqn = event.node if event.node.startswith("/") else "/" + event.node
        if fqn in self.node_names.values():
            return
        values = {p.name: _parameter_value(p.value) for p in list(event.new_parameters) + list(event.changed_parameters)}
        deleted = [p.name for p in event.deleted_parameters]
        if values or deleted:
            send({"op": "params", "node": fqn, "values": values, "deleted": deleted})

    def _endpoints(self, pairs) -> list:
        return sorted(
            [name, self.type_name(types[0])]
            for name, types in pairs
            if types and name not in INFRASTRUCTURE_TOPICS and "/_action/" not in name
        )

    def _services(self, pairs) -> list:
        return sorted(
            [name, self.type_name(types[0])]
            for name, types in pairs
            if types and name.rsplit("/", 1)[-1] not in PARAMETER_SERVICES and "/_action/" not in name
        )

    # -- helpers -----------------------------------------------------------------------------------
    def _future(self):
        from rclpy.task import Future

        return Future(executor=self.executor)

    def _next_id(self) -> int:
        self._ids += 1
        return self._ids


def _callbacks_take_message_info() -> bool:
    """Whether rclpy hands subscriptions the publisher of each message (Iron on)."""
    from rclpy.subscription import Subscription

    return hasattr(Subscription, "CallbackType")


def _parameter_value(value):
    """A rcl_interfaces ParameterValue as a plain value (None when not set)."""
    kind = value.type
    fields = {1: "bool_value", 2: "integer_value", 3: "double_value", 4: "string_value",
              5: "byte_array_value", 6: "bool_array_value", 7: "integer_array_value",
              8: "double_array_value", 9: "string_array_value"}
    if kind not in fields:
        return None
    return _plain_value(getattr(value, fields[kind]))


def _fqn(name: str, namespace: str) -> str:
    return (namespace.rstrip("/") + "/" + name) if namespace and namespace != "/" else "/" + name


def _qos(depth: int):
    from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy

    return QoSProfile(depth=max(int(depth), 1), history=HistoryPolicy.KEEP_LAST,
                      reliability=ReliabilityPolicy.RELIABLE)


def _rosout_qos():
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    return QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE,
                      durability=DurabilityPolicy.VOLATILE)


def _descriptor(name: str, value, spec):
    from rcl_interfaces.msg import IntegerRange, ParameterDescriptor

    descriptor = ParameterDescriptor()
    if spec:
        descriptor.description = spec.get("description", "")
        if "range" in spec:
            low, high = spec["range"]
            descriptor.integer_range = [IntegerRange(from_value=low, to_value=high, step=1)]
        descriptor.read_only = bool(spec.get("read_only", False))
    return descriptor


def choose_turtlesim_package(wanted: str) -> str:
    """The installed package with turtlesim's types: ``turtlesim`` up to Jazzy,
    ``turtlesim_msgs`` from Kilted on (or the one asked for)."""
    candidates = [wanted] if wanted else ["turtlesim", "turtlesim_msgs"]
    errors = []
    for package in candidates:
        try:
            importlib.import_module(f"{package}.msg").Pose  # noqa: B018 - the check
            importlib.import_module(f"{package}.action").RotateAbsolute  # noqa: B018
            return package
        except (ImportError, AttributeError) as err:
            errors.append(f"{package}: {err}")
    raise ImportError("turtlesim's interfaces are not installed (" + "; ".join(errors) + ")")


def main() -> int:
    try:
        import rclpy
    except ImportError as err:
        send({"op": "error", "error": f"cannot import rclpy ({err})", "python": sys.executable})
        return 3
    try:
        package = choose_turtlesim_package(os.environ.get("TURTLETUI_TURTLESIM_PACKAGE", ""))
    except ImportError as err:
        send({"op": "error", "error": str(err), "python": sys.executable})
        return 3
    try:
        rclpy.init(args=["--ros-args", "--disable-stdout-logs"])
    except Exception as err:
        send({"op": "error", "error": f"rclpy.init() failed ({err})", "python": sys.executable})
        return 3
    twin = Twin(rclpy, package)
    version = ""
    try:
        from importlib.metadata import version as dist_version

        for dist in ("rclpy", "ros-rclpy"):
            try:
                version = dist_version(dist)
                break
            except Exception:
                continue
    except ImportError:
        pass
    send({
        "op": "ready",
        "python": sys.executable,
        "rclpy": version,
        "distro": os.environ.get("ROS_DISTRO", ""),
        "rmw": rclpy.get_rmw_implementation_identifier(),
        "turtlesim_package": package,
        "domain": os.environ.get("ROS_DOMAIN_ID", "0"),
    })
    threading.Thread(target=twin.read_stdin, daemon=True).start()
    try:
        twin.executor.spin()
    except (SystemExit, KeyboardInterrupt):
        pass
    finally:
        try:
            twin.executor.shutdown(timeout_sec=0.5)
            rclpy.try_shutdown()
        except Exception:
            pass
    return 0


if __name__ == "__main__":
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]
    sys.exit(main())
