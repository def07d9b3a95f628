"""The ``ros2`` command line of the ROS 2 beginner tutorials, run against a live
turtletui simulation.

Students type the real commands (same arguments, same output) and practise
them safely on the simulated graph. Pure library: no Textual, no I/O; the app
shows the lines and drives the simulation.

API
---
``cli = Ros2Cli(sim)`` wraps a :class:`~turtletui.runtime.simulation.Simulation`.

``cli.run(line) -> CommandResult`` interprets one command line (the leading
``ros2`` is optional) and never raises:

* ``result.lines`` -- what the command prints at once (list of str, no newlines);
* ``result.error`` -- True when the command failed; ``lines`` is then exactly
  one line such as ``ros2: unknown command 'topik' (did you mean 'topic'?)``;
* ``result.stream`` -- for commands that go on (``topic echo``, ``topic hz``,
  ``topic pub`` without ``--once``, ``service call``, ``action send_goal``) a
  :class:`Stream`, else None. After each simulation step the app calls
  ``stream.poll()`` for the lines printed since the last poll; ``stream.done``
  turns True when the command ended by itself (``--once``, a service
  response, an action result); ``stream.close()`` stops it (Ctrl+C: the
  subscription, publisher, timer and the hidden node go, a running goal is
  canceled). Streams buffer at most ``MAX_BUFFERED_LINES`` lines between polls
  (oldest whole messages are dropped first) and ``topic pub`` publishes at
  ``MAX_PUB_RATE_HZ`` at most.

Like the real CLI, every streaming command makes a hidden node
(``/_ros2cli_1``, ``/_ros2cli_2``, ...) that ``ros2 node list`` does not show
(``-a`` does). ``cli.streams`` holds the streams still running and
``cli.close_all()`` stops them. ``ros2 param set`` goes through the node's
``parameter_setter`` (turtlesim, in-process and sandboxed controllers have one).

Commands
--------
``node list [-a] [-c]``, ``node info NODE``;
``topic list [-t] [-c]``, ``topic echo TOPIC [TYPE] [--once] [--field F]``,
``topic hz TOPIC [-w N]``, ``topic info TOPIC [-v]``, ``topic type TOPIC``,
``topic find TYPE``,
``topic pub [--once|-1] [-r RATE] [-t TIMES] [-p N] TOPIC TYPE [YAML]``;
``service list [-t] [-c]``, ``service type NAME``, ``service find TYPE``,
``service info NAME``, ``service call NAME [TYPE] [YAML]``;
``param list [NODE]``, ``param get NODE NAME``, ``param set NODE NAME VALUE``,
``param dump NODE``;
``action list [-t] [-c]``, ``action info NAME [-t]``,
``action send_goal [-f|--feedback] NAME TYPE YAML``;
``interface show TYPE``, ``interface list``, ``interface packages``,
``interface package PKG``.

Message arguments are YAML as ``ros2`` reads them, parsed here by a small
flow-style parser (no PyYAML): ``"{linear: {x: 2.0}, angular: {z: 1.8}}"``,
``"linear: {x: 2.0}"`` (outer braces optional), ``"{x: 1, name: ''}"``,
``"{}"``. Values are converted to the field types as ``ros2 topic pub`` does
(``x: 1`` for a float field gives 1.0, numbers for a string field their
text). Echoed messages are printed as ros2's YAML (``x: 5.544444561004639``).

Not modelled: ``/parameter_events``, ``/rosout`` and the parameter services
(turtletui's graph has none), QoS options, ``ros2 run``/``launch``/``bag``.
"""

from __future__ import annotations

import difflib
import math
import random
import re
import shlex
import uuid
from collections import deque
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from turtletui.graph.core import NS_PER_S, GoalHandle, Graph, GraphError, NodeRecord, Topic
from turtletui.graph.introspection import GraphSnapshot, NodeInfo, snapshot
from turtletui.interfaces import (
    Action,
    InterfaceError,
    Message,
    Service,
    all_interfaces,
    definition_text,
    from_dict,
    get_interface,
    interface_name,
    to_dict,
)

if TYPE_CHECKING:
    from turtletui.runtime.simulation import Simulation

__all__ = [
    "MAX_BUFFERED_LINES",
    "MAX_PUB_RATE_HZ",
    "CommandResult",
    "Ros2Cli",
    "Stream",
    "YamlError",
    "parse_yaml",
    "yaml_lines",
]

MAX_BUFFERED_LINES = 200
"""Lines a stream keeps between two polls; older whole messages are dropped."""

MAX_PUB_RATE_HZ = 100.0
"""``ros2 topic pub -r`` is capped here so a typo cannot flood the graph."""

HIDDEN_NODE_PREFIX = "_ros2cli_"
"""The real CLI names its per-command node ``_ros2cli_<pid>``; '_' hides it."""

OWNER = "ros2cli"
"""Owner of the hidden nodes' endpoints in the graph."""

_DEFAULT_DEPTH = 10  # rclpy's default QoS depth, as ros2 topic echo/pub use

COMMANDS = ("action", "interface", "node", "param", "service", "topic")
_SHELL_OPERATORS = frozenset((">", ">>", "<", "|", "||", "&", "&&", ";", "2>", "2>&1"))
_NOT_HERE = ("bag", "component", "daemon", "doctor", "launch", "lifecycle", "multicast",
             "pkg", "run", "security", "wtf")

USAGE = [
    "usage: ros2 <command> <verb> [arguments]",
    "  ros2 node list | info NODE",
    "  ros2 topic list [-t] | echo TOPIC [--once] | hz TOPIC | info TOPIC [-v] | type TOPIC",
    "  ros2 topic pub [--once | -r RATE | -t TIMES] TOPIC TYPE 'YAML'",
    "  ros2 service list [-t] | type NAME | call NAME TYPE 'YAML'",
    "  ros2 param list [NODE] | get NODE NAME | set NODE NAME VALUE | dump NODE",
    "  ros2 action list [-t] | info NAME | send_goal [--feedback] NAME TYPE 'YAML'",
    "  ros2 interface show TYPE | list | package PKG",
]


# ---------------------------------------------------------------------------
# results and streams
# ---------------------------------------------------------------------------

@dataclass
class CommandResult:
    """What one command printed at once, whether it failed, and what goes on."""

    lines: list[str] = field(default_factory=list)
    error: bool = False
    stream: Stream | None = None
    """Set for commands that keep printing (echo, hz, pub, call, send_goal)."""


class Stream:
    """Output of a command that goes on after ``run()`` returned.

    Owns a hidden node in the graph; everything it created goes with the
    node when the stream is closed or ends by itself.
    """

    def __init__(self, cli: Ros2Cli, command: str) -> None:
        self.command = command
        """The command line that started it (for the app's display)."""
        self._cli = cli
        self._graph = cli.graph
        self.node: NodeRecord = cli._hidden_node()
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

    def close(self) -> None:
        """Stop the command (Ctrl+C): remove its hidden node and endpoints."""
        if self._closed:
            return
        self._closed = True
        self._on_close()
        self._graph.remove_node(self.node)
        if self in self._cli.streams:
            self._cli.streams.remove(self)

    # -- for subclasses -------------------------------------------------------
    def _on_close(self) -> None:
        """Extra clean-up before the node goes (cancel a goal...)."""

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
        if not self._closed:
            self._closed = True
            self._on_close()
            self._graph.remove_node(self.node)
            if self in self._cli.streams:
                self._cli.streams.remove(self)


