"""One rclpy program, the same behaviour in both hosts (in-process and sandboxed).

Each expectation is what the real rclpy does (Kilted, Fast DDS); the ones the
sandbox does not meet yet are marked ``differs_in_sandbox``. A program that
is one Node subclass has no main(): turtletui creates and spins it.
"""

from __future__ import annotations

import pytest
from support.hosts import node_logs

HEADER = """
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from std_srvs.srv import Empty
"""


def test_a_message_changed_after_publish_is_delivered_as_it_was_sent(controller_host):
    # The message is serialised by publish(): resetting the same object for the
    # next command must not stop the turtle (3.94 m sandboxed, 0 m in-process once).
    result = controller_host.run(
        HEADER
        + """
class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.msg = Twist()
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.msg.linear.x = 2.0
        self.pub.publish(self.msg)
        self.msg.linear.x = 0.0
""",
        duration=2.0,
    )
    assert result.ok, result.crashes
    assert result.turtles["turtle1"].distance == pytest.approx(3.808, abs=0.05)


def test_each_subscription_gets_its_own_copy_of_a_message(controller_host):
    result = controller_host.run(
        HEADER
        + """
class Two(Node):
    def __init__(self):
        super().__init__("two")
        self.create_subscription(Pose, "/turtle1/pose", self.spoil, 10)
        self.create_subscription(Pose, "/turtle1/pose", self.read, 10)
        self.done = False

    def spoil(self, msg):
        msg.x = -1.0

    def read(self, msg):
        if not self.done:
            self.done = True
            self.get_logger().info(f"x={msg.x:.3f}")
""",
        duration=0.2,
    )
    assert node_logs(result, "two") == ["x=5.544"]


def test_a_message_a_subscriber_changes_is_unchanged_for_its_publisher(controller_host):
    result = controller_host.run(
        HEADER
        + """
class Loop(Node):
    def __init__(self):
        super().__init__("loop")
        self.create_subscription(Twist, "/loop", self.spoil, 10)
        self.pub = self.create_publisher(Twist, "/loop", 10)
        self.sent = Twist()
        self.sent.angular.z = 1.0
        self.pub.publish(self.sent)

    def spoil(self, msg):
        msg.angular.z = 5.0
        self.get_logger().info(f"sent {self.sent.angular.z}, got {msg.angular.z}")
""",
        duration=0.1,
    )
    assert node_logs(result, "loop") == ["sent 1.0, got 5.0"]


DESTROY_SERVICE = (
    HEADER
    + """
class Server(Node):
    def __init__(self):
        super().__init__("server")
        self.service = self.create_service(Empty, "/ping", self.ping)

    def ping(self, request, response):
        self.get_logger().info("ping answered")
        return response

class Caller(Node):
    def __init__(self, server):
        super().__init__("caller")
        self.server = server
        self.client = self.create_client(Empty, "/ping")
        self.create_timer(0.1, self.tick)
        self.ticks = 0

    def tick(self):
        self.ticks += 1
        log = self.get_logger().info
        if self.ticks == 1:
            log(f"ready {self.client.service_is_ready()} services {self.count_services('/ping')}")
            self.client.call_async(Empty.Request()).add_done_callback(lambda f: log("first answered"))
        elif self.ticks == 2:
            log(f"destroyed {self.server.destroy_service(self.server.service)}")
            log(f"again {self.server.destroy_service(self.server.service)}")
        elif self.ticks == 3:
            log(f"ready {self.client.service_is_ready()} services {self.count_services('/ping')}")
            log(f"listed {[n for n, _ in self.get_service_names_and_types() if n == '/ping']}")
            self.client.call_async(Empty.Request()).add_done_callback(lambda f: log("second answered"))

def main():
    rclpy.init()
    server = Server()
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(server)
    executor.add_node(Caller(server))
    executor.spin()
"""
)


