"""What the graph keeps of each message's origin for a callback that takes
rclpy's MessageInfo: publishers count their messages from 1, and only a
``stamped`` subscription queues the origin with the message."""

from __future__ import annotations

from collections import deque

from turtletui.graph.core import Graph, MessageOrigin
from turtletui.graph.qos import Policies
from turtletui.interfaces import copier, interface_name
from turtletui.interfaces.std_msgs import String


def test_only_a_stamped_subscription_queues_where_each_message_comes_from():
    graph = Graph(type_name=interface_name)
    node = graph.add_node("n", "", "me")
    plain = graph.add_subscription(node, "/t", String, 10, lambda msg: None, copy=copier(String))
    stamped = graph.add_subscription(node, "/t", String, 10, lambda entry: None, copy=copier(String), stamped=True)
    first = graph.add_publisher(node, "/t", String, 10)
    second = graph.add_publisher(node, "/t", String, 10)
    graph.now_ns = 7
    for publisher, text in ((first, "a"), (second, "b"), (first, "c")):
        graph.publish(publisher.topic, String(data=text), None, publisher)
    # an ordinary subscription's queue stays a bare deque: nothing more per message
    assert type(plain.queue) is deque
    assert [msg.data for msg in plain.queue] == ["a", "b", "c"]
    assert [(msg.data, origin) for msg, origin in stamped.queue] == [
        ("a", MessageOrigin(7, 7, 1, first)),
        ("b", MessageOrigin(7, 7, 1, second)),
        ("c", MessageOrigin(7, 7, 2, first)),
    ]
    got = []
    stamped.callback = got.append
    stamped.deliver()
    assert [(msg.data, origin.sequence) for msg, origin in got] == [("a", 1), ("b", 1), ("c", 2)]


def test_a_late_joiner_gets_the_kept_messages_with_when_they_were_sent():
    graph = Graph(type_name=interface_name)
    node = graph.add_node("n", "", "me")
    latched = Policies.named("reliable", "transient_local")
    publisher = graph.add_publisher(node, "/map", String, 2, qos=latched)
    for i, now in enumerate((10, 20, 30)):
        graph.now_ns = now
        graph.publish(publisher.topic, String(data=f"v{i}"), None, publisher)
    graph.now_ns = 40
    late = graph.add_subscription(node, "/map", String, 2, lambda entry: None, qos=latched, stamped=True)
    assert [(msg.data, origin) for msg, origin in late.queue] == [
        ("v1", MessageOrigin(20, 40, 2, publisher)),
        ("v2", MessageOrigin(30, 40, 3, publisher)),
    ]
