"""The app at 80x24 as a student uses it: every log line readable, every
ros2 command stoppable with Ctrl+C, the key bar and help complete, the
topics and the lesson fitting their pane, the controller switched off and on."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from support.pilot import SIZE, log_text, pilot_test, type_command, wait_for
from textual.widgets import DataTable
from textual.widgets._markdown import MarkdownFence

from turtletui.graph.introspection import TopicInfo
from turtletui.lessons.loader import find_lesson
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.resolve import resolve_controllers
from turtletui.tui.app import TurtleApp
from turtletui.tui.screens.help import HelpScreen
from turtletui.tui.widgets.keybar import KeyBar
from turtletui.tui.widgets.panels import FLOOD_LINES_PER_S, ConsolePanel, graph_text, topic_columns
from turtletui.tui.widgets.textlog import TextLog

SMALL = (80, 24)


@pilot_test
async def test_at_80x24_the_log_shows_whole_lines_with_their_numbers() -> None:
    """Part 3 logs "Hello 0", "Hello 1"...: the number must be on screen."""
    app = TurtleApp(resolve_controllers(["part3_first_node"]))
    async with app.run_test(size=SMALL) as pilot:
        await wait_for(pilot, lambda: "Hello 1" in log_text(app), timeout=60)
        await pilot.pause(0.3)
        view = app.query_one("#log-lines", TextLog)
        width = view.scrollable_content_region.width
        assert 20 < width < 45
        screen = [line.rstrip() for line in view.visible_lines]
        assert all(len(line) <= width for line in screen)
        words = " ".join(screen).split()
        assert "[first_node] Hello 1" in " ".join(words), screen


@pilot_test
async def test_a_node_that_floods_shows_its_rate(tmp_path: Path) -> None:
    path = tmp_path / "chatty.py"
    path.write_text(textwrap.dedent("""
        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("chatty")
            node.create_timer(0.002, lambda: node.get_logger().info("tick"))
            rclpy.spin(node)
    """))
    app = TurtleApp([ControllerSpec("chatty", path=path)])
    async with app.run_test(size=SMALL) as pilot:
        rate = app.query_one("#log-rate")
        await wait_for(pilot, lambda: rate.display and "chatty:" in str(rate.render()), timeout=60)
        lines_per_s = float(str(rate.render()).split("chatty:")[1].split()[0].replace(",", ""))
        # 500 lines per simulated second; at x1 simulated time never runs ahead of
        # the wall clock, but falls behind on a busy machine: per wall second, at most 500
        assert FLOOD_LINES_PER_S <= lines_per_s <= 600


@pilot_test
async def test_ctrl_c_stops_the_running_command_and_never_quits() -> None:
    app = TurtleApp()
    async with app.run_test(size=SMALL) as pilot:
        main = app.screen
        await type_command(pilot, "ros2 topic echo /turtle1/pose")
        await wait_for(pilot, lambda: "theta: 0.0" in log_text(app, "#console"))
        assert app.terminal.foreground is not None
        await pilot.press("ctrl+c")
        await pilot.pause()
        assert app.terminal.foreground is None and app.is_running
        assert not [n for n in app.session.sim.graph.nodes if n.name.startswith("_ros2cli")]
        assert log_text(app, "#console").endswith("^C")
        await pilot.press("ctrl+c")  # nothing runs now: a hint, still no quitting
        await pilot.pause()
        assert app.is_running and app.screen is main and app.return_code is None  # no quit dialog


@pilot_test
async def test_a_new_command_stops_the_last_stream_and_publishers_can_be_listed() -> None:
    app = TurtleApp()
    async with app.run_test(size=SMALL) as pilot:
        await type_command(pilot, "ros2 topic hz /turtle1/pose")
        await type_command(pilot, "ros2 topic pub -r 5 /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: 1.0}}'")
        await type_command(pilot, "jobs")
        console = log_text(app, "#console")
        assert "\n^C\n$ ros2 topic pub" in console
        assert "average rate" not in console.split("$ ros2 topic pub")[1]  # hz output stopped there
        assert "[1]  Running  ros2 topic pub -r 5" in console
        await wait_for(pilot, lambda: app.session.sim.world.turtles["turtle1"].vx == 1.0)
        await type_command(pilot, "kill %1")
        assert app.terminal.jobs == []


@pilot_test
async def test_the_key_bar_keeps_help_and_quit_at_80_columns(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text("import rclpy\n")
    app = TurtleApp([ControllerSpec("node", path=node)])
    async with app.run_test(size=SMALL) as pilot:
        await pilot.pause()
        bar = app.query_one(KeyBar)
        text = str(bar.render())
        assert {"?", ":", "k", "E", "q"} <= set(bar.shown)
        assert text.startswith(" ? Help") and text.rstrip().endswith("q Quit")
        assert len(text.rstrip()) <= 80
        await pilot.press("colon")
        assert "Esc" in bar.shown and "^C" in bar.shown  # the command line's own keys
        await pilot.press("escape")
        assert "?" in bar.shown


@pilot_test
async def test_the_key_bar_leaves_out_keys_that_do_nothing_here() -> None:
    app = TurtleApp()  # turtlesim alone: no file to edit, no node to stop
    async with app.run_test(size=(120, 30)) as pilot:
        await pilot.pause()
        shown = app.query_one(KeyBar).shown
        assert not {"E", "s", "k"} & set(shown) and {"?", "n", "l", "q"} <= set(shown)


@pytest.mark.parametrize("key", ["question_mark", "f1"])
def test_the_help_screen_lists_every_key(key) -> None:
    _help_scenario(key)


@pilot_test
async def _help_scenario(key: str) -> None:
    app = TurtleApp()
    async with app.run_test(size=SMALL) as pilot:
        await pilot.press(key)
        assert isinstance(app.screen, HelpScreen)
        page = app.screen.query_one("#help-text")
        for binding in TurtleApp.BINDINGS:
            assert binding.tooltip, f"{binding.key} has no help text"
        lines = app.console.render_lines(page.content, app.console.options.update_width(200))
        plain = " ".join("".join(seg.text for seg in line) for line in lines)
        for tip in {b.tooltip for b in TurtleApp.BINDINGS}:
            assert tip in plain
        for shown in ("space", "Ctrl+C", "? F1", "jobs", "kill %N"):
            assert shown in plain
        await pilot.press("escape")
        assert not isinstance(app.screen, HelpScreen)


@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
def test_every_topics_column_is_on_screen(size) -> None:
    _topics_scenario(size)


@pilot_test
async def _topics_scenario(size) -> None:
    app = TurtleApp(resolve_controllers(["part6_wall_avoider"]))
    async with app.run_test(size=size) as pilot:
        await pilot.press("2")
        table = app.query_one("#topics-table", DataTable)
        await wait_for(pilot, lambda: table.row_count == 3)
        await pilot.pause(0.3)
        labels = [str(column.label) for column in table.columns.values()]
        assert labels[-3:] == ["pub", "sub", "Hz"]
        used = sum(column.get_render_width(table) for column in table.columns.values())
        assert used <= table.scrollable_content_region.width
        assert ("type" in labels) == (size == (120, 40))
        hint = app.query_one("#topics-hint")
        shown = " ".join(line.text.strip() for line in hint.render_lines(hint.region.reset_offset))
        assert shown.endswith("echoes it live (ctrl+c stops it).")  # whole, not cut at the pane's edge


@pilot_test
async def test_lesson_code_wraps_inside_the_pane() -> None:
    app = TurtleApp(lesson=find_lesson("part6-closed-loop").path)
    async with app.run_test(size=SMALL) as pilot:
        await pilot.press("4")
        await pilot.pause(0.5)
        fences = list(app.query(MarkdownFence))
        assert fences
        for fence in fences:
            assert fence.virtual_size.width <= fence.size.width
        lesson = app.query_one("#lesson")
        assert lesson.max_scroll_y > 0  # the lesson is longer than the pane: it scrolls
        await pilot.press("pagedown")
        await pilot.pause()
        assert lesson.scroll_y > 0


@pilot_test
async def test_s_stops_and_starts_the_controller() -> None:
    app = TurtleApp(resolve_controllers(["part6_wall_avoider"]))
    async with app.run_test(size=SMALL) as pilot:
        await wait_for(pilot, lambda: app.session.slots[0].status == "running")
        await pilot.press("s")
        slot = app.session.slots[0]
        assert slot.host is None and slot.status == "stopped" and slot.held
        await wait_for(pilot, lambda: "part6_wall_avoider: stopped (by you)" in str(app.query_one("#status").render()))
        assert "controller" not in " ".join(n.name for n in app.session.sim.graph.nodes)
        await pilot.press("s")
        assert slot.status == "running" and slot.host is not None and not slot.held


@pilot_test
async def test_the_lesson_switcher_opens_a_lesson_and_shows_progress(tmp_path: Path) -> None:
    from turtletui.tui.screens.lessons import LessonScreen

    app = TurtleApp(lesson=find_lesson("part6-closed-loop").path)
    async with app.run_test(size=SMALL) as pilot:
        app.progress.record("part5-pose-subscriber", 4, 4)
        app.progress.record("part4-open-loop-circle", 2, 5)
        await pilot.press("l")
        assert isinstance(app.screen, LessonScreen)
        options = app.screen.query_one("#lessons-list")
        labels = {options.get_option_at_index(i).id: str(options.get_option_at_index(i).prompt)
                  for i in range(options.option_count)}
        assert labels["part5-pose-subscriber"].lstrip().startswith("✓")
        assert labels["part4-open-loop-circle"].lstrip().startswith("2/5")
        assert labels["part3-first-node"].lstrip().startswith("-")
        assert options.get_option_at_index(options.highlighted).id == "part6-closed-loop"
        options.highlighted = list(labels).index("part5-pose-subscriber")
        await pilot.press("enter")
        await pilot.pause()
        assert not isinstance(app.screen, LessonScreen)
        assert app._lesson == find_lesson("part5-pose-subscriber").path
        assert app.query_one("#side").current == "lesson"
        assert "pose" in app.query_one("#lesson").source.lower()
        assert "restart with" not in app.query_one("#lesson").source  # same (empty) world


async def choose_lesson(pilot, lesson_id: str) -> None:
    """l (from the arena), then Enter on ``lesson_id`` in the switcher."""
    await pilot.press("escape", "l")
    options = pilot.app.screen.query_one("#lessons-list")
    ids = [options.get_option_at_index(i).id for i in range(options.option_count)]
    options.highlighted = ids.index(lesson_id)
    await pilot.press("enter")
    await pilot.pause()


@pilot_test
async def test_a_lesson_in_another_world_starts_the_simulation_again_in_it(tmp_path: Path) -> None:
    node = tmp_path / "node.py"
    node.write_text("import rclpy\nfrom rclpy.node import Node\n\n\ndef main():\n"
                    "    rclpy.init()\n    rclpy.spin(Node('mine'))\n")
    app = TurtleApp([ControllerSpec("node", path=node)], lesson=find_lesson("part6-closed-loop").path)
    async with app.run_test(size=SIZE) as pilot:
        await wait_for(pilot, lambda: any(n.name == "mine" for n in app.session.sim.graph.nodes), timeout=15)
        arena = app.query_one("#arena")
        assert arena.overlays  # Part 6's safe box
        await type_command(pilot, "ros2 topic echo /turtle1/pose")
        old = app.session.sim
        await choose_lesson(pilot, "lidar-obstacles")
        sim = app.session.sim
        assert sim is not old and app.session.world_spec.name == "lidar-course"
        assert sim.world.obstacles and arena.world is sim.world and arena.overlays == ()
        assert "started again in this lesson's world, `lidar-course`" in app.query_one("#lesson").source
        assert app.terminal.foreground is None and "a new world: the ros2 commands stopped" in log_text(app, "#console")
        # the controller runs again, in the new world, and the LiDAR scans in it
        await wait_for(pilot, lambda: any(n.name == "mine" for n in sim.graph.nodes), timeout=15)
        await type_command(pilot, "ros2 topic list")
        assert "/turtle1/scan" in log_text(app, "#console").split("$ ros2 topic list")[-1]
        await wait_for(pilot, lambda: sim.t > 0.2)
        await choose_lesson(pilot, "part3-first-node")  # back to turtlesim's empty arena
        assert app.session.world_spec is None and not app.session.sim.world.obstacles
        assert "started again in this lesson's world, `empty`" in app.query_one("#lesson").source


@pilot_test
async def test_a_recording_keeps_the_session_in_its_world(tmp_path: Path) -> None:
    app = TurtleApp(lesson=find_lesson("part6-closed-loop").path, record=str(tmp_path / "run.mcap"))
    async with app.run_test(size=SMALL) as pilot:
        old = app.session.sim
        await choose_lesson(pilot, "lidar-obstacles")
        assert app.session.sim is old and not old.world.obstacles
        assert (f"but the recording to {tmp_path / 'run.mcap'} (--record) keeps this session in `empty`:"
                " restart with `turtletui run FILE --lesson lidar-obstacles`") in app.query_one("#lesson").source


@pilot_test
async def test_a_damaged_progress_file_is_a_warning_not_a_crash() -> None:
    import os

    data = Path(os.environ["XDG_DATA_HOME"]) / "turtletui"
    data.mkdir(parents=True, exist_ok=True)
    (data / "progress.json").write_text("{not json")
    app = TurtleApp()
    async with app.run_test(size=SMALL) as pilot:
        await wait_for(pilot, lambda: "your progress could not be read" in log_text(app))
        assert app.progress.lessons == {}


@pilot_test
async def test_the_console_wraps_and_keeps_everything_after_a_resize() -> None:
    app = TurtleApp()
    async with app.run_test(size=SMALL) as pilot:
        await type_command(pilot, "ros2 interface show turtlesim/srv/Spawn")
        console = app.query_one(ConsolePanel)
        await pilot.pause()
        narrow = console.visible_lines
        assert all(len(line.rstrip()) <= console.scrollable_content_region.width for line in narrow)
        await pilot.resize_terminal(120, 40)
        await pilot.pause(0.3)
        wide = [line.rstrip() for line in console.visible_lines]
        assert "$ ros2 interface show turtlesim/srv/Spawn" in wide
        long = next(line for line in wide if line.startswith("string name"))
        assert len(long) > max(map(len, narrow))  # wrapped again at the new width
        assert "created and returned if this is empty" in " ".join(wide)


def test_the_graph_panel_leaves_out_what_every_node_has() -> None:
    # as rqt_graph hides /rosout and /parameter_events: every node is on them
    from turtletui.graph.introspection import GraphSnapshot, NodeInfo, TopicInfo

    def node(name: str) -> NodeInfo:
        return NodeInfo(name, (), (), (), (), (), (), ())

    graph = GraphSnapshot(1.0, (node("/alone"), node("/talker"), node("/turtlesim")), (
        TopicInfo("/chatter", "std_msgs/msg/String", ("/talker",), (), 10.0, 10),
        TopicInfo("/parameter_events", "rcl_interfaces/msg/ParameterEvent",
                  ("/alone", "/talker", "/turtlesim"), ("/turtlesim",), 0.0, 0),
        TopicInfo("/rosout", "rcl_interfaces/msg/Log", ("/alone", "/talker", "/turtlesim"), (), 0.0, 0),
    ), (), ())
    assert graph_text(graph) == "/talker -> /chatter -> (no subscriber)\n\nnot connected: /alone, /turtlesim"


def test_the_topics_table_lists_every_type_a_name_is_used_with() -> None:
    # as ros2 topic list -t: a student's geometry_msgs Pose subscription on
    # turtlesim's /turtle1/pose is a second type, not hidden behind the first
    pose = TopicInfo("/turtle1/pose", "turtlesim_msgs/msg/Pose", ("/turtlesim",), ("/pose_subscriber",), 62.5, 10,
                     ("geometry_msgs/msg/Pose",))
    headers, rows = topic_columns((pose,), 200)
    assert headers[1] == "type"
    assert rows[0][1] == "geometry_msgs/msg/Pose, turtlesim_msgs/msg/Pose"
    _, rows = topic_columns((pose,), 45)
    assert rows[0][1] == "Pose, Pose"


@pytest.mark.parametrize(
    ("args", "panel", "lesson", "node"),
    [
        (["--lesson", "part5-pose-subscriber", "part3_first_node"], "lesson", "part5-pose-subscriber", "part3_first_node"),
        # no file: the lesson's own reference node shows what the lesson's node does
        (["--lesson", "part5-pose-subscriber"], "lesson", "part5-pose-subscriber", "part5_pose_subscriber"),
        (["--lesson", "part7-pen-service"], "lesson", "part7-pen-service", "part7_pen_color"),
        (["part5_pose_subscriber"], "log", None, "part5_pose_subscriber"),
        ([], "log", "part6-closed-loop", "part6_wall_avoider"),  # the demo: its node's log streaming
    ],
)
def test_run_opens_on_the_lesson_it_was_asked_for_else_on_the_log(monkeypatch, args, panel, lesson, node) -> None:
    from typer.testing import CliRunner

    from turtletui.cli import app as cli

    shown = []
    monkeypatch.setattr(TurtleApp, "run", lambda self: shown.append(self))
    result = CliRunner().invoke(cli, ["run", *args], env={"TEXTUAL_DRIVER": "headless"})
    assert result.exit_code == 0, result.output
    app = shown[0]
    assert app._panel == panel
    assert app._lesson == (find_lesson(lesson).path if lesson else None)
    assert [spec.name for spec in app._controllers] == [node]


def test_a_headless_run_of_a_lesson_without_a_file_runs_the_lessons_reference_node(tmp_path) -> None:
    from typer.testing import CliRunner

    from turtletui.cli import app as cli

    result = CliRunner().invoke(cli, ["run", "--lesson", "part5-pose-subscriber", "--headless", "-d", "0.3"])
    assert result.exit_code == 0, result.output
    assert "[pose_subscriber]: (5.544444561004639, 5.544444561004639)" in result.stderr


@pilot_test
async def test_the_app_shows_first_the_panel_it_is_given() -> None:
    app = TurtleApp(lesson=find_lesson("part5-pose-subscriber").path, panel="lesson")
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.query_one("#side").current == "lesson"
        assert "pose" in app.query_one("#lesson").source.lower()
