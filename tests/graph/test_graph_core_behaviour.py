"""The middleware under the turtlesim node: time, delivery order, queues, services, actions."""

from __future__ import annotations

import pytest

from turtletui.graph.core import LOCKSTEP_EPOCH_NS, NS_PER_S, Graph, GraphError, TopicTypeConflict
from turtletui.graph.logs import INFO, WARN, LogRecord, parse_level
from turtletui.graph.qos import Policies
from turtletui.interfaces import copier, interface_name
from turtletui.interfaces.geometry_msgs import Twist, Vector3
from turtletui.interfaces.std_msgs import String
from turtletui.interfaces.std_srvs import Empty
from turtletui.interfaces.turtlesim import Pose, RotateAbsolute


def make_graph() -> Graph:
    return Graph(type_name=interface_name)


def test_time_starts_at_zero_on_a_fixed_epoch():
    graph = make_graph()
    assert graph.now_ns == 0
    assert graph.t == 0.0
    assert graph.stamp_ns == LOCKSTEP_EPOCH_NS == 1_700_000_000 * NS_PER_S


def test_advance_jumps_to_the_next_timer_and_fires_it():
    graph = make_graph()
    node = graph.add_node("n")
    fired: list[int] = []
    graph.add_timer(node, 250_000_000, lambda: fired.append(graph.now_ns))
    assert graph.advance(until_ns=100_000_000) is False
    assert graph.now_ns == 100_000_000 and fired == []
    assert graph.advance() is True
    graph.run_ready()
    assert graph.now_ns == 250_000_000
    assert fired == [250_000_000]
    graph.advance()
    graph.run_ready()
    assert fired == [250_000_000, 500_000_000]


def test_timers_due_together_fire_in_creation_order():
    graph = make_graph()
    node = graph.add_node("n")
    order: list[str] = []
    graph.add_timer(node, 100, lambda: order.append("a"))
    graph.add_timer(node, 50, lambda: order.append("b"))
    graph.add_timer(node, 100, lambda: order.append("c"))
    graph.advance()
    graph.run_ready()
    graph.advance()
    graph.run_ready()
    assert order == ["b", "a", "b", "c"]


def test_timer_period_must_be_positive():
    graph = make_graph()
    with pytest.raises(GraphError, match="positive"):
        graph.add_timer(graph.add_node("n"), 0, lambda: None)


def test_publish_delivers_to_every_subscription_in_order():
    graph = make_graph()
    node = graph.add_node("n")
    got: list[tuple[str, str]] = []
    graph.add_subscription(node, "/chat", String, 10, lambda m: got.append(("a", m.data)))
    graph.add_subscription(node, "/chat", String, 10, lambda m: got.append(("b", m.data)))
    topic = graph.topic("/chat", String)
    graph.publish(topic, String(data="1"))
    graph.publish(topic, String(data="2"))
    assert got == []  # delivered when ready callbacks run
    graph.run_ready()
    assert got == [("a", "1"), ("a", "2"), ("b", "1"), ("b", "2")]
    assert topic.count == 2


def test_keep_last_depth_drops_the_oldest_messages():
    graph = make_graph()
    node = graph.add_node("n")
    got: list[str] = []
    graph.add_subscription(node, "/chat", String, 3, lambda m: got.append(m.data))
    topic = graph.topic("/chat", String)
    for i in range(6):
        graph.publish(topic, String(data=str(i)))
    graph.run_ready()
    assert got == ["3", "4", "5"]


def test_one_process_uses_a_topic_with_one_type():
    # Fast DDS refuses a second type in one participant (rcl raises RCLError)
    graph = make_graph()
    one = graph.add_node("one", owner="p")
    other = graph.add_node("other", owner="p")
    graph.add_publisher(one, "/turtle1/pose", Pose, 10)
    with pytest.raises(TopicTypeConflict, match="used here with type turtlesim/msg/Pose, not geometry_msgs/msg/Twist"):
        graph.add_subscription(other, "/turtle1/pose", Twist, 10, lambda msg: None)
    with pytest.raises(TopicTypeConflict):
        graph.add_publisher(one, "/turtle1/pose", Twist, 10)
    assert graph.topic_names_and_types() == [("/turtle1/pose", ["turtlesim/msg/Pose"])]


