"""Worlds: WorldSpec, TOML world files, finding worlds by name, and ``run --world``."""

from __future__ import annotations

import itertools
import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import turtletui
from turtletui.api import run
from turtletui.runtime.loader import ControllerSpec
from turtletui.sim import ARENA_SIZE, BACKGROUND, CENTER, Box, Circle, Lidar
from turtletui.sim.obstacles import surface_distance
from turtletui.worlds import (
    WorldError,
    WorldSpec,
    load_world_file,
    parse_world,
    resolve_world,
    world_names,
)

PACKAGE_ROOT = Path(turtletui.__file__).resolve().parents[1]

FULL = """\
name = "garden"
description = "two obstacles"
background = [10, 20, 30]

[[circles]]
x = 3.0
y = 8.0
r = 0.5

[[boxes]]
x0 = 1.0
y0 = 1.0
x1 = 2.0
y1 = 1.5

[lidar]
samples = 90
range_min = 0.1
range_max = 4.0
noise_std = 0.02
dropout = 0.01
rate = 5
"""


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


@pytest.fixture(autouse=True)
def no_installed_plugins(monkeypatch):
    monkeypatch.setenv("TURTLETUI_DISABLE_PLUGIN_AUTOLOAD", "1")


# -- WorldSpec ----------------------------------------------------------------------------


def test_build_gives_a_fresh_world_with_turtle1_at_the_centre():
    spec = WorldSpec("w", obstacles=[Circle(2.0, 2.0, 0.5)], lidar=Lidar(samples=8), background=(1, 2, 3))
    first, second = spec.build(3), spec.build(3)
    assert first is not second
    assert first.obstacles == second.obstacles == (Circle(2.0, 2.0, 0.5),)
    assert first.lidar == Lidar(samples=8) and first.seed == 3
    assert first.background == (1, 2, 3)
    turtle = first.turtles["turtle1"]
    assert (turtle.x, turtle.y, turtle.theta) == pytest.approx((CENTER, CENTER, 0.0))
    first.command_velocity("turtle1", 1.0, 0.0, 0.0)
    first.step()
    first.step()
    assert second.turtles["turtle1"].x == pytest.approx(CENTER)


def test_the_empty_world_is_turtlesims():
    world = resolve_world("empty").build(0)
    assert world.obstacles == () and world.lidar is None and world.background == BACKGROUND


# -- world files --------------------------------------------------------------------------


def test_a_world_file_with_every_field(tmp_path):
    spec = load_world_file(write(tmp_path, "garden.toml", FULL))
    assert spec.name == "garden" and spec.description == "two obstacles"
    assert spec.background == (10, 20, 30)
    assert spec.obstacles == (Circle(3.0, 8.0, 0.5), Box(1.0, 1.0, 2.0, 1.5))
    assert spec.lidar == Lidar(samples=90, range_min=0.1, range_max=4.0, noise_std=0.02, rate=5.0, dropout=0.01)


def test_the_name_defaults_to_the_file_name_and_everything_else_is_optional(tmp_path):
    spec = load_world_file(write(tmp_path, "bare.toml", ""))
    assert spec == WorldSpec("bare")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("nmae = 'x'\n", "bare.toml:1: unknown field 'nmae' (did you mean 'name'?)"),
        (
            "[[circles]]\nx = 1\ny = 1\nr = 1\n\n[[circles]]\nx = 1\ny = 2\nr = -1\n",
            "bare.toml:9: [[circles]] #2: field 'r' must be a positive number, got -1.0",
        ),
        ("[[circles]]\nx = 1\nr = 1\n", "bare.toml:1: [[circles]] #1: field 'y' is required"),
        (
            "[[boxes]]\nx0 = 2\ny0 = 1\nx1 = 1\ny1 = 2\n",
            "bare.toml:4: [[boxes]] #1: field 'x1' must be greater than x0 (2.0), got 1.0",
        ),
        ("[[boxes]]\nx0 = 'a'\n", "bare.toml:2: [[boxes]] #1: field 'x0' must be a finite number, got 'a'"),
        ("background = [1, 2]\n", "bare.toml:1: field 'background' must be [r, g, b] with integers 0..255, got [1, 2]"),
        ("\n[lidar]\nsamples = 0\n", "bare.toml:3: [lidar]: field 'samples' must be a positive integer, got 0"),
        ("[lidar]\nrange_max = 2\nrange_min = 3\n", "bare.toml:3: [lidar]: need 0 <= range_min < range_max"),
        ("[lidar]\nrate = 0\n", "bare.toml:2: [lidar]: rate must be a positive number of Hz, got 0.0"),
        (
            "[lidar]\ndropout = 1\n",
            "bare.toml:2: [lidar]: dropout must be a share of readings from 0 up to (not including) 1, got 1.0",
        ),
        ("[lidar]\nbeams = 3\n", "bare.toml:2: [lidar]: unknown field 'beams'"),
        ("name = \n", "bare.toml:1: invalid TOML"),
    ],
)
def test_bad_world_files_give_one_line_naming_file_line_and_field(tmp_path, text, expected):
    path = write(tmp_path, "bare.toml", text)
    with pytest.raises(WorldError) as info:
        load_world_file(path)
    message = str(info.value)
    assert "\n" not in message
    assert message.startswith(f"{tmp_path}{os.sep}")
    assert message[len(f"{tmp_path}{os.sep}") :].startswith(expected)


