"""The introspection API: what ros2 node/topic/service/action and rqt_graph would show."""

import textwrap
from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.graph.introspection import GraphSnapshot, snapshot

PART6 = Path(__file__).resolve().parents[2] / "plugins" / "reference" / "turtle_controller.py"


def snapshot_at(t: float, controllers: list, **kwargs) -> GraphSnapshot:
    """Run the controllers and take a snapshot of the graph at simulated time t."""
    taken: list[GraphSnapshot] = []

    def setup(sim):
        timer = sim.graph.add_timer(sim.turtlesim.node, int(t * 1e9), lambda: (
            taken.append(snapshot(sim.graph)), setattr(timer, "canceled", True)))

    run(controllers, duration=t + 0.1, setup=setup, **kwargs)
    assert len(taken) == 1
    return taken[0]


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_the_part6_graph_as_rqt_graph_draws_it(sandbox: bool) -> None:
    graph = snapshot_at(1.0, [PART6], sandbox=sandbox)
    assert [n.name for n in graph.nodes] == ["/turtle_controller", "/turtlesim"]
    for arrow in [
        ("/turtlesim", "/turtle1/pose"),
        ("/turtle1/pose", "/turtle_controller"),
        ("/turtle_controller", "/turtle1/cmd_vel"),
        ("/turtle1/cmd_vel", "/turtlesim"),
    ]:
        assert arrow in graph.edges()
    pose = graph.topic("/turtle1/pose")
    assert pose.type == "turtlesim/msg/Pose"
    assert pose.publishers == ("/turtlesim",) and pose.subscribers == ("/turtle_controller",)
    assert pose.rate_hz == pytest.approx(62.5, rel=0.01)
    assert graph.topic("/turtle1/cmd_vel").rate_hz == pytest.approx(62.5, rel=0.01)
    assert graph.topic("/turtle1/color_sensor").subscribers == ()


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_every_node_has_rosout_and_parameter_events_as_in_ros(sandbox: bool) -> None:
    graph = snapshot_at(1.0, [PART6], sandbox=sandbox)
    assert graph.topic("/rosout").publishers == ("/turtle_controller", "/turtlesim")
    events = graph.topic("/parameter_events")
    assert events.type == "rcl_interfaces/msg/ParameterEvent"
    assert events.publishers == ("/turtle_controller", "/turtlesim")
    assert events.subscribers == ("/turtlesim",)  # rclcpp's own; rclpy nodes have none
    assert ("/turtle_controller", "/rosout") in graph.edges()


def test_services_actions_and_parameters_of_turtlesim() -> None:
    graph = snapshot_at(0.5, [PART6], sandbox=False)
    services = {s.name: s for s in graph.services}
    assert set(services) >= {"/clear", "/reset", "/spawn", "/kill", "/turtle1/set_pen",
                             "/turtle1/teleport_absolute", "/turtle1/teleport_relative"}
    assert services["/spawn"].type == "turtlesim/srv/Spawn" and services["/spawn"].server == "/turtlesim"
    [action] = graph.actions
    assert (action.name, action.type, action.server) == (
        "/turtle1/rotate_absolute", "turtlesim/action/RotateAbsolute", "/turtlesim")
    turtlesim = graph.node("turtlesim")
    assert dict(turtlesim.parameters) == {  # its own, and what rclcpp declares on every node
        "background_r": 69, "background_g": 86, "background_b": 255, "holonomic": False,
        "use_sim_time": False, "start_type_description_service": True,
        "qos_overrides./parameter_events.publisher.depth": 1000,
        "qos_overrides./parameter_events.publisher.durability": "volatile",
        "qos_overrides./parameter_events.publisher.history": "keep_last",
        "qos_overrides./parameter_events.publisher.reliability": "reliable"}
    assert ("/turtle1/pose", "turtlesim/msg/Pose") in turtlesim.publishers
    assert ("/turtle1/cmd_vel", "geometry_msgs/msg/Twist") in turtlesim.subscribers
    with pytest.raises(KeyError, match="did you mean /turtle1/pose"):
        graph.topic("/turtle1/pos")