def test_processes_share_a_name_with_several_types_that_never_match():
    graph = make_graph()
    sim = graph.add_node("turtlesim", owner="sim")
    student = graph.add_node("student", owner="student")
    got: list[str] = []
    pose = graph.add_publisher(sim, "/turtle1/pose", Pose, 10)
    graph.add_subscription(student, "/turtle1/pose", Twist, 10, lambda m: got.append("twist"))
    graph.add_subscription(student, "/other", Pose, 10, lambda m: got.append("pose"))
    graph.publish(pose.topic, Pose(x=1.0), publisher=pose)
    graph.run_ready()
    assert got == []  # endpoints of different types never match
    assert graph.topic_names_and_types() == [
        ("/other", ["turtlesim/msg/Pose"]),
        ("/turtle1/pose", ["geometry_msgs/msg/Twist", "turtlesim/msg/Pose"]),
    ]
    assert graph.count_publishers("/turtle1/pose") == 1 and graph.count_subscribers("/turtle1/pose") == 1
    assert [s.topic.type_name for s in graph.subscriptions_of("/turtle1/pose")] == ["geometry_msgs/msg/Twist"]
    assert graph.names_and_types_by_node(student, "subscriptions") == [
        ("/other", ["turtlesim/msg/Pose"]),
        ("/turtle1/pose", ["geometry_msgs/msg/Twist"]),
    ]
    assert graph.topics["/turtle1/pose"].msg_type is Pose  # the first type keeps the name


def test_the_next_type_takes_the_name_when_the_first_leaves():
    graph = make_graph()
    a = graph.add_node("a", owner="a")
    b = graph.add_node("b", owner="b")
    first = graph.add_publisher(a, "/x", String, 10)
    second = graph.add_publisher(b, "/x", Twist, 10)
    graph.remove_endpoint(first)
    assert graph.topics["/x"] is second.topic and graph.retyped == {}
    assert graph.topic_names_and_types() == [("/x", ["geometry_msgs/msg/Twist"])]
    graph.remove_node(b)
    assert graph.topics == {} and graph.retyped == {}


def test_a_topic_leaves_the_graph_with_its_last_endpoint_and_may_return_with_another_type():
    graph = make_graph()
    node = graph.add_node("n")
    pub = graph.add_publisher(node, "/reuse", Twist, 10)
    sub = graph.add_subscription(node, "/reuse", Twist, 10, lambda msg: None)
    graph.remove_endpoint(pub)
    assert "/reuse" in graph.topics  # the subscription still uses it
    graph.remove_endpoint(sub)
    assert "/reuse" not in graph.topics
    graph.add_publisher(node, "/reuse", String, 10)
    assert graph.topic_names_and_types() == [("/reuse", ["std_msgs/msg/String"])]
    graph.remove_node(node)
    assert graph.topics == {}  # thousands of spawned and killed turtles leave nothing behind


def test_publish_skips_the_source_owner():
    graph = make_graph()
    mine = graph.add_node("mine", owner="sandbox")
    other = graph.add_node("other", owner="local")
    got: list[str] = []
    graph.add_subscription(mine, "/chat", String, 10, lambda m: got.append("mine"))
    graph.add_subscription(other, "/chat", String, 10, lambda m: got.append("other"))
    graph.publish(graph.topic("/chat", String), String(data="x"), source="sandbox")
    graph.run_ready()
    assert got == ["other"]


