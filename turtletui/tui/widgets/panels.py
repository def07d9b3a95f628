"""The side panels: log (rqt_console), topics (ros2 topic list/hz/echo),
graph (rqt_graph), lesson and the ros2 console."""

from __future__ import annotations

from rich.text import Text
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.widgets import DataTable, Input, Markdown, RichLog, Select, Static

from turtletui.graph.introspection import GraphSnapshot
from turtletui.graph.logs import LEVEL_NAMES, LogRecord

LEVEL_STYLES = {10: "dim", 20: "", 30: "yellow", 40: "bold red", 50: "bold white on red"}
MAX_LOG_LINES = 1000
"""Lines a log view keeps; older ones scroll away (memory stays flat)."""


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
        yield RichLog(id="log-lines", max_lines=MAX_LOG_LINES, wrap=True, auto_scroll=True)

    def on_mount(self) -> None:
        self._records: list[LogRecord] = []

    def add(self, records: list[LogRecord]) -> None:
        """Append new records (the panel keeps the latest for refiltering)."""
        self._records.extend(records)
        del self._records[:-MAX_LOG_LINES]
        view = self.query_one("#log-lines", RichLog)
        for record in records:
            if self._shown(record):
                view.write(format_record(record))

    def _shown(self, record: LogRecord) -> bool:
        level = self.query_one("#log-level", Select).value
        node = self.query_one("#log-node", Input).value.strip()
        return record.level >= (level if isinstance(level, int) else 0) and node in record.node

    def _refilter(self) -> None:
        view = self.query_one("#log-lines", RichLog)
        view.clear()
        for record in self._records:
            if self._shown(record):
                view.write(format_record(record))

    def on_select_changed(self, event: Select.Changed) -> None:
        self._refilter()

    def on_input_changed(self, event: Input.Changed) -> None:
        event.stop()
        self._refilter()


class TopicsPanel(Vertical):
    """Topics with types, publisher/subscriber counts and rates; Enter echoes one."""

    def compose(self) -> ComposeResult:
        table: DataTable = DataTable(id="topics-table", cursor_type="row", zebra_stripes=True)
        table.add_columns("topic", "type", "pub", "sub", "Hz")
        yield table
        yield Static("Select a topic and press Enter to echo it.", id="topics-hint")
        yield RichLog(id="topics-echo", max_lines=400, wrap=False)

    def update_topics(self, graph: GraphSnapshot) -> None:
        table = self.query_one("#topics-table", DataTable)
        rows = [
            (t.name, t.type, str(len(t.publishers)), str(len(t.subscribers)), f"{t.rate_hz:.1f}")
            for t in graph.topics
        ]
        if rows == getattr(self, "_rows", None):
            return
        self._rows = rows
        cursor = table.cursor_row
        table.clear()
        for row in rows:
            table.add_row(*row, key=row[0])
        if rows:
            table.move_cursor(row=min(cursor, len(rows) - 1))

    def selected_topic(self) -> str | None:
        table = self.query_one("#topics-table", DataTable)
        rows = getattr(self, "_rows", [])
        return rows[table.cursor_row][0] if rows and 0 <= table.cursor_row < len(rows) else None

    def echo(self, lines: list[str]) -> None:
        view = self.query_one("#topics-echo", RichLog)
        for line in lines:
            view.write(line)


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
        if not topic.publishers and not topic.subscribers:
            continue
        pubs = ", ".join(topic.publishers) or "(no publisher)"
        subs = ", ".join(topic.subscribers) or "(no subscriber)"
        lines.append(f"{pubs} -> {topic.name} -> {subs}")
        connected.update(topic.publishers + topic.subscribers)
    alone = [n.name for n in graph.nodes if n.name not in connected and not n.name.split("/")[-1].startswith("_")]
    if alone:
        lines.append("")
        lines.append("not connected: " + ", ".join(alone))
    return "\n".join(lines) or "(no nodes)"


class LessonPanel(Markdown):
    """The current lesson, rendered as Markdown."""


class ConsolePanel(RichLog):
    """Output of the ros2 commands typed on the command line."""

    def show(self, lines: list[str], *, error: bool = False) -> None:
        for line in lines:
            self.write(Text(line, style="red" if error else ""))

    def command(self, line: str) -> None:
        self.write(Text(f"$ {line}", style="bold cyan"))

