"""Commands that go on after they were typed (``topic echo``, ``topic hz``,
``topic pub``, ``service call``, ``action send_goal``), as objects that can be
polled for their output and stopped.

Each owns a hidden node in the graph (``/_ros2cli_1``...), as the real CLI
makes ``/_ros2cli_<pid>``; everything it created goes with the node when the
stream is closed (Ctrl+C) or ends by itself (``--once``, a response, a result).
"""

from __future__ import annotations

import math
import random
import uuid
from collections import deque
from typing import TYPE_CHECKING, Any

from turtletui.graph.core import NS_PER_S, GoalHandle, NodeRecord, Topic
from turtletui.graph.logs import LogRecord, to_log_message
from turtletui.graph.qos import SENSOR_DATA, SENSOR_DATA_DEPTH, Policies
from turtletui.interfaces import Message, from_dict, to_dict
from turtletui.ros2cli.common import message_repr
from turtletui.ros2cli.values import message_yaml, yaml_lines

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

MAX_BUFFERED_LINES = 200
"""Lines a stream keeps between two polls; older whole messages are dropped."""

DEFAULT_DEPTH = 10
"""rclpy's default QoS depth, as ``ros2 topic echo`` and ``pub`` use it."""

WAIT_CHECK_NS = 100_000_000
"""How often ``ros2 topic pub -w N`` looks for matching subscriptions (ros2cli: 0.1 s)."""

OWNER = "ros2cli"
"""Prefix of the owners of the commands' nodes ("ros2cli:3"): each command is a
process of its own, as in a terminal."""


class Stream:
    """Output of a command that goes on after ``Ros2Cli.run()`` returned.

    ``poll()`` gives the lines printed since the last poll, ``done`` turns True
    when the command ended (by itself or closed), ``close()`` stops it.
    """

    runs_in_background = False
    """True for commands whose work is their effect, not their output
    (``topic pub``, ``bag record``, ``bag play``): a console may keep them
    running in the background."""

    def __init__(self, cli: Ros2Cli, command: str, node: NodeRecord | None = None) -> None:
        self.command = command
        """The command line that started it."""
        self._cli = cli
        self._graph = cli.graph
        self.node: NodeRecord = node if node is not None else cli.hidden_node()
        """The command's node: a hidden one, unless the command names its own
        (``rosbag2_recorder``); it goes when the stream ends."""
        self._blocks: deque[list[str]] = deque()
        self._buffered = 0
        self._done = False
        self._closed = False

    @property
    def done(self) -> bool:
        """True once the command ended by itself or was closed."""
        return self._done or self._closed

    def poll(self) -> list[str]:
        """The lines printed since the last poll (at most MAX_BUFFERED_LINES)."""
        lines = [line for block in self._blocks for line in block]
        self._blocks.clear()
        self._buffered = 0
        return lines

    @property
    def progress(self) -> str:
        """How far it got, for a list of jobs (``120 published``); '' if nothing to say."""
        return ""

    def close(self) -> None:
        """Stop the command (Ctrl+C): remove its node and endpoints. What it
        says as it stops (a recorder's last lines) is left for ``poll``."""
        if self._closed:
            return
        try:
            self._on_close()
        finally:
            self._closed = True
            self._graph.remove_node(self.node)
            self._cli.forget(self)

    # -- for subclasses -------------------------------------------------------
    def _on_close(self) -> None:
        """Extra clean-up before the node goes (cancel a goal, write a bag...);
        it may still ``_emit``."""

    def _emit(self, lines: list[str]) -> None:
        """Buffer one message's lines, dropping the oldest whole messages."""
        if self._closed:
            return
        if len(lines) > MAX_BUFFERED_LINES:
            lines = lines[-MAX_BUFFERED_LINES:]
        self._blocks.append(lines)
        self._buffered += len(lines)
        while self._buffered > MAX_BUFFERED_LINES:
            self._buffered -= len(self._blocks.popleft())

    def _finish(self) -> None:
        """The command ended by itself: keep the output, free the graph."""
        self._done = True
        self.close()