def test_topic_rate_is_messages_per_simulated_second():
    graph = make_graph()
    topic = graph.topic("/p", Pose)
    for i in range(11):
        graph.now_ns = i * 100_000_000
        graph.publish(topic, Pose())
    assert topic.rate(graph.now_ns) == pytest.approx(10.0)
    assert topic.rate(graph.now_ns + 3 * NS_PER_S) == 0.0


def test_service_call_is_answered_through_the_ready_queue():
    graph = make_graph()
    server = graph.add_node("server", owner="a")
    calls: list[object] = []

    def handler(request, respond):
        calls.append(request)
        respond(Empty.Response())

    graph.add_service(server, "/do", Empty, handler)
    responses: list[object] = []
    graph.call("/do", Empty.Request(), responses.append, owner="b")
    assert calls == [] and responses == []
    graph.run_ready()
    assert len(calls) == 1 and responses == [Empty.Response()]


def test_a_call_to_a_missing_service_is_never_answered():
    graph = make_graph()
    responses: list[object] = []
    graph.call("/nobody", Empty.Request(), responses.append, owner="b")
    graph.run_ready()
    assert responses == []
    assert graph.ready == type(graph.ready)()


def test_a_service_name_can_be_provided_once():
    graph = make_graph()
    node = graph.add_node("n")
    graph.add_service(node, "/do", Empty, lambda r, respond: respond(Empty.Response()))
    with pytest.raises(GraphError, match="already provided by /n"):
        graph.add_service(node, "/do", Empty, lambda r, respond: None)


def test_service_taps_see_request_and_response():
    graph = make_graph()
    node = graph.add_node("n")
    seen: list[tuple[str, object]] = []
    graph.taps.append(lambda kind, payload: seen.append((kind, payload)))
    graph.add_service(node, "/do", Empty, lambda r, respond: respond(Empty.Response()))
    graph.call("/do", Empty.Request(), lambda r: None, owner="x")
    graph.run_ready()
    assert seen == [("service", ("/do", Empty.Request(), Empty.Response()))]


def test_action_goal_feedback_result_and_cancel():
    graph = make_graph()
    node = graph.add_node("server")
    handles = []

    def on_goal(handle):
        handles.append(handle)
        handle.on_cancel = lambda: handle.finish("canceled", RotateAbsolute.Result(delta=0.5))

    graph.add_action_server(node, "/rot", RotateAbsolute, on_goal)
    accepted, feedback, results = [], [], []
    graph.send_goal(
        "/rot", RotateAbsolute.Goal(theta=1.0), "client", accepted.append, feedback.append,
        lambda status, result: results.append((status, result)),
    )
    graph.run_ready()
    assert accepted == handles and handles[0].goal == RotateAbsolute.Goal(theta=1.0)
    handles[0].publish_feedback(RotateAbsolute.Feedback(remaining=0.25))
    graph.run_ready()
    assert feedback == [RotateAbsolute.Feedback(remaining=0.25)]
    graph.cancel_goal(handles[0])
    graph.run_ready()
    assert results == [("canceled", RotateAbsolute.Result(delta=0.5))]
    # a finished goal sends nothing more
    handles[0].publish_feedback(RotateAbsolute.Feedback(remaining=0.1))
    handles[0].finish("succeeded", RotateAbsolute.Result())
    graph.run_ready()
    assert len(feedback) == 1 and len(results) == 1


def test_remove_owner_destroys_its_nodes_endpoints_and_queued_callbacks():
    graph = make_graph()
    keep = graph.add_node("keep", owner="sim")
    gone = graph.add_node("gone", owner="ctl")
    got: list[str] = []
    graph.add_subscription(gone, "/chat", String, 10, lambda m: got.append("gone"))
    graph.add_subscription(keep, "/chat", String, 10, lambda m: got.append("keep"))
    graph.add_publisher(gone, "/cmd", Twist, 10)
    graph.add_service(gone, "/svc", Empty, lambda r, respond: None)
    fired: list[int] = []
    graph.add_timer(gone, 10, lambda: fired.append(1))
    graph.publish(graph.topic("/chat", String), String(data="x"))
    graph.remove_owner("ctl")
    graph.run_ready()
    assert got == ["keep"]
    assert [n.name for n in graph.nodes] == ["keep"]
    assert "/cmd" not in graph.topics  # its only publisher is gone
    assert "/svc" not in graph.services
    assert graph.advance(until_ns=1000) is False and fired == []
    assert gone.alive is False


