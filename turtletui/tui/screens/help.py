"""The help screen (``?`` or F1): every key of the app, what it does, and
the commands of the ros2 console. It is made from the app's own bindings
(their tooltips), so a new key is listed without anyone remembering to."""

from __future__ import annotations

from collections.abc import Iterable

from rich.console import Group
from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Static

KEY_NAMES = {
    "space": "space", "plus": "+", "minus": "-", "equals_sign": "=", "colon": ":", "slash": "/",
    "question_mark": "?", "escape": "Esc", "enter": "Enter", "up": "↑", "down": "↓", "left": "←",
    "right": "→", "f1": "F1", "ctrl+c": "Ctrl+C", "ctrl+p": "Ctrl+P", "tab": "Tab",
    "less_than_sign": "<", "greater_than_sign": ">", "pageup": "PageUp", "pagedown": "PageDown",
}
ASCII_KEY_NAMES = {"up": "up", "down": "down", "left": "left", "right": "right"}

CONTEXT_KEYS = (
    ("Enter", "in the topics panel: echo the selected topic live below the table"),
    ("Enter", "on the command line: run the command (its output goes to the console panel)"),
    ("↑ ↓", "on the command line: the commands typed before"),
    ("Tab", "move between the fields of a panel (log filters, topics table)"),
    ("Ctrl+P", "command palette: every control, searchable"),
)

CONSOLE_COMMANDS = (
    ("ros2 ... -h", "the help of any ros2 command, as ros2 prints it"),
    ("ros2 topic pub ... &", "start a repeating publisher in the background"),
    ("ros2 bag record|info|play", "record topics into a bag folder (Ctrl+C writes it), describe it, play it"),
    ("jobs", "list the publishers and recordings running in the background"),
    ("kill %N  /  kill all", "stop background job N, or every one"),
    ("Ctrl+C", "stop the command running in the foreground (echo, hz, pub, send_goal, bag)"),
)


def key_label(keys: str, ascii: bool = False) -> str:
    """``plus,equals_sign`` -> ``+ =``: the keys of a binding as people write them."""
    names = {**KEY_NAMES, **ASCII_KEY_NAMES} if ascii else KEY_NAMES
    return " ".join(names.get(key, key) for key in keys.split(","))


def key_rows(bindings: Iterable[Binding], ascii: bool = False) -> list[tuple[str, str]]:
    """(keys, what they do) per binding with a tooltip; bindings with the same
    tooltip (the eight rotation keys) share one row."""
    rows: dict[str, list[str]] = {}
    for binding in bindings:
        if binding.tooltip:
            rows.setdefault(binding.tooltip, []).append(key_label(binding.key, ascii))
    return [(" ".join(keys), tip) for tip, keys in rows.items()]


class HelpScreen(ModalScreen[None]):
    """Every key, on one scrollable page."""

    BINDINGS = [Binding("escape,question_mark,f1,q", "dismiss", "Close", show=False)]

    def __init__(self, bindings: Iterable[Binding], ascii: bool = False, distro: str | None = None) -> None:
        super().__init__()
        self._rows = key_rows(bindings, ascii)
        self._ascii = ascii
        self._distro = distro

    def compose(self) -> ComposeResult:
        with VerticalScroll(id="help-box"):
            yield Static(self._table(), id="help-text")

    def _table(self) -> Group:
        context = [(key_label("up,down", True) if self._ascii and keys == "↑ ↓" else keys, what)
                   for keys, what in CONTEXT_KEYS]
        return Group(
            Text.assemble(("turtletui keys", "bold underline"), "   Esc, ?, F1 or q closes this page\n"),
            _grid([*self._rows, ("", ""), *context]),
            Text("\nros2 console", style="bold underline"),
            _grid(CONSOLE_COMMANDS),
            *([Text("\nROS 2", style="bold underline"), _grid([distro_row(self._distro)])] if self._distro else []),
        )


def distro_row(distro: str) -> tuple[str, str]:
    """What the help says about the run's ROS 2 distro (--distro)."""
    from turtletui.compat.distro import DISTROS

    info = DISTROS[distro]
    return (
        info.title,
        f"your nodes run as on ROS 2 {info.name.capitalize()}: turtlesim's types are in"
        f" {info.turtlesim_package} (turtletui run --distro humble|jazzy|kilted|lyrical)",
    )


def _grid(rows: Iterable[tuple[str, str]]) -> Table:
    table = Table.grid(padding=(0, 2))
    table.add_column(style="bold", no_wrap=True)
    table.add_column(ratio=1)
    for first, second in rows:
        table.add_row(first, second)
    return table
