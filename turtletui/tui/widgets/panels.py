"""The side panels: log (rqt_console), topics (ros2 topic list/hz/echo),
graph (rqt_graph), lesson and the ros2 console."""

from __future__ import annotations

from collections import deque

from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.events import Resize
from textual.widgets import DataTable, Input, Markdown, Select, Static

from turtletui.graph.introspection import GraphSnapshot, TopicInfo, is_plumbing_topic
from turtletui.graph.logs import LEVEL_NAMES, LogRecord
from turtletui.ros2cli.terminal import Line
from turtletui.tui.widgets.textlog import TextLog

LEVEL_STYLES = {10: "dim", 20: "", 30: "yellow", 40: "bold red", 50: "bold white on red"}
MAX_LOG_LINES = 5000
"""Log lines the log panel keeps; older ones are counted ("N older lines")."""

FLOOD_LINES_PER_S = 20.0
"""A node logging faster than this (per wall second) has its rate shown:
faster than anyone reads."""


def format_record(record: LogRecord) -> Text:
    """A log line for a narrow panel: level, simulated time, node, message
    (ROS's full console line, with its 20-digit stamp, would leave no room
    for the message), coloured by level."""
    line = Text(f"{record.level_name:<5} {record.t:8.3f} ", style="dim")
    line.append(f"[{record.node}] ", style="bold")
    line.append(record.msg)
    line.stylize(LEVEL_STYLES.get(record.level, ""))
    return line


class LogPanel(Vertical):
    """Every node's log lines, filtered by minimum level and node name."""

    def compose(self) -> ComposeResult:
        with Horizontal(id="log-filters"):
            yield Select(
                [(name, level) for level, name in sorted(LEVEL_NAMES.items())],
                value=10,
                allow_blank=False,
                compact=True,
                id="log-level",
            )
            yield Input(placeholder="node filter", compact=True, id="log-node")
        yield Static(id="log-rate")
        yield TextLog(MAX_LOG_LINES, id="log-lines")

    def on_mount(self) -> None:
        self._records: deque[LogRecord] = deque(maxlen=MAX_LOG_LINES)
        self._older = 0
        """Records that left the window or never reached the panel."""
        self.query_one("#log-rate").display = False

    def add(self, records: list[LogRecord], skipped: int = 0) -> None:
        """Append new records; ``skipped`` counts records lost on the way
        (the panel keeps the latest for refiltering)."""
        self._older += skipped + max(0, len(self._records) + len(records) - MAX_LOG_LINES)
        self._records.extend(records)
        view = self.query_one("#log-lines", TextLog)
        view.skip(skipped)
        view.write_all(format_record(r) for r in records if self._shown(r))

    def show_rates(self, rates: dict[str, float]) -> None:
        """Name the nodes that log faster than anyone reads, with their rate."""
        flooding = sorted(((rate, node) for node, rate in rates.items() if rate >= FLOOD_LINES_PER_S),
                          reverse=True)
        label = self.query_one("#log-rate", Static)
        label.display = bool(flooding)
        if flooding:
            label.update(Text("  ".join(f"{node}: {rate:,.0f} lines/s" for rate, node in flooding),
                              style="yellow"))

    def _shown(self, record: LogRecord) -> bool:
        level = self.query_one("#log-level", Select).value
        node = self.query_one("#log-node", Input).value.strip()
        return record.level >= (level if isinstance(level, int) else 0) and node in record.node

    def _refilter(self) -> None:
        view = self.query_one("#log-lines", TextLog)
        view.clear()
        view.older = self._older
        view.write_all(format_record(r) for r in self._records if self._shown(r))

    def on_select_changed(self, event: Select.Changed) -> None:
        self._refilter()

    def on_input_changed(self, event: Input.Changed) -> None:
        event.stop()
        self._refilter()


class TopicsPanel(Vertical):
    """Topics with types, publisher/subscriber counts and rates; Enter echoes one.
    /rosout and /parameter_events, which every node has, are left out.

    The columns fit the panel: topic names keep their width, the type is
    shortened (``Pose``) or left out when the panel is narrow."""

    def compose(self) -> ComposeResult:
        yield DataTable(id="topics-table", cursor_type="row", zebra_stripes=True)
        yield Static("Tab to the table, then Enter on a topic echoes it live (ctrl+c stops it).", id="topics-hint")
        yield TextLog(400, id="topics-echo")

    def on_mount(self) -> None:
        self._topics: tuple[TopicInfo, ...] = ()
        self._shown: tuple = ()

    def update_topics(self, graph: GraphSnapshot) -> None:
        # as rqt_graph, not /rosout and /parameter_events (every node's): ros2 topic list shows them
        self._topics = tuple(topic for topic in graph.topics if not is_plumbing_topic(topic.name))
        self._show()

    def on_resize(self, event: Resize) -> None:
        self._show()

    def _show(self) -> None:
        table = self.query_one("#topics-table", DataTable)
        width = table.scrollable_content_region.width or self.size.width
        layout = topic_columns(self._topics, width)
        if layout == self._shown:
            return
        self._shown = layout
        headers, rows = layout
        cursor = table.cursor_row
        table.clear(columns=True)
        table.add_columns(*headers)
        for topic, row in zip(self._topics, rows, strict=True):
            table.add_row(*row, key=topic.name)
        if rows:
            table.move_cursor(row=min(cursor, len(rows) - 1))

    def selected_topic(self) -> str | None:
        table = self.query_one("#topics-table", DataTable)
        topics = self._topics
        return topics[table.cursor_row].name if topics and 0 <= table.cursor_row < len(topics) else None

    def echo(self, lines: list[str]) -> None:
        self.query_one("#topics-echo", TextLog).write_all(lines)