def test_a_sandboxed_nodes_parameters_and_clients_are_visible(tmp_path: Path) -> None:
    path = tmp_path / "params.py"
    path.write_text(textwrap.dedent("""
        import rclpy
        from rclpy.node import Node
        from turtlesim.srv import SetPen


        def main():
            rclpy.init()
            node = Node("tuned")
            node.declare_parameter("speed", 1.5)
            node.create_client(SetPen, "/turtle1/set_pen")
            rclpy.spin(node)
    """))
    graph = snapshot_at(0.5, [path], ros_args=["-p", "speed:=2.5"])
    node = graph.node("/tuned")
    # with what every rclpy node declares
    assert dict(node.parameters) == {"speed": 2.5, "use_sim_time": False, "start_type_description_service": True}
    assert node.service_clients == (("/turtle1/set_pen", "turtlesim/srv/SetPen"),)
    assert {s.name: s.clients for s in graph.services}["/turtle1/set_pen"] == ("/tuned",)


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_topic_name_typos_are_pointed_out_after_a_second(tmp_path: Path, sandbox: bool) -> None:
    path = tmp_path / "typo.py"
    path.write_text(textwrap.dedent("""
        import rclpy
        from rclpy.node import Node
        from geometry_msgs.msg import Twist
        from turtlesim.msg import Pose


        class Typo(Node):
            def __init__(self):
                super().__init__("typo")
                self.create_publisher(Twist, "/turtle1/cmd_vell", 10)
                self.create_publisher(Twist, "/debug/twist", 10)
                self.create_subscription(Pose, "/turtle1/pos", lambda msg: None, 10)
    """))
    result = run([path], duration=2.0, sandbox=sandbox)
    warnings = [(r.t, r.msg) for r in result.logs if r.node == "turtletui"]
    assert warnings == [
        (1.0, "/typo publishes on /turtle1/cmd_vell, but nothing subscribes to it (did you mean /turtle1/cmd_vel?)"),
        (1.0, "/typo subscribes to /turtle1/pos, but nothing publishes it (did you mean /turtle1/pose?)"),
    ]


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_names_without_their_turtles_namespace_and_unserved_clients_are_pointed_out(
    tmp_path: Path, sandbox: bool
) -> None:
    path = tmp_path / "bare.py"
    path.write_text(textwrap.dedent("""
        import rclpy
        from rclpy.action import ActionClient
        from rclpy.node import Node
        from geometry_msgs.msg import Twist
        from turtlesim.action import RotateAbsolute
        from turtlesim.srv import SetPen


        class Bare(Node):
            def __init__(self):
                super().__init__("bare")
                self.create_publisher(Twist, "cmd_vel", 10)
                self.create_client(SetPen, "set_pen")
                self.client = ActionClient(self, RotateAbsolute, "rotate_absolute")
    """))
    result = run([path], duration=2.0, sandbox=sandbox)
    warnings = [(r.t, r.msg) for r in result.logs if r.node == "turtletui"]
    assert warnings == [
        (1.0, "/bare is a client of /set_pen, but nothing serves it (did you mean /turtle1/set_pen?)"),
        (
            1.0,
            "/bare is an action client of /rotate_absolute, but nothing serves it "
            "(did you mean /turtle1/rotate_absolute?)",
        ),
        (1.0, "/bare publishes on /cmd_vel, but nothing subscribes to it (did you mean /turtle1/cmd_vel?)"),
    ]


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_endpoints_whose_qos_never_match_are_pointed_out_with_what_to_change(tmp_path: Path, sandbox: bool) -> None:
    # Both ends of a classic mix-up: the sensor QoS copied onto cmd_vel (turtlesim's
    # subscription is reliable), and a reliable subscription of a best-effort publisher.
    path = tmp_path / "mixed_up.py"
    path.write_text(textwrap.dedent("""
        import rclpy
        from rclpy.node import Node
        from rclpy.qos import qos_profile_sensor_data
        from geometry_msgs.msg import Twist
        from std_msgs.msg import String


        class MixedUp(Node):
            def __init__(self):
                super().__init__("mixed_up")
                self.create_publisher(Twist, "/turtle1/cmd_vel", qos_profile_sensor_data)
                self.create_publisher(String, "/chatter", qos_profile_sensor_data)
                self.create_subscription(String, "/chatter", lambda msg: None, 10)
    """))
    result = run([path], duration=2.0, sandbox=sandbox)
    warnings = [(r.t, r.msg) for r in result.logs if r.node == "turtletui"]
    assert warnings == [
        (
            1.0,
            "/mixed_up subscribes to /chatter asking for RELIABLE delivery, but /mixed_up publishes it "
            "BEST_EFFORT: their QoS never match, so nothing passes between them (subscribe with "
            "qos_profile_sensor_data: best effort hears best-effort and reliable publishers alike, and a "
            "robot's sensors publish best effort; or publish with a plain depth such as 10, which is reliable "
            "and heard by every subscription)",
        ),
        (
            1.0,
            "/turtlesim subscribes to /turtle1/cmd_vel asking for RELIABLE delivery, but /mixed_up publishes it "
            "BEST_EFFORT: their QoS never match, so nothing passes between them (publish with a plain depth "
            "such as 10, which is reliable and heard by every subscription)",
        ),
    ]


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_a_node_made_later_is_looked_at_a_second_after_it_appears(tmp_path: Path, sandbox: bool) -> None:
    # as a node reloaded in the app is: its mistakes are pointed out again
    path = tmp_path / "late.py"
    path.write_text(textwrap.dedent("""
        import rclpy
        from rclpy.node import Node
        from turtlesim.msg import Pose


        class First(Node):
            def __init__(self):
                super().__init__("first")
                self.create_subscription(Pose, "/turtle1/pose", lambda msg: None, 10)
                self.later = self.create_timer(2.0, self.make_another)
                self.others = []

            def make_another(self):
                self.later.cancel()
                other = Node("late")
                other.create_subscription(Pose, "/turtle1/pos", lambda msg: None, 10)
                self.others.append(other)


        def main():
            rclpy.init()
            rclpy.spin(First())
    """))
    result = run([path], duration=4.0, sandbox=sandbox, distro="jazzy")
    warnings = [(r.t, r.msg) for r in result.logs if r.node == "turtletui"]
    assert warnings == [
        (3.0, "/late subscribes to /turtle1/pos, but nothing publishes it (did you mean /turtle1/pose?)"),
    ]


