"""The Textual app: watch, drive and debug the turtle in any terminal."""

from __future__ import annotations

import gc
import time
from collections import deque
from collections.abc import Iterable, Sequence
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

from textual.app import App, ComposeResult, SystemCommand
from textual.binding import Binding
from textual.containers import Horizontal
from textual.css.query import NoMatches
from textual.events import DescendantFocus
from textual.screen import Screen
from textual.widgets import ContentSwitcher, DataTable, Input, Static

from turtletui.graph.introspection import snapshot
from turtletui.graph.logs import ERROR, INFO, WARN
from turtletui.ros2cli import Ros2Cli, Terminal
from turtletui.ros2cli.terminal import Line
from turtletui.runtime.loader import ControllerSpec
from turtletui.tui import lesson_checks
from turtletui.tui.ascii_filter import AsciiFilter
from turtletui.tui.progress import Progress
from turtletui.tui.screens.help import HelpScreen
from turtletui.tui.screens.lessons import LessonScreen
from turtletui.tui.session import LiveSession
from turtletui.tui.ticker import Ticker
from turtletui.tui.widgets.arena import MIN_WIDTH, ArenaView, Overlay
from turtletui.tui.widgets.command_input import CommandInput
from turtletui.tui.widgets.keybar import APP_KEYS, COMMAND_LINE_KEYS, EDITOR_KEYS, KeyBar
from turtletui.tui.widgets.panels import (
    ConsolePanel,
    GraphPanel,
    LessonPanel,
    LogPanel,
    TopicsPanel,
)
from turtletui.tui.widgets.splitter import Splitter
from turtletui.worlds import WorldError, WorldSpec, resolve_world

if TYPE_CHECKING:
    from turtletui.bridge.run import RosConnection
    from turtletui.lessons.model import Lesson
    from turtletui.runtime.replay import Recording
    from turtletui.runtime.turtlesim_args import TurtlesimArgs

TICK_SECONDS = 0.016
"""The simulation advances every 16 ms of wall time, like turtlesim's timer."""

FRAME_SECONDS = 1 / 30
"""Screen updates at most 30 times a second, and only when something changed."""

PANEL_SECONDS = 0.2
"""Text panels and the status line update 5 times a second: each update makes
Textual re-render the panel, and the log scrolls on every line a node logs."""

RELOAD_SECONDS = 0.5
"""How often controller files are checked for changes."""

PANELS = ("log", "topics", "graph", "lesson", "console")

NARROW = 60
"""Columns below which the side panel gives way to the arena."""

SIDE_MIN = 30
"""Fewest columns the side panel is made (keys, dragging its edge)."""


_ASCII = AsciiFilter()


def _freeze_startup_heap() -> None:
    """Move everything alive after start-up (Textual, Rich, numpy, our modules)
    out of the garbage collector's reach: its full collections then scan only
    what the run allocates, and stop pausing the 16 ms loop for 25-50 ms."""
    gc.collect()
    gc.freeze()


