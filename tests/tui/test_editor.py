"""The editor pane, as a student uses it in the terminal or the browser: open
it with E, type, ctrl+s saves the file and the node reloads; a syntax error
is shown and the running version kept; nothing typed is ever lost."""

from __future__ import annotations

import os
import shutil
import stat
import textwrap
from pathlib import Path

from support.pilot import SIZE, pilot_test, type_command, wait_for
from textual import events
from textual.widgets import ContentSwitcher, Static
from textual.widgets.text_area import Selection

from turtletui.runtime.loader import ControllerSpec
from turtletui.tui.app import TurtleApp
from turtletui.tui.source_file import SourceFile
from turtletui.tui.widgets.arena import ArenaView
from turtletui.tui.widgets.editor import EditorPanel
from turtletui.tui.widgets.keybar import KeyBar

NODE = textwrap.dedent("""
    import rclpy
    from rclpy.node import Node


    def main():
        rclpy.init()
        node = Node("talker")
        node.create_timer(0.1, lambda: node.get_logger().info("version one"))
        rclpy.spin(node)
""").lstrip()


def logged(app: TurtleApp) -> str:
    return "\n".join(record.msg for record in app.session.logs)


def status(app: TurtleApp) -> str:
    return str(app.query_one("#editor-status", Static).render())


def select(panel: EditorPanel, text: str) -> None:
    """Put the selection on the first ``text`` in the editor (typing replaces it)."""
    for row, line in enumerate(panel.code.text.splitlines()):
        col = line.find(text)
        if col >= 0:
            panel.code.selection = Selection((row, col), (row, col + len(text)))
            return
    raise AssertionError(f"{text!r} not in the editor")


def started(tmp_path: Path, source: str = NODE) -> tuple[TurtleApp, Path]:
    path = tmp_path / "talker.py"
    path.write_text(source, encoding="utf-8")
    return TurtleApp([ControllerSpec("talker", path=path)]), path