class EchoStream(Stream):
    """``ros2 topic echo``: every message as YAML, then ``---``."""

    def __init__(self, cli: Ros2Cli, command: str, topic: Topic, once: bool,
                 field_path: list[str], qos: Policies | None = None, depth: int = DEFAULT_DEPTH) -> None:
        """``qos`` and ``depth``: what ``ros2 topic echo``'s options chose (ros2cli.qos_args.echo_qos)."""
        super().__init__(cli, command)
        self._once = once
        self._field = field_path
        self._qos = qos
        self._depth = depth
        self._subscribe(topic)

    def _subscribe(self, topic: Topic) -> None:
        self.subscription = self._graph.add_subscription(
            self.node, topic.name, topic.msg_type, self._depth, self._on_message, qos=self._qos)

    def _on_message(self, msg: Any) -> None:
        if self.done:
            return
        value: Any = to_dict(msg) if isinstance(msg, Message) else msg
        for name in self._field:
            value = value[name]
        self._emit([*yaml_lines(value), "---"])
        if self._once:
            self._finish()


class RosoutEchoStream(EchoStream):
    """``ros2 topic echo /rosout``: every node's log lines as rcl_interfaces/msg/Log
    (turtletui's graph keeps its log itself, not as a topic)."""

    def _subscribe(self, topic: Any) -> None:
        self._graph.log_sinks.append(self._on_log)

    def _on_log(self, record: LogRecord) -> None:
        self._on_message(to_log_message(record))

    def _on_close(self) -> None:
        if self._on_log in self._graph.log_sinks:
            self._graph.log_sinks.remove(self._on_log)


class HzStream(Stream):
    """``ros2 topic hz``: the rate over a window of messages, once a second."""

    def __init__(self, cli: Ros2Cli, command: str, topic: Topic, window: int) -> None:
        super().__init__(cli, command)
        self._stamps: deque[int] = deque(maxlen=window + 1)
        self._new = False
        # ros2topic's hz subscribes with qos_profile_sensor_data: it hears every publisher
        self.subscription = self._graph.add_subscription(
            self.node, topic.name, topic.msg_type, SENSOR_DATA_DEPTH, self._on_message, qos=SENSOR_DATA)
        self.timer = self._graph.add_timer(self.node, NS_PER_S, self._report)

    def _on_message(self, msg: Any) -> None:
        self._stamps.append(self._graph.now_ns)
        self._new = True

    def _report(self) -> None:
        """ros2topic's print_hz, once per (simulated) second with new messages."""
        stamps = list(self._stamps)
        if not self._new or len(stamps) < 2:
            return
        self._new = False
        times = [(b - a) / NS_PER_S for a, b in zip(stamps, stamps[1:], strict=False)]
        n = len(times)
        mean = sum(times) / n
        rate = 1.0 / mean if mean > 0.0 else 0.0
        std_dev = math.sqrt(sum((x - mean) ** 2 for x in times) / n)
        self._emit([
            f"average rate: {rate:.3f}",
            f"\tmin: {min(times):.3f}s max: {max(times):.3f}s std dev: {std_dev:.5f}s window: {n + 1}",
        ])


