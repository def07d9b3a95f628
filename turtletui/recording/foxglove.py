"""A live view of a run in Foxglove (or Lichtblick): the recording's channels
served over Foxglove's WebSocket protocol, with foxglove-sdk.

The same channels as an MCAP recording (turtletui.recording.stream), in CDR
with ros2msg schemas, plus turtlesim's parameters and every service of the
graph: Foxglove's Parameters panel sets ``/turtlesim.background_r`` as
``ros2 param set`` does, its Service Call panel calls ``/spawn``,
``/clear``, ``/turtle1/set_pen``... The server also sends the simulation's
time. It shows in the graph as the node ``/foxglove_bridge``, as ROS's own
bridge does.

The server answers on its own threads; what they ask of the simulation is
queued and done by a 16 ms timer of the bridge's node, in the simulation's
thread, so the simulation stays single-threaded.
"""

from __future__ import annotations

import functools
import queue
import threading
from collections.abc import Callable
from typing import Any

from turtletui.errors import UsageError
from turtletui.graph.logs import INFO, WARN
from turtletui.graph.simulated_node import SimulatedNode
from turtletui.interfaces import InterfaceError, cdr, from_dict, get_interface
from turtletui.recording.errors import FoxgloveError
from turtletui.recording.qos import profiles_yaml
from turtletui.recording.schema import message_definition, recorded_type_name
from turtletui.recording.stream import Channel, RosStream
from turtletui.recording.tap import RunTap

DEFAULT_ADDRESS = "127.0.0.1:8765"
"""Foxglove's default port, on this machine only."""

OWNER = "foxglove"
NODE = "foxglove_bridge"
CALL_TIMEOUT = 10.0
"""Wall seconds a service call from Foxglove waits for its response."""

_TICK_NS = 16_000_000
_PARAMETER_CHECK_TICKS = 30


def parse_address(text: str) -> tuple[str, int]:
    """``HOST:PORT``, ``PORT`` or ``[IPv6]:PORT`` -> (host, port); UsageError (a
    ValueError) naming the text."""
    host, _, port = text.rpartition(":")
    host = host.strip("[]") or "127.0.0.1"
    try:
        number = int(port)
    except ValueError:
        number = -1
    if not 0 <= number <= 65535:
        raise UsageError(f"--foxglove {text!r}: give HOST:PORT (such as {DEFAULT_ADDRESS}) or a port")
    return host, number


