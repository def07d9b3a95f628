"""The simulation's side of the bridge: mirrors its graph onto the twin and back.

``RosBridge`` joins a real-time Simulation as one of its remote hosts (as a
sandboxed controller does). Each time the simulation is idle it passes on
what the twin received and brings the twin up to date with the graph: every
node of turtletui's (the /turtlesim node first of all) with its publishers,
subscriptions, services, action servers and parameters. What turtletui's
nodes publish and log goes out as it happens (a graph tap and a log sink).

Timing follows turtlesim: the simulation wakes just before each 16 ms update
(``wake_ns``) to hand over the velocity commands that arrived since the last
one, so a command received between two updates is applied at the next, as
turtlesim_node applies it, and stamped with the last update's time.

Other nodes of the DDS graph are added to the simulation's graph as nodes of
owner ``ros`` with their endpoints, so ``ros2 node list``, the graph panel and
``ros2 service call`` on their services see them; their log lines (from
/rosout) go to the log sinks marked as relayed (``relaying``).
"""

from __future__ import annotations

import queue
from collections.abc import Callable
from typing import Any

from turtletui.bridge.process import TwinProcess
from turtletui.graph.core import GoalHandle, Graph, GraphError, NodeRecord, Publisher
from turtletui.graph.introspection import is_plumbing_topic
from turtletui.graph.logs import INFO, WARN, LogRecord
from turtletui.graph.parameter_services import is_parameter_service
from turtletui.graph.qos import adapted
from turtletui.graph.simulated_node import rclcpp_parameters
from turtletui.graph.type_description_service import is_type_description_service
from turtletui.interfaces import InterfaceError, from_dict, get_interface, to_dict

OWNER = "ros"
"""Owner of the nodes of other processes in the simulation's graph."""

TURTLESIM_PARAMETERS = {
    "background_r": {"description": "Red channel of the background color", "range": [0, 255]},
    "background_g": {"description": "Green channel of the background color", "range": [0, 255]},
    "background_b": {"description": "Blue channel of the background color", "range": [0, 255]},
    "holonomic": {"description": "If true, then turtles will be holonomic"},
}
"""turtlesim's parameter descriptors (integer ranges 0..255), as turtlesim_node declares them."""


class _Foreign:
    """A node of another process as the simulation's graph holds it."""

    __slots__ = ("record", "signature")

    def __init__(self, record: NodeRecord, signature: Any) -> None:
        self.record = record
        self.signature = signature