def test_destroy_service_takes_the_service_off_the_graph(controller_host):
    result = controller_host.run(DESTROY_SERVICE, duration=1.0)
    assert result.ok, result.crashes
    assert node_logs(result, "caller") == [
        "ready True services 1",
        "first answered",
        "destroyed True",
        "again False",
        "ready False services 0",
        "listed ['/ping']",  # the caller's client keeps the name on the graph (real rclpy: the same)
    ]
    assert node_logs(result, "server") == ["ping answered"]


def test_destroyed_publishers_subscriptions_timers_and_clients(controller_host):
    result = controller_host.run(
        HEADER
        + """
from rclpy.exceptions import InvalidHandle

class Owner(Node):
    def __init__(self):
        super().__init__("owner")
        log = self.get_logger().info
        pub = self.create_publisher(Twist, "/mine", 10)
        sub = self.create_subscription(Twist, "/mine", lambda m: log("delivered"), 10)
        timer = self.create_timer(0.1, lambda: log("tick"))
        client = self.create_client(Empty, "/clear")
        other = rclpy.create_node("other")
        log(f"counts {self.count_publishers('/mine')} {self.count_subscribers('/mine')}")
        log(f"other node's {other.destroy_publisher(pub)} {other.destroy_subscription(sub)}")
        pub.publish(Twist())
        for name, entity in (("pub", pub), ("sub", sub), ("timer", timer), ("client", client)):
            destroy = getattr(self, f"destroy_{'subscription' if name == 'sub' else 'publisher' if name == 'pub' else name}")
            log(f"{name} {destroy(entity)} {destroy(entity)}")
        log(f"counts {self.count_publishers('/mine')} {self.count_subscribers('/mine')}")
        for what, use in (
            ("publish", lambda: pub.publish(Twist())),
            ("subscription count", pub.get_subscription_count),
            ("topic_name", lambda: sub.topic_name),
            ("cancel", timer.cancel),
            ("service_is_ready", client.service_is_ready),
            ("call_async", lambda: client.call_async(Empty.Request())),
        ):
            try:
                use()
                log(f"{what} worked")
            except InvalidHandle as err:
                log(f"{what}: {err}")
""",
        duration=0.5,
    )
    assert result.ok, result.crashes
    refused = "cannot use Destroyable because destruction was requested"
    assert node_logs(result, "owner") == [
        "counts 1 1",
        "other node's False False",
        "pub True False",
        "sub True False",
        "timer True False",
        "client True False",
        "counts 0 0",
        *(f"{what}: {refused}" for what in (
            "publish", "subscription count", "topic_name", "cancel", "service_is_ready", "call_async"
        )),
    ]


def test_a_topic_whose_endpoints_are_gone_may_be_used_with_another_type(controller_host):
    # as the real rclpy (Kilted, Fast DDS) does with 0.5 s between the steps
    result = controller_host.run(
        HEADER
        + """
from std_msgs.msg import String

def main():
    rclpy.init()
    node = Node("reuser")
    log = node.get_logger().info
    listed = lambda: [(n, t) for n, t in node.get_topic_names_and_types() if n == "/reuse"]
    pub = node.create_publisher(Twist, "/reuse", 10)
    log(f"first {listed()}")
    node.destroy_publisher(pub)
    log(f"destroyed {listed()}")
    node.create_publisher(String, "/reuse", 10)
    log(f"again {listed()}")
""",
        duration=0.5,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "reuser") == [
        "first [('/reuse', ['geometry_msgs/msg/Twist'])]",
        "destroyed []",
        "again [('/reuse', ['std_msgs/msg/String'])]",
    ]


