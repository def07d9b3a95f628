"""turtletui on a real ROS 2 graph, checked from real rclpy processes.

Each test starts the bridge (its twin runs in the ROS 2 python) and looks at
it from other ROS 2 processes, as a student would from other terminals.
Deadlines are generous: these run on a busy 2-core machine.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from support.real_ros import run_ros_script

from turtletui.bridge.run import attach
from turtletui.graph.introspection import snapshot
from turtletui.runtime.simulation import Simulation

pytestmark = pytest.mark.realros

PART6 = Path(__file__).resolve().parents[2] / "plugins" / "reference" / "turtle_controller.py"


class Running:
    """A real-time simulation on the ROS 2 graph, stepped in a thread of its own."""

    def __init__(self, ros_python: str) -> None:
        self.logs: list = []
        self.sim = Simulation(realtime=True, log_sinks=[self.logs.append])
        self.bridge = attach(self.sim, ros_python, earlier_logs=self.logs)
        self.lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.is_set():
            with self.lock:
                self.sim.run_until(self.sim.graph.now_ns + 16_000_000)

    def wait_for(self, check, seconds: float = 30.0) -> bool:
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            with self.lock:
                if check():
                    return True
            time.sleep(0.05)
        with self.lock:
            return check()

    def close(self) -> None:
        self._stop.set()
        self._thread.join(10)
        self.bridge.close()


@pytest.fixture
def running(ros_python: str, ros_domain: str):
    sim = Running(ros_python)
    try:
        yield sim
    finally:
        sim.close()


def test_another_process_sees_and_uses_every_part_of_turtlesim(running: Running, ros_python: str) -> None:
    done = run_ros_script(ros_python, "ros_probe.py", "90", "0")
    assert done.returncode == 0, done.stderr[-3000:]
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert report["found"] and "turtlesim" in report["nodes"]
    topics = report["topics"]
    assert topics["/turtle1/pose"] in (["turtlesim/msg/Pose"], ["turtlesim_msgs/msg/Pose"])
    assert topics["/turtle1/cmd_vel"] == ["geometry_msgs/msg/Twist"]
    assert "/turtle1/color_sensor" in topics and "/rosout" in topics and "/parameter_events" in topics
    for service in ("/clear", "/reset", "/spawn", "/kill", "/turtle1/set_pen", "/turtle1/teleport_absolute",
                    "/turtle1/teleport_relative", "/turtlesim/set_parameters", "/turtlesim/get_parameters"):
        assert service in report["services"]
    assert report["pose_reliable"] == [True]  # one publisher, reliable (its depth is not on the graph)
    assert 50.0 < report["pose_rate"] < 75.0  # 62.5 Hz; wide: the machine may be busy
    assert report["spawned"] == "turtle2"
    assert report["turtle2_pose"] == pytest.approx([2.0, 3.0, 0.5], abs=1e-5)
    assert report["spawn_again"] == ""  # turtlesim refuses a name in use with an empty name
    ok, reason = report["set_300"]
    assert not ok and "255" in reason
    assert report["set_10"] == [True, ""]
    assert report["get"] == [10, False]
    assert report["turtle2_after_teleport"][:2] == pytest.approx([4.0, 4.0], abs=1e-4)
    assert report["action_server"] and report["goal_accepted"]
    assert report["goal_status"] == 4  # GoalStatus.STATUS_SUCCEEDED
    assert report["feedback_count"] > 0
    assert report["turtle2_theta"] == pytest.approx(1.0, abs=0.03)
    assert report["turtle2_publishers_after_kill"] == 0
    texts = [entry[2] for entry in report["rosout"]]
    assert "Spawning turtle [turtle2] at x=[2.000000], y=[3.000000], theta=[0.500000]" in texts
    assert "A turtle named [turtle2] already exists" in texts
    assert "Clearing turtlesim." in texts
    # what the other process did, the simulation did
    assert running.sim.world.background[0] == 10
    assert "turtle2" not in running.sim.world.turtles


def test_turtlesim_msgs_types_for_kilted_and_later(ros_python: str, ros_domain: str, monkeypatch) -> None:
    monkeypatch.setenv("TURTLETUI_TURTLESIM_PACKAGE", "turtlesim_msgs")
    running = Running(ros_python)
    try:
        assert running.bridge.info["turtlesim_package"] == "turtlesim_msgs"
        done = run_ros_script(ros_python, "ros_probe.py", "90", "0")
    finally:
        running.close()
    assert done.returncode == 0, done.stderr[-3000:]
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert report["topics"]["/turtle1/pose"] == ["turtlesim_msgs/msg/Pose"]
    assert report["spawned"] == "turtle2" and report["goal_status"] == 4


def test_nodes_of_other_processes_are_in_the_simulations_graph(running: Running, ros_python: str) -> None:
    probe = subprocess.Popen(
        [ros_python, str(Path(__file__).with_name("ros_probe.py")), "90", "30"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        assert running.wait_for(lambda: "/probe" in [n.name for n in snapshot(running.sim.graph).nodes], 60)
        assert running.wait_for(lambda: running.sim.graph.has_service("/probe_trigger"), 30)
        with running.lock:
            node = snapshot(running.sim.graph).node("/probe")
        assert ("/probe_trigger", "std_srvs/srv/Trigger") in node.service_servers
        # a call from turtletui's side (the app's ros2 service call) reaches the other process
        from turtletui.interfaces.std_srvs import Trigger

        answers: list = []
        with running.lock:
            running.sim.graph.call("/probe_trigger", Trigger.Request(), answers.append, "test")
        assert running.wait_for(lambda: bool(answers), 30)
        assert answers[0].success and answers[0].message == "probe here"
        # its parameters, as ros2 param shows them
        assert running.wait_for(lambda: ("use_sim_time", False) in snapshot(running.sim.graph).node("/probe").parameters)
        from turtletui.ros2cli import Ros2Cli

        with running.lock:
            shown = Ros2Cli(running.sim).run("ros2 param get /probe use_sim_time").lines
        assert shown == ["Boolean value is: False"]
        # its log lines arrive from /rosout
        assert running.wait_for(lambda: any(r.node == "probe" and r.msg == "probe done" for r in running.logs), 90)
    finally:
        probe.send_signal(signal.SIGINT)  # it leaves the graph (a killed one goes only when its lease ends)
        try:
            probe.wait(20)
        except subprocess.TimeoutExpired:
            probe.kill()
            probe.wait()
    assert running.wait_for(lambda: "/probe" not in [n.name for n in snapshot(running.sim.graph).nodes], 60)


def test_run_ros_drives_turtlesim_with_the_unchanged_course_controller(ros_python: str, ros_domain: str) -> None:
    run = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "run", str(PART6), "--headless", "--ros",
         "--ros-python", ros_python, "--duration", "120"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        done = run_ros_script(ros_python, "ros_probe.py", "60", "0", "turtle_controller", "--driven")
        time.sleep(3.0)  # a few more seconds of driving, then Ctrl-C
    finally:
        run.send_signal(signal.SIGINT)
        out, err = run.communicate(timeout=120)
    assert run.returncode == 130, err[-3000:]
    summary = out.strip().splitlines()[-1]
    assert summary.endswith("wall hits 0: interrupted, ok"), summary
    assert float(summary.split("distance ")[1].split(" m")[0]) > 10.0
    assert "Warning: Approaching wall detected! Changing direction." in err  # the controller's own log
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert report["spawned"] == "turtle2" and 50.0 < report["pose_rate"] < 75.0
    assert "turtle_controller" in report["nodes"]


def test_ctrl_c_ends_the_run_and_its_ros_processes(ros_python: str, ros_domain: str, tmp_path: Path) -> None:
    marker = tmp_path / "pid"
    node = tmp_path / "forever.py"
    node.write_text(
        "import os, rclpy\n"
        f"open({str(marker)!r}, 'w').write(str(os.getpid()))\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    rclpy.spin(rclpy.create_node('forever'))\n"
    )
    run = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "run", str(node), "--headless", "--ros", "--ros-python", ros_python,
         "--duration", "300"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    end = time.monotonic() + 60
    while not marker.exists() and time.monotonic() < end:
        time.sleep(0.1)
    assert marker.exists()
    time.sleep(1.0)
    run.send_signal(signal.SIGINT)
    out, err = run.communicate(timeout=60)
    assert run.returncode == 130, err
    assert "interrupted" in out.strip().splitlines()[-1]
    pid = int(marker.read_text())
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


def test_a_crashing_file_fails_the_run(ros_python: str, ros_domain: str, tmp_path: Path) -> None:
    node = tmp_path / "broken.py"
    node.write_text("import rclpy\ndef main():\n    rclpy.init()\n    raise RuntimeError('boom')\n")
    done = subprocess.run(
        [sys.executable, "-m", "turtletui", "run", str(node), "--headless", "--ros", "--ros-python", ros_python,
         "--duration", "60"],
        capture_output=True, text=True, timeout=120,
    )
    assert done.returncode == 1
    assert "RuntimeError: boom" in done.stderr
    assert "broken.py exited" in done.stderr
    assert "run_file.py" not in done.stderr  # the traceback shows the student's own lines


def test_the_apps_session_shows_the_real_graph_and_its_ros2_command_line_works(
    ros_python: str, ros_domain: str
) -> None:
    from turtletui.bridge.run import connect
    from turtletui.ros2cli import Ros2Cli
    from turtletui.runtime.loader import ControllerSpec
    from turtletui.tui.session import LiveSession

    session = LiveSession([ControllerSpec(name="part6", path=PART6)], ros=connect(ros_python), start=False)
    try:
        session.start_controllers()
        end = time.monotonic() + 90
        moved = False
        while time.monotonic() < end and not moved:
            session.advance(time.monotonic())
            time.sleep(0.016)
            with session.lock:
                moved = (
                    session.sim.world.turtles["turtle1"].distance > 2.0
                    and any(r.node == "turtle_controller" for r in session.logs)
                    and "/turtle_controller" in [n.fqn for n in session.sim.graph.nodes]
                )
        assert moved, "the ROS 2 controller process did not drive the turtle"
        # ROS's own plumbing (parameter services, /rosout) stays out of the views, as before
        assert not session.sim.graph.has_service("/turtle_controller/describe_parameters")
        with session.lock:
            cli = Ros2Cli(session.sim)
            nodes = cli.run("ros2 node list").lines
            info = cli.run("ros2 node info /turtle_controller").lines
            topic = cli.run("ros2 topic info /turtle1/cmd_vel").lines
        assert "/turtle_controller" in nodes and "/turtlesim" in nodes
        assert any("/turtle1/pose: turtlesim/msg/Pose" in line for line in info)
        assert "Publisher count: 2" in topic  # the controller process, and the app's teleop
        assert session.slots[0].status == "running"
    finally:
        session.close()


def test_ros2_topic_echo_and_pub_in_the_app_reach_other_processes(running: Running, ros_python: str) -> None:
    from turtletui.ros2cli import Ros2Cli

    chatter = subprocess.Popen(
        [ros_python, str(Path(__file__).with_name("ros_chatter.py")), "60"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        assert running.wait_for(lambda: "/chatter" in running.sim.graph.topics, 60)
        with running.lock:
            cli = Ros2Cli(running.sim)
            assert "/chatter" in cli.run("ros2 topic list").lines
            echo = cli.run("ros2 topic echo /chatter --once").stream
            pub = cli.run('ros2 topic pub -r 5 /from_app std_msgs/msg/String "{data: hi from turtletui}"').stream
        assert echo is not None and pub is not None
        lines: list[str] = []

        def echoed() -> bool:
            lines.extend(echo.poll())
            return echo.done
        assert running.wait_for(echoed, 30)
        assert "data: hello from ROS 2" in lines
        end = time.monotonic() + 30
        received = ""
        while "got hi from turtletui" not in received and time.monotonic() < end:
            received += chatter.stdout.readline()
        assert "got hi from turtletui" in received
        with running.lock:
            pub.close()
    finally:
        chatter.kill()
        chatter.wait()


def test_a_run_whose_ros_side_dies_fails_with_one_line(ros_python: str, ros_domain: str) -> None:
    run = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "run", str(PART6), "--headless", "--ros", "--ros-python", ros_python,
         "--duration", "120"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        twin = None
        end = time.monotonic() + 60
        while twin is None and time.monotonic() < end:
            for entry in os.listdir("/proc"):
                try:
                    with open(f"/proc/{entry}/cmdline", "rb") as f:
                        command = f.read()
                except OSError:
                    continue
                if b"ros_node.py" in command and entry.isdigit():
                    with open(f"/proc/{entry}/stat", "rb") as f:
                        parent = int(f.read().rpartition(b")")[2].split()[1])
                    if parent == run.pid:
                        twin = int(entry)
            time.sleep(0.2)
        assert twin is not None
        time.sleep(2.0)
        os.kill(twin, signal.SIGKILL)
        out, err = run.communicate(timeout=60)
    finally:
        if run.poll() is None:
            run.kill()
    assert run.returncode == 1
    assert "the ROS 2 side (the bridge's twin) ended" in err
    assert "ROS 2 bridge: the ROS 2 side ended" in err


def test_ros2_action_send_goal_in_the_app_reaches_another_processes_server(running: Running, ros_python: str) -> None:
    from turtletui.ros2cli import Ros2Cli

    server = subprocess.Popen(
        [ros_python, str(Path(__file__).with_name("ros_action_server.py")), "60"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        assert running.wait_for(lambda: running.sim.graph.has_action_server("/other/rotate"), 60)
        with running.lock:
            goal = Ros2Cli(running.sim).run(
                'ros2 action send_goal /other/rotate turtlesim/action/RotateAbsolute "{theta: 1.0}" --feedback'
            ).stream
        assert goal is not None
        lines: list[str] = []

        def finished() -> bool:
            lines.extend(goal.poll())
            return goal.done
        assert running.wait_for(finished, 60), lines
        text = "\n".join(lines)
        assert "remaining: 0.75" in text and "remaining: 0.25" in text
        assert "delta: 0.5" in text and "SUCCEEDED" in text
    finally:
        server.kill()
        server.wait()


def test_every_form_of_controller_file_runs_as_a_ros_process(ros_python: str, ros_domain: str, tmp_path: Path) -> None:
    forms = {
        "with_main.py": "import rclpy\ndef main():\n    rclpy.init()\n    rclpy.spin(rclpy.create_node('with_main'))\n",
        "guarded.py": (
            "import rclpy\nif __name__ == '__main__':\n    rclpy.init()\n"
            "    rclpy.spin(rclpy.create_node('guarded'))\n"
        ),
        "node_class.py": (
            "from rclpy.node import Node\nclass Mine(Node):\n    def __init__(self):\n"
            "        super().__init__('node_class')\n"
        ),
    }
    for name, text in forms.items():
        (tmp_path / name).write_text(text)
    run = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "run", *(str(tmp_path / n) for n in forms), "--headless", "--ros",
         "--ros-python", ros_python, "--duration", "40"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        done = run_ros_script(ros_python, "ros_probe.py", "60", "0", "with_main", "guarded", "node_class")
    finally:
        run.send_signal(signal.SIGINT)
        run.communicate(timeout=60)
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert {"with_main", "guarded", "node_class"} <= set(report["nodes"])


def test_sim_ros_headless_is_turtlesim_for_the_unchanged_course_controller(ros_python: str, ros_domain: str) -> None:
    """The issue's check: `turtletui sim --ros --headless`, the course's Part 6
    controller run with the real rclpy (python3 turtle_controller.py), and a
    third process that finds /turtlesim, its poses at about 62.5 Hz, and spawns."""
    sim = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "sim", "--ros", "--headless", "--ros-python", ros_python,
         "--ros-args", "-p", "background_g:=0", "--log-level", "info"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    controller = subprocess.Popen([ros_python, str(PART6)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        done = run_ros_script(ros_python, "ros_probe.py", "60", "0", "turtle_controller", "--driven")
    finally:
        controller.send_signal(signal.SIGINT)
        controller.communicate(timeout=30)
        sim.send_signal(signal.SIGINT)  # how turtlesim_node ends
        out, err = sim.communicate(timeout=60)
    assert sim.returncode == 0, err
    assert done.returncode == 0, done.stderr[-3000:]
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert "turtlesim" in report["nodes"] and "turtle_controller" in report["nodes"], (report, err[-2000:])
    assert 50.0 < report["pose_rate"] < 75.0, report
    # driven all the while the probe measured (3 s once it moved), at 1 m/s turning and 5 m/s straight
    assert report["turtle1_travel"] > 2.0, (report, err[-2000:])
    assert report["spawned"] == "turtle2"
    assert report["get"][0] == 10  # the probe set background_r; background_g came from --ros-args
    lines = err.splitlines()  # as turtlesim_node's, the log is on stderr
    assert lines[0].endswith("[turtlesim]: Starting turtlesim with node name /turtlesim")
    assert any("Spawning turtle [turtle2] at x=[2.000000], y=[3.000000], theta=[0.500000]" in line for line in lines)
    assert not any("hit the wall" in line for line in lines), [line for line in lines if "wall" in line]
    assert not any("[turtle_controller]" in line for line in lines)  # its lines are its own to print
