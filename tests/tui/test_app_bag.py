"""``ros2 bag`` in the app's console, as the official tutorial uses it: record
while driving with the arrows, Ctrl+C writes the bag, info describes it,
play drives the turtle again until Ctrl+C."""

from __future__ import annotations

from pathlib import Path

from support.pilot import log_text, pilot_test, type_command, wait_for

from turtletui.tui.app import TurtleApp

SIZE = (100, 30)


@pilot_test
async def test_record_info_and_play_in_the_console(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    app = TurtleApp()
    async with app.run_test(size=SIZE) as pilot:
        await wait_for(pilot, lambda: app.session.t > 0.1)
        turtle = app.session.sim.world.turtles["turtle1"]
        await type_command(pilot, "ros2 bag record /turtle1/cmd_vel /turtle1/pose -o subset")
        await wait_for(pilot, lambda: "[rosbag2_recorder]: Recording..." in log_text(app, "#console"))
        await pilot.press("escape", "up", "left", "up")  # drive, as with turtle_teleop_key
        await wait_for(pilot, lambda: turtle.distance > 1.0, timeout=10)
        await pilot.press("colon", "ctrl+c")  # stops the recording, as in a terminal
        await wait_for(pilot, lambda: (tmp_path / "subset" / "metadata.yaml").is_file())
        stopped = log_text(app, "#console").split("\n")[-2:]
        assert stopped[0] == "^C" and stopped[1].endswith("[rosbag2_recorder]: Recording stopped")
        assert app.terminal.foreground is None and app.is_running

        await type_command(pilot, "ros2 bag info subset")
        console = log_text(app, "#console")
        assert "Topic: /turtle1/cmd_vel | Type: geometry_msgs/msg/Twist | Count: 3 |" in console

        await pilot.press("escape", "R")  # /reset: turtle1 back at the centre
        await wait_for(pilot, lambda: app.session.sim.world.turtles["turtle1"].distance == 0.0)
        replayed = app.session.sim.world.turtles["turtle1"]
        await type_command(pilot, "ros2 bag play subset")
        await wait_for(pilot, lambda: replayed.distance > 0.5, timeout=10)
        await pilot.press("ctrl+c")
        await wait_for(pilot, lambda: app.terminal.foreground is None)
        assert not [node for node in app.session.sim.graph.nodes if node.name.startswith("rosbag2")]
        assert app.is_running