def test_a_destroyed_node_refuses_new_entities_with_rclpys_error(controller_host):
    result = controller_host.run(
        HEADER
        + """
from rclpy.exceptions import InvalidHandle

def main():
    rclpy.init()
    node = rclpy.create_node("gone")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    node.destroy_node()
    node.destroy_node()  # twice is fine, as in rclpy
    log = rclpy.logging.get_logger("check").info
    for what, use in (
        ("create_publisher", lambda: node.create_publisher(Twist, "/x", 10)),
        ("create_subscription", lambda: node.create_subscription(Twist, "/x", print, 10)),
        ("create_client", lambda: node.create_client(Empty, "/x")),
        ("create_service", lambda: node.create_service(Empty, "/x", print)),
        ("get_name", node.get_name),
        ("get_node_names", node.get_node_names),
        ("declare_parameter", lambda: node.declare_parameter("p", 1)),
        ("publish", lambda: pub.publish(Twist())),
    ):
        try:
            use()
            log(f"{what} worked")
        except InvalidHandle as err:
            log(f"{what}: {type(err).__name__}")
    node.create_timer(0.1, lambda: log("a destroyed node's timer fired"))
    rclpy.spin_once(rclpy.create_node("other"), timeout_sec=0.3)
    rclpy.shutdown()
""",
        duration=0.5,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "check") == [
        f"{what}: InvalidHandle"
        for what in (
            "create_publisher",
            "create_subscription",
            "create_client",
            "create_service",
            "get_name",
            "get_node_names",
            "declare_parameter",
            "publish",
        )
    ]


def test_an_uncaught_invalid_handle_is_a_crash_report_not_an_internal_error(controller_host):
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    node = rclpy.create_node("gone")
    node.destroy_node()
    node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
""",
        duration=0.5,
    )
    [crash] = result.crashes
    assert crash.message == "InvalidHandle: cannot use Destroyable because destruction was requested"
    assert any("create_publisher" in frame for frame in crash.frames)


GRAPH_QUERIES = (
    HEADER
    + """
class Watcher(Node):
    def __init__(self):
        super().__init__("watcher", namespace="/lab")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "pose_in", lambda m: None, 5)
        self.create_timer(0.05, self.report)

    def report(self):
        log = self.get_logger().info
        log(f"nodes {sorted(self.get_node_names_and_namespaces())}")
        log(f"subscribers {self.pub.get_subscription_count()} {self.count_subscribers('/turtle1/cmd_vel')}")
        log(f"publishers {self.count_publishers('/turtle1/pose')} {self.count_publishers('pose_in')}")
        topics = dict(self.get_topic_names_and_types())
        log(f"topics {topics.get('/turtle1/pose')} {topics.get('/lab/pose_in')}")
        services = dict(self.get_service_names_and_types())
        log(f"services {services.get('/spawn')} {services.get('/turtle1/set_pen')}")
        [info] = self.get_publishers_info_by_topic("/turtle1/pose")
        log(f"pose publisher {info.node_namespace}{info.node_name} {info.topic_type} {info.endpoint_type.name}")
        log(f"by node {self.get_subscriber_names_and_types_by_node('turtlesim', '/')}")
        from rclpy.action import get_action_names_and_types
        log(f"actions {get_action_names_and_types(self)}")
        raise SystemExit
"""
)


def test_graph_queries_see_turtlesim_and_the_nodes_own_endpoints(controller_host):
    result = controller_host.run(GRAPH_QUERIES, duration=0.2)
    assert result.ok, result.crashes
    assert node_logs(result, "lab.watcher") == [
        "nodes [('turtlesim', '/'), ('watcher', '/lab')]",
        "subscribers 1 1",
        "publishers 1 0",
        "topics ['turtlesim/msg/Pose'] ['turtlesim/msg/Pose']",
        "services ['turtlesim/srv/Spawn'] ['turtlesim/srv/SetPen']",
        "pose publisher /turtlesim turtlesim/msg/Pose PUBLISHER",
        # rclcpp's own /parameter_events subscription, as every rclcpp node has
        "by node [('/parameter_events', ['rcl_interfaces/msg/ParameterEvent']),"
        " ('/turtle1/cmd_vel', ['geometry_msgs/msg/Twist'])]",
        "actions [('/turtle1/rotate_absolute', ['turtlesim/action/RotateAbsolute'])]",
    ]


def test_node_names_come_in_creation_order_with_turtlesim_first(controller_host):
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    first = rclpy.create_node("first")
    second = rclpy.create_node("second", namespace="/ns")
    log = first.get_logger().info
    log(f"names {first.get_node_names()}")
    log(f"with namespaces {second.get_node_names_and_namespaces()}")
    log(f"qualified {first.get_fully_qualified_node_names()}")
    second.destroy_node()
    third = rclpy.create_node("third")
    rclpy.spin_once(first, timeout_sec=0.1)
    log(f"after {first.get_node_names()} {third.wait_for_node('/turtlesim', 1.0)}")
"""
    )
    assert result.ok, result.crashes
    assert node_logs(result, "first") == [
        "names ['turtlesim', 'first', 'second']",
        "with namespaces [('turtlesim', '/'), ('first', '/'), ('second', '/ns')]",
        "qualified ['/turtlesim', '/first', '/ns/second']",
        "after ['turtlesim', 'first', 'third'] True",
    ]