class PubStream(Stream):
    """``ros2 topic pub``: once ``wait`` subscriptions match (discovery takes
    time), one message at once, then one per period."""

    runs_in_background = True

    def __init__(self, cli: Ros2Cli, command: str, topic_name: str, msg: Message,
                 period_ns: int, times: int, print_nth: int, wait: int = 0,
                 qos: Policies | None = None, depth: int = DEFAULT_DEPTH) -> None:
        super().__init__(cli, command)
        self._cls = type(msg)
        self._values = to_dict(msg)
        self._times = times
        self._print_nth = print_nth
        self._period_ns = period_ns
        self._wait = wait
        self.count = 0
        """Messages published so far."""
        self.publisher = self._graph.add_publisher(self.node, topic_name, self._cls, depth, qos=qos)
        self.timer = None
        if self._matched() < wait:
            self._checks = 0
            self.timer = self._graph.add_timer(self.node, WAIT_CHECK_NS, self._check_matching)
            self._check_matching()
        else:
            self._begin()

    def _matched(self) -> int:
        graph, pub = self._graph, self.publisher
        # as DDS counts them: discovered, and not kept apart by their QoS
        return sum(1 for sub in pub.topic.subscriptions if graph.matched(pub, sub) and sub not in pub.muted)

    def _check_matching(self) -> None:
        """ros2cli checks every 100 ms and says so every second."""
        if self.done:
            return
        if self._matched() >= self._wait:
            self._graph.cancel_timer(self.timer)
            self._begin()
            return
        if self._checks % 10 == 0:
            self._emit([f"Waiting for at least {self._wait} matching subscription(s)..."])
        self._checks += 1

    def _begin(self) -> None:
        self._emit(["publisher: beginning loop"])
        self._publish()  # ros2 topic pub publishes once at once, then on its timer
        self.timer = None
        if not self.done:
            self.timer = self._graph.add_timer(self.node, self._period_ns, self._publish)

    @property
    def progress(self) -> str:
        return f"{self.count} published"

    def _publish(self) -> None:
        if self.done:
            return
        msg = from_dict(self._cls, self._values)  # a fresh message each time, as on a wire
        self.count += 1
        if self._print_nth and self.count % self._print_nth == 0:
            self._emit([f"publishing #{self.count}: {message_repr(self._cli, msg)}", ""])
        self._graph.publish(self.publisher.topic, msg, None, self.publisher)
        if self._times and self.count >= self._times:
            self._finish()


class CallStream(Stream):
    """``ros2 service call``: the request, then the response."""

    def __init__(self, cli: Ros2Cli, command: str, name: str, srv_cls: type, request: Any) -> None:
        super().__init__(cli, command)
        self.client = self._graph.add_client(self.node, name, srv_cls)
        self._emit([f"requester: making request: {message_repr(self._cli, request)}", ""])
        self._graph.call(name, request, self._on_response, self.node.owner)

    def _on_response(self, response: Any) -> None:
        if self.done:
            return
        self._emit(["response:", message_repr(self._cli, response), ""])
        self._finish()


class GoalStream(Stream):
    """``ros2 action send_goal``: acceptance, feedback if asked, the result.
    Closing it cancels a goal still running, as Ctrl+C does."""

    def __init__(self, cli: Ros2Cli, command: str, name: str, action_cls: type, goal: Any,
                 feedback: bool) -> None:
        super().__init__(cli, command)
        self.handle: GoalHandle | None = None
        self._feedback = feedback
        self.client = self._graph.add_action_client(self.node, name, action_cls)
        self._emit(["Waiting for an action server to become available..."])
        # ros2action prints message_to_yaml(goal) after five spaces: only the
        # first line of a multi-field goal is indented.
        self._emit((f"Sending goal:\n     {message_yaml(goal)}").split("\n"))
        self._graph.send_goal(name, goal, self.node.owner, self._on_accepted, self._on_feedback,
                              self._on_result)

    def _on_accepted(self, handle: GoalHandle | None) -> None:
        if self.done:
            return
        if handle is None:
            self._emit(["Goal was rejected."])
            self._finish()
            return
        self.handle = handle
        goal_id = uuid.UUID(int=random.Random(handle.goal_id).getrandbits(128), version=4)
        self._emit([f"Goal accepted with ID: {goal_id.hex}", ""])

    def _on_feedback(self, feedback: Any) -> None:
        if self._feedback and not self.done:
            self._emit(f"Feedback:\n    {message_yaml(feedback)}".split("\n"))

    def _on_result(self, status: str, result: Any) -> None:
        if self.done:
            return
        self._emit([*f"Result:\n    {message_yaml(result)}".split("\n"),
                    f"Goal finished with status: {status.upper()}"])
        self._finish()

    def _on_close(self) -> None:
        if self.handle is not None and self.handle.status == "executing":
            self._graph.cancel_goal(self.handle)