def test_log_records_carry_ros_time_and_format_like_rcutils():
    graph = make_graph()
    records: list[LogRecord] = []
    graph.log_sinks.append(records.append)
    graph.now_ns = 1_500_000_000
    graph.log("turtle_controller", WARN, "careful")
    graph.info("turtle_controller", "hello")
    assert [r.level_name for r in records] == ["WARN", "INFO"]
    assert records[1].level == INFO
    assert records[0].t == 1.5
    assert records[0].format() == "[WARN] [1700000001.500000000] [turtle_controller]: careful"


@pytest.mark.parametrize(("text", "level"), [("info", 20), ("WARNING", 30), ("Warn", 30), ("debug", 10), (40, 40)])
def test_parse_level(text, level):
    assert parse_level(text) == level


def test_parse_level_rejects_unknown_names():
    with pytest.raises(ValueError, match="unknown log level 'loud'"):
        parse_level("loud")


def test_twist_is_delivered_as_the_same_object_type():
    graph = make_graph()
    node = graph.add_node("n")
    got: list[object] = []
    graph.add_subscription(node, "/turtle1/cmd_vel", Twist, 7, got.append)
    msg = Twist(linear=Vector3(x=1.0))
    graph.publish(graph.topics["/turtle1/cmd_vel"], msg)
    graph.run_ready()
    assert got == [msg] and type(got[0]) is Twist


def test_a_subscription_with_a_copy_function_gets_its_own_copy():
    graph = make_graph()
    node = graph.add_node("n")
    shared: list[object] = []
    own: list[object] = []
    graph.add_subscription(node, "/cmd", Twist, 7, shared.append)
    graph.add_subscription(node, "/cmd", Twist, 7, own.append, copy=copier(Twist))
    msg = Twist(linear=Vector3(x=1.0))
    graph.publish(graph.topic("/cmd", Twist), msg)
    msg.linear.x = 3.0
    graph.run_ready()
    assert shared[0] is msg
    assert own[0] is not msg and own[0].linear.x == 1.0


@pytest.mark.parametrize("other", ["copying subscription", "shared subscription", "tap", "transient local"])
def test_a_fresh_message_is_still_copied_for_a_subscription_where_someone_else_gets_it(other):
    graph = make_graph()
    node = graph.add_node("n")
    own: list[Twist] = []
    also: list[Twist] = []
    qos = None
    if other == "transient local":
        qos = Policies.named("reliable", "transient_local")
    pub = graph.add_publisher(node, "/cmd", Twist, 7, qos=qos)
    graph.add_subscription(node, "/cmd", Twist, 7, own.append, copy=copier(Twist))
    if other == "copying subscription":
        graph.add_subscription(node, "/cmd", Twist, 7, also.append, copy=copier(Twist))
    elif other == "shared subscription":
        graph.add_subscription(node, "/cmd", Twist, 7, also.append)
    elif other == "tap":
        graph.taps.append(lambda kind, payload: also.append(payload[1]))
    msg = Twist(linear=Vector3(x=1.0))
    graph.publish(pub.topic, msg, None, pub, fresh=True)
    graph.run_ready()
    kept = [m for _, m, _ in pub.kept] if other == "transient local" else also
    assert own[0] == msg and own[0] is not msg and own[0].linear is not msg.linear
    own[0].linear.x = 3.0  # the subscriber's to change: nobody else sees it
    assert msg.linear.x == 1.0 and [m.linear.x for m in kept] == [1.0]