class TurtleApp(App):
    """turtlesim, rqt_console, rqt_graph and the ros2 command line in one screen."""

    CSS_PATH = "app.tcss"
    TITLE = "turtletui"
    BINDINGS = [
        Binding("space", "pause", "Pause", tooltip="pause or resume the simulation"),
        Binding("n", "step", "Step", tooltip="one 16 ms step (pauses first)"),
        Binding("plus,equals_sign", "faster", "Faster", show=False, tooltip="speed up: x0.25 ... x8"),
        Binding("minus", "slower", "Slower", show=False, tooltip="slow down"),
        Binding("R", "reset", "Reset", show=False, tooltip="call /reset: one turtle1 at the centre, drawing cleared"),
        Binding("C", "clear", "Clear", show=False, tooltip="call /clear: the drawing goes"),
        Binding("S", "restart", "Restart node", show=False, tooltip="restart the controller nodes"),
        Binding("s", "toggle_controllers", "Stop node", show=False,
                tooltip="stop the controller nodes (teleop and ros2 topic pub then drive alone), or start them again"),
        Binding("1", "panel('log')", "Log", tooltip="log panel: every node's log lines (the same key again hides the panel)"),
        Binding("2", "panel('topics')", "Topics", tooltip="topics panel: types, publishers, subscribers, rates"),
        Binding("3", "panel('graph')", "Graph", tooltip="graph panel: nodes and topics, as rqt_graph"),
        Binding("4", "panel('lesson')", "Lesson", tooltip="lesson panel: the open lesson, and your checks"),
        Binding("5", "panel('console')", "Console", show=False, tooltip="console panel: the ros2 commands and their output"),
        Binding("colon,slash", "command_line", "ros2 command", tooltip="the ros2 command line (Esc returns to the arena)"),
        Binding("ctrl+c", "interrupt", "Stop command", show=False, priority=True,
                tooltip="stop the running ros2 command, as in a terminal (q quits; in the editor ctrl+c copies)"),
        Binding("k", "check_lesson", "Check", tooltip="run the open lesson's checks on your controller file"),
        Binding("E", "editor", "Editor",
                tooltip="edit the controller file beside the arena (ctrl+s saves, the node reloads)"),
        Binding("l", "lessons", "Lessons", show=False, tooltip="choose a lesson (your progress is shown)"),
        *(Binding(key, f"drive({x}, {z})", name, show=False,
                  tooltip="drive: one Twist each, linear.x = +-2.0, angular.z = +-2.0 (turtle_teleop_key)")
          for key, x, z, name in (("up", 1, 0, "Forward"), ("down", -1, 0, "Back"),
                                  ("left", 0, 1, "Left"), ("right", 0, -1, "Right"))),
        *(Binding(key, f"rotate('{key}')", f"Rotate {key}", show=False,
                  tooltip="rotate_absolute to 0, 45, 90, 135, 180, -135, -90, -45 degrees (turtle_teleop_key)")
          for key in "gtredcvb"),
        Binding("f", "cancel_rotation", "Cancel rotation", show=False, tooltip="cancel the rotation"),
        Binding("escape", "focus_arena", "Back to the arena", show=False, tooltip="back to the arena"),
        Binding("pageup", "scroll_side(-1)", "Scroll up", show=False, tooltip="scroll the side panel (lesson, log, console)"),
        Binding("pagedown", "scroll_side(1)", "Scroll down", show=False, tooltip="scroll the side panel (lesson, log, console)"),
        Binding("z", "zoom(1)", "Zoom in", show=False, tooltip="zoom in on the arena / out"),
        Binding("Z", "zoom(-1)", "Zoom out", show=False, tooltip="zoom in on the arena / out"),
        Binding("o", "follow_next", "Follow the next turtle", show=False,
                tooltip="zoomed in: follow the next turtle"),
        Binding("p", "pixels", "Half blocks / braille / picture", show=False,
                tooltip="draw the arena in half blocks, braille dots or the real picture"),
        Binding("less_than_sign", "side_width(4)", "Wider side panel", show=False,
                tooltip="a wider / narrower side panel (or drag its edge)"),
        Binding("greater_than_sign", "side_width(-4)", "Narrower side panel", show=False,
                tooltip="a wider / narrower side panel (or drag its edge)"),
        Binding("question_mark,f1", "help", "Help", tooltip="this help"),
        Binding("q", "quit", "Quit", tooltip="quit turtletui"),
    ]

    def __init__(
        self,
        controllers: Sequence[ControllerSpec] = (),
        *,
        lesson: Path | None = None,
        ascii: bool = False,
        ros_args: Sequence[str] = (),
        seed: int = 0,
        overlays: Sequence[tuple[float, float, float, float]] = (),
        clock: object = time.monotonic,
        world: WorldSpec | None = None,
        replay: Recording | None = None,
        pixels: str = "half",
        graphics: str | None = None,
        record: str | None = None,
        foxglove: str | None = None,
        turtlesim: TurtlesimArgs | None = None,
        distro: str | None = None,
        ros: RosConnection | None = None,
        panel: str = "log",
    ) -> None:
        """``panel``: the side panel shown first ("log", "topics", "graph", "lesson")."""
        super().__init__()
        self._panel = panel
        self._distro = distro
        """The ROS 2 distro nodes run as (--distro); None: the default."""
        self._record = record
        """Where to record the session (--record), or None."""
        self._foxglove = foxglove
        """HOST:PORT to serve the session to Foxglove on (--foxglove), or None."""
        self._ros = ros
        """A started twin on a real ROS 2 graph (``--ros``), else None."""
        self._turtlesim = turtlesim
        """turtlesim's own --ros-args (turtletui sim): its node name and parameters."""
        self._replay = replay
        """A recorded run to play instead of controllers (turtletui replay)."""
        self._controllers = list(controllers)
        self._lesson = lesson
        self._ascii = ascii
        self._pixels = pixels
        """The arena's pixel mode: "half" or "braille" (turtletui.tui.cells)."""
        self._graphics = graphics
        """The terminal's graphics protocol for the real picture (turtletui.tui.terminal)."""
        self._ros_args = list(ros_args)
        self._seed = seed
        self._overlays = tuple(overlays)
        self._clock = clock
        self._world = world
        """The world to run in; None: the lesson's world, else the empty arena."""
        self.session: LiveSession | None = None
        self._log_seen = 0
        self._last_panels = 0.0
        self._last_reload = 0.0
        self._echo = None
        """The stream echoing the topic chosen in the topics panel."""
        self.progress = Progress()
        """Which lessons the student passed (kept across runs)."""
        self._ticker: Ticker | None = None
        self._side_open = True
        self._shown_status = ""
        self.tick_gaps: deque[float] = deque(maxlen=4096)
        """Wall seconds between the latest simulation ticks: how steady the loop is."""

    # -- layout --------------------------------------------------------------
    def compose(self) -> ComposeResult:
        yield Static(id="status")
        with Horizontal(id="main"):
            yield ArenaView(
                None,
                ascii=self._ascii,
                mode=self._pixels,
                graphics=self._graphics,
                overlays=self._overlays + self._lesson_overlays(),
                id="arena",
            )
            yield Splitter(ascii=self._ascii, id="splitter")
            with ContentSwitcher(initial=self._panel, id="side"):
                yield LogPanel(id="log")
                yield TopicsPanel(id="topics")
                yield GraphPanel(id="graph")
                yield LessonPanel(self._lesson_text(), id="lesson")
                yield ConsolePanel(2000, id="console")
        yield CommandInput(
            placeholder="ros2 topic list   (Enter runs it, Esc returns to the arena)", compact=True, id="command"
        )
        yield KeyBar(self._arena_keys(), id="keys")

    def _lesson_text(self) -> str:
        if self._lesson is None:
            return "No lesson is open. Start one with `turtletui run --lesson ID` (see `turtletui lessons`)."
        from turtletui.lessons.loader import LessonError, load_lesson

        try:
            return load_lesson(self._lesson).body
        except LessonError as err:
            return f"**This lesson cannot be shown:** {err}"

    def _lesson_overlays(self) -> tuple:
        """The open lesson's [[overlays]] (e.g. Part 6's safe box), as the arena draws them."""
        if self._lesson is None:
            return ()
        from turtletui.lessons.loader import LessonError, load_lesson

        try:
            overlays = load_lesson(self._lesson).overlays
        except LessonError:
            return ()  # the lesson pane says what is wrong with it
        return tuple(
            Overlay(o.x0, o.y0, o.x1, o.y1) if o.color is None else Overlay(o.x0, o.y0, o.x1, o.y1, o.color)
            for o in overlays
        )

    def _lesson_world(self) -> tuple[WorldSpec | None, str | None]:
        """(the lesson's world, or None for the empty arena; a problem to log)."""
        if self._lesson is None:
            return None, None
        from turtletui.lessons.loader import LessonError, load_lesson

        try:
            name = load_lesson(self._lesson).world
        except LessonError:
            return None, None  # the lesson pane says what is wrong with it
        if name == "empty":
            return None, None
        try:
            return resolve_world(name), None
        except WorldError as err:
            return None, f"{err}: running in the empty arena"

    def _default_distro(self) -> tuple[str | None, str | None]:
        """The distro when none was given, as :func:`choose_distro` chooses it
        from the lesson and the files (with the line that says why)."""
        from turtletui.compat.distro import choose_distro

        lesson_distro = None
        if self._lesson is not None:
            from turtletui.lessons.loader import LessonError, load_lesson

            try:
                lesson_distro = load_lesson(self._lesson).distro
            except LessonError:
                pass  # the lesson pane says what is wrong with it
        return choose_distro(None, lesson_distro, (spec.path for spec in self._controllers if spec.path is not None))

    def on_mount(self) -> None:
        distro, distro_note = (self._distro, None) if self._distro is not None else self._default_distro()
        world, problem = (self._world, None) if self._world is not None else self._lesson_world()
        # The controllers start once the first frame is on the screen: a
        # sandbox takes a few hundred milliseconds to start.
        self.session = LiveSession(
            self._controllers,
            ros_args=self._ros_args,
            seed=self._seed,
            world=world,
            start=False,
            record=self._record,
            foxglove=self._foxglove,
            turtlesim=self._turtlesim,
            distro=distro,
            ros=self._ros,
        )
        self.sub_title = f"ROS 2 {self.session.sim.distro.capitalize()}"
        if distro_note is not None:
            self.session.sim.graph.log("turtletui", INFO, distro_note)
        if problem is not None:
            self.session.sim.graph.log("turtletui", ERROR, problem)
        if self._replay is not None:
            from turtletui.runtime.replay import install_replay

            install_replay(self.session.sim, self._replay)
            self.session.hold_at_ns = round(self._replay.duration * 1e9)
        self.cli = Ros2Cli(self.session.sim)
        self.terminal = Terminal(self.cli)
        if self.progress.warning:
            self.session.sim.graph.log("turtletui", WARN, self.progress.warning)
        arena = self.query_one(ArenaView)
        arena.lock = self.session.lock
        arena.hits = self.session.hits
        arena.world = self.session.sim.world
        arena.focus()
        self.session.advance(self._clock())
        self._ticker = Ticker(
            TICK_SECONDS,
            self._tick,
            self.session.lock,
            clock=self._clock,
            on_error=lambda err: self.call_from_thread(self._handle_exception, err),
            gaps=self.tick_gaps,
        )
        self._ticker.start()
        self.set_interval(FRAME_SECONDS, self._frame)
        self._render_frame()
        self.call_after_refresh(self.session.start_controllers)
        self.set_timer(1.0, _freeze_startup_heap)
        if self.is_web and self._editable_file() is not None:
            # A browser user has no other editor; it opens once the first frame is out.
            self.call_after_refresh(self.action_editor)

    def on_unmount(self) -> None:
        if self._ticker is not None:
            self._ticker.stop()
        if self.session is not None:
            self.action_stop_all_commands()
            self.session.close()

    # -- the loop ---------------------------------------------------------------
    def _tick(self, now: float) -> None:
        """One step of the simulation clock (the ticker's thread, holding session.lock)."""
        session = self.session
        holding = session.hold_at_ns is not None
        session.advance(now)
        if holding and session.hold_at_ns is None:  # the recording is over: its last frame is held
            session.sim.graph.log("turtletui", INFO, "replay finished: space resumes the simulation")

    def _frame(self) -> None:
        """The screen's side of the loop, at most 30 times a second: streams,
        reloads, then the frame (which repaints only what changed)."""
        session = self.session
        now = time.monotonic()  # the screen's own pace; self._clock is the simulation's
        with session.lock:
            console = self.terminal.poll()
            echoed = self._echo.poll() if self._echo is not None else []
            if self._echo is not None and self._echo.done:
                self._echo = None
        if console:
            self.query_one(ConsolePanel).show(console)
        if echoed:
            self.query_one(TopicsPanel).echo(echoed)
        if now - self._last_reload >= RELOAD_SECONDS:
            self._last_reload = now
            session.check_for_changes()
        self._render_frame(panels=now - self._last_panels >= PANEL_SECONDS)

    def _render_frame(self, panels: bool = True) -> None:
        try:
            self._draw_frame(panels)
        except NoMatches:
            return  # shutting down: the widgets go one by one, the timer not yet

    def _draw_frame(self, panels: bool) -> None:
        session = self.session
        self.query_one(ArenaView).refresh_frame()
        if not panels:
            return
        self._last_panels = time.monotonic()
        side = self.query_one(ContentSwitcher).current
        # Read what the panels show holding the lock, then let go before
        # Textual lays them out and paints them.
        with session.lock:
            new_logs, skipped = [], 0
            if session.log_count != self._log_seen:
                unseen = session.log_count - self._log_seen
                new = min(unseen, len(session.logs))
                skipped = unseen - new
                self._log_seen = session.log_count
                new_logs = list(session.logs)[-new:]
            rates = session.log_rates(time.monotonic())
            graph = snapshot(session.sim.graph) if side in ("topics", "graph") else None
            status = self._status()
        log = self.query_one(LogPanel)
        if new_logs or skipped:
            log.add(new_logs, skipped=skipped)
        log.show_rates(rates)
        if graph is not None:
            if side == "topics":
                self.query_one(TopicsPanel).update_topics(graph)
            else:
                self.query_one(GraphPanel).update_graph(graph)
        if status != self._shown_status:
            self._shown_status = status
            # One line of fixed size: no need for Textual to lay out the screen again.
            self.query_one("#status", Static).update(status, layout=False)

    def _status(self) -> str:
        session = self.session
        state = "paused" if session.paused else "running"
        controllers = "; ".join(
            f"{slot.spec.name}: {slot.status}" + (f" ({slot.detail})" if slot.status == "failed" or slot.held else "")
            for slot in session.slots
        )
        return f" t = {session.t:8.3f} s   x{session.speed:g}   {state}   {controllers or 'no controller'}"

    def get_line_filters(self):
        """With --ascii, every widget's text is turned into ASCII (turtletui.tui.ascii_filter)."""
        filters = super().get_line_filters()
        return [*filters, _ASCII] if self._ascii else filters

    def get_system_commands(self, screen: Screen) -> Iterable[SystemCommand]:
        """The command palette (ctrl+p) offers every control the keys do."""
        yield from super().get_system_commands(screen)
        commands = [
            ("Pause / resume", "Stop or restart simulated time (space)", self.action_pause),
            ("Step", "Advance one 16 ms step (n)", self.action_step),
            ("Faster", "Double the simulation speed, up to x8 (+)", self.action_faster),
            ("Slower", "Halve the simulation speed, down to x0.25 (-)", self.action_slower),
            ("Reset turtlesim", "Call /reset: one turtle1 at the centre, drawing cleared (R)", self.action_reset),
            ("Clear the drawing", "Call /clear (C)", self.action_clear),
            ("Restart the controller", "Stop and start the controller nodes again (S)", self.action_restart),
            ("Stop / start the controller", "Let teleop and ros2 topic pub drive alone (s)",
             self.action_toggle_controllers),
            ("ros2 command line", "Type ros2 commands against the simulation (:)", self.action_command_line),
            ("Stop the ros2 command", "Stop the command running in the console (ctrl+c)", self.action_interrupt),
            ("Stop every ros2 command", "The foreground command and the background publishers",
             self.action_stop_all_commands),
            ("Check the lesson", "Run the open lesson's checks on your controller file (k)", self.action_check_lesson),
            ("Lessons", "Choose a lesson; your progress is shown (l)", self.action_lessons),
            ("Help", "Every key (? or F1)", self.action_help),
        ]
        commands += [
            (f"Show the {name} panel", f"Toggle the {name} panel ({key})", partial(self.action_panel, name))
            for key, name in enumerate(PANELS, start=1)
        ]
        for title, help_text, callback in commands:
            yield SystemCommand(title, help_text, callback)

    # -- actions -------------------------------------------------------------------
    def action_pause(self) -> None:
        self.session.toggle_pause()
        self._render_frame()

    def action_step(self) -> None:
        self.session.step()
        self._render_frame()

    def action_faster(self) -> None:
        self.session.faster()
        self._render_frame()

    def action_slower(self) -> None:
        self.session.slower()
        self._render_frame()

    def action_reset(self) -> None:
        self.session.reset()

    def action_clear(self) -> None:
        self.session.clear()

    def action_restart(self) -> None:
        self.session.restart_controllers()

    def action_toggle_controllers(self) -> None:
        if not self.session.slots:
            self.notify("No controller runs in this session.", timeout=3)
            return
        self.session.toggle_controllers()
        self._render_frame()

    def action_help(self) -> None:
        if not isinstance(self.screen, HelpScreen):
            distro = self.session.sim.distro if self.session is not None else None
            self.push_screen(HelpScreen(self.BINDINGS, ascii=self._ascii, distro=distro))

    def action_lessons(self) -> None:
        from turtletui.lessons.loader import LessonError, discover_lessons

        try:
            found = discover_lessons()
        except LessonError as err:
            self.notify(str(err), severity="error")
            return
        self.push_screen(LessonScreen(found, self.progress.lessons, self._lesson, self._ascii), self._open_lesson)

    def _open_lesson(self, lesson: Lesson | None) -> None:
        if lesson is None or lesson.path == self._lesson:
            return
        self.workers.cancel_group(self, "checks")  # a check of the previous lesson
        self._lesson = lesson.path
        note = self._enter_lesson_world(lesson)
        self.query_one(ArenaView).overlays = self._overlays + self._lesson_overlays()
        self.query_one(LessonPanel).update(note + self._lesson_text())
        self._show_side("lesson")

    def _enter_lesson_world(self, lesson: Lesson) -> str:
        """Start the simulation again in the lesson's world when it runs in
        another one; what the lesson pane says about it ('' when nothing changed)."""
        running = self.session.world_spec.name if self.session.world_spec else "empty"
        if lesson.world == running:
            return ""
        fixed = "the replay" if self._replay is not None else self.session.world_fixed_by()
        world, problem = self._lesson_world()
        if fixed is not None or problem is not None:
            why = f"{fixed} keeps this session in `{running}`" if fixed else problem
            return (f"*This lesson runs in the world `{lesson.world}`, but {why}: restart with"
                    f" `turtletui run FILE --lesson {lesson.id}` to run in it.*\n\n")
        with self.session.lock:
            stopped = self.terminal.foreground is not None or bool(self.terminal.jobs)
            self.action_stop_all_commands()  # they run on the old simulation's graph
            self.session.change_world(world)
            self.cli = Ros2Cli(self.session.sim)
            self.terminal = Terminal(self.cli)
        self.query_one(ArenaView).world = self.session.sim.world
        if stopped:
            self.query_one(ConsolePanel).show([Line("^C (a new world: the ros2 commands stopped)", "note")])
        return f"*The simulation started again in this lesson's world, `{lesson.world}`.*\n\n"

    def action_drive(self, linear: int, angular: int) -> None:
        self.session.teleop.drive(float(linear), float(angular))

    def action_rotate(self, key: str) -> None:
        self.session.teleop.rotate(key)

    def action_cancel_rotation(self) -> None:
        self.session.teleop.cancel()

    def action_panel(self, name: str) -> None:
        switcher = self.query_one(ContentSwitcher)
        self._side_open = not (switcher.display and switcher.current == name)
        switcher.current = name
        self._layout_side()
        self._render_frame()

    def action_scroll_side(self, pages: int) -> None:
        switcher = self.query_one(ContentSwitcher)
        if not switcher.display or switcher.current is None:
            return
        panel = switcher.query_one(f"#{switcher.current}")
        target = next((w for w in (panel, *panel.query("*")) if w.allow_vertical_scroll), None)
        if target is not None:
            target.scroll_to(y=target.scroll_y + pages * max(1, target.size.height - 1), animate=False)

    def on_resize(self) -> None:
        self._layout_side()

    def _layout_side(self) -> None:
        # Below NARROW columns the arena gets the whole width: a panel opened
        # there would leave neither readable.
        shown = self._side_open and self.size.width >= NARROW
        self.query_one(ContentSwitcher).display = shown
        self.query_one(Splitter).display = shown

    # -- the arena's view and the side panel's width ---------------------------------------
    def action_zoom(self, steps: int) -> None:
        arena = self.query_one(ArenaView)
        if steps > 0:
            arena.zoom_in()
        else:
            arena.zoom_out()

    def action_follow_next(self) -> None:
        self.query_one(ArenaView).follow_next()

    def action_pixels(self) -> None:
        """Switch the arena between half blocks, braille dots and the picture."""
        self.query_one(ArenaView).cycle_drawing()

    def action_side_width(self, delta: int) -> None:
        self._set_side_width(self.query_one(ContentSwitcher).outer_size.width + delta)

    def on_splitter_dragged(self, event: Splitter.Dragged) -> None:
        self._set_side_width(self.size.width - event.x - 1)

    def _set_side_width(self, width: int) -> None:
        """Give the side panel ``width`` columns, leaving the arena its minimum."""
        width = max(SIDE_MIN, min(width, self.size.width - MIN_WIDTH - 1))
        self.query_one(ContentSwitcher).styles.width = width

    def _show_side(self, name: str) -> None:
        self.query_one(ContentSwitcher).current = name
        self._side_open = True
        self._layout_side()

    def _editable_file(self) -> Path | None:
        """The student's controller file: the first file named to run. The nodes
        that come with turtletui (the default part6_wall_avoider) are not theirs
        to edit, nor to be checked as their work."""
        return next((spec.path for spec in self._controllers if spec.path is not None and not spec.trusted), None)

    def _no_file_of_yours(self) -> str:
        """Why there is nothing to edit or check, and how to start a file."""
        from turtletui.lessons.loader import LessonError, load_lesson

        try:
            lesson = "ID" if self._lesson is None else load_lesson(self._lesson).id
        except LessonError:
            lesson = "ID"
        start = f"write yours with `turtletui new --lesson {lesson} my_node.py` and run the command it prints"
        theirs = next((spec.name for spec in self._controllers), None)
        if theirs is None:
            return f"no controller file is running: {start}"
        return f"{theirs} is a node that comes with turtletui: {start}"

    async def action_editor(self) -> None:
        """Show the editor on the controller file and give it the keys (ctrl+s
        saves and the node reloads; Esc gives the keys back to the arena)."""
        path = self._editable_file()
        if path is None:
            self.notify(f"Nothing to edit: {self._no_file_of_yours()}.".replace("`", ""), severity="warning",
                        timeout=8)
            return
        switcher = self.query_one(ContentSwitcher)
        if not switcher.query_children("#editor"):
            # TextArea and its parser load only when the editor is first opened
            from turtletui.tui.widgets.editor import EditorPanel

            await switcher.mount(EditorPanel(path, id="editor"))
        editor = self.query("#editor-text")
        if not editor:
            return  # the app is closing (the editor was asked for as a tab opened and closed)
        self._show_side("editor")
        editor.first().focus()

    def action_check_lesson(self) -> None:
        """Grade the running controller file against the open lesson, in another
        process, and show the result at the top of the lesson pane."""
        self._show_side("lesson")
        panel = self.query_one(LessonPanel)
        file = self._editable_file()
        if self._lesson is None or file is None:
            missing = "no lesson is open (turtletui run FILE --lesson ID)" if self._lesson is None else (
                self._no_file_of_yours()
            )
            panel.update(f"## Your checks\n\n**Nothing to check:** {missing}.\n\n" + self._lesson_text())
            return
        panel.update(lesson_checks.RUNNING + "\n" + self._lesson_text())
        self.run_worker(self._check(file), exclusive=True, group="checks")

    async def _check(self, controller: Path) -> None:
        import asyncio

        panel = self.query_one(LessonPanel)
        command = lesson_checks.check_command(controller, self._lesson, lesson_checks.results_dir(self._lesson))
        process = await asyncio.create_subprocess_exec(
            *command, stdin=asyncio.subprocess.DEVNULL, stdout=asyncio.subprocess.PIPE,
            stderr=asyncio.subprocess.STDOUT,
        )
        progress = lesson_checks.CheckProgress()
        try:
            async for line in process.stdout:
                if progress.feed(line.decode(errors="replace")):
                    panel.update(progress.running() + "\n" + self._lesson_text())
            await process.wait()
        finally:
            if process.returncode is None:  # a new check, or the app quits: stop this one
                await lesson_checks.stop(process)
        graded = None if progress.report is None else lesson_checks.graded_score(progress.report)
        if graded is not None:
            self.progress.record(*graded)
            if self.progress.warning:
                with self.session.lock:
                    self.session.sim.graph.log("turtletui", WARN, self.progress.warning)
        panel.update(progress.result(process.returncode) + "\n" + self._lesson_text())

    def action_command_line(self) -> None:
        command = self.query_one("#command", Input)
        command.add_class("open")
        command.focus()

    def action_focus_arena(self) -> None:
        self.query_one("#command", Input).remove_class("open")
        self.query_one(ArenaView).focus()

    # -- the ros2 command line -------------------------------------------------------
    def on_input_submitted(self, event: Input.Submitted) -> None:
        if event.input.id != "command":
            return
        line = event.value.strip()
        event.input.value = ""
        event.input.remember(line)
        if not line:
            return
        console = self.query_one(ConsolePanel)
        self._show_side("console")
        self.cli.help_width = console.scrollable_content_region.width or 80
        with self.session.lock:
            lines = self.terminal.run(line)
        console.show(lines)

    def action_interrupt(self) -> None:
        """Ctrl+C: stop the ros2 command running in the console (or the topics
        panel's echo), as a terminal would; never quit."""
        with self.session.lock:
            lines = self.terminal.interrupt()
            echo, jobs = self._echo, len(self.terminal.jobs)
            if not lines and echo is not None:
                echo.close()
                self._echo = None
        if lines:
            self.query_one(ConsolePanel).show(lines)
        elif echo is not None:
            self.query_one(TopicsPanel).echo(["^C"])
        elif jobs:
            self.notify(f"{jobs} command(s) run in the background: "
                        "jobs lists them, kill %N or kill all stops them.", timeout=5)
        else:
            self.notify("No ros2 command is running. q quits turtletui.", timeout=3)

    def action_stop_all_commands(self) -> None:
        with self.session.lock:
            self.terminal.close()
            if self._echo is not None:
                self._echo.close()
                self._echo = None

    def on_descendant_focus(self, event: DescendantFocus) -> None:
        if event.widget is self.query_one("#command"):
            keys = COMMAND_LINE_KEYS
        elif self._editing(event.widget):
            keys = EDITOR_KEYS
        else:
            keys = self._arena_keys()
        self.query_one(KeyBar).set_keys(keys)

    def _arena_keys(self) -> tuple:
        """The arena's keys, without those that do nothing in this session (the
        editor with no controller file of the student's, checks and stopping
        nodes with no node at all, as in turtletui sim)."""
        idle = set()
        if self._editable_file() is None:
            idle.add("editor")
        if not self._controllers:
            idle.update(("toggle_controllers", "check_lesson"))
        return tuple(hint for hint in APP_KEYS if hint.action not in idle)

    @staticmethod
    def _editing(widget: object) -> bool:
        return getattr(widget, "id", None) == "editor-text"

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        """Ctrl+C in the editor copies, as in any editor: the app's priority
        binding (stop the ros2 command) lets the key through to it."""
        if action == "interrupt" and self._editing(self.focused):
            return False
        return True

    def on_data_table_row_selected(self, event: DataTable.RowSelected) -> None:
        topic = self.query_one(TopicsPanel).selected_topic()
        if topic is None:
            return
        with self.session.lock:
            if self._echo is not None:
                self._echo.close()
            result = self.cli.run(f"ros2 topic echo {topic}")
            self._echo = result.stream
        self.query_one(TopicsPanel).echo([f"--- echo {topic} ---", *result.lines])