class _EchoStream(Stream):
    def __init__(self, cli: Ros2Cli, command: str, topic: Topic, once: bool,
                 field_path: list[str]) -> None:
        super().__init__(cli, command)
        self._once = once
        self._field = field_path
        self.subscription = self._graph.add_subscription(
            self.node, topic.name, topic.msg_type, _DEFAULT_DEPTH, self._on_message)

    def _on_message(self, msg: Any) -> None:
        if self.done:
            return
        value: Any = to_dict(msg) if isinstance(msg, Message) else msg
        for name in self._field:
            value = value[name]
        self._emit([*yaml_lines(value), "---"])
        if self._once:
            self._finish()


class _HzStream(Stream):
    def __init__(self, cli: Ros2Cli, command: str, topic: Topic, window: int) -> None:
        super().__init__(cli, command)
        self._stamps: deque[int] = deque(maxlen=window + 1)
        self._new = False
        self.subscription = self._graph.add_subscription(
            self.node, topic.name, topic.msg_type, _DEFAULT_DEPTH, self._on_message)
        self.timer = self._graph.add_timer(self.node, NS_PER_S, self._report)

    def _on_message(self, msg: Any) -> None:
        self._stamps.append(self._graph.now_ns)
        self._new = True

    def _report(self) -> None:
        """ros2topic's print_hz, once per (simulated) second with new messages."""
        stamps = self._stamps
        if not self._new or len(stamps) < 2:
            return
        self._new = False
        times = [(b - a) / NS_PER_S for a, b in zip(list(stamps), list(stamps)[1:], strict=False)]
        n = len(times)
        mean = sum(times) / n
        rate = 1.0 / mean if mean > 0.0 else 0.0
        std_dev = math.sqrt(sum((x - mean) ** 2 for x in times) / n)
        self._emit([
            f"average rate: {rate:.3f}",
            f"\tmin: {min(times):.3f}s max: {max(times):.3f}s std dev: {std_dev:.5f}s window: {n + 1}",
        ])


class _PubStream(Stream):
    def __init__(self, cli: Ros2Cli, command: str, topic_name: str, msg_cls: type,
                 values: dict, period_ns: int, times: int, print_nth: int) -> None:
        super().__init__(cli, command)
        self._cls = msg_cls
        self._values = values
        self._times = times
        self._print_nth = print_nth
        self.count = 0
        """Messages published so far."""
        self.publisher = self._graph.add_publisher(self.node, topic_name, msg_cls, _DEFAULT_DEPTH)
        self._emit(["publisher: beginning loop"])
        self._publish()  # ros2 topic pub publishes once at once, then on its timer
        self.timer = None
        if not self.done:
            self.timer = self._graph.add_timer(self.node, period_ns, self._publish)

    def _publish(self) -> None:
        if self.done:
            return
        msg = from_dict(self._cls, self._values)  # a fresh message each time, as on a wire
        self.count += 1
        if self._print_nth and self.count % self._print_nth == 0:
            self._emit([f"publishing #{self.count}: {msg!r}", ""])
        self._graph.publish(self.publisher.topic, msg)
        if self._times and self.count >= self._times:
            self._finish()


class _CallStream(Stream):
    def __init__(self, cli: Ros2Cli, command: str, name: str, srv_cls: type, request: Any) -> None:
        super().__init__(cli, command)
        self.client = self._graph.add_client(self.node, name, srv_cls)
        self._emit([f"requester: making request: {request!r}", ""])
        self._graph.call(name, request, self._on_response, OWNER)

    def _on_response(self, response: Any) -> None:
        if self.done:
            return
        self._emit(["response:", repr(response), ""])
        self._finish()