def test_a_fresh_message_with_one_subscription_and_nobody_else_is_that_subscriptions():
    graph = make_graph()
    node = graph.add_node("n")
    own: list[Twist] = []
    pub = graph.add_publisher(node, "/cmd", Twist, 7)
    graph.add_subscription(node, "/cmd", Twist, 7, own.append, copy=copier(Twist))
    msg = Twist(linear=Vector3(x=1.0))
    graph.publish(pub.topic, msg, None, pub, fresh=True)
    graph.publish(pub.topic, Twist(linear=Vector3(x=2.0)), None, pub)
    graph.run_ready()
    assert own[0] is msg and own[1].linear.x == 2.0


@pytest.mark.parametrize("keeper", ["shared subscription", "copying subscription", "tap", "transient local"])
def test_a_snapshot_publish_gives_every_keeper_the_message_as_it_was(keeper):
    graph = make_graph()
    node = graph.add_node("n")
    kept: list[Twist] = []
    qos = Policies.named("reliable", "transient_local") if keeper == "transient local" else None
    pub = graph.add_publisher(node, "/cmd", Twist, 7, qos=qos)
    if keeper == "shared subscription":
        graph.add_subscription(node, "/cmd", Twist, 7, kept.append)
    elif keeper == "copying subscription":
        graph.add_subscription(node, "/cmd", Twist, 7, kept.append, copy=copier(Twist))
    elif keeper == "tap":
        graph.taps.append(lambda kind, payload: kept.append(payload[1]))
    msg = Twist(linear=Vector3(x=1.0))
    graph.publish(pub.topic, msg, None, pub, snapshot=copier(Twist))
    msg.linear.x = 3.0  # the publisher's: changed after publish
    graph.run_ready()
    if keeper == "transient local":
        kept = [m for _, m, _ in pub.kept]
    assert [m.linear.x for m in kept] == [1.0] and kept[0] is not msg


def test_a_snapshot_publish_copies_nothing_for_a_subscription_that_takes_its_values():
    graph = make_graph()
    node = graph.add_node("n")
    got: list[tuple] = []
    pub = graph.add_publisher(node, "/cmd", Twist, 7)
    copies: list[Twist] = []

    def snapshot(msg: Twist) -> Twist:
        copies.append(msg)
        return copier(Twist)(msg)

    graph.add_subscription(node, "/cmd", Twist, 7, got.append, copy=lambda m: (m.linear.x, m.angular.z))
    msg = Twist(linear=Vector3(x=1.0))
    graph.publish(pub.topic, msg, None, pub, snapshot=snapshot)
    msg.linear.x = 3.0
    graph.run_ready()
    assert got == [(1.0, 0.0)] and copies == []


def test_endpoints_come_off_the_graph_once():
    graph = make_graph()
    node = graph.add_node("n")
    got: list[str] = []
    pub = graph.add_publisher(node, "/chat", String, 10)
    sub = graph.add_subscription(node, "/chat", String, 10, lambda m: got.append(m.data))
    service = graph.add_service(node, "/svc", Empty, lambda r, respond: respond(Empty.Response()))
    client = graph.add_client(node, "/svc", Empty)
    server = graph.add_action_server(node, "/act", RotateAbsolute, lambda handle: None)
    action_client = graph.add_action_client(node, "/act", RotateAbsolute)
    graph.publish(pub.topic, String(data="queued"))
    assert (graph.count_publishers("/chat"), graph.count_subscribers("/chat")) == (1, 1)
    assert (graph.count_services("/svc"), graph.count_clients("/svc")) == (1, 1)
    for remove, record in (
        (graph.remove_endpoint, pub),
        (graph.remove_endpoint, sub),
        (graph.remove_service, service),
        (graph.remove_client, client),
        (graph.remove_action_server, server),
        (graph.remove_action_client, action_client),
    ):
        assert remove(record) is True
        assert remove(record) is False
    graph.run_ready()
    assert got == []  # a destroyed subscription's queue goes with it
    assert (graph.count_publishers("/chat"), graph.count_subscribers("/chat")) == (0, 0)
    assert (graph.count_services("/svc"), graph.count_clients("/svc")) == (0, 0)
    assert not graph.has_service("/svc") and not graph.has_action_server("/act")
    assert graph.topic_names_and_types() == graph.service_names_and_types() == []
    assert graph.action_names_and_types() == []


