"""The editor pane: the controller file in a Python TextArea. ctrl+s saves it
(atomically); the app's hot reload then restarts the node with it, or keeps
the running version when the file no longer compiles. A browser user (the app
under ``turtletui serve``) has no other editor."""

from __future__ import annotations

import time
from pathlib import Path

from textual import events
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import Static, TextArea

from turtletui.tui.source_file import SourceFile

DISK_CHECK_SECONDS = 1.0
"""How often the pane looks for changes made to the file by another editor."""


class CodeArea(TextArea):
    """A code TextArea that keeps keys in the order they were typed, saves on
    ctrl+s, and lets Esc go back to the app (the arena) instead of moving the
    focus to the next widget."""

    BINDINGS = [Binding("ctrl+s", "save", "Save")]

    async def _on_key(self, event: events.Key) -> None:
        # prevent_default() below keeps TextArea's own handler from the key,
        # which Textual would call next; the key still bubbles up to the app.
        if self.screen.focused is not self:
            event.prevent_default()  # typed after Esc, though sent here before Esc was handled
            return
        if event.key == "escape":
            # Let go of the keys now (keys already on their way here see it
            # above); the app's escape binding, which this key bubbles up to,
            # then gives them to the arena.
            self.screen.set_focus(None)
            event.prevent_default()
            return
        # Textual runs a widget's key bindings only once the key has bubbled up
        # to the app, while typed characters go in at once: keys that arrive
        # close together (a browser's, over a WebSocket) would be applied out of
        # order ("x", backspace, "y" giving "yx" or a cursor move landing late),
        # and a save could miss the last characters. Bound keys run here instead.
        for binding in self._bindings.key_to_bindings.get(event.key, ()):
            if await self.app.run_action(binding.action, self):
                event.stop()
                event.prevent_default()
                return
        await super()._on_key(event)

    def action_save(self) -> None:
        self.query_ancestor(EditorPanel).action_save()


class EditorPanel(Vertical):
    """Edit and save one controller file; the first line says what happened."""

    DEFAULT_CSS = """
    EditorPanel > #editor-status {
        height: auto;
        max-height: 4;
        background: $primary-background;
    }
    EditorPanel > #editor-status.problem {
        background: $error;
        color: $text;
    }
    EditorPanel > CodeArea {
        height: 1fr;
        border: none;
        padding: 0;
    }
    """

    def __init__(self, path: Path, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.source = SourceFile(path)
        self._dirty = False
        self._message = ""
        self._problem = False
        self._editing = False

    def compose(self) -> ComposeResult:
        yield Static(id="editor-status")
        # Wrapped, not cut at the pane's edge: every character of the file stays in view.
        yield CodeArea.code_editor(language="python", theme="monokai", soft_wrap=True, id="editor-text")

    def on_mount(self) -> None:
        self._load()
        self.set_interval(DISK_CHECK_SECONDS, self._check_disk)

    @property
    def code(self) -> CodeArea:
        return self.query_one(CodeArea)

    @property
    def modified(self) -> bool:
        """Edits not saved yet."""
        return self._dirty

    def _load(self) -> None:
        area = self.code
        try:
            text = self.source.load()
        except (OSError, UnicodeDecodeError) as err:
            area.read_only = True
            self._status(f"cannot edit {self.source.path}: {_reason(err)}", problem=True)
            return
        area.read_only = False
        cursor = area.cursor_location
        area.load_text(text)
        if cursor[0] < area.document.line_count:
            area.cursor_location = cursor
        self._dirty = False
        self._status(f"{self.source.path.name}   ctrl+s saves and reloads the node")

    def on_text_area_changed(self, event: TextArea.Changed) -> None:
        dirty = event.text_area.text != self.source.saved_text
        if dirty != self._dirty:
            self._dirty = dirty  # undone back to the saved text: no longer modified
            modified = " (modified)" if dirty else ""
            self._status(f"{self.source.path.name}{modified}   ctrl+s saves and reloads the node")

    def action_save(self) -> None:
        """Write the file; the app's hot reload picks it up within half a second."""
        if self.code.read_only:
            return
        try:
            problem = self.source.save(self.code.text)
        except OSError as err:
            self._status(f"not saved: {_reason(err)} (your edits are still here)", problem=True)
            return
        self._dirty = False
        stamp = time.strftime("%H:%M:%S")
        if problem is not None:
            # The pane is narrow: the file's name says enough, its folder is known.
            problem = problem.replace(str(self.source.path), self.source.path.name, 1)
            self._status(f"saved {stamp}, but {problem}: the running version is kept", problem=True)
        else:
            self._status(f"saved {stamp}: the node restarts with it")

    def _check_disk(self) -> None:
        if not self.source.changed_on_disk():
            return
        if self._dirty:
            self.source.seen_on_disk()  # warn once; the user's edits stay
            self._status("the file changed on disk as well: ctrl+s writes your version over it", problem=True)
            return
        self._load()
        self._status(f"{self.source.path.name} changed on disk: reloaded")

    def on_descendant_focus(self) -> None:
        self._editing = True
        self._show_status()

    def on_descendant_blur(self) -> None:
        self._editing = False
        self._show_status()

    def _status(self, text: str, *, problem: bool = False) -> None:
        self._message, self._problem = text, problem
        self._show_status()

    def _show_status(self) -> None:
        # Whether keys go to the editor or drive the turtle, said where the eyes are.
        where = "Esc: back to the arena" if self._editing else "E: edit here"
        status = self.query_one("#editor-status", Static)
        status.update(f"{where} | {self._message}")
        status.set_class(self._problem, "problem")


def _reason(err: Exception) -> str:
    if isinstance(err, OSError):
        return err.strerror or str(err)
    return str(err)