WAITER = (
    HEADER
    + """
from turtlesim.srv import SetPen, Spawn

def main():
    rclpy.init()
    node = rclpy.create_node("waiter")
    log = node.get_logger().info
    spawn = node.create_client(Spawn, "/spawn")
    while not spawn.wait_for_service(timeout_sec=1.0):
        log("waiting for /spawn")
    log("spawn ready")
    pen = node.create_client(SetPen, "/t2/set_pen")
    log(f"t2 pen ready {pen.wait_for_service(timeout_sec=0.5)}")
    pub = node.create_publisher(Twist, "/t2/cmd_vel", 10)
    log(f"t2 subscribers {pub.get_subscription_count()} {node.count_subscribers('/t2/cmd_vel')}")
    future = spawn.call_async(Spawn.Request(x=2.0, y=2.0, theta=0.0, name="t2"))
    while pub.get_subscription_count() == 0:  # the usual 'wait until turtlesim listens'
        rclpy.spin_once(node, timeout_sec=0.1)
    log(f"t2 subscribed, spawned {future.done()} {future.result().name}")
    log(f"t2 pen ready {pen.wait_for_service(timeout_sec=0.5)}")
    log(f"t2 pose publishers {node.count_publishers('/t2/pose')}")
    msg = Twist()
    msg.linear.x = 1.0
    pub.publish(msg)
    rclpy.spin_once(node, timeout_sec=0.5)
"""
)


def test_waiting_for_turtlesims_services_and_subscriptions(controller_host):
    result = controller_host.run(WAITER, duration=2.0)
    assert result.ok, result.crashes
    logs = [(round(r.t, 3), r.msg) for r in result.logs if r.node == "waiter"]
    assert logs == [
        (0.05, "spawn ready"),  # discovery takes 50 ms (tests/compat/test_discovery.py)
        (0.55, "t2 pen ready False"),
        (0.55, "t2 subscribers 0 0"),
        # turtlesim's new subscription is discovered 50 ms after the spawn; the
        # loop's spin_once(timeout_sec=0.1) then returns at its timeout
        (0.65, "t2 subscribed, spawned True t2"),
        (0.65, "t2 pen ready True"),
        (0.65, "t2 pose publishers 1"),
    ]
    assert result.turtles["t2"].distance > 0.5


LEAVER = (
    HEADER
    + """
from rclpy.qos import QoSProfile, ReliabilityPolicy

class Leaver(Node):
    def __init__(self):
        super().__init__("leaver")
        best_effort = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
        self.pub = self.create_publisher(Twist, "/chatter", best_effort)
        self.sub = self.create_subscription(Twist, "/chatter", lambda m: None, best_effort)  # compatible QoS
        self.client = self.create_client(Empty, "/clear")
        self.service = self.create_service(Empty, "/ping", self.ping)
        self.steps = [self.drop_service, self.drop_endpoints, self.destroy_node]
        self.create_timer(0.25, lambda: self.steps.pop(0)())

    def ping(self, request, response):
        self.get_logger().info("ping answered")
        return response

    def drop_service(self):
        self.destroy_service(self.service)

    def drop_endpoints(self):
        self.destroy_publisher(self.pub)
        self.destroy_subscription(self.sub)
        self.destroy_client(self.client)
"""
)
OBSERVER = (
    HEADER
    + """
class Observer(Node):
    def __init__(self):
        super().__init__("observer")
        self.ping = self.create_client(Empty, "/ping")
        self.create_timer(0.2, self.look)

    def look(self):
        log = self.get_logger().info
        names = [n for n in self.get_node_names() if n != "turtlesim"]
        qos = [i.qos_profile.reliability.name for i in self.get_publishers_info_by_topic("/chatter")]
        log(
            f"{names} pubs {self.count_publishers('/chatter')} {qos} subs {self.count_subscribers('/chatter')}"
            f" clear clients {self.count_clients('/clear')} ping {self.ping.service_is_ready()}"
        )
        if self.ping.service_is_ready():
            self.ping.call_async(Empty.Request()).add_done_callback(lambda f: log("pinged"))
"""
)