def test_a_service_removed_before_its_queued_call_runs_never_answers():
    graph = make_graph()
    node = graph.add_node("n")
    handled: list[str] = []
    service = graph.add_service(node, "/svc", Empty, lambda r, respond: handled.append("handled"))
    graph.call("/svc", Empty.Request(), lambda response: handled.append("answered"), "client")
    graph.remove_service(service)
    graph.run_ready()
    assert handled == []


def test_a_removed_service_name_can_be_provided_again():
    graph = make_graph()
    node = graph.add_node("n")
    first = graph.add_service(node, "/svc", Empty, lambda r, respond: None)
    graph.remove_service(first)
    second = graph.add_service(node, "/svc", Empty, lambda r, respond: None)
    assert graph.remove_service(first) is False and graph.has_service("/svc")
    assert graph.remove_service(second) is True


def test_graph_queries_list_names_types_and_endpoints_by_node():
    graph = make_graph()
    sim = graph.add_node("turtlesim", owner="sim")
    ctl = graph.add_node("ctl", "/lab")
    graph.add_publisher(sim, "/turtle1/pose", Pose, 7)
    graph.add_subscription(ctl, "/turtle1/pose", Pose, 5, lambda m: None, qos="sensor")
    graph.add_publisher(ctl, "/turtle1/cmd_vel", Twist, 10)
    graph.add_service(sim, "/spawn", Empty, lambda r, respond: None)
    graph.add_client(ctl, "/spawn", Empty)
    graph.add_client(ctl, "/kill", Empty)  # no server: listed all the same, as rcl lists it
    graph.add_action_client(ctl, "/turtle1/rotate_absolute", RotateAbsolute)
    assert graph.node_names_and_namespaces() == [("turtlesim", "/"), ("ctl", "/lab")]
    assert graph.find_node("ctl", "/lab/") is ctl and graph.find_node("ctl", "/") is None
    hidden = "/turtle1/rotate_absolute/_action/"  # the action client's (see the next test)
    assert [name for name, _ in graph.topic_names_and_types() if not name.startswith(hidden)] == [
        "/turtle1/cmd_vel", "/turtle1/pose"]
    assert ("/turtle1/pose", ["turtlesim/msg/Pose"]) in graph.topic_names_and_types()
    [sub] = graph.subscriptions_of("/turtle1/pose")
    assert (sub.node, sub.depth, sub.qos) == (ctl, 5, "sensor")
    assert graph.publishers_of("/nothing") == []
    assert [entry for entry in graph.service_names_and_types() if not entry[0].startswith(hidden)] == [
        ("/kill", ["std_srvs/srv/Empty"]), ("/spawn", ["std_srvs/srv/Empty"])]
    assert (graph.count_services("/kill"), graph.count_clients("/kill")) == (0, 1)
    assert graph.action_names_and_types() == [("/turtle1/rotate_absolute", ["turtlesim/action/RotateAbsolute"])]
    assert graph.names_and_types_by_node(ctl, "publishers") == [("/turtle1/cmd_vel", ["geometry_msgs/msg/Twist"])]
    assert graph.names_and_types_by_node(ctl, "subscriptions")[0] == ("/turtle1/pose", ["turtlesim/msg/Pose"])
    assert graph.names_and_types_by_node(ctl, "clients")[:2] == [
        ("/kill", ["std_srvs/srv/Empty"]), ("/spawn", ["std_srvs/srv/Empty"])]
    assert graph.names_and_types_by_node(sim, "services") == [("/spawn", ["std_srvs/srv/Empty"])]
    assert graph.names_and_types_by_node(ctl, "action_clients") == [
        ("/turtle1/rotate_absolute", ["turtlesim/action/RotateAbsolute"])
    ]
    assert graph.names_and_types_by_node(ctl, "action_servers") == []


