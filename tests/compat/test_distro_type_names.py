"""The type names a run shows follow its distro: turtlesim/... up to Jazzy,
turtlesim_msgs/... from Kilted on (graph queries, reprs, the ros2 command line,
recordings), under both hosts."""

from __future__ import annotations

import pytest
from support.hosts import node_logs

from turtletui.compat.distro import distro_of_ros, package_renames, ros_type_name
from turtletui.ros2cli import Ros2Cli
from turtletui.runtime.simulation import Simulation

PACKAGE = {"humble": "turtlesim", "jazzy": "turtlesim", "kilted": "turtlesim_msgs", "lyrical": "turtlesim_msgs"}

PROBE = """
    import rclpy
    from rclpy.action import ActionServer, get_action_names_and_types
    from rclpy.node import Node
    from {package}.action import RotateAbsolute
    from {package}.msg import Pose
    from {package}.srv import Spawn


    def main():
        rclpy.init()
        node = Node("probe")
        log = node.get_logger().info
        node.create_publisher(Pose, "probe_pose", 10)
        node.create_subscription(Pose, "/turtle1/pose", lambda msg: None, 10)
        node.create_service(Spawn, "probe_spawn", lambda request, response: response)
        ActionServer(node, RotateAbsolute, "probe_rotate", lambda goal: RotateAbsolute.Result())
        rclpy.spin_once(node, timeout_sec=0.5)
        log(str(dict(node.get_topic_names_and_types())))
        log(str(dict(node.get_service_names_and_types())))
        log(str(dict(node.get_service_names_and_types_by_node("turtlesim", "/"))))
        log(str([i.topic_type for i in node.get_publishers_info_by_topic("/turtle1/pose")]))
        log(str(dict(get_action_names_and_types(node))))
        log(repr(Pose(x=1.0)))
        log(repr(Spawn.Request(name="t2")))
        rclpy.shutdown()
"""


@pytest.mark.parametrize("distro", ["jazzy", "kilted", "lyrical"])
def test_a_node_sees_the_names_its_distro_has(controller_host, distro):
    package = PACKAGE[distro]
    result = controller_host.run(PROBE.format(package=package), distro=distro)
    assert result.ok, result.crashes
    topics, services, by_node, infos, actions, pose, request = (eval(line) if i < 5 else line  # noqa: S307
                                                                for i, line in enumerate(node_logs(result, "probe")))
    assert topics["/probe_pose"] == [f"{package}/msg/Pose"]
    assert topics["/turtle1/pose"] == [f"{package}/msg/Pose"]
    assert topics["/turtle1/color_sensor"] == [f"{package}/msg/Color"]
    assert topics["/turtle1/cmd_vel"] == ["geometry_msgs/msg/Twist"]  # other packages keep their names
    assert services["/probe_spawn"] == services["/spawn"] == [f"{package}/srv/Spawn"]
    assert by_node["/spawn"] == [f"{package}/srv/Spawn"] and by_node["/kill"] == [f"{package}/srv/Kill"]
    assert infos == [f"{package}/msg/Pose"]
    assert actions["/probe_rotate"] == actions["/turtle1/rotate_absolute"] == [f"{package}/action/RotateAbsolute"]
    assert pose == f"{package}.msg.Pose(x=1.0, y=0.0, theta=0.0, linear_velocity=0.0, angular_velocity=0.0)"
    assert request == f"{package}.srv.Spawn_Request(x=0.0, y=0.0, theta=0.0, name='t2')"


def test_one_mapping_names_every_distros_types():
    assert package_renames("jazzy") == {} and package_renames("kilted") == {"turtlesim": "turtlesim_msgs"}
    assert ros_type_name("turtlesim/srv/Spawn", "lyrical") == "turtlesim_msgs/srv/Spawn"
    assert ros_type_name("turtlesim/srv/Spawn", "humble") == "turtlesim/srv/Spawn"
    assert ros_type_name("std_srvs/srv/Empty", "kilted") == "std_srvs/srv/Empty"
    # on a real graph: its own distro, else the newest with its package
    assert distro_of_ros("kilted", "turtlesim_msgs") == "kilted"
    assert distro_of_ros("humble", "turtlesim") == "humble"
    assert distro_of_ros("rolling", "turtlesim_msgs") == "lyrical"
    assert distro_of_ros("", "turtlesim") == "jazzy"


def _cli(distro: str) -> Ros2Cli:
    sim = Simulation(distro=distro)
    sim.run_until(100_000_000)
    return Ros2Cli(sim)