def test_what_a_node_destroys_is_gone_for_the_nodes_of_another_process(controller_host):
    """The leaver runs in the host under test; the observer, always sandboxed,
    sees its service, endpoints and then the node itself go."""
    from turtletui.api import run
    from turtletui.runtime.loader import ControllerSpec

    leaver = controller_host.write(LEAVER, "leaver.py")
    observer = controller_host.write(OBSERVER, "observer.py")
    result = run(
        [
            ControllerSpec("observer", path=observer),
            ControllerSpec("leaver", path=leaver, trusted=not controller_host.sandboxed),
        ],
        duration=0.9,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "observer") == [
        "['observer', 'leaver'] pubs 1 ['BEST_EFFORT'] subs 1 clear clients 1 ping True",
        "pinged",
        "['observer', 'leaver'] pubs 1 ['BEST_EFFORT'] subs 1 clear clients 1 ping False",
        "['observer', 'leaver'] pubs 0 [] subs 0 clear clients 0 ping False",
        "['observer'] pubs 0 [] subs 0 clear clients 0 ping False",
    ]
    assert node_logs(result, "leaver") == ["ping answered"]


def test_a_node_nothing_spins_runs_none_of_its_callbacks(controller_host):
    # A student's two nodes, only one of them spun: the other's timer never
    # drives the turtle and its server never answers, as in ROS 2.
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    main_node = Node("main_node")
    driver = Node("driver")
    pub = driver.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    twist = Twist()
    twist.linear.x = 1.0
    driver.create_timer(0.1, lambda: pub.publish(twist))
    driver.create_service(Empty, "ping", lambda request, response: response)
    client = main_node.create_client(Empty, "ping")
    future = client.call_async(Empty.Request())
    rclpy.spin_until_future_complete(main_node, future, timeout_sec=1.0)
    main_node.get_logger().info(f"answered {future.done()}")
    for _ in range(10):
        rclpy.spin_once(main_node, timeout_sec=0.1)
    rclpy.spin_until_future_complete(driver, future, timeout_sec=0.35)
    main_node.get_logger().info(f"answered {future.done()}")  # the response waits for main_node
    rclpy.spin_until_future_complete(main_node, future, timeout_sec=1.0)
    main_node.get_logger().info(f"answered {future.done()}")
""",
        duration=3.0,
    )
    assert node_logs(result, "main_node") == ["answered False", "answered False", "answered True"]
    notes = [line for line in node_logs(result, "turtletui") if "no executor has this node" in line]
    assert len(notes) == 1 and notes[0].startswith("/driver: ")
    # driven only from t=2 s, when the driver was first spun, to the run's end
    assert result.turtles["turtle1"].distance == pytest.approx(1.0, abs=0.02)


def test_a_node_added_to_an_executor_soon_after_is_not_said_to_be_unspun(controller_host):
    # A node added a moment later (after some spin_once calls of another) is
    # spun as the student meant: no note, and its missed timer runs once.
    result = controller_host.run(
        HEADER
        + """
from rclpy.executors import SingleThreadedExecutor