class _GoalStream(Stream):
    def __init__(self, cli: Ros2Cli, command: str, name: str, action_cls: type, goal: Any,
                 feedback: bool) -> None:
        super().__init__(cli, command)
        self.handle: GoalHandle | None = None
        self._feedback = feedback
        self.client = self._graph.add_action_client(self.node, name, action_cls)
        self._emit(["Waiting for an action server to become available..."])
        # ros2action prints message_to_yaml(goal) after five spaces: only the
        # first line of a multi-field goal is indented.
        self._emit((f"Sending goal:\n     {_yaml_text(goal)}").split("\n"))
        self._graph.send_goal(name, goal, OWNER, self._on_accepted, self._on_feedback,
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
            self._emit(f"Feedback:\n    {_yaml_text(feedback)}".split("\n"))

    def _on_result(self, status: str, result: Any) -> None:
        if self.done:
            return
        self._emit([*f"Result:\n    {_yaml_text(result)}".split("\n"),
                    f"Goal finished with status: {status.upper()}"])
        self._finish()

    def _on_close(self) -> None:
        if self.handle is not None and self.handle.status == "executing":
            self._graph.cancel_goal(self.handle)


# ---------------------------------------------------------------------------
# YAML: the flow style ros2 arguments use, and the block style echo prints
# ---------------------------------------------------------------------------

class YamlError(ValueError):
    """Text that is not the YAML ros2 accepts; the message says why."""


_INT = re.compile(r"[-+]?[0-9][0-9_]*$|[-+]?0[xX][0-9a-fA-F_]+$|[-+]?0[oO][0-7_]+$|[-+]?0[bB][01_]+$")
_FLOAT = re.compile(r"[-+]?(\.[0-9]+|[0-9][0-9_]*(\.[0-9_]*)?)([eE][-+]?[0-9]+)?$")
_SPECIAL_FLOATS = {".inf": math.inf, "+.inf": math.inf, "-.inf": -math.inf, ".nan": math.nan}
_TRUE = {"true", "yes", "on"}
_FALSE = {"false", "no", "off"}
_NULL = {"", "~", "null"}
_ESCAPES = {"0": "\0", "a": "\a", "b": "\b", "t": "\t", "\t": "\t", "n": "\n", "v": "\v",
            "f": "\f", "r": "\r", "e": "\x1b", " ": " ", '"': '"', "/": "/", "\\": "\\",
            "N": "\x85", "_": "\xa0", "L": "\u2028", "P": "\u2029"}
_HEX_ESCAPES = {"x": 2, "u": 4, "U": 8}


def _resolve_plain(text: str) -> Any:
    """A plain (unquoted) scalar as YAML 1.1 / PyYAML's safe_load reads it."""
    lower = text.lower()
    if lower in _NULL and (text == lower or text in ("Null", "NULL")):
        return None
    if lower in _TRUE and text in (lower, lower.capitalize(), lower.upper()):
        return True
    if lower in _FALSE and text in (lower, lower.capitalize(), lower.upper()):
        return False
    if _INT.match(text):
        return int(text.replace("_", ""), 0 if text.lstrip("+-")[:2].lower() in ("0x", "0o", "0b") else 10)
    if _FLOAT.match(text) and any(c.isdigit() for c in text):
        return float(text.replace("_", ""))
    if lower in _SPECIAL_FLOATS:
        return _SPECIAL_FLOATS[lower]
    return text


class _FlowParser:
    """Recursive descent over YAML's flow style: {mappings}, [sequences],
    'single' and "double" quoted and plain scalars, # comments."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.i = 0

    def peek(self) -> str:
        return self.text[self.i] if self.i < len(self.text) else ""

    def skip_space(self) -> None:
        text, n = self.text, len(self.text)
        while self.i < n:
            c = text[self.i]
            if c in " \t\r\n":
                self.i += 1
            elif c == "#" and (self.i == 0 or text[self.i - 1] in " \t\r\n"):
                end = text.find("\n", self.i)
                self.i = n if end < 0 else end
            else:
                break

    def at_end(self) -> bool:
        self.skip_space()
        return self.i >= len(self.text)

    def value(self, closer: str) -> Any:
        self.skip_space()
        c = self.peek()
        if c == "{":
            return self.mapping()
        if c == "[":
            return self.sequence()
        if c in ("'", '"'):
            return self.quoted()
        if c in ("", ",", "]", "}"):
            if c in ("]", "}") and c != closer:
                raise YamlError(_unbalanced(closer or c))
            return None  # an empty value is null
        return _resolve_plain(self.plain(key=False))

    def key(self) -> str:
        c = self.peek()
        if c in ("'", '"'):
            return self.quoted()
        if c in ("{", "["):
            raise YamlError("a key must be a name, not a collection")
        text = self.plain(key=True)
        if not text:
            raise YamlError(f"expected a field name, found {c!r}" if c else "expected a field name")
        return text

    def plain(self, key: bool) -> str:
        text, n = self.text, len(self.text)
        start = self.i
        while self.i < n:
            c = text[self.i]
            if c in ",[]{}":
                break
            if c == ":" and (self.i + 1 >= n or text[self.i + 1] in " \t\r\n,[]{}"):
                break
            if c == "#" and self.i > start and text[self.i - 1] in " \t":
                break
            if c == "\n" and not key:
                break
            self.i += 1
        return text[start:self.i].strip()

    def quoted(self) -> str:
        text, n = self.text, len(self.text)
        quote = text[self.i]
        self.i += 1
        out: list[str] = []
        while self.i < n:
            c = text[self.i]
            if c == quote:
                if quote == "'" and text[self.i + 1:self.i + 2] == "'":
                    out.append("'")
                    self.i += 2
                    continue
                self.i += 1
                return "".join(out)
            if c == "\\" and quote == '"':
                esc = text[self.i + 1:self.i + 2]
                if esc in _ESCAPES:
                    out.append(_ESCAPES[esc])
                    self.i += 2
                    continue
                if esc in _HEX_ESCAPES:
                    digits = text[self.i + 2:self.i + 2 + _HEX_ESCAPES[esc]]
                    if len(digits) == _HEX_ESCAPES[esc] and all(d in "0123456789abcdefABCDEF" for d in digits):
                        out.append(chr(int(digits, 16)))
                        self.i += 2 + len(digits)
                        continue
                raise YamlError(f"unknown escape '\\{esc}' in a double-quoted string")
            out.append(c)
            self.i += 1
        raise YamlError("unclosed quote")

    def mapping(self) -> dict[str, Any]:
        self.i += 1  # '{'
        result: dict[str, Any] = {}
        while True:
            self.skip_space()
            c = self.peek()
            if c == "}":
                self.i += 1
                return result
            if c == "":
                raise YamlError("unbalanced braces")
            if c == "]":
                raise YamlError("unbalanced braces")
            if c == ",":
                raise YamlError("unexpected ','")
            self.entry(result, "}")
            self.skip_space()
            c = self.peek()
            if c == ",":
                self.i += 1
            elif c == "":
                raise YamlError("unbalanced braces")
            elif c != "}":
                raise YamlError("unbalanced braces" if c == "]" else f"expected ',' or '}}', found {c!r}")

    def entry(self, result: dict[str, Any], closer: str) -> None:
        key = self.key()
        self.skip_space()
        if self.peek() == ":":
            self.i += 1
            value = self.value(closer)
        elif self.peek() in ("", ",", closer):
            value = None  # {a, b}: keys without values are null
        else:
            raise YamlError(f"expected ':' after '{key}'")
        if key in result:
            raise YamlError(f"field '{key}' is given twice")
        result[key] = value

    def sequence(self) -> list[Any]:
        self.i += 1  # '['
        result: list[Any] = []
        while True:
            self.skip_space()
            c = self.peek()
            if c == "]":
                self.i += 1
                return result
            if c == "":
                raise YamlError("unbalanced brackets")
            if c == "}":
                raise YamlError("unbalanced brackets")
            if c == ",":
                raise YamlError("unexpected ','")
            result.append(self.item())
            self.skip_space()
            c = self.peek()
            if c == ",":
                self.i += 1
            elif c == "":
                raise YamlError("unbalanced brackets")
            elif c != "]":
                raise YamlError("unbalanced brackets" if c == "}" else f"expected ',' or ']', found {c!r}")

    def item(self) -> Any:
        """A sequence item; ``[x: 1]`` is a one-pair mapping, as in YAML."""
        if self.peek() not in ("{", "[", ",", "]", "}", ""):
            start = self.i
            key = self.key()
            self.skip_space()
            if self.peek() == ":":
                self.i += 1
                return {key: self.value("]")}
            self.i = start
        return self.value("]")

    def implicit_mapping(self) -> dict[str, Any]:
        """``linear: {x: 2.0}, angular: {z: 1.0}``: a mapping without its braces
        (entries separated by commas or new lines)."""
        result: dict[str, Any] = {}
        while not self.at_end():
            c = self.peek()
            if c in ("}", "]"):
                raise YamlError(_unbalanced(c))
            self.entry(result, "")
            self.skip_inline_space()
            c = self.peek()
            if c in (",", "\n"):
                self.i += 1
            elif c in ("}", "]"):
                raise YamlError(_unbalanced(c))
            elif c:
                raise YamlError(f"expected ',' or the end, found {c!r}")
        return result

    def skip_inline_space(self) -> None:
        while self.peek() in (" ", "\t", "\r"):
            self.i += 1
        if self.peek() == "#":
            end = self.text.find("\n", self.i)
            self.i = len(self.text) if end < 0 else end


def _unbalanced(c: str) -> str:
    return "unbalanced braces" if c in "{}" else "unbalanced brackets"


def _looks_like_mapping(text: str) -> bool:
    """Whether text starts with ``key:`` (so braces were left out)."""
    parser = _FlowParser(text)
    try:
        parser.skip_space()
        parser.key()
    except YamlError:
        return False
    parser.skip_space()
    return parser.peek() == ":"


def parse_yaml(text: str) -> Any:
    """Parse one flow-style YAML value as ``ros2`` reads its arguments.

    Mappings, sequences, quoted and plain scalars (YAML 1.1 resolution:
    ``1`` int, ``1.5`` float, ``true``/``on`` bool, ``~`` None); a top-level
    mapping may leave out its braces. Keys are always strings (``off: 1``
    works, unlike PyYAML). Raises :class:`YamlError` with a short reason
    (``unbalanced braces``, ``unclosed quote``...).
    """
    try:
        return _parse(text)
    except YamlError as exc:
        # A missing closer often shows up first as something unexpected
        # further on: name the real cause.
        problem = None if "unbalanced" in str(exc) else _balance_problem(text)
        if problem is None:
            raise
        raise YamlError(problem) from None


def _balance_problem(text: str) -> str | None:
    """'unbalanced braces' / 'unbalanced brackets' if the text's collections
    do not pair up (quoted scalars skipped), else None."""
    stack: list[str] = []
    i, n = 0, len(text)
    token_start = True
    while i < n:
        c = text[i]
        if c in ("'", '"') and token_start:
            end = i + 1
            while end < n and not (text[end] == c and (c == '"' or text[end + 1:end + 2] != "'")):
                end += 2 if (c == '"' and text[end] == "\\") or (c == "'" and text[end:end + 2] == "''") else 1
            if end >= n:
                return None  # an unclosed quote is reported as such
            i = end + 1
            token_start = False
            continue
        if c in ("{", "["):
            stack.append(c)
        elif c in ("}", "]"):
            if not stack or stack[-1] != {"}": "{", "]": "["}[c]:
                return _unbalanced(stack[-1] if stack else c)
            stack.pop()
        token_start = c in " \t\n,{[:"
        i += 1
    return _unbalanced(stack[-1]) if stack else None


def _parse(text: str) -> Any:
    parser = _FlowParser(text)
    if parser.at_end():
        return None
    c = parser.peek()
    if c in ("{", "[", '"', "'"):
        value = parser.value("")
        if not parser.at_end():
            c = parser.peek()
            if c in ("{", "}", "[", "]"):
                raise YamlError(_unbalanced(c))
            if c == ":" or _looks_like_mapping(text):
                return _FlowParser(text).implicit_mapping()
            raise YamlError(f"unexpected text after the value: {text[parser.i:].strip()!r}")
        return value
    if c in ("}", "]"):
        raise YamlError(_unbalanced(c))
    if _looks_like_mapping(text):
        return parser.implicit_mapping()
    stripped = text.strip()
    if "#" in stripped:
        stripped = _FlowParser(stripped).plain(key=True)
    return _resolve_plain(stripped)


_YAML_BOOL_WORDS = {"yes", "no", "true", "false", "on", "off", "null", "~"}
_YAML_INDICATORS = "-?:,[]{}#&*!|>'\"%@`"


def _yaml_str(text: str) -> str:
    """A string as PyYAML's dump writes it: plain when it reads back the
    same, single-quoted otherwise, double-quoted with control characters."""
    if text == "":
        return "''"
    if any((ord(c) < 32 and c not in "\t") or c in "\x7f\x85\u2028\u2029" for c in text):
        body = text.replace("\\", "\\\\").replace('"', '\\"')
        body = "".join(c if ord(c) >= 32 and c not in "\x7f\x85\u2028\u2029" else
                       {"\n": "\\n", "\r": "\\r", "\0": "\\0", "\x1b": "\\e"}.get(c, f"\\x{ord(c):02X}")
                       for c in body)
        return f'"{body}"'
    plain = (
        text.lower() not in _YAML_BOOL_WORDS
        and not isinstance(_resolve_plain(text), (int, float))
        and text[0] not in _YAML_INDICATORS
        and text[0] not in " \t" and text[-1] not in " \t:"
        and ": " not in text and " #" not in text
        and not text.startswith(("---", "..."))
    )
    if plain:
        return text
    return "'" + text.replace("'", "''") + "'"


def _yaml_scalar(value: Any) -> str:
    if value is None:
        return "null"
    if value is True:
        return "true"
    if value is False:
        return "false"
    if isinstance(value, float):
        if value != value:
            return ".nan"
        if math.isinf(value):
            return ".inf" if value > 0 else "-.inf"
        text = repr(float(value)).lower()
        if "." not in text and "e" in text:
            text = text.replace("e", ".0e", 1)  # PyYAML's fix for repr(1e17)
        return text
    if isinstance(value, int):
        return str(int(value))
    if isinstance(value, (bytes, bytearray)):
        return "!!binary |\n  " + value.hex()
    if isinstance(value, dict):
        return "{}" if not value else "{" + ", ".join(
            f"{_yaml_str(str(k))}: {_yaml_scalar(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_yaml_scalar(v) for v in value) + "]"
    return _yaml_str(str(value))


def yaml_lines(value: Any, indent: int = 0) -> list[str]:
    """``value`` (from ``to_dict``) in PyYAML's block style, as ``ros2 topic
    echo`` prints it: two spaces per level, sequences not indented under
    their key, floats as ``repr``, strings quoted only where needed."""
    pad = " " * indent
    if isinstance(value, dict):
        if not value:
            return [pad + "{}"]
        out = []
        for key, item in value.items():
            name = _yaml_str(str(key))
            if isinstance(item, dict) and item:
                out.append(f"{pad}{name}:")
                out.extend(yaml_lines(item, indent + 2))
            elif isinstance(item, (list, tuple)) and item:
                out.append(f"{pad}{name}:")
                out.extend(yaml_lines(item, indent))
            else:
                out.append(f"{pad}{name}: {_yaml_scalar(item)}")
        return out
    if isinstance(value, (list, tuple)):
        if not value:
            return [pad + "[]"]
        out = []
        for item in value:
            if isinstance(item, (dict, list, tuple)) and item:
                inner = yaml_lines(item, indent + 2)
                out.append(f"{pad}- {inner[0][indent + 2:]}")
                out.extend(inner[1:])
            else:
                out.append(f"{pad}- {_yaml_scalar(item)}")
        return out
    return [pad + _yaml_scalar(value)]


def _yaml_text(msg: Any) -> str:
    """rosidl_runtime_py's message_to_yaml (with its final newline)."""
    return "\n".join(yaml_lines(to_dict(msg))) + "\n"


# ---------------------------------------------------------------------------
# YAML values -> message fields, as rosidl_runtime_py.set_message_fields does
# ---------------------------------------------------------------------------

def _coerce(cls: type, data: Any) -> Any:
    """Convert plain YAML values to the field types of ``cls`` where ROS would
    (int -> float, number -> str...); anything else is left for from_dict to
    reject with a field path."""
    if not isinstance(data, dict):
        return data
    specs = {spec.name: spec for spec in cls._FIELDS}
    out = {}
    for key, value in data.items():
        spec = specs.get(key)
        if spec is None:
            out[key] = value
        elif spec.array and isinstance(value, list):
            out[key] = [_coerce_one(spec, item) for item in value]
        else:
            out[key] = _coerce_one(spec, value)
    return out


def _coerce_one(spec: Any, value: Any) -> Any:
    kind = spec.kind
    if kind == "msg":
        return _coerce(spec.msg_cls, value)
    if isinstance(value, bool):
        if kind == "bool":
            return value
        return str(value) if kind == "str" else value
    if kind == "float":
        if isinstance(value, int):
            return float(value)
        if isinstance(value, str):
            try:
                return float(value)
            except ValueError:
                return value
    elif kind in ("int", "byte"):
        if isinstance(value, float) and value.is_integer():
            return int(value)
        if isinstance(value, str):
            try:
                return int(value, 0)
            except ValueError:
                return value
    elif kind == "bool":
        if isinstance(value, int) and value in (0, 1):
            return bool(value)
    elif kind == "str":
        if isinstance(value, (int, float)):
            return str(value)
    return value


# ---------------------------------------------------------------------------
# command-line arguments
# ---------------------------------------------------------------------------

class _Usage(Exception):
    """A command's one-line error (the prefix is added by the dispatcher)."""


@dataclass
class _Verb:
    """One ``ros2 <command> <verb>``: its arguments and what runs it."""

    usage: str
    required: tuple[str, ...] = ()
    optional: tuple[str, ...] = ()
    flags: dict[str, tuple[str, Callable[[str], Any] | None]] = field(default_factory=dict)
    """Option spelling -> (destination, converter; None for a switch)."""
    rest: bool = False
    """Extra positionals are joined into the last one (an unquoted YAML)."""


_NUMBER = re.compile(r"-[0-9.]")


def _parse_args(verb: _Verb, tokens: Sequence[str]) -> tuple[list[str], dict[str, Any]]:
    positionals: list[Any] = []
    options: dict[str, Any] = {dest: (False if conv is None else None) for dest, conv in verb.flags.values()}
    tokens = list(tokens)
    i = 0
    while i < len(tokens):
        token = tokens[i]
        i += 1
        name, eq, inline = token.partition("=") if token.startswith("--") else (token, "", "")
        if name in verb.flags:
            dest, conv = verb.flags[name]
            if conv is None:
                if eq:
                    raise _Usage(f"option {name} takes no value")
                options[dest] = True
                continue
            if eq:
                raw = inline
            elif i < len(tokens):
                raw = tokens[i]
                i += 1
            else:
                raise _Usage(f"option {name} needs a value (usage: {verb.usage})")
            try:
                options[dest] = conv(raw)
            except ValueError:
                raise _Usage(f"option {name}: invalid value '{raw}'") from None
            continue
        if token.startswith("-") and len(token) > 1 and not _NUMBER.match(token):
            if verb.rest and len(positionals) >= len(verb.required) + len(verb.optional):
                positionals.append(token)
                continue
            close = difflib.get_close_matches(name, list(verb.flags), n=1, cutoff=0.6)
            hint = f" (did you mean {close[0]}?)" if close else f" (usage: {verb.usage})"
            raise _Usage(f"unrecognized option '{token}'{hint}")
        positionals.append(token)
    most = len(verb.required) + len(verb.optional)
    if len(positionals) < len(verb.required):
        missing = verb.required[len(positionals)]
        raise _Usage(f"missing argument {missing} (usage: {verb.usage})")
    if len(positionals) > most:
        if verb.rest and most:
            positionals[most - 1:] = [" ".join(positionals[most - 1:])]
        else:
            raise _Usage(f"unrecognized argument '{positionals[most]}' (usage: {verb.usage})")
    return positionals + [None] * (most - len(positionals)), options


def _positive_int(text: str) -> int:
    value = int(text)
    if value < 0:
        raise ValueError(text)
    return value


def _hint(name: str, known: Sequence[str], quote: bool = False) -> str:
    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.6)
    if not close:
        return ""
    return f" (did you mean '{close[0]}'?)" if quote else f" (did you mean {close[0]}?)"