def test_a_missing_world_file(tmp_path):
    with pytest.raises(WorldError, match="no such world file"):
        load_world_file(tmp_path / "nope.toml")


def test_a_dict_in_the_file_format_names_its_source_in_errors():
    spec = parse_world({"circles": [{"x": 1, "y": 2, "r": 0.5}]}, name="dicty")
    assert spec == WorldSpec("dicty", obstacles=(Circle(1.0, 2.0, 0.5),))
    with pytest.raises(WorldError, match=r"^world 'dicty': \[\[circles\]\] #1: field 'r'"):
        parse_world({"circles": [{"x": 1, "y": 2, "r": 0}]}, name="dicty")


# -- the bundled course -------------------------------------------------------------------


def test_the_lidar_course_leaves_room_to_roam():
    spec = resolve_world("lidar-course")
    assert spec.name == "lidar-course" and spec.description
    obstacles = spec.obstacles
    assert len(obstacles) >= 5
    assert {type(o) for o in obstacles} == {Circle, Box}
    # turtle1's start is free, with room to turn
    assert min(surface_distance(o, CENTER, CENTER) for o in obstacles) > 1.5
    # at least 1.2 m between obstacles, and between obstacles and walls
    for a, b in itertools.combinations(obstacles, 2):
        assert _gap(a, b) >= 1.2, (a, b)
    for o in obstacles:
        lo, hi = _extent(o)
        assert min(lo[0], lo[1], ARENA_SIZE - hi[0], ARENA_SIZE - hi[1]) >= 1.2, o
    lidar = spec.lidar
    assert lidar.samples in (72, 90, 360) and lidar.range_max == 3.5 and lidar.noise_std == 0.01
    assert lidar.angle_increment * lidar.samples == pytest.approx(2 * math.pi)


def _extent(o) -> tuple[tuple[float, float], tuple[float, float]]:
    if isinstance(o, Circle):
        return (o.cx - o.r, o.cy - o.r), (o.cx + o.r, o.cy + o.r)
    return (o.x0, o.y0), (o.x1, o.y1)


def _gap(a, b) -> float:
    """Surface-to-surface distance, sampled along b's outline (good to a few mm)."""
    if isinstance(b, Circle):
        a, b = b, a
    if isinstance(a, Circle) and isinstance(b, Circle):
        return math.dist((a.cx, a.cy), (b.cx, b.cy)) - a.r - b.r
    points = [(b.x0 + (b.x1 - b.x0) * i / 200, y) for i in range(201) for y in (b.y0, b.y1)]
    points += [(x, b.y0 + (b.y1 - b.y0) * i / 200) for i in range(201) for x in (b.x0, b.x1)]
    return min(surface_distance(a, x, y) for x, y in points)


def test_a_run_in_the_lidar_course_blocks_the_turtle_and_scans(tmp_path):
    node = write(
        tmp_path,
        "straight.py",
        """\
        import rclpy
        from rclpy.node import Node
        from geometry_msgs.msg import Twist
        from sensor_msgs.msg import LaserScan
        from rclpy.qos import qos_profile_sensor_data


        class Straight(Node):
            def __init__(self):
                super().__init__("straight")
                self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
                self.create_subscription(LaserScan, "/turtle1/scan", self.on_scan, qos_profile_sensor_data)
                self.create_timer(0.1, self.drive)

            def drive(self):
                msg = Twist()
                msg.linear.x = 2.0
                self.pub.publish(msg)

            def on_scan(self, msg):
                self.get_logger().info(f"ahead {min(msg.ranges[0], 99.0):.2f}")


        def main():
            rclpy.init()
            rclpy.spin(Straight())
        """,
    )
    spec = ControllerSpec("straight", node, trusted=True)
    result = run([spec], duration=3.0, world=resolve_world("lidar-course").build(0))
    turtle = result.turtles["turtle1"]
    # The box in front starts at x = 8.6: the turtle stops there, not at the wall.
    assert turtle.x == pytest.approx(8.6) and turtle.wall_hits == 0
    messages = [record.msg for record in result.logs]
    assert any(m.startswith("Oh no! I hit an obstacle! (Blocked at [x=8.600000") for m in messages)
    assert any(m.startswith("ahead 3.0") for m in messages)
    assert result.summary().endswith(", wall hits 0, obstacle hits 1: ok")


# -- finding worlds -------------------------------------------------------------------------