@pilot_test
async def test_type_save_and_the_node_reloads_with_the_new_code(tmp_path: Path) -> None:
    app, path = started(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await wait_for(pilot, lambda: "version one" in logged(app))
        await pilot.press("E")
        panel = app.query_one(EditorPanel)
        assert app.query_one(ContentSwitcher).current == "editor"
        assert app.focused is panel.code and panel.code.text == NODE
        assert panel.code.language == "python"
        await pilot.press("x")
        assert panel.modified and "(modified)" in status(app)
        await pilot.press("ctrl+z")  # undone: the text is the file's again
        assert not panel.modified and "(modified)" not in status(app)
        select(panel, "one")
        await pilot.press(*"two")
        assert panel.modified and "(modified)" in status(app)
        assert path.read_text(encoding="utf-8") == NODE  # nothing written before ctrl+s
        await pilot.press("ctrl+s")
        assert path.read_text(encoding="utf-8") == NODE.replace("version one", "version two")
        assert not panel.modified and "the node restarts with it" in status(app)
        await wait_for(pilot, lambda: "version two" in logged(app))
        assert "talker.py changed: reloading its node" in logged(app)
        assert not list(tmp_path.glob(".*.tmp"))


@pilot_test
async def test_keys_arriving_together_are_applied_in_order_and_saved(tmp_path: Path) -> None:
    """As from a browser, where a WebSocket can deliver keys in one burst."""
    app, path = started(tmp_path, "SPEED = 0.0\n" + NODE)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("E")
        for key in ("end", "backspace", "backspace", "backspace", "1", "full_stop", "5", "ctrl+s"):
            character = {"1": "1", "5": "5", "full_stop": "."}.get(key)
            app.post_message(events.Key(key, character))  # all queued before any is handled
        await wait_for(pilot, lambda: "SPEED = 1.5\n" in path.read_text(encoding="utf-8"))
        assert path.read_text(encoding="utf-8") == "SPEED = 1.5\n" + NODE
        assert not app.query_one(EditorPanel).modified
        for key in ("escape", "space"):  # Esc, then a key for the app at once
            app.post_message(events.Key(key, " " if key == "space" else None))
        await wait_for(pilot, lambda: app.session.paused)
        assert path.read_text(encoding="utf-8") == app.query_one(EditorPanel).code.text
        assert isinstance(app.focused, ArenaView)


@pilot_test
async def test_a_syntax_error_is_shown_and_the_running_version_kept(tmp_path: Path) -> None:
    app, path = started(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await wait_for(pilot, lambda: "version one" in logged(app))
        await pilot.press("E")
        panel = app.query_one(EditorPanel)
        select(panel, "def main():")
        await pilot.press(*"def main(:", "ctrl+s")
        assert "talker.py:5" in status(app) and "SyntaxError" in status(app)
        assert "the running version is kept" in status(app)
        assert panel.query_one("#editor-status").has_class("problem")
        await wait_for(pilot, lambda: "previous version keeps running" in logged(app))
        assert app.session.slots[0].status == "running"
        before = logged(app).count("version one")
        await wait_for(pilot, lambda: logged(app).count("version one") > before)  # still the old node


@pilot_test
async def test_escape_returns_the_keys_to_the_arena_and_E_takes_them_back(tmp_path: Path) -> None:
    app, _ = started(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("E")
        panel = app.query_one(EditorPanel)
        assert status(app).startswith("Esc: back to the arena | ")
        await pilot.press("escape")
        assert isinstance(app.focused, ArenaView)
        assert status(app).startswith("E: edit here | ")  # the pane says where the keys go
        turtle = app.session.sim.world.turtles["turtle1"]
        start = turtle.x
        await pilot.press("up")  # drives again, types nothing
        await wait_for(pilot, lambda: turtle.x > start + 0.3)
        assert panel.code.text == NODE
        await pilot.press("E")  # the pane is open: E gives it the keys again
        assert app.focused is panel.code
        await pilot.press("escape", "1")  # another panel in its place
        switcher = app.query_one(ContentSwitcher)
        assert switcher.current == "log"
        await pilot.press("E")  # back, with the edits and the cursor where they were
        assert switcher.current == "editor" and app.focused is panel.code
        assert len(app.query(EditorPanel)) == 1


@pilot_test
async def test_ctrl_c_copies_in_the_editor_and_stops_commands_everywhere_else(tmp_path: Path) -> None:
    app, _ = started(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await type_command(pilot, "ros2 topic echo /turtle1/pose")
        assert app.terminal.foreground is not None
        await pilot.press("escape", "E")
        panel = app.query_one(EditorPanel)
        keys = app.query_one(KeyBar)
        assert keys.shown == ["^S", "^C", "^Z", "Esc", "F1"]  # the arena's keys would type here
        select(panel, "rclpy.init()")
        await pilot.press("ctrl+c")
        assert app.clipboard == "rclpy.init()"
        assert app.terminal.foreground is not None and panel.code.text == NODE  # the echo goes on
        await pilot.press("escape")
        assert "E" in keys.shown and "^S" not in keys.shown
        await pilot.press("ctrl+c")  # from the arena: stops the command
        assert app.terminal.foreground is None
        await type_command(pilot, "ros2 topic hz /turtle1/pose")
        await pilot.press("ctrl+c")  # and from the command line
        assert app.terminal.foreground is None


@pilot_test
async def test_without_a_controller_file_there_is_nothing_to_edit() -> None:
    app = TurtleApp()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("E")
        await pilot.pause(0.1)
        assert not app.query(EditorPanel)
        assert any("Nothing to edit" in str(n.message) for n in app._notifications)


@pilot_test
async def test_a_failed_save_keeps_the_edits_and_says_why(tmp_path: Path) -> None:
    folder = tmp_path / "work"
    folder.mkdir()
    app, path = started(folder)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("E")
        panel = app.query_one(EditorPanel)
        select(panel, "one")
        await pilot.press(*"two")
        shutil.rmtree(folder)  # the folder went away under the editor
        await pilot.press("ctrl+s")
        assert "| not saved: " in status(app) and "your edits are still here" in status(app)
        assert "version two" in panel.code.text and panel.modified


@pilot_test
async def test_changes_on_disk_reload_an_unmodified_pane_and_never_overwrite_edits(tmp_path: Path) -> None:
    app, path = started(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("E")
        panel = app.query_one(EditorPanel)
        path.write_text(NODE.replace("one", "three"), encoding="utf-8")
        await wait_for(pilot, lambda: "version three" in panel.code.text)
        assert "changed on disk: reloaded" in status(app)
        select(panel, "three")
        await pilot.press(*"four")
        path.write_text(NODE.replace("one", "five"), encoding="utf-8")
        await wait_for(pilot, lambda: "changed on disk as well" in status(app))
        assert "version four" in panel.code.text


@pilot_test
async def test_a_file_that_is_not_text_is_shown_read_only_with_the_reason(tmp_path: Path) -> None:
    path = tmp_path / "talker.py"
    path.write_bytes(b"\xff\xfe not utf-8")
    app = TurtleApp([ControllerSpec("talker", path=path)])
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("E")
        panel = app.query_one(EditorPanel)
        assert panel.code.read_only and f"cannot edit {path}" in status(app)
        await pilot.press("ctrl+s")
        assert path.read_bytes() == b"\xff\xfe not utf-8"


def test_saving_keeps_the_files_mode_and_writes_through_a_symlink(tmp_path: Path) -> None:
    real = tmp_path / "real.py"
    real.write_text("x = 1\n")
    real.chmod(0o640)
    link = tmp_path / "link.py"
    link.symlink_to(real)
    source = SourceFile(link)
    assert source.load() == "x = 1\n"
    assert source.save("x = 2\n") is None
    assert link.is_symlink() and real.read_text() == "x = 2\n"
    assert stat.S_IMODE(os.stat(real).st_mode) == 0o640
    assert not source.changed_on_disk()
    assert source.save("x = (\n").startswith(f"{link}:1")