def _absolute(name: str) -> str:
    """ros2 resolves relative names against the root namespace."""
    return name if name.startswith("/") else f"/{name}"


def _param_type_line(value: Any) -> str:
    """``ros2 param get``'s sentence for a value."""
    if value is None:
        return "Parameter not set."
    words = {bool: "Boolean", int: "Integer", float: "Double", str: "String"}
    if type(value) in words:
        return f"{words[type(value)]} value is: {value}"
    if isinstance(value, (bytes, bytearray)):
        return f"Byte values are: {list(value)}"
    if isinstance(value, (list, tuple)):
        items = list(value)
        kind = type(items[0]) if items else str
        return f"{words.get(kind, 'String')} values are: {items}"
    return f"String value is: {value}"


# ---------------------------------------------------------------------------
# the interpreter
# ---------------------------------------------------------------------------

class Ros2Cli:
    """Interprets ``ros2`` command lines against a live Simulation (see the
    module docstring for the API and the commands)."""

    def __init__(self, sim: Simulation) -> None:
        self.sim = sim
        self.graph: Graph = sim.graph
        self.streams: list[Stream] = []
        """Streams still running, oldest first."""
        self._hidden = 0
        self._verbs: dict[str, dict[str, tuple[_Verb, Callable[..., CommandResult]]]] = {
            "node": {
                "list": (_Verb("ros2 node list [-a] [-c]", flags={
                    "-a": ("show_all", None), "--all": ("show_all", None),
                    "-c": ("count", None), "--count-nodes": ("count", None)}), self._node_list),
                "info": (_Verb("ros2 node info NODE", ("NODE",)), self._node_info),
            },
            "topic": {
                "list": (_Verb("ros2 topic list [-t] [-c]", flags={
                    "-t": ("types", None), "--show-types": ("types", None),
                    "-c": ("count", None), "--count-topics": ("count", None),
                    "--include-hidden-topics": ("hidden", None)}), self._topic_list),
                "echo": (_Verb("ros2 topic echo TOPIC [TYPE] [--once] [--field FIELD]", ("TOPIC",),
                               ("TYPE",), flags={"--once": ("once", None), "--field": ("field_name", str)}),
                         self._topic_echo),
                "hz": (_Verb("ros2 topic hz TOPIC [-w WINDOW]", ("TOPIC",), flags={
                    "-w": ("window", _positive_int), "--window": ("window", _positive_int)}),
                       self._topic_hz),
                "info": (_Verb("ros2 topic info TOPIC [-v]", ("TOPIC",), flags={
                    "-v": ("verbose", None), "--verbose": ("verbose", None)}), self._topic_info),
                "type": (_Verb("ros2 topic type TOPIC", ("TOPIC",)), self._topic_type),
                "find": (_Verb("ros2 topic find TYPE", ("TYPE",)), self._topic_find),
                "pub": (_Verb("ros2 topic pub [--once | -r RATE | -t TIMES] TOPIC TYPE 'YAML'",
                              ("TOPIC", "TYPE"), ("YAML",), flags={
                                  "-1": ("once", None), "--once": ("once", None),
                                  "-r": ("rate", float), "--rate": ("rate", float),
                                  "-t": ("times", _positive_int), "--times": ("times", _positive_int),
                                  "-p": ("print_nth", _positive_int), "--print": ("print_nth", _positive_int),
                              }, rest=True), self._topic_pub),
            },
            "service": {
                "list": (_Verb("ros2 service list [-t] [-c]", flags={
                    "-t": ("types", None), "--show-types": ("types", None),
                    "-c": ("count", None), "--count-services": ("count", None)}), self._service_list),
                "type": (_Verb("ros2 service type NAME", ("NAME",)), self._service_type),
                "find": (_Verb("ros2 service find TYPE", ("TYPE",)), self._service_find),
                "info": (_Verb("ros2 service info NAME", ("NAME",)), self._service_info),
                "call": (_Verb("ros2 service call NAME TYPE 'YAML'", ("NAME",), ("TYPE", "YAML"),
                               rest=True), self._service_call),
            },
            "param": {
                "list": (_Verb("ros2 param list [NODE]", (), ("NODE",)), self._param_list),
                "get": (_Verb("ros2 param get NODE NAME", ("NODE", "NAME")), self._param_get),
                "set": (_Verb("ros2 param set NODE NAME VALUE", ("NODE", "NAME", "VALUE"), rest=True),
                        self._param_set),
                "dump": (_Verb("ros2 param dump NODE", ("NODE",)), self._param_dump),
            },
            "action": {
                "list": (_Verb("ros2 action list [-t] [-c]", flags={
                    "-t": ("types", None), "--show-types": ("types", None),
                    "-c": ("count", None), "--count-actions": ("count", None)}), self._action_list),
                "info": (_Verb("ros2 action info NAME [-t]", ("NAME",), flags={
                    "-t": ("types", None), "--show-types": ("types", None)}), self._action_info),
                "send_goal": (_Verb("ros2 action send_goal [--feedback] NAME TYPE 'YAML'",
                                    ("NAME", "TYPE", "YAML"), flags={
                                        "-f": ("feedback", None), "--feedback": ("feedback", None)},
                                    rest=True), self._action_send_goal),
            },
            "interface": {
                "show": (_Verb("ros2 interface show TYPE", ("TYPE",)), self._interface_show),
                "list": (_Verb("ros2 interface list"), self._interface_list),
                "packages": (_Verb("ros2 interface packages"), self._interface_packages),
                "package": (_Verb("ros2 interface package PKG", ("PKG",)), self._interface_package),
            },
        }

    # -- entry point -------------------------------------------------------------
    def run(self, line: str) -> CommandResult:
        """Interpret one command line; never raises (errors are one line)."""
        try:
            tokens = shlex.split(line, comments=False)
        except ValueError as exc:
            return _error(f"ros2: could not split the command line ({str(exc).lower()})")
        operators = [t for t in tokens if t in _SHELL_OPERATORS]
        if operators:
            return _error(f"ros2: shell operators such as '{operators[0]}' are not supported here"
                          " (quote YAML arguments: '{x: 1.0}')")
        if tokens and tokens[0] == "ros2":
            tokens = tokens[1:]
        if not tokens:
            if line.strip().startswith("ros2"):
                return CommandResult(list(USAGE))
            return CommandResult([])
        command, *rest = tokens
        if command in ("-h", "--help", "help"):
            return CommandResult(list(USAGE))
        if command not in self._verbs:
            if command in _NOT_HERE:
                return _error(f"ros2: '{command}' is not available in turtletui"
                              f" (available: {', '.join(COMMANDS)})")
            hint = _hint(command, COMMANDS, quote=True) or f" (available: {', '.join(COMMANDS)})"
            return _error(f"ros2: unknown command '{command}'{hint}")
        verbs = self._verbs[command]
        if not rest or rest[0] in ("-h", "--help"):
            if not rest:
                return _error(f"ros2 {command}: missing verb (one of: {', '.join(sorted(verbs))})")
            return CommandResult([f"usage: {verbs[v][0].usage}" for v in sorted(verbs)])
        verb_name, *args = rest
        if verb_name not in verbs:
            hint = _hint(verb_name, list(verbs), quote=True) or f" (one of: {', '.join(sorted(verbs))})"
            return _error(f"ros2 {command}: unknown verb '{verb_name}'{hint}")
        verb, handler = verbs[verb_name]
        prefix = f"ros2 {command} {verb_name}"
        if any(a in ("-h", "--help") for a in args):
            return CommandResult([f"usage: {verb.usage}"])
        try:
            positionals, options = _parse_args(verb, args)
            return handler(line.strip(), *positionals, **options)
        except _Usage as exc:
            return _error(f"{prefix}: {exc}")
        except (GraphError, InterfaceError) as exc:
            return _error(f"{prefix}: {_one_line(str(exc))}")
        except Exception as exc:  # a bug here must not take the app down: say what it was
            return _error(f"{prefix}: internal error: {type(exc).__name__}: {_one_line(str(exc))}")

    def close_all(self) -> None:
        """Stop every running stream (the app quits or resets)."""
        for stream in list(self.streams):
            stream.close()

    # -- helpers -------------------------------------------------------------------
    def _hidden_node(self) -> NodeRecord:
        self._hidden += 1
        return self.graph.add_node(f"{HIDDEN_NODE_PREFIX}{self._hidden}", owner=OWNER)

    def _start(self, stream: Stream) -> CommandResult:
        lines = stream.poll()
        if not stream.done:
            self.streams.append(stream)
            return CommandResult(lines, stream=stream)
        return CommandResult(lines)

    def _live_topic(self, name: str) -> Topic | None:
        topic = self.graph.topics.get(name)
        if topic is None or not (topic.publishers or topic.subscriptions):
            return None
        return topic

    def _live_topic_names(self) -> list[str]:
        return sorted(n for n, t in self.graph.topics.items() if t.publishers or t.subscriptions)

    def _topic_or_error(self, name: str, what: str) -> Topic:
        topic = self._live_topic(name)
        if topic is None:
            raise _Usage(f"topic '{name}' {what}{_hint(name, self._live_topic_names())}")
        return topic

    def _node(self, snap: GraphSnapshot, name: str) -> NodeInfo:
        wanted = _absolute(name)
        for node in snap.nodes:
            if node.name == wanted:
                return node
        raise _Usage(f"node '{wanted}' not found{_hint(wanted, [n.name for n in snap.nodes])}")

    def _interface(self, name: str, base: type, what: str) -> type:
        cls = get_interface(name)
        if not issubclass(cls, base):
            raise _Usage(f"'{name}' is a {_kind_word(cls)} type, not a {what} type")
        return cls

    def _values(self, text: str | None, cls: type, what: str) -> dict[str, Any]:
        """Parse a YAML argument and check it against ``cls``; returns the dict."""
        text = "{}" if text is None else text
        try:
            data = parse_yaml(text)
        except YamlError as exc:
            raise _Usage(f"could not parse {what} '{text}' ({exc})") from None
        if data is None:
            data = {}
        if not isinstance(data, dict):
            raise _Usage(f"the {what} must be a YAML dictionary such as '{{x: 1.0}}', got '{text}'")
        data = _coerce(cls, data)
        try:
            from_dict(cls, data)
        except InterfaceError as exc:
            raise _Usage(f"failed to populate field: {_one_line(str(exc))}") from None
        return data

    # -- ros2 node ------------------------------------------------------------------
    def _node_list(self, line: str, show_all: bool, count: bool) -> CommandResult:
        names = [n.name for n in snapshot(self.graph).nodes
                 if show_all or not n.name.rsplit("/", 1)[-1].startswith("_")]
        return CommandResult([str(len(names))] if count else names)

    def _node_info(self, line: str, name: str) -> CommandResult:
        node = self._node(snapshot(self.graph), name)
        lines = [node.name]
        for title, entries in (
            ("Subscribers", node.subscribers),
            ("Publishers", node.publishers),
            ("Service Servers", node.service_servers),
            ("Service Clients", node.service_clients),
            ("Action Servers", node.action_servers),
            ("Action Clients", node.action_clients),
        ):
            lines.append(f"  {title}:")
            # ros2node prints the entries with print(*entries, sep='\n'): an
            # empty section leaves one blank line.
            lines.extend([f"    {entry}: {kind}" for entry, kind in entries] or [""])
        return CommandResult(lines)

    # -- ros2 topic -------------------------------------------------------------------
    def _topic_list(self, line: str, types: bool, count: bool, hidden: bool) -> CommandResult:
        topics = [t for t in snapshot(self.graph).topics
                  if hidden or not any(part.startswith("_") for part in t.name.split("/"))]
        if count:
            return CommandResult([str(len(topics))])
        return CommandResult([f"{t.name} [{t.type}]" if types else t.name for t in topics])

    def _topic_echo(self, line: str, name: str, msg_type: str | None, once: bool,
                    field_name: str | None) -> CommandResult:
        name = _absolute(name)
        topic = self._topic_or_error(name, "does not appear to be published yet")
        if msg_type is not None:
            self._check_type(get_interface(msg_type), topic.type_name, f"topic '{name}'")
        path = self._field_path(topic.msg_type, field_name) if field_name else []
        return self._start(_EchoStream(self, line, topic, once, path))

    def _field_path(self, cls: type, text: str) -> list[str]:
        path = text.split(".")
        current: Any = cls
        for part in path:
            specs = {s.name: s for s in getattr(current, "_FIELDS", ())}
            if part not in specs:
                names = ", ".join(specs) or "none"
                raise _Usage(f"invalid field '{text}' of {interface_name(cls)} (fields: {names})")
            current = specs[part].msg_cls if specs[part].kind == "msg" and not specs[part].array else None
        return path

    def _check_type(self, cls: type, actual: str, what: str) -> None:
        wanted = interface_name(cls)
        if wanted != actual:
            raise _Usage(f"{what} has type {actual}, not {wanted}")

    def _topic_hz(self, line: str, name: str, window: int | None) -> CommandResult:
        name = _absolute(name)
        topic = self._topic_or_error(name, "does not appear to be published yet")
        return self._start(_HzStream(self, line, topic, window or 10000))

    def _topic_info(self, line: str, name: str, verbose: bool) -> CommandResult:
        name = _absolute(name)
        topic = self._topic_or_error(name, "does not exist")
        if not verbose:
            return CommandResult([
                f"Type: {topic.type_name}",
                f"Publisher count: {len(topic.publishers)}",
                f"Subscription count: {len(topic.subscriptions)}",
            ])
        lines = [f"Type: {topic.type_name}", ""]
        for title, kind, endpoints in (("Publisher", "PUBLISHER", topic.publishers),
                                       ("Subscription", "SUBSCRIPTION", topic.subscriptions)):
            lines += [f"{title} count: {len(endpoints)}", ""]
            for endpoint in endpoints:
                lines += [
                    f"Node name: {endpoint.node.name}",
                    f"Node namespace: {endpoint.node.namespace or '/'}",
                    f"Topic type: {topic.type_name}",
                    f"Endpoint type: {kind}",
                    "QoS profile:",
                    "  Reliability: RELIABLE",
                    f"  History (Depth): KEEP_LAST ({endpoint.depth})",
                    "  Durability: VOLATILE",
                    "  Lifespan: Infinite",
                    "  Deadline: Infinite",
                    "  Liveliness: AUTOMATIC",
                    "  Liveliness lease duration: Infinite",
                    "",
                ]
        return CommandResult(lines)

    def _topic_type(self, line: str, name: str) -> CommandResult:
        name = _absolute(name)
        return CommandResult([self._topic_or_error(name, "does not exist").type_name])

    def _topic_find(self, line: str, msg_type: str) -> CommandResult:
        wanted = interface_name(self._interface(msg_type, Message, "message"))
        return CommandResult([t.name for t in snapshot(self.graph).topics if t.type == wanted])

    def _topic_pub(self, line: str, name: str, msg_type: str, text: str | None, once: bool,
                   rate: float | None, times: int | None, print_nth: int | None) -> CommandResult:
        name = _absolute(name)
        cls = self._interface(msg_type, Message, "message")
        topic = self._live_topic(name)
        if topic is not None:
            self._check_type(cls, topic.type_name, f"topic '{name}'")
        values = self._values(text, cls, "message")
        rate = 1.0 if rate is None else rate
        if not rate > 0 or math.isinf(rate):
            raise _Usage(f"the rate must be a positive number of Hz, got {rate:g}")
        notes = []
        if rate > MAX_PUB_RATE_HZ:
            notes.append(f"WARNING: rate limited to {MAX_PUB_RATE_HZ:g} Hz in turtletui")
            rate = MAX_PUB_RATE_HZ
        if topic is None or not topic.subscriptions:
            near = _hint(name, [n for n in self._live_topic_names() if n != name])
            if near:
                notes.append(f"WARNING: nothing subscribes to '{name}' yet{near}")
        stream = _PubStream(self, line, name, cls, values, round(NS_PER_S / rate),
                            1 if once else (times or 0), 1 if print_nth is None else print_nth)
        result = self._start(stream)
        result.lines[:0] = notes
        return result

    # -- ros2 service -----------------------------------------------------------------
    def _service_list(self, line: str, types: bool, count: bool) -> CommandResult:
        services = snapshot(self.graph).services
        if count:
            return CommandResult([str(len(services))])
        return CommandResult([f"{s.name} [{s.type}]" if types else s.name for s in services])

    def _service(self, name: str, what: str = "is not available"):
        name = _absolute(name)
        service = self.graph.services.get(name)
        if service is None:
            raise _Usage(f"service '{name}' {what}{_hint(name, sorted(self.graph.services))}")
        return service

    def _service_type(self, line: str, name: str) -> CommandResult:
        return CommandResult([self._service(name, "does not exist").type_name])

    def _service_find(self, line: str, srv_type: str) -> CommandResult:
        wanted = interface_name(self._interface(srv_type, Service, "service"))
        return CommandResult([s.name for s in snapshot(self.graph).services if s.type == wanted])

    def _service_info(self, line: str, name: str) -> CommandResult:
        service = self._service(name, "does not exist")
        clients = [c for c in self.graph.clients if c.name == service.name]
        return CommandResult([f"Type: {service.type_name}", f"Clients count: {len(clients)}",
                              "Services count: 1"])

    def _service_call(self, line: str, name: str, srv_type: str | None,
                      text: str | None) -> CommandResult:
        service = self._service(name)
        if srv_type is not None and _looks_like_values(srv_type):
            # The type may be left out (newer ros2 too); the YAML is then all the rest.
            srv_type, text = None, " ".join(t for t in (srv_type, text) if t)
        cls = service.srv_type if srv_type is None else self._interface(srv_type, Service, "service")
        self._check_type(cls, service.type_name, f"service '{service.name}'")
        values = self._values(text, cls.Request, "request")
        request = from_dict(cls.Request, values)
        return self._start(_CallStream(self, line, service.name, cls, request))

    # -- ros2 param ---------------------------------------------------------------------
    def _visible_nodes(self, snap: GraphSnapshot) -> list[NodeInfo]:
        return [n for n in snap.nodes if not n.name.rsplit("/", 1)[-1].startswith("_")]

    def _param_list(self, line: str, node_name: str | None) -> CommandResult:
        snap = snapshot(self.graph)
        if node_name is not None:
            node = self._node(snap, node_name)
            return CommandResult([f"  {name}" for name, _ in node.parameters])
        lines = []
        for node in self._visible_nodes(snap):
            lines.append(f"{node.name}:")
            lines.extend(f"  {name}" for name, _ in node.parameters)
        return CommandResult(lines)

    def _param_get(self, line: str, node_name: str, name: str) -> CommandResult:
        node = self._node(snapshot(self.graph), node_name)
        params = dict(node.parameters)
        if name not in params:
            return _error(f"Parameter not set.{_hint(name, sorted(params))}")
        return CommandResult([_param_type_line(params[name])])

    def _param_set(self, line: str, node_name: str, name: str, text: str) -> CommandResult:
        node = self._node(snapshot(self.graph), node_name)
        try:
            value = parse_yaml(text)
        except YamlError:
            value = text  # ros2 param set falls back to a string
        if isinstance(value, dict):
            value = text
        params = dict(node.parameters)
        record = next((n for n in self.graph.nodes if n.fqn == node.name), None)
        setter = None if record is None else record.parameter_setter
        if name not in params:
            reason = f"parameter '{name}' is not declared by {node.name}{_hint(name, sorted(params))}"
        elif setter is None:
            reason = f"turtletui can not set parameters of {node.name} from here"
        else:
            reason = setter(name, value)
        if reason:
            return _error(f"Setting parameter failed: {_one_line(reason)}")
        return CommandResult(["Set parameter successful"])

    def _param_dump(self, line: str, node_name: str) -> CommandResult:
        node = self._node(snapshot(self.graph), node_name)
        lines = [f"{node.name}:", "  ros__parameters:"]
        for name, value in node.parameters:
            if isinstance(value, (list, tuple)) and value:
                lines.append(f"    {_yaml_str(name)}:")
                lines.extend(yaml_lines(list(value), 4))
            else:
                lines.append(f"    {_yaml_str(name)}: {_yaml_scalar(value)}")
        return CommandResult(lines)

    # -- ros2 action --------------------------------------------------------------------
    def _action_list(self, line: str, types: bool, count: bool) -> CommandResult:
        actions = snapshot(self.graph).actions
        if count:
            return CommandResult([str(len(actions))])
        return CommandResult([f"{a.name} [{a.type}]" if types else a.name for a in actions])

    def _action(self, name: str, what: str = "is not available"):
        name = _absolute(name)
        server = self.graph.action_servers.get(name)
        if server is None:
            raise _Usage(f"action '{name}' {what}{_hint(name, sorted(self.graph.action_servers))}")
        return server

    def _action_info(self, line: str, name: str, types: bool) -> CommandResult:
        server = self._action(name, "does not exist")
        suffix = f" [{server.type_name}]" if types else ""
        clients = sorted(c.node.fqn for c in self.graph.action_clients if c.name == server.name)
        return CommandResult([
            f"Action: {server.name}",
            f"Action clients: {len(clients)}",
            *(f"    {client}{suffix}" for client in clients),
            "Action servers: 1",
            f"    {server.node.fqn}{suffix}",
        ])

    def _action_send_goal(self, line: str, name: str, action_type: str, text: str,
                          feedback: bool) -> CommandResult:
        server = self._action(name)
        cls = self._interface(action_type, Action, "action")
        self._check_type(cls, server.type_name, f"action '{server.name}'")
        goal = from_dict(cls.Goal, self._values(text, cls.Goal, "goal"))
        return self._start(_GoalStream(self, line, server.name, cls, goal, feedback))

    # -- ros2 interface -------------------------------------------------------------------
    def _interface_show(self, line: str, name: str) -> CommandResult:
        return CommandResult(definition_text(name).split("\n"))

    def _interface_list(self, line: str) -> CommandResult:
        lines = []
        for title, kind in (("Messages", "msg"), ("Services", "srv"), ("Actions", "action")):
            lines.append(f"{title}:")
            lines.extend(f"    {n}" for n in all_interfaces() if n.split("/")[1] == kind)
        return CommandResult(lines)

    def _interface_packages(self, line: str) -> CommandResult:
        return CommandResult(sorted({n.split("/")[0] for n in all_interfaces()}))

    def _interface_package(self, line: str, package: str) -> CommandResult:
        names = [n for n in all_interfaces() if n.split("/")[0] == package]
        if not names:
            packages = sorted({n.split("/")[0] for n in all_interfaces()})
            raise _Usage(f"unknown package '{package}'{_hint(package, packages)}")
        return CommandResult(names)


def _looks_like_values(text: str) -> bool:
    return text.lstrip().startswith(("{", "[")) or ":" in text


def _kind_word(cls: type) -> str:
    if issubclass(cls, Service):
        return "service"
    if issubclass(cls, Action):
        return "action"
    return "message"


def _one_line(text: str) -> str:
    """An exception's text as one line, pointing at ros2 commands rather than
    the Python helpers it may name."""
    text = " ".join(text.split())
    return re.sub(r"\(see all_interfaces\(\) for the (\d+) known types\)",
                  r"(see 'ros2 interface list' for the \1 known types)", text)


def _error(line: str) -> CommandResult:
    return CommandResult([line], error=True)