def test_a_well_connected_controller_gets_no_warning() -> None:
    result = run([PART6], duration=2.0, sandbox=False)
    assert [r for r in result.logs if r.node == "turtletui"] == []


ACTION_USER = """
import rclpy
from rclpy.action import ActionClient, ActionServer
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class User(Node):
    def __init__(self):
        super().__init__("user")
        self.client = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.server = ActionServer(self, RotateAbsolute, "spin", lambda goal_handle: RotateAbsolute.Result())
        # a hidden topic named on purpose: turtlesim's action server publishes there
        feedback = RotateAbsolute.Impl.FeedbackMessage
        self.create_subscription(feedback, "/turtle1/rotate_absolute/_action/feedback", lambda msg: None, 10)
"""


@pytest.mark.parametrize("sandbox", [True, False], ids=["sandboxed", "in-process"])
def test_hidden_action_endpoints_are_for_the_ros2_tools_not_the_views(tmp_path: Path, sandbox: bool) -> None:
    path = tmp_path / "user.py"
    path.write_text(ACTION_USER)
    taken: list[tuple[GraphSnapshot, GraphSnapshot]] = []

    def setup(sim):
        sim.graph.call_later(sim.turtlesim.node, 500_000_000, lambda: taken.append(
            (snapshot(sim.graph), snapshot(sim.graph, action_endpoints=True))))

    result = run([path], duration=2.0, sandbox=sandbox, setup=setup)
    assert result.ok, result.crashes
    [(view, ros)] = taken
    # the views (Topics and Graph panels), as rqt_graph: only the topic the file subscribed to by name
    assert [t.name for t in view.topics if "/_action/" in t.name] == ["/turtle1/rotate_absolute/_action/feedback"]
    assert not any("/_action/" in s.name for s in view.services)
    feedback = ros.topic("/turtle1/rotate_absolute/_action/feedback")
    assert (feedback.type, feedback.publishers, feedback.subscribers) == (
        "turtlesim/action/RotateAbsolute_FeedbackMessage", ("/turtlesim",), ("/user", "/user"))
    status = ros.topic("/turtle1/rotate_absolute/_action/status")
    assert (status.type, status.publishers, status.subscribers) == (
        "action_msgs/msg/GoalStatusArray", ("/turtlesim",), ("/user",))
    assert ros.topic("/spin/_action/feedback").publishers == ("/user",)
    services = {s.name: s for s in ros.services}
    assert services["/turtle1/rotate_absolute/_action/send_goal"].clients == ("/user",)
    assert services["/spin/_action/get_result"].server == "/user"
    user = ros.node("/user")
    assert ("/spin/_action/status", "action_msgs/msg/GoalStatusArray") in user.publishers
    assert ("/turtle1/rotate_absolute/_action/feedback", "turtlesim/action/RotateAbsolute_FeedbackMessage") in (
        user.subscribers)
    assert ("/turtle1/rotate_absolute/_action/cancel_goal", "action_msgs/srv/CancelGoal") in user.service_clients
    # no typo warning: turtlesim's action server publishes the feedback the file listens to
    assert [r.msg for r in result.logs if r.node == "turtletui"] == []