PLUGIN = """\
from pathlib import Path

from turtletui.plugins import hookimpl
from turtletui.sim import Circle
from turtletui.worlds import WorldSpec

HERE = Path(__file__).parent


@hookimpl
def turtletui_register_worlds(register):
    register("spec-world", lambda: WorldSpec("whatever", obstacles=[Circle(1, 1, 0.5)]), "a spec")
    register("dict-world", lambda: {"boxes": [{"x0": 1, "y0": 1, "x1": 2, "y1": 2}]}, "a dict")
    register("file-world", lambda: HERE / "garden.toml", "a file")
    register("broken-world", lambda: 1 / 0)
    register("odd-world", lambda: 42)
"""


@pytest.fixture
def plugin(tmp_path) -> Path:
    write(tmp_path, "garden.toml", FULL)
    return write(tmp_path, "worlds_plugin.py", PLUGIN)


def test_plugins_register_worlds_as_specs_dicts_or_files(plugin):
    spec = resolve_world("spec-world", plugins=[plugin])
    assert spec.name == "spec-world" and spec.obstacles == (Circle(1, 1, 0.5),)
    assert resolve_world("dict-world", plugins=[plugin]).obstacles == (Box(1, 1, 2, 2),)
    from_file = resolve_world("file-world", plugins=[plugin])
    assert from_file.name == "file-world" and from_file.lidar.samples == 90
    assert set(world_names(plugins=[plugin])) >= {"empty", "lidar-course", "spec-world", "file-world"}


def test_a_world_factory_that_fails_or_returns_junk_is_a_one_line_error(plugin):
    with pytest.raises(WorldError, match=r"^world 'broken-world' \(plugin .*\): its factory failed: ZeroDivisionError"):
        resolve_world("broken-world", plugins=[plugin])
    with pytest.raises(WorldError, match=r"returned int; expected a WorldSpec"):
        resolve_world("odd-world", plugins=[plugin])


def test_a_path_to_a_toml_file_is_a_world(tmp_path):
    path = write(tmp_path, "garden.toml", FULL)
    assert resolve_world(str(path)).name == "garden"
    assert resolve_world(path).name == "garden"


def test_an_unknown_world_suggests_and_lists_the_known_ones():
    with pytest.raises(WorldError) as info:
        resolve_world("lidar-corse")
    assert str(info.value) == (
        "unknown world 'lidar-corse' (did you mean 'lidar-course'?); known: empty, lidar-course"
    )


def test_world_names_include_the_built_ins():
    assert world_names()[:2] == ["empty", "lidar-course"]


# -- turtletui run --world ----------------------------------------------------------------


def cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(PACKAGE_ROOT), env.get("PYTHONPATH")) if p)
    return subprocess.run(
        [sys.executable, "-m", "turtletui", *args],
        cwd=cwd,
        env=env,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=60,
    )


def test_run_world_unknown_is_one_line_and_exit_2(tmp_path):
    proc = cli("run", "--headless", "--world", "moon", "--duration", "0.1", cwd=tmp_path)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.splitlines() == [
        "turtletui: error: --world: unknown world 'moon'; known: empty, lidar-course"
    ]


def test_run_headless_in_a_world_file(tmp_path):
    write(tmp_path, "wall.toml", "[[boxes]]\nx0 = 6.0\ny0 = 0.0\nx1 = 6.5\ny1 = 11.0\n")
    proc = cli(
        "run", "part6_wall_avoider", "--headless", "--in-process", "--world", "wall.toml",
        "--duration", "3", cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    assert "Oh no! I hit an obstacle! (Blocked at [x=6.000000" in proc.stderr


LESSON = """\
+++
id = "roam"
title = "Roam"
world = "{world}"
+++
# Roam
"""


@pytest.fixture
def app_launches(monkeypatch) -> list:
    """``turtletui run`` in the app mode, as from a terminal, with the app's
    run() recorded instead of started."""

    import turtletui.cli.screen as screen
    from turtletui.tui.app import TurtleApp

    launched: list = []
    monkeypatch.setattr(TurtleApp, "run", lambda self: launched.append(self))
    monkeypatch.setattr(screen, "has_screen", lambda: True)
    return launched


def invoke(*args: str):
    from typer.testing import CliRunner

    from turtletui.cli import app

    return CliRunner().invoke(app, list(args))


def test_the_app_runs_in_the_lessons_world_unless_world_says_otherwise(tmp_path, app_launches):
    lesson = write(tmp_path, "roam.md", LESSON.format(world="lidar-course"))
    node = write(tmp_path, "idle.py", "def main():\n    pass\n")
    result = invoke("run", str(node), "--lesson", str(lesson))
    assert result.exit_code == 0, result.output
    assert app_launches[-1]._world.name == "lidar-course"
    result = invoke("run", str(node), "--lesson", str(lesson), "--world", "empty")
    assert result.exit_code == 0, result.output
    assert app_launches[-1]._world.obstacles == ()


def test_a_lessons_unknown_world_is_a_clean_error(tmp_path, app_launches):
    lesson = write(tmp_path, "roam.md", LESSON.format(world="moon"))
    node = write(tmp_path, "idle.py", "def main():\n    pass\n")
    result = invoke("run", str(node), "--lesson", str(lesson))
    assert result.exit_code == 2 and not app_launches
    assert "lesson roam: world: unknown world 'moon'" in result.output