def test_an_actions_hidden_topics_and_services_are_in_the_queries():
    # rcl_action's endpoints behind every action server and client (measured on
    # the real rclpy: tests/fidelity/programs/action_graph.py)
    graph = make_graph()
    sim = graph.add_node("turtlesim", owner="sim")
    ctl = graph.add_node("ctl", "/lab")
    server = graph.add_action_server(sim, "/turtle1/rotate_absolute", RotateAbsolute, lambda handle: None)
    first = graph.add_action_client(ctl, "/turtle1/rotate_absolute", RotateAbsolute)
    graph.add_action_client(ctl, "/turtle1/rotate_absolute", RotateAbsolute)
    feedback, status = "/turtle1/rotate_absolute/_action/feedback", "/turtle1/rotate_absolute/_action/status"
    topics = [
        (feedback, ["turtlesim/action/RotateAbsolute_FeedbackMessage"]),
        (status, ["action_msgs/msg/GoalStatusArray"]),
    ]
    services = [
        ("/turtle1/rotate_absolute/_action/cancel_goal", ["action_msgs/srv/CancelGoal"]),
        ("/turtle1/rotate_absolute/_action/get_result", ["turtlesim/action/RotateAbsolute_GetResult"]),
        ("/turtle1/rotate_absolute/_action/send_goal", ["turtlesim/action/RotateAbsolute_SendGoal"]),
    ]
    assert graph.topic_names_and_types() == topics
    assert graph.service_names_and_types() == services
    assert graph.names_and_types_by_node(sim, "publishers") == topics
    assert graph.names_and_types_by_node(sim, "services") == services
    assert graph.names_and_types_by_node(ctl, "subscriptions") == topics  # two clients, each name once
    assert graph.names_and_types_by_node(ctl, "clients") == services
    assert graph.names_and_types_by_node(sim, "subscriptions") == graph.names_and_types_by_node(ctl, "services") == []
    assert (graph.count_publishers(status), graph.count_subscribers(status)) == (1, 2)
    assert (graph.count_services(services[0][0]), graph.count_clients(services[0][0])) == (1, 2)
    [publisher] = graph.publishers_of(status)
    assert (publisher.node, publisher.topic.type_name, publisher.depth) == (sim, "action_msgs/msg/GoalStatusArray", 1)
    assert (publisher.qos.reliability, publisher.qos.durability) == (1, 1)  # reliable, transient local
    assert [s.qos.durability for s in graph.subscriptions_of(feedback)] == [2, 2]  # volatile
    assert graph.topics == {}  # derived for the queries: nothing is published there

    graph.remove_action_client(first)
    assert graph.count_subscribers(feedback) == 1
    graph.remove_action_server(server)
    assert graph.count_publishers(status) == 0 and graph.count_services(services[2][0]) == 0
    assert graph.topic_names_and_types() == topics  # the other client's are still there
    graph.remove_node(ctl)
    assert graph.topic_names_and_types() == graph.service_names_and_types() == []


def test_a_timer_made_without_autostart_waits_for_a_reset():
    graph = make_graph()
    node = graph.add_node("n")
    fired: list[int] = []
    timer = graph.add_timer(node, 100, lambda: fired.append(graph.now_ns), autostart=False)
    assert timer.canceled and graph.next_due() is None
    graph.now_ns = 50
    graph.reset_timer(timer)
    graph.advance()
    graph.run_ready()
    assert fired == [150]
    graph.cancel_timer(timer)
    assert graph.advance(until_ns=1000) is False and fired == [150]