class FoxgloveBridge:
    """Serves ``sim`` (a turtletui.runtime.simulation.Simulation) live until ``close``."""

    def __init__(self, sim: Any, address: str = DEFAULT_ADDRESS) -> None:
        host, port = parse_address(address)
        try:
            import foxglove
            from foxglove.websocket import Capability
        except ImportError:
            raise FoxgloveError("--foxglove needs foxglove-sdk: pip install 'turtletui[foxglove]'") from None
        self._foxglove = foxglove
        self._graph = sim.graph
        self._context = foxglove.Context()
        self._channels: dict[int, Any] = {}
        self._tap = RunTap(sim)
        self._stream = RosStream(
            self, epoch_ns=self._graph.epoch_ns, scene=self._tap.scene(), type_name=self._graph.type_name_of
        )
        self._inbox: queue.SimpleQueue[Callable[[], None]] = queue.SimpleQueue()
        self._services: dict[str, str] = {}
        self._parameters: dict[str, Any] = {}
        self._ticks = 0
        try:
            self._server = foxglove.start_server(
                name="turtletui",
                host=host,
                port=port,
                capabilities=[Capability.Parameters, Capability.Services, Capability.Time],
                server_listener=self,
                supported_encodings=["cdr"],
                context=self._context,
            )
        except Exception as err:  # the SDK raises its own errors (address in use...)
            self._tap.detach()
            raise FoxgloveError(f"--foxglove {address}: cannot serve ({err})") from None
        self.url = f"ws://{host if ':' not in host else f'[{host}]'}:{self._server.port}"
        self._node = SimulatedNode(self._graph, NODE, OWNER).node  # foxglove_bridge: an rclcpp node
        self._timer = self._graph.add_timer(self._node, _TICK_NS, self._pump)
        self._graph.log(NODE, INFO, f"Foxglove: open a connection to {self.url}")
        self._pump()

    # -- the simulation's side --------------------------------------------------------------
    def _pump(self) -> None:
        """Every 16 ms: do what clients asked, send what happened, keep services current."""
        while True:
            try:
                job = self._inbox.get_nowait()
            except queue.Empty:
                break
            job()
        feed = self._stream.feed
        for t_ns, kind, payload in self._tap.take():
            feed(t_ns, kind, payload)
        self._advertise_services()
        self._ticks += 1
        if self._ticks % _PARAMETER_CHECK_TICKS == 1:
            self._publish_changed_parameters()
        self._server.broadcast_time(self._graph.stamp_ns)

    def close(self) -> None:
        """Stop serving and leave the graph as it was."""
        self._tap.detach()
        self._timer.canceled = True
        self._graph.remove_node(self._node)
        self._server.stop()

    # -- Sink (RosStream writes here) ----------------------------------------------------------
    def add_channel(self, channel: Channel) -> None:
        foxglove = self._foxglove
        schema = foxglove.Schema(
            name=channel.type_name, encoding="ros2msg", data=message_definition(channel.type_name).encode()
        )
        served = foxglove.Channel(
            channel.topic,
            schema=schema,
            message_encoding="cdr",
            context=self._context,
            metadata={"offered_qos_profiles": profiles_yaml(channel.qos)},
        )
        channel.id = served.id()
        self._channels[channel.id] = served

    def write(self, channel: Channel, log_time_ns: int, data: bytes) -> None:
        self._channels[channel.id].log(data, log_time=log_time_ns)

    # -- services ------------------------------------------------------------------------------
    def _advertise_services(self) -> None:
        current = {name: service.type_name for name, service in self._graph.services.items()}
        if current == self._services:
            return
        gone = [name for name, kind in self._services.items() if current.get(name) != kind]
        if gone:
            self._server.remove_services(gone)
        new = [name for name, kind in current.items() if self._services.get(name) != kind]
        self._services = current
        if new:
            self._server.add_services([self._service(name, current[name]) for name in new])

    def _service(self, name: str, type_name: str) -> Any:
        foxglove = self._foxglove

        def schema(part: str) -> Any:
            full = f"{type_name}_{part}"
            text = message_definition(recorded_type_name(full)).encode()
            return foxglove.MessageSchema(encoding="cdr", schema=foxglove.Schema(name=full, encoding="ros2msg", data=text))

        return foxglove.Service(
            name,
            schema=foxglove.ServiceSchema(type_name, request=schema("Request"), response=schema("Response")),
            handler=self._call,
        )

    def _call(self, request: Any) -> bytes:
        """A client's service call (on a server thread): the response's CDR, or an error."""
        name = request.service_name
        type_name = self._services.get(name)
        if type_name is None:
            raise ValueError(f"{name}: no such service")
        srv = get_interface(type_name)
        message = _decode(recorded_type_name(f"{type_name}_Request"), srv.Request, request.payload)
        answered = threading.Event()
        box: list[Any] = []

        def call() -> None:
            self._graph.call(name, message, lambda response: (box.append(response), answered.set()), OWNER)

        self._inbox.put(call)
        if not answered.wait(CALL_TIMEOUT):
            raise TimeoutError(f"{name}: no response within {CALL_TIMEOUT:g} s (is the simulation paused?)")
        return cdr.serialize(box[0])

    # -- parameters ------------------------------------------------------------------------------
    def _current_parameters(self) -> dict[str, Any]:
        return {
            f"{node.fqn}.{name}": value
            for node in list(self._graph.nodes)
            if node.parameter_setter is not None
            for name, value in list(node.parameters.items())
        }

    def _parameter(self, name: str, value: Any) -> Any:
        foxglove = self._foxglove
        if isinstance(value, float):
            return foxglove.Parameter(name, value=value, type=foxglove.ParameterType.Float64)
        return foxglove.Parameter(name, value=value)

    def _publish_changed_parameters(self) -> None:
        current = self._current_parameters()
        changed = [self._parameter(n, v) for n, v in current.items() if self._parameters.get(n, _UNSET) != v]
        self._parameters = current
        if changed:
            self._server.publish_parameter_values(changed)

    def on_get_parameters(self, client: Any, param_names: list[str], request_id: str | None = None) -> list[Any]:
        current = self._current_parameters()
        wanted = param_names or list(current)
        return [self._parameter(name, current[name]) for name in wanted if name in current]

    def on_set_parameters(self, client: Any, parameters: list[Any], request_id: str | None = None) -> list[Any]:
        done = threading.Event()

        def apply() -> None:
            try:
                for parameter in parameters:
                    self._set(parameter.name, parameter.get_value())
            finally:
                done.set()

        self._inbox.put(apply)
        done.wait(CALL_TIMEOUT)
        current = self._current_parameters()
        return [self._parameter(p.name, current[p.name]) for p in parameters if p.name in current]

    def _set(self, full_name: str, value: Any) -> None:
        """Set a parameter as ``ros2 param set`` does (in the simulation's thread)."""
        node_name, _, name = full_name.rpartition(".")
        node = next((n for n in self._graph.nodes if n.fqn == node_name), None)
        if node is None or node.parameter_setter is None:
            self._graph.log(NODE, WARN, f"Setting parameter {full_name} failed: no node {node_name} takes parameters")
            return
        current = node.parameters.get(name)
        if isinstance(current, int) and not isinstance(current, bool) and isinstance(value, float):
            value = int(value) if value.is_integer() else value  # JSON does not keep 150 apart from 150.0
        reason = node.parameter_setter(name, value)
        if reason is not None:
            self._graph.log(NODE, WARN, f"Setting parameter {full_name} failed: {reason}")


_UNSET = object()


@functools.cache
def _decoder(type_name: str) -> Callable[[bytes], Any]:
    from mcap_ros2._dynamic import generate_dynamic

    return generate_dynamic(type_name, message_definition(type_name))[type_name]


def _decode(type_name: str, cls: type, payload: bytes) -> Any:
    """A client's CDR message as a checked turtletui message; ValueError if it is not one."""
    from turtletui.recording.read import plain

    try:
        return from_dict(cls, plain(cls, _decoder(type_name)(bytes(payload))))
    except (InterfaceError, ValueError, IndexError, KeyError, TypeError) as err:
        raise ValueError(f"{type_name}: cannot decode the request ({err})") from None
    except Exception as err:  # struct.error and the like from a malformed payload
        raise ValueError(f"{type_name}: cannot decode the request ({type(err).__name__})") from None

