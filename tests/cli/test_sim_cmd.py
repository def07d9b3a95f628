"""``turtletui sim``: turtlesim alone, headless (real time, its log in ROS's
console format) and in the app (driven with the keys and the ros2 command line)."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from support.pilot import SIZE, pilot_test, type_command, wait_for
from support.web_driver import run_app_and_quit
from textual.widgets import Input

import turtletui
from turtletui.graph.core import DISCOVERY_NS
from turtletui.runtime.turtlesim_args import parse_turtlesim_args
from turtletui.tui.app import TurtleApp

REPO = Path(turtletui.__file__).resolve().parents[1]
LOG_LINE = re.compile(r"\[(INFO|WARN|ERROR)\] \[\d{10}\.\d{9}\] \[([a-z_]+)\]: (.*)\Z")


_STARTED: list[subprocess.Popen[str]] = []


@pytest.fixture(autouse=True)
def _no_process_outlives_its_test():
    """A test that fails waiting for its process does not leave it running."""
    yield
    while _STARTED:
        proc = _STARTED.pop()
        if proc.poll() is None:
            proc.kill()
            proc.communicate()


def sim_process(*args: str, cwd: Path, **popen) -> subprocess.Popen[str]:
    """``python -m turtletui sim ARGS`` with no terminal."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "sim", *args],
        cwd=cwd,
        env=dict(os.environ, PYTHONPATH=str(REPO)),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        **popen,
    )
    _STARTED.append(proc)
    return proc


def _ignore_sigint() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def test_headless_keeps_running_without_a_duration(tmp_path: Path) -> None:
    proc = sim_process("--headless", cwd=tmp_path)
    try:
        proc.stderr.readline()
        time.sleep(1.0)
        assert proc.poll() is None
    finally:
        proc.kill()
        proc.communicate()


def test_headless_prints_turtlesims_log_with_its_parameters_and_name(tmp_path: Path) -> None:
    proc = sim_process(
        "--headless", "--duration", "0.5",
        "--ros-args", "-p", "background_r:=0", "-p", "holonomic:=true", "-r", "__node:=my_sim",
        cwd=tmp_path,
    )
    out, err = proc.communicate(timeout=30)  # as ROS 2: the log on stderr
    assert proc.returncode == 0 and out == ""
    lines = [LOG_LINE.match(line).groups() for line in err.splitlines()]
    assert lines == [
        ("INFO", "my_sim", "Starting turtlesim with node name /my_sim"),
        ("INFO", "my_sim", "Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]"),
    ]
    # Real time: ROS stamps from the wall clock, not the lockstep epoch.
    stamp = float(err.split("] [")[1].split("]")[0])
    assert abs(stamp - time.time()) < 60


@pytest.mark.parametrize("inherited", ["default", "ignored"])
def test_headless_runs_until_ctrl_c_and_ends_cleanly(tmp_path: Path, inherited: str) -> None:
    # started with SIGINT ignored (a script's background job): Ctrl-C still ends
    # it, as turtlesim_node's own handler does
    ignore = {"preexec_fn": _ignore_sigint} if inherited == "ignored" else {}
    proc = sim_process("--headless", cwd=tmp_path, **ignore)
    first = proc.stderr.readline()  # turtlesim is up
    assert "Starting turtlesim with node name /turtlesim" in first
    proc.send_signal(signal.SIGINT)  # at once: Ctrl-C right as it starts ends it cleanly too
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 0
    assert "Traceback" not in err and out == ""
    assert all(LOG_LINE.match(line) for line in (first + err).splitlines())  # whole log lines only


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["--headless", "--ros-args", "-p", "background_r:=256"], "background_r:=256"),
        (["--headless", "--ros-args", "-p", "holonomic:=yes please"], "holonomic"),
        (["--headless", "--ros-args", "-r", "__node:=bad-name"], "'bad-name' is not a valid node name"),
        (["--headless", "--ros-args", "-r", "/turtle1/pose:=/p"], "-r /turtle1/pose:=/p"),
        (["--headless", "--duration", "-1"], "--duration must be a positive number"),
        (["--headless", "--world", "no-such-world"], "no-such-world"),
        (["--duration", "5"], "--duration is for --headless runs"),
        (["--pixels", "nope"], "--pixels: expected one of auto, half, braille, graphics"),
        (["--headless", "--record", "nowhere/run.mcap"], "nowhere/run.mcap: cannot write the recording"),
        # a folder only the kernel writes: refused before the run, also for root
        (["--headless", "--record", "/proc/run.jsonl"], "/proc/run.jsonl: cannot write the recording"),
        (["--headless", "--foxglove", "nowhere:99999"], "--foxglove 'nowhere:99999': give HOST:PORT"),
        (["--record", "nowhere/run.mcap"], "nowhere/run.mcap: cannot write the recording"),
        ([], "no terminal to draw the app in; run headless instead: turtletui sim --headless"),
    ],
)
def test_bad_input_is_a_one_line_error(tmp_path: Path, args: list[str], expected: str) -> None:
    proc = sim_process(*args, cwd=tmp_path)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == 2, err
    assert out == "" and "Traceback" not in err
    [line] = err.splitlines()
    assert line.startswith("turtletui: error: ") and expected in line