def topic_columns(topics: tuple[TopicInfo, ...], width: int) -> tuple[tuple[str, ...], tuple]:
    """(headers, rows) of the topics table for ``width`` columns: full types
    (every one a name is used with) when they fit, else their last part
    (``Pose``), else no type column;
    names too long for what is left are cut in the middle."""
    counts = [(str(len(t.publishers)), str(len(t.subscribers)), f"{t.rate_hz:.1f}") for t in topics]
    fixed = sum(max(len(h), *(len(c[i]) for c in counts)) + 2 for i, h in enumerate(("pub", "sub", "Hz"))) \
        if counts else 0
    names = [t.name for t in topics]
    name_width = max(map(len, names), default=5)
    # a name some process uses with another type lists them all, as ros2 topic list -t
    full = [", ".join(t.types) for t in topics]
    short = [", ".join(ty.rsplit("/", 1)[-1] for ty in t.types) for t in topics]
    for types in (full, short, None):
        type_width = 0 if types is None else max(map(len, types), default=4) + 2
        if types is None or name_width + 2 + type_width + fixed <= width:
            break
    room = max(8, width - fixed - type_width - 2)
    shown = [_cut(name, room) for name in names]
    if types is None:
        headers = ("topic", "pub", "sub", "Hz")
        rows = tuple((n, *c) for n, c in zip(shown, counts, strict=True))
    else:
        headers = ("topic", "type", "pub", "sub", "Hz")
        rows = tuple((n, ty, *c) for n, ty, c in zip(shown, types, counts, strict=True))
    return headers, rows


def _cut(name: str, width: int) -> str:
    """``/turtle1/co~sensor``: the start and end of a name kept, the middle cut."""
    if len(name) <= width:
        return name
    head = (width - 1) // 2
    return name[:head] + "~" + name[len(name) - (width - 1 - head):]


class GraphPanel(Static):
    """The node/topic graph as rqt_graph draws it, one arrow chain per topic."""

    def update_graph(self, graph: GraphSnapshot) -> None:
        text = graph_text(graph)
        if text != getattr(self, "_text", None):
            self._text = text
            self.update(text)


def graph_text(graph: GraphSnapshot) -> str:
    """``/turtlesim -> /turtle1/pose -> /turtle_controller`` per connected topic,
    then the nodes that are not connected to anything."""
    lines = []
    connected = set()
    for topic in graph.topics:
        if (not topic.publishers and not topic.subscribers) or is_plumbing_topic(topic.name):
            continue  # rqt_graph too hides /rosout and /parameter_events
        pubs = ", ".join(topic.publishers) or "(no publisher)"
        subs = ", ".join(topic.subscribers) or "(no subscriber)"
        lines.append(f"{pubs} -> {topic.name} -> {subs}")
        connected.update(topic.publishers + topic.subscribers)
    alone = [n.name for n in graph.nodes if n.name not in connected and not n.name.split("/")[-1].startswith("_")]
    if alone:
        lines.append("")
        lines.append("not connected: " + ", ".join(alone))
    return "\n".join(lines) or "(no nodes)"


class LessonPanel(Markdown, can_focus=True):
    """The current lesson, rendered as Markdown; it scrolls (Tab to it, then
    the arrows, or PageUp/PageDown from anywhere), its code blocks wrap."""

    BINDINGS = [
        Binding("up", "scroll_up", "Scroll up", show=False),
        Binding("down", "scroll_down", "Scroll down", show=False),
        Binding("home", "scroll_home", "Top", show=False),
        Binding("end", "scroll_end", "End", show=False),
    ]


LINE_STYLES = {"prompt": "bold cyan", "out": "", "error": "red", "note": "dim"}


class ConsolePanel(TextLog):
    """What the ros2 command line printed: the commands typed, their output,
    the console's own notes (^C, background jobs)."""

    def show(self, lines: list[Line]) -> None:
        self.write_all(Text(line.text, style=LINE_STYLES.get(line.kind, "")) for line in lines)