@pytest.mark.parametrize("distro", ["humble", "jazzy", "kilted", "lyrical"])
def test_the_ros2_command_line_names_types_as_the_distro(distro):
    package, other = PACKAGE[distro], "turtlesim" if PACKAGE[distro] == "turtlesim_msgs" else "turtlesim_msgs"
    cli = _cli(distro)

    def out(line: str) -> list[str]:
        result = cli.run(line)
        assert not result.error, result.lines
        return result.lines

    assert f"/turtle1/pose [{package}/msg/Pose]" in out("ros2 topic list -t")
    assert out("ros2 topic type /turtle1/pose") == [f"{package}/msg/Pose"]
    assert out("ros2 topic info /turtle1/color_sensor")[0] == f"Type: {package}/msg/Color"
    assert out("ros2 service type /spawn") == [f"{package}/srv/Spawn"]
    assert f"/kill [{package}/srv/Kill]" in out("ros2 service list -t")
    assert out(f"ros2 service find {package}/srv/Spawn") == ["/spawn"]
    assert out(f"ros2 topic find {package}/msg/Pose") == ["/turtle1/pose"]
    assert f"/turtle1/rotate_absolute [{package}/action/RotateAbsolute]" in out("ros2 action list -t")
    listed = out("ros2 interface list")
    assert f"    {package}/msg/Pose" in listed and not any(other + "/" in line for line in listed)
    assert package in out("ros2 interface packages") and other not in out("ros2 interface packages")
    assert out(f"ros2 interface package {package}")[0] == f"{package}/action/RotateAbsolute"
    assert out(f"ros2 interface show {package}/srv/Kill") == ["string name", "---"]
    call = out(f"ros2 service call /spawn {package}/srv/Spawn '{{x: 2.0, y: 3.0, name: t2}}'")
    assert call[0] == f"requester: making request: {package}.srv.Spawn_Request(x=2.0, y=3.0, theta=0.0, name='t2')"
    # the package the distro lacks fails as ros2cli fails when it cannot import it
    reason = "turtlesim's types are in " + (
        "'turtlesim_msgs' from Kilted on" if package == "turtlesim_msgs" else "'turtlesim' up to Jazzy")
    for line, sentence in [
        (f"ros2 service call /spawn {other}/srv/Spawn '{{x: 2.0}}'", "ros2 service call: The passed service type is invalid"),
        (f"ros2 topic echo /turtle1/pose {other}/msg/Pose", "ros2 topic echo: The passed message type is invalid"),
        (f"ros2 topic pub /turtle1/pose {other}/msg/Pose", "ros2 topic pub: The passed message type is invalid"),
        (f"ros2 action send_goal /turtle1/rotate_absolute {other}/action/RotateAbsolute '{{theta: 1.0}}'",
         "ros2 action send_goal: The passed action type is invalid"),
    ]:
        result = cli.run(line)
        assert result.error and result.lines == [f"{sentence} ({reason}; this run is --distro {distro}, use --distro "
                                                 f"{'jazzy or older' if other == 'turtlesim' else 'kilted or newer'}"
                                                 f" for '{other}')"]
    shown = cli.run(f"ros2 interface show {other}/msg/Pose")
    assert shown.error and shown.lines[0].startswith(f"ros2 interface show: unknown interface type '{other}/msg/Pose'")
    assert cli.run(f"ros2 interface package {other}").error


def test_a_recording_names_types_as_the_distro(tmp_path):
    from mcap.reader import make_reader

    from turtletui.recording.recorder import McapRecorder

    for distro in ("jazzy", "kilted"):
        sim = Simulation(distro=distro)
        recorder = McapRecorder(sim, f"{tmp_path}/{distro}/")
        cli = Ros2Cli(sim)
        sim.run_until(200_000_000)
        package = PACKAGE[distro]
        assert not cli.run(f"ros2 service call /spawn {package}/srv/Spawn '{{x: 2.0, y: 3.0}}'").error
        sim.run_until(400_000_000)
        recorder.close()
        with open(tmp_path / distro / f"{distro}_0.mcap", "rb") as stream:
            summary = make_reader(stream).get_summary()
        schemas = {schema.name for schema in summary.schemas.values()}
        assert {f"{package}/msg/Pose", f"{package}/msg/Color", f"{package}/msg/Spawn_Request"} <= schemas
        assert not any(name.startswith("turtlesim/") for name in schemas) or package == "turtlesim"
        metadata = (tmp_path / distro / "metadata.yaml").read_text()
        assert f"type: {package}/msg/Pose" in metadata and metadata.endswith(f"ros_distro: {distro}")
    # Kilted's own hash of turtlesim_msgs/msg/Pose (share/turtlesim_msgs/msg/Pose.json)
    assert "RIHS01_37b07ace09a0ed2c5b774b1410dec972dfd1d292de5656ebc2b075ac646e09c8" in (
        tmp_path / "kilted" / "metadata.yaml").read_text()