def main():
    rclpy.init()
    a = Node("a")
    b = Node("b")
    calls = []
    a.create_timer(0.2, lambda: calls.append("a"))
    b.create_timer(0.3, lambda: calls.append("b"))
    executor = SingleThreadedExecutor()
    executor.add_node(a)
    for _ in range(3):
        executor.spin_once(timeout_sec=1.0)
    executor.add_node(b)
    for _ in range(4):
        executor.spin_once(timeout_sec=1.0)
    a.get_logger().info(" ".join(calls))
""",
        duration=3.0,
    )
    assert node_logs(result, "a") == ["a a a b a b a"]
    assert not [line for line in node_logs(result, "turtletui") if "no executor has this node" in line]


def test_a_node_never_spun_by_a_program_that_ends_soon_is_said_at_shutdown(controller_host):
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    spun = Node("spun")
    forgotten = Node("forgotten")
    forgotten.create_timer(0.1, lambda: None)
    for _ in range(3):
        rclpy.spin_once(spun, timeout_sec=0.1)
    rclpy.shutdown()
""",
        duration=2.0,
    )
    notes = [line for line in node_logs(result, "turtletui") if "no executor has this node" in line]
    assert len(notes) == 1 and notes[0].startswith("/forgotten: ")


def test_a_program_starts_in_the_folder_it_is_run_from(controller_host, tmp_path, monkeypatch):
    # as python3 FILE: a relative path is the caller's, not the file's folder's
    here = tmp_path / "here"
    here.mkdir()
    (here / "speed.txt").write_text("1.5")
    monkeypatch.chdir(here)
    result = controller_host.run(
        HEADER
        + """
import os

def main():
    rclpy.init()
    node = Node("reader")
    with open("speed.txt") as f:
        node.get_logger().info(f"{os.path.basename(os.getcwd())} {f.read()}")
""",
        duration=0.1,
    )
    assert node_logs(result, "reader") == ["here 1.5"]


def test_the_same_program_logs_and_moves_the_same_in_both_hosts(tmp_path):
    """Not one expectation per host: both hosts' whole runs, side by side."""
    from support.hosts import HOSTS, ControllerHost

    runs = [ControllerHost(host, tmp_path).run(WAITER, duration=2.0, keep_poses=True) for host in HOSTS]
    logs = [[(r.t, r.level, r.node, r.msg) for r in result.logs] for result in runs]
    assert logs[0] == logs[1]
    assert runs[0].poses == runs[1].poses
    assert set(runs[0].poses) == {"turtle1", "t2"}


CALLS = (
    HEADER
    + """
class Calls(Node):
    def __init__(self):
        super().__init__("calls")
        self.get_logger().info("made")
        self.create_timer(0.25, self.tick)
        self.create_subscription(Pose, "/turtle1/pose", self.pose, 10)
        self.poses = 0

    def tick(self):
        self.get_logger().info("tick")
        self.get_logger().info("tock")

    def pose(self, msg):
        self.poses += 1
        if self.poses % 20 == 0:
            self.get_logger().info("pose")
"""
)


def test_the_lines_of_one_callback_call_share_its_number_the_same_in_every_run(tmp_path):
    """LogRecord.call: 0 outside callbacks, one number per call (both lines of a
    tick share it), numbered from 1 in each run, in both hosts alike."""
    from support.hosts import HOSTS, ControllerHost

    runs = [ControllerHost(host, tmp_path).run(CALLS, duration=1.0) for host in HOSTS for _ in range(2)]
    calls = [[(r.msg, r.call) for r in result.logs if r.node == "calls"] for result in runs]
    assert calls[0] == calls[1] == calls[2] == calls[3]
    assert calls[0][0] == ("made", 0)
    ticks = [(msg, call) for msg, call in calls[0] if msg in ("tick", "tock")]
    assert len(ticks) == 8
    assert all(ticks[i][1] == ticks[i + 1][1] for i in range(0, 8, 2))
    numbers = [call for msg, call in calls[0][1:] if msg != "tock"]
    assert numbers == sorted(set(numbers)) and numbers[0] > 0