@pilot_test
async def test_the_app_runs_turtlesim_alone_driven_by_keys_and_ros2_commands() -> None:
    args = parse_turtlesim_args(["-p", "holonomic:=true", "-r", "__node:=my_sim", "-p", "background_r:=0"])
    app = TurtleApp([], turtlesim=args)
    async with app.run_test(size=SIZE) as pilot:
        sim = app.session.sim
        assert app.session.slots == [] and "no controller" in app._status()
        assert sim.world.background == (0, 86, 255)
        turtle = sim.world.turtles["turtle1"]
        start = turtle.x
        # as for turtle_teleop_key on a robot, a key pressed before turtlesim
        # has discovered teleop would be lost
        await wait_for(pilot, lambda: sim.graph.now_ns >= DISCOVERY_NS)
        await pilot.press("up")  # turtle_teleop_key: one Twist of linear.x 2.0
        await wait_for(pilot, lambda: turtle.x > start + 0.5)
        # holonomic:=true: a sideways command moves the turtle sideways.
        y = turtle.y
        await pilot.press("colon")
        command = app.focused
        assert isinstance(command, Input)
        # Typed key by key, a long command takes Pilot seconds: the first is pasted.
        command.value = 'ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist "{linear: {y: 1.5}}"'
        await pilot.press("enter")
        await wait_for(pilot, lambda: turtle.y > y + 0.3)
        await type_command(pilot, "ros2 param set /my_sim background_g 0")
        await wait_for(pilot, lambda: sim.world.background == (0, 0, 255))


def poses_and_log(path: Path) -> tuple[int, list[str]]:
    """Poses of turtle1 and /rosout lines in an MCAP file, read with mcap_ros2."""
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    poses, log = 0, []
    with open(path, "rb") as stream:
        for _, channel, _, msg in make_reader(stream, decoder_factories=[DecoderFactory()]).iter_decoded_messages():
            if channel.topic == "/turtle1/pose":
                poses += 1
            elif channel.topic == "/rosout":
                log.append(msg.msg)
    return poses, log


def test_headless_records_as_run_does(tmp_path: Path) -> None:
    proc = sim_process("--headless", "--duration", "0.5", "--record", "run.mcap", cwd=tmp_path)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == 0 and out == "" and "Traceback" not in err
    poses, log = poses_and_log(tmp_path / "run.mcap")
    assert poses > 0 and log[0] == "Starting turtlesim with node name /turtlesim"  # the start lines too
    proc = sim_process("--headless", "--duration", "0.5", "--record", "bag/", cwd=tmp_path)
    assert proc.communicate(timeout=30)[0] == "" and proc.returncode == 0
    assert sorted(p.name for p in (tmp_path / "bag").iterdir()) == ["bag_0.mcap", "metadata.yaml"]


def test_ctrl_c_keeps_the_recording(tmp_path: Path) -> None:
    proc = sim_process("--headless", "--record", "run.jsonl", cwd=tmp_path)
    assert "Starting turtlesim" in proc.stderr.readline()
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=10)
    assert proc.returncode == 0 and out == "" and "Traceback" not in err
    events = (tmp_path / "run.jsonl").read_text().splitlines()
    assert "Starting turtlesim with node name /turtlesim" in events[0]


def test_the_app_records_too(tmp_path: Path) -> None:
    run_app_and_quit(["sim", "--record", "run.mcap"], tmp_path)
    assert "Starting turtlesim with node name /turtlesim" in poses_and_log(tmp_path / "run.mcap")[1]


def test_headless_serves_foxglove(tmp_path: Path) -> None:
    pytest.importorskip("foxglove", reason="the live view needs turtletui[foxglove]")
    proc = sim_process("--headless", "--foxglove", "127.0.0.1:0", "--duration", "30", cwd=tmp_path)
    try:
        for line in proc.stderr:
            if "[foxglove_bridge]: Foxglove: open a connection to ws://127.0.0.1:" in line:
                break
        else:
            raise AssertionError("no Foxglove address line")
    finally:
        proc.send_signal(signal.SIGINT)
        proc.communicate(timeout=10)
    assert proc.returncode == 0
