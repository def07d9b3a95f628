"""A third ROS 2 process (run by the real rclpy) that looks at the bridged turtlesim.

``python3 ros_probe.py SECONDS [LINGER [NODE...] [--driven]]`` waits for /turtlesim (and the NODEs;
with --driven, until turtle1 moves: a NODE drives it), then does what a
student does from another terminal (ros2 node/topic/service/param/action)
and prints one JSON report on its last line. It offers the service
/probe_trigger (std_srvs/srv/Trigger) while it runs, and logs on /rosout.
"""

import json
import os
import sys
import time

import rclpy
from rcl_interfaces.msg import Log, Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import GetParameters, SetParameters
from rclpy.action import ActionClient
from rclpy.qos import ReliabilityPolicy
from std_srvs.srv import Empty, Trigger

if os.environ.get("TURTLETUI_TURTLESIM_PACKAGE") == "turtlesim_msgs":  # as a Kilted user imports them
    from turtlesim_msgs.action import RotateAbsolute
    from turtlesim_msgs.msg import Pose
    from turtlesim_msgs.srv import Kill, SetPen, Spawn, TeleportAbsolute
else:
    from turtlesim.action import RotateAbsolute
    from turtlesim.msg import Pose
    from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute


def main() -> None:
    budget = float(sys.argv[1]) if len(sys.argv) > 1 else 60.0
    deadline = time.monotonic() + budget
    rclpy.init()
    node = rclpy.create_node("probe")
    report = {}
    rosout = []
    node.create_subscription(Log, "/rosout", lambda m: rosout.append([m.name, m.level, m.msg]), 100)
    node.create_service(Trigger, "/probe_trigger", lambda req, res: _trigger(res))

    def spin_until(check, seconds):
        end = min(time.monotonic() + seconds, deadline)
        while time.monotonic() < end:
            if check():
                return True
            rclpy.spin_once(node, timeout_sec=0.05)
        return check()

    def call(srv_type, name, request, seconds=10.0):
        client = node.create_client(srv_type, name)
        if not client.wait_for_service(timeout_sec=seconds):
            return None
        future = client.call_async(request)
        spin_until(future.done, seconds)
        return future.result()

    report["found"] = spin_until(lambda: ("turtlesim", "/") in node.get_node_names_and_namespaces(), 30)
    spin_until(lambda: len(node.get_publishers_info_by_topic("/turtle1/pose")) > 0, 10)
    driven = "--driven" in sys.argv[3:]
    for wanted in [a for a in sys.argv[3:] if a != "--driven"]:  # nodes the caller expects (they may start later)
        spin_until(lambda wanted=wanted: wanted in [n for n, _ in node.get_node_names_and_namespaces()], 30)
    report["topics"] = {t: types for t, types in node.get_topic_names_and_types()}
    report["services"] = sorted(s for s, _ in node.get_service_names_and_types())
    report["pose_reliable"] = [
        e.qos_profile.reliability == ReliabilityPolicy.RELIABLE
        for e in node.get_publishers_info_by_topic("/turtle1/pose")
    ]
    stamps = []
    turtle1 = []

    moving = []

    def on_pose(msg):
        stamps.append(time.monotonic())
        turtle1.append((msg.x, msg.y))
        if msg.linear_velocity != 0.0:
            moving.append(True)

    node.create_subscription(Pose, "/turtle1/pose", on_pose, 7)
    if driven:  # its driver's commands may take a while to reach turtlesim on a busy machine
        spin_until(lambda: moving, 30)
        stamps.clear()
        turtle1.clear()
    spin_until(lambda: len(stamps) > 190, 10)
    report["pose_rate"] = (len(stamps) - 1) / (stamps[-1] - stamps[0]) if len(stamps) > 2 else 0.0
    report["turtle1_travel"] = sum(
        ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5 for (x0, y0), (x1, y1) in zip(turtle1, turtle1[1:])  # noqa: B905 (Python 3.8 too)
    )
    report["nodes"] = sorted(n for n, ns in node.get_node_names_and_namespaces() if not n.startswith("_"))

    spawned = call(Spawn, "/spawn", Spawn.Request(x=2.0, y=3.0, theta=0.5, name=""))
    report["spawned"] = spawned.name if spawned else None
    turtle2 = []
    node.create_subscription(Pose, "/turtle2/pose", lambda m: turtle2.append([m.x, m.y, m.theta]), 7)
    spin_until(lambda: len(turtle2) > 3, 10)
    report["turtle2_pose"] = turtle2[-1] if turtle2 else None
    again = call(Spawn, "/spawn", Spawn.Request(x=2.0, y=3.0, theta=0.5, name="turtle2"))
    report["spawn_again"] = again.name if again else None

    setter = "/turtlesim/set_parameters"

    def set_int(name, value):
        value = ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)
        result = call(SetParameters, setter, SetParameters.Request(parameters=[Parameter(name=name, value=value)]))
        return [result.results[0].successful, result.results[0].reason] if result else None

    report["set_300"] = set_int("background_r", 300)
    report["set_10"] = set_int("background_r", 10)
    got = call(GetParameters, "/turtlesim/get_parameters", GetParameters.Request(names=["background_r", "holonomic"]))
    report["get"] = [got.values[0].integer_value, got.values[1].bool_value] if got else None

    report["set_pen"] = call(SetPen, "/turtle2/set_pen", SetPen.Request(r=255, g=0, b=0, width=4, off=0)) is not None
    report["teleport"] = call(
        TeleportAbsolute, "/turtle2/teleport_absolute", TeleportAbsolute.Request(x=4.0, y=4.0, theta=0.0)
    ) is not None
    spin_until(lambda: bool(turtle2) and abs(turtle2[-1][0] - 4.0) < 1e-3, 5)
    report["turtle2_after_teleport"] = turtle2[-1] if turtle2 else None

    action = ActionClient(node, RotateAbsolute, "/turtle2/rotate_absolute")
    feedback = []
    report["action_server"] = action.wait_for_server(timeout_sec=10)
    goal_future = action.send_goal_async(
        RotateAbsolute.Goal(theta=1.0), feedback_callback=lambda f: feedback.append(f.feedback.remaining)
    )
    spin_until(goal_future.done, 10)
    handle = goal_future.result()
    report["goal_accepted"] = bool(handle and handle.accepted)
    if handle and handle.accepted:
        result_future = handle.get_result_async()
        spin_until(result_future.done, 10)
        outcome = result_future.result()
        report["goal_status"] = outcome.status if outcome else None
        report["goal_delta"] = outcome.result.delta if outcome else None
    report["feedback_count"] = len(feedback)
    spin_until(lambda: bool(turtle2) and abs(turtle2[-1][2] - 1.0) < 0.05, 5)
    report["turtle2_theta"] = turtle2[-1][2] if turtle2 else None

    report["kill"] = call(Kill, "/kill", Kill.Request(name="turtle2")) is not None
    spin_until(lambda: not node.get_publishers_info_by_topic("/turtle2/pose"), 5)
    report["turtle2_publishers_after_kill"] = len(node.get_publishers_info_by_topic("/turtle2/pose"))
    report["clear"] = call(Empty, "/clear", Empty.Request()) is not None
    node.get_logger().info("probe done")
    spin_until(lambda: any("Clearing" in r[2] for r in rosout), 5)
    report["rosout"] = [r for r in rosout if r[0] == "turtlesim"]
    print(json.dumps(report), flush=True)
    # stay on the graph a little: the test looks at what turtletui saw of this node
    spin_until(lambda: False, float(sys.argv[2]) if len(sys.argv) > 2 else 0.0)
    node.destroy_node()
    rclpy.try_shutdown()


def _trigger(response):
    response.success = True
    response.message = "probe here"
    return response


if __name__ == "__main__":
    main()