class RosBridge:
    """Mirrors ``sim``'s graph onto a twin process and the DDS graph back (see module)."""

    owner = OWNER

    def __init__(
        self,
        sim: Any,
        twin: TwinProcess,
        info: dict[str, Any],
        log_filter: Callable[[Callable[[LogRecord], None]], Callable[[LogRecord], None]] | None = None,
    ) -> None:
        """``log_filter`` wraps the sink that puts turtletui's log lines on
        /rosout (turtlesim's ``--log-level``: TurtlesimArgs.log_filter)."""
        self.graph: Graph = sim.graph
        self.twin = twin
        self.info = info
        """The twin's report: python, rclpy version, rmw, turtlesim_package, domain."""
        self.relaying = False
        """True while a log line of another process is handed to the log sinks."""
        self._turtlesim = sim.turtlesim.node
        self._ids = 0
        self._nodes: dict[NodeRecord, int] = {}
        self._node_parameters: dict[int, dict[str, Any]] = {}
        self._endpoints: dict[Any, int] = {}
        """Local endpoint (Publisher, Subscription, Service, ActionServer) -> twin id."""
        self._publishers: dict[str, int] = {}
        """Topic -> the twin publisher that carries local messages out."""
        self._foreign: dict[tuple[str, str], _Foreign] = {}
        self._foreign_parameters: dict[str, dict[str, Any]] = {}
        """Other nodes' parameters by node (ros2 param list|get|dump show them)."""
        self._goals: dict[int, GoalHandle] = {}
        """Goals other processes sent to turtletui's action servers, by twin goal id."""
        self._remote_goals: dict[int, tuple[GoalHandle, type]] = {}
        """Goals turtletui's nodes sent to other processes' action servers."""
        self._calls: dict[int, Callable[[Any], None]] = {}
        self._warned: set[str] = set()
        self._injecting = False
        self._synced_at: int | None = None
        self._gone = False
        self.log_sink = self.forward_log if log_filter is None else log_filter(self.forward_log)
        """The log sink this bridge adds: lines of turtletui's nodes go to /rosout."""
        self.graph.taps.append(self._tap)
        self.graph.log_sinks.append(self.log_sink)
        self.graph.log(
            "turtletui",
            INFO,
            f"On the ROS 2 graph: ROS_DOMAIN_ID {info.get('domain', '0')}, {info.get('rmw', '?')},"
            f" rclpy {info.get('rclpy') or '?'} ({info.get('python', '?')}),"
            f" turtlesim's types from {info.get('turtlesim_package', '?')}",
        )
        self.sync()

    # -- RemoteHost ---------------------------------------------------------------------
    @property
    def wake_ns(self) -> int | None:
        """Just before the next update: commands that came meanwhile go in first."""
        due = self.graph.next_due()
        if due is None or due - 1 <= self.graph.now_ns:
            return None
        return due - 1

    def wants_exchange(self, now_ns: int) -> bool:
        return now_ns != self._synced_at or not self.twin.replies.empty()

    def exchange(self) -> bool:
        """Hand over what the twin received; bring the twin up to date."""
        self._synced_at = self.graph.now_ns
        ready_before = len(self.graph.ready)
        while True:
            try:
                reply = self.twin.replies.get_nowait()
            except queue.Empty:
                break
            if reply is None:
                self._twin_ended()
                break
            handler = getattr(self, "_on_" + str(reply.get("op")), None)
            if handler is None:
                continue
            try:
                handler(reply)
            except (KeyError, TypeError, ValueError, AttributeError) as err:  # a malformed line: skip it
                self._warn(f"reply:{reply.get('op')}", f"ROS 2 bridge: ignored a malformed {reply.get('op')!r} ({err!r})")
        self.sync()
        return len(self.graph.ready) > ready_before

    @property
    def gone(self) -> bool:
        """True once the twin ended (the simulation goes on, off the ROS 2 graph)."""
        return self._gone

    def close(self) -> None:
        """Leave the DDS graph and the simulation's graph."""
        if self._tap in self.graph.taps:
            self.graph.taps.remove(self._tap)
        if self.log_sink in self.graph.log_sinks:
            self.graph.log_sinks.remove(self.log_sink)
        for foreign in self._foreign.values():
            self.graph.remove_node(foreign.record)
        self._foreign.clear()
        self.twin.close()

    def local_only(self, sink: Callable[[LogRecord], None]) -> Callable[[LogRecord], None]:
        """``sink`` without the log lines relayed from other processes."""

        def filtered(record: LogRecord) -> None:
            if not self.relaying:
                sink(record)

        return filtered

    # -- the simulation's graph -> the twin ------------------------------------------------
    def _send(self, request: dict[str, Any]) -> None:
        if not self.twin.send(request):
            self._twin_ended()

    def _new_id(self) -> int:
        self._ids += 1
        return self._ids

    def sync(self) -> None:
        """Give the twin a node or endpoint for each new one of turtletui's, drop the gone."""
        if self._gone:
            return
        graph = self.graph
        local_nodes = [node for node in graph.nodes if node.owner != OWNER]
        for node in local_nodes:
            if node not in self._nodes:
                self._add_node(node)
            else:
                self._sync_parameters(node)
        wanted: dict[Any, tuple[str, dict[str, Any]]] = {}
        for name, topic in graph.topics.items():
            if is_plumbing_topic(name):
                continue  # the twins are rclpy nodes: they have their own
            for pub in topic.publishers:
                if pub.owner != OWNER:
                    wanted[pub] = ("pub", {"topic": name, "type": topic.type_name, "depth": pub.depth})
            for sub in topic.subscriptions:
                if sub.owner != OWNER:
                    wanted[sub] = ("sub", {"topic": name, "type": topic.type_name, "depth": sub.depth})
        for name, service in graph.services.items():
            # the twin's nodes serve their parameters and type descriptions themselves
            if service.owner != OWNER and not is_parameter_service(service) and not is_type_description_service(service):
                wanted[service] = ("srv", {"name": name, "type": service.type_name})
        for name, server in graph.action_servers.items():
            if server.owner != OWNER:
                wanted[server] = ("action", {"name": name, "type": server.type_name})
        for endpoint in [e for e in self._endpoints if e not in wanted]:
            self._send({"op": "remove", "id": self._endpoints.pop(endpoint)})
            if isinstance(endpoint, Publisher):
                self._forget_publisher(endpoint)
        for endpoint, (kind, fields) in wanted.items():
            if endpoint in self._endpoints or endpoint.node not in self._nodes:
                continue
            self._endpoints[endpoint] = endpoint_id = self._new_id()
            self._send({"op": kind, "id": endpoint_id, "node": self._nodes[endpoint.node], **fields})
            if kind == "pub":
                self._publishers.setdefault(fields["topic"], endpoint_id)
        for node in [n for n in self._nodes if n not in local_nodes]:
            node_id = self._nodes.pop(node)
            self._node_parameters.pop(node_id, None)
            self._send({"op": "drop_node", "id": node_id})

    def _forget_publisher(self, endpoint: Publisher) -> None:
        topic = endpoint.topic.name
        self._publishers.pop(topic, None)
        for other, other_id in self._endpoints.items():
            if isinstance(other, Publisher) and other.topic.name == topic:
                self._publishers[topic] = other_id
                break

    def _add_node(self, node: NodeRecord) -> None:
        node_id = self._nodes[node] = self._new_id()
        parameters = {k: v for k, v in node.parameters.items() if _is_parameter_value(v)}
        self._node_parameters[node_id] = dict(parameters)
        descriptors = dict(TURTLESIM_PARAMETERS) if node is self._turtlesim else {}
        for name, _, descriptor in rclcpp_parameters():
            if descriptor.read_only and name in parameters:  # rclcpp's qos_overrides: read-only on the twin too
                descriptors[name] = {"description": descriptor.description, "read_only": True}
        self._send({
            "op": "node",
            "id": node_id,
            "name": node.name,
            "namespace": node.namespace,
            "parameters": parameters,
            "descriptors": descriptors,
        })

    def _sync_parameters(self, node: NodeRecord) -> None:
        node_id = self._nodes[node]
        sent = self._node_parameters[node_id]
        for name, value in node.parameters.items():
            if name in sent and sent[name] != value and _is_parameter_value(value):
                sent[name] = value
                self._send({"op": "param", "node": node_id, "name": name, "value": value})

    def _tap(self, kind: str, payload: Any) -> None:
        if kind != "topic" or self._injecting or self._gone:
            return
        topic, msg = payload
        publisher = self._publishers.get(topic.name)
        if publisher is None:
            if not any(p.owner != OWNER for p in topic.publishers):
                return
            self.sync()  # a publisher created and used in one go (ros2 topic pub --once)
            publisher = self._publishers.get(topic.name)
            if publisher is None:
                return
        self._send({"op": "publish", "id": publisher, "msg": to_dict(msg)})

    def forward_log(self, record: LogRecord) -> None:
        """Log a line of one of turtletui's nodes on /rosout, through its twin."""
        if self.relaying or self._gone:
            return
        for node, node_id in self._nodes.items():
            if node.name == record.node:
                self._send({"op": "log", "node": node_id, "level": record.level, "msg": record.msg})
                return

    # -- the twin -> the simulation's graph ------------------------------------------------
    def _on_message(self, reply: dict[str, Any]) -> None:
        topic = self.graph.topics.get(reply["topic"])
        if topic is None:
            return
        msg = self._checked(topic.msg_type, reply["msg"], f"a message on {topic.name}")
        if msg is None:
            return
        self._injecting = True
        try:
            self.graph.publish(topic, msg, source=OWNER)
        finally:
            self._injecting = False

    def _on_request(self, reply: dict[str, Any]) -> None:
        name, call = reply["service"], reply["call"]
        service = self.graph.services.get(name)
        request = None
        if service is not None:
            request = self._checked(service.srv_type.Request, reply["msg"], f"a call of {name}")
        if service is None or service.owner == OWNER or request is None:
            self._send({"op": "response", "call": call, "msg": None})
            return

        def respond(response: Any) -> None:
            self._send({"op": "response", "call": call, "msg": to_dict(response)})

        self.graph.call(name, request, respond, OWNER)

    def _on_goal(self, reply: dict[str, Any]) -> None:
        name, goal_id = reply["action"], reply["goal"]
        server = self.graph.action_servers.get(name)
        goal = None
        if server is not None:
            goal = self._checked(server.action_type.Goal, reply["msg"], f"a goal of {name}")
        if server is None or server.owner == OWNER or goal is None:
            self._send({"op": "result", "goal": goal_id, "status": "aborted", "msg": {}})
            return

        def accepted(handle: GoalHandle | None) -> None:
            if handle is not None:
                self._goals[goal_id] = handle

        def feedback(msg: Any) -> None:
            self._send({"op": "feedback", "goal": goal_id, "msg": to_dict(msg)})

        def result(status: str, msg: Any) -> None:
            self._goals.pop(goal_id, None)
            self._send({"op": "result", "goal": goal_id, "status": status, "msg": to_dict(msg)})

        self.graph.send_goal(name, goal, OWNER, accepted, feedback, result)

    def _on_cancel(self, reply: dict[str, Any]) -> None:
        handle = self._goals.get(reply["goal"])
        if handle is not None:
            self.graph.cancel_goal(handle)

    def _on_param_set(self, reply: dict[str, Any]) -> None:
        node = next((n for n, i in self._nodes.items() if i == reply["node"]), None)
        if node is None:
            return
        name, value = reply["name"], reply["value"]
        self._node_parameters[reply["node"]][name] = value
        if node.parameter_setter is not None:
            reason = node.parameter_setter(name, value)
            if reason is not None:
                self._warn(f"param:{name}", f"Setting parameter {name} from the ROS 2 graph failed: {reason}")
        else:
            self.graph.set_parameter(node, name, value)

    def _on_reply(self, reply: dict[str, Any]) -> None:
        respond = self._calls.pop(reply["call"], None)
        if respond is not None:
            respond(reply["msg"])

    def _on_rosout(self, reply: dict[str, Any]) -> None:
        self.relaying = True
        try:
            self.graph.log(reply["node"], reply["level"], reply["msg"])
        finally:
            self.relaying = False

    def _on_problem(self, reply: dict[str, Any]) -> None:
        self._warn(reply["text"], f"ROS 2: {reply['text']}")

    def _on_graph(self, reply: dict[str, Any]) -> None:
        seen = set()
        for entry in reply["nodes"]:
            key = (entry["namespace"], entry["name"])
            seen.add(key)
            signature = tuple(tuple(map(tuple, entry[k])) for k in ("pub", "sub", "srv", "cli", "asrv", "acli"))
            current = self._foreign.get(key)
            if current is not None and current.signature == signature:
                continue
            if current is not None:
                self.graph.remove_node(current.record)
            self._foreign[key] = _Foreign(self._add_foreign(entry), signature)
        for key in [k for k in self._foreign if k not in seen]:
            record = self._foreign.pop(key).record
            self.graph.remove_node(record)
            self._foreign_parameters.pop(record.fqn, None)

    def _on_params(self, reply: dict[str, Any]) -> None:
        parameters = self._foreign_parameters.setdefault(reply["node"], {})
        parameters.update((name, value) for name, value in reply["values"].items() if value is not None)
        for name in reply["deleted"]:
            parameters.pop(name, None)
        for foreign in self._foreign.values():
            if foreign.record.fqn == reply["node"]:
                foreign.record.parameters = dict(parameters)

    def _add_foreign(self, entry: dict[str, Any]) -> NodeRecord:
        graph = self.graph
        node = graph.add_node(entry["name"], entry["namespace"], owner=OWNER)
        node.parameters = dict(self._foreign_parameters.get(node.fqn, {}))
        for kind in ("pub", "sub", "srv", "cli", "asrv", "acli"):
            for name, type_name in entry[kind]:
                try:
                    cls = get_interface(type_name)
                except InterfaceError:
                    continue  # a type turtletui does not know: its topic stays out of the views
                try:
                    if kind == "pub":
                        graph.add_publisher(node, name, cls, 7)
                    elif kind == "sub":
                        # its QoS does not cross the bridge: as one that hears every publisher
                        known = graph.topics.get(name)
                        qos = adapted(known.publishers if known is not None else ())
                        graph.add_subscription(node, name, cls, 7, _ignore, qos=qos)
                    elif kind == "srv":
                        if not graph.has_service(name):
                            graph.add_service(node, name, cls, self._foreign_service(name, type_name))
                    elif kind == "cli":
                        graph.add_client(node, name, cls)
                    elif kind == "asrv":
                        if not graph.has_action_server(name):
                            graph.add_action_server(node, name, cls, self._foreign_action(name, type_name))
                    else:
                        graph.add_action_client(node, name, cls)
                except GraphError as err:
                    self._warn(f"graph:{node.fqn}:{name}", f"{node.fqn}: {err}")
        return node

    def _foreign_service(self, name: str, type_name: str) -> Callable[[Any, Callable[[Any], None]], None]:
        """A handler that calls a service of another process through the twin."""
        srv_type = get_interface(type_name)

        def handler(request: Any, respond: Callable[[Any], None]) -> None:
            call = self._new_id()

            def answered(msg: Any) -> None:
                response = self._checked(srv_type.Response, msg or {}, f"the response of {name}")
                respond(response if response is not None else srv_type.Response())

            self._calls[call] = answered
            self._send({"op": "call", "call": call, "service": name, "type": type_name, "msg": to_dict(request)})

        return handler

    def _foreign_action(self, name: str, type_name: str) -> Callable[[GoalHandle], None]:
        """A goal handler that sends goals to another process's action server through the twin."""
        action_type = get_interface(type_name)

        def on_goal(handle: GoalHandle) -> None:
            goal_id = self._new_id()
            self._remote_goals[goal_id] = (handle, action_type)
            handle.on_cancel = lambda: self._send({"op": "cancel_goal", "goal": goal_id})
            self._send(
                {"op": "send_goal", "goal": goal_id, "action": name, "type": type_name, "msg": to_dict(handle.goal)}
            )

        return on_goal

    def _on_goal_feedback(self, reply: dict[str, Any]) -> None:
        handle, action_type = self._remote_goals.get(reply["goal"], (None, None))
        if handle is not None:
            feedback = self._checked(action_type.Feedback, reply["msg"], f"feedback of {handle.action.name}")
            if feedback is not None:
                handle.publish_feedback(feedback)

    def _on_goal_done(self, reply: dict[str, Any]) -> None:
        handle, action_type = self._remote_goals.pop(reply["goal"], (None, None))
        if handle is not None:
            result = self._checked(action_type.Result, reply["msg"], f"the result of {handle.action.name}")
            handle.finish(reply["status"], result if result is not None else action_type.Result())

    # -- helpers -------------------------------------------------------------------------------
    def _checked(self, cls: type, data: Any, what: str) -> Any:
        try:
            return from_dict(cls, data)
        except InterfaceError as err:
            self._warn(f"bad:{what}", f"ROS 2 bridge: ignored {what}: {err}")
            return None

    def _warn(self, key: str, text: str) -> None:
        if key not in self._warned:
            self._warned.add(key)
            self.graph.log("turtletui", WARN, text)

    def _twin_ended(self) -> None:
        if self._gone:
            return
        self._gone = True
        last = self.twin.last_error()
        self.graph.log("turtletui", WARN, "ROS 2 bridge: the ROS 2 side ended" + (f" ({last})" if last else ""))


def _ignore(msg: Any) -> None:
    """Other processes' subscriptions get their messages from DDS, not here."""


def _is_parameter_value(value: Any) -> bool:
    if isinstance(value, (bool, int, float, str)):
        return True
    return isinstance(value, list) and all(isinstance(v, (bool, int, float, str)) for v in value)

