"""The sandbox protocol: every message round trips, and whatever a hostile child
sends decodes to a Report or fails with a WireError that says what and where."""

from __future__ import annotations

import json
import os
import random
import struct
import threading
import time
import typing

import pytest

from turtletui.runtime import protocol, wire
from turtletui.runtime.graph_mirror import (
    GraphMirror,
    MirrorEndpoint,
    MirrorNode,
    MirrorRecord,
    MirrorTopic,
    QosPolicies,
)

TWIST = [[1.5, 0.0, 0.0], [0.0, 0.0, -0.25]]

CHANGES: dict[type, tuple] = {
    protocol.DeclareNode: protocol.DeclareNode(1, "driver", "/robots"),
    protocol.RemoveNode: protocol.RemoveNode(1),
    protocol.DeclarePublisher: protocol.DeclarePublisher(2, 1, "/turtle1/cmd_vel", "geometry_msgs/msg/Twist", 10, QosPolicies(1, 2, 1)),
    protocol.DeclareSubscription: protocol.DeclareSubscription(3, 1, "/turtle1/pose", "turtlesim/msg/Pose", 1, "on_pose", None, True),
    protocol.RemoveEndpoint: protocol.RemoveEndpoint(3),
    protocol.DeclareTimer: protocol.DeclareTimer(1, 100_000_000, "tick"),
    protocol.DeclareService: protocol.DeclareService(1, "/reset_count", "std_srvs/srv/Empty"),
    protocol.DeclareClient: protocol.DeclareClient(1, "/spawn", "turtlesim/srv/Spawn"),
    protocol.DeclareActionClient: protocol.DeclareActionClient(1, "/turtle1/rotate_absolute", "turtlesim/action/RotateAbsolute"),
    protocol.DeclareActionServer: protocol.DeclareActionServer(1, "/spin", "turtlesim/action/RotateAbsolute"),
    protocol.RemoveRecord: protocol.RemoveRecord("action_server", 1, "/spin"),
    protocol.SetParameter: protocol.SetParameter(1, "gains", [0.5, 1, None, "x", True], False),
}
"""One of each graph change, with every kind of field value."""


def every_change_kind() -> set[type]:
    return set(typing.get_args(protocol.GraphChange))


def full_report() -> protocol.Report:
    return protocol.Report(
        changes=tuple(CHANGES.values()),
        logs=(protocol.Log(20, "driver", "hello ✓"), protocol.Log(40, "driver", "")),
        publishes=(protocol.Publish("/turtle1/cmd_vel", TWIST),),
        calls=(protocol.CallService(7, "/spawn", [1.0, 2.0, 0.5, "t2"]),),
        goals=(protocol.SendGoal(8, "/turtle1/rotate_absolute", [1.57]),),
        cancels=(protocol.CancelGoal(8),),
        responses=(protocol.ServiceResponse(3, []),),
        served=(
            protocol.AcceptServedGoal(4, "executing"),
            protocol.ServedGoalStatus(4, "canceling"),
            protocol.ServedGoalFeedback(4, [0.5]),
            protocol.AnswerServedCancel(4, 0, True),
            protocol.FinishServedGoal(4, "canceled", [0.25]),
            protocol.RejectServedGoal(5),
        ),
        logs_dropped=12,
        wake_ns=1_016_000_000,
        done=True,
        crash=protocol.Crash("exception", "ZeroDivisionError: division by zero", ('  File "x.py", line 3',)),
    )


def test_every_graph_change_kind_has_an_example_here():
    assert set(CHANGES) == every_change_kind()


def test_every_served_goal_event_kind_is_in_the_full_report():
    assert {type(e) for e in full_report().served} == set(typing.get_args(protocol.ServedGoalEvent))


def test_a_report_with_every_message_kind_round_trips():
    report = full_report()
    assert protocol.decode_report(protocol.encode_report(report)) == report


@pytest.mark.parametrize("kind", sorted(CHANGES, key=lambda cls: cls.__name__), ids=lambda cls: cls.__name__)
def test_each_graph_change_round_trips_as_its_own_type(kind):
    report = protocol.Report(changes=(CHANGES[kind],))
    [decoded] = protocol.decode_report(protocol.encode_report(report)).changes
    assert type(decoded) is kind
    assert decoded == CHANGES[kind]


def test_an_empty_report_is_an_empty_object():
    payload = protocol.encode_report(protocol.Report())
    assert payload == b"{}"
    assert protocol.decode_report(payload) == protocol.Report()


def test_qos_policies_come_back_as_their_type():
    [pub] = protocol.decode_report(protocol.encode_report(protocol.Report(changes=(CHANGES[protocol.DeclarePublisher],)))).changes
    assert isinstance(pub.qos, QosPolicies)


def test_a_tick_with_everything_round_trips():
    mirror = GraphMirror(
        (MirrorNode("turtlesim", "", 0), MirrorNode("driver", "", 1)),
        (MirrorTopic("/turtle1/pose", "turtlesim/msg/Pose", (MirrorEndpoint(0, QosPolicies(1, 2, 1), 0),), (MirrorEndpoint(0, None, 3),)),),
        (MirrorRecord(0, "/spawn", "turtlesim/srv/Spawn"),),
        (),
        (MirrorRecord(0, "/turtle1/rotate_absolute", "turtlesim/action/RotateAbsolute"),),
        (),
    )
    tick = protocol.Tick(
        16_000_000,
        (protocol.Delivery(3, [5.5, 5.5, 0.0, 0.0, 0.0]),),
        (protocol.ServiceResult(7, "turtlesim/srv/Spawn_Response", ["turtle2"]),),
        (
            protocol.GoalAccepted(8, 31, "accepted"),
            protocol.GoalStatus(8, "executing"),
            protocol.GoalFeedback(8, [0.7]),
            protocol.CancelAnswer(8, 1, False),
            protocol.GoalResult(8, "succeeded", [0.1]),
            protocol.GoalRejected(9),
        ),
        (protocol.ServiceRequest(1, "/reset_count", []),),
        (protocol.ParameterUpdate(1, "gain", 2.5),),
        (protocol.ServeGoal(12, "/spin", [1.0]), protocol.ServeCancel(12)),
        mirror,
        (protocol.StampedDelivery(1, 4, [5.5, 5.5, 0.0, 0.0, 0.0], 16_000_000, 2, bytes(range(16))),),
    )
    decoded = protocol.decode_from_parent(protocol.encode_tick(tick))
    assert decoded == tick
    assert type(decoded.stamped[0]) is protocol.StampedDelivery
    assert [type(e) for e in decoded.goal_events] == [type(e) for e in tick.goal_events]
    assert {type(e) for e in tick.goal_events} == set(typing.get_args(protocol.GoalEvent))
    assert [type(e) for e in decoded.served] == [protocol.ServeGoal, protocol.ServeCancel]
    assert type(decoded.graph) is GraphMirror


def test_a_bare_tick_and_the_end_round_trip():
    assert protocol.decode_from_parent(protocol.encode_tick(protocol.Tick(5))) == protocol.Tick(5)
    assert type(protocol.decode_from_parent(protocol.encode_end())) is protocol.End


# -- hostile input ------------------------------------------------------------------------------

MALFORMED = {
    # payload: what the error says
    b"{not json": "sent a malformed reply",
    b'{"log": []} {}': "more after the JSON value",
    b' {"log": []}': "no JSON value at char 0",
    b'{"log": "\xff"}': "sent a malformed reply",
    b"[1, 2]": "not an object",
    b"[" * 100_000 + b"]" * 100_000: "nested too deeply",
    b"": "no JSON value",
}


@pytest.mark.parametrize("payload", list(MALFORMED), ids=lambda p: repr(p[:16]))
def test_what_is_not_json_is_a_malformed_reply(payload):
    with pytest.raises(wire.WireError, match=MALFORMED[payload]) as caught:
        protocol.decode_report(payload)
    assert type(caught.value) is wire.WireError


REFUSED = [
    # (report entries, what the ProtocolError says)
    ({"teleport": []}, "unknown report entry 'teleport'"),
    ({"log": {"a": 1}}, "log: must be an array of Log records"),
    ({"log": [[20, "n"]]}, r"log\[0\]: a Log has 5 fields \(level, node, text, in_callback, call_step\), got 2"),
    ({"log": [[20, "n", "m", True, 0, "extra"]]}, "a Log has 5 fields"),
    ({"log": [[20, "n", "m", "yes", 0]]}, r"log\[0\]: Log.in_callback must be true or false, got str 'yes'"),
    ({"log": [[20, "n", "m", True, "first"]]}, r"log\[0\]: Log.call_step must be an integer, got str 'first'"),
    ({"log": [["loud", "n", "m", True, 0]]}, r"log\[0\]: Log.level must be an integer, got str 'loud'"),
    ({"log": [[True, "n", "m", True, 0]]}, "Log.level must be an integer, got bool True"),
    ({"log": [[20, 5, "m", True, 0]]}, "Log.node must be a string, got int 5"),
    ({"log": [[20, "n", "m", True, 0], 7]}, r"log\[1\]: a Log must be an array of its fields, got int 7"),
    ({"pub": [["/t", {"x": 1}, 0, False]]}, "Publish.values must be a list of field values, got dict"),
    ({"pub": [[5, [], 0, False]]}, "Publish.topic must be a string"),
    ({"call": [[1.0, "/spawn", []]]}, "CallService.call_id must be an integer, got float 1.0"),
    ({"goal": [[1, "/a"]]}, "a SendGoal has 3 fields"),
    ({"cancel": [5]}, r"cancel\[0\]: a CancelGoal must be an array of its fields, got int 5"),
    ({"resp": [["1", []]]}, "ServiceResponse.request_id must be an integer"),
    ({"decl": "node"}, "decl: must be an array of graph changes"),
    ({"decl": [[]]}, r"decl\[0\]: a graph change must be an array \[kind, fields...\]"),
    ({"decl": [[3, 1]]}, "unknown graph change int 3"),
    ({"decl": [["banana", 1]]}, "unknown graph change str 'banana' \\(known: node, rmnode, pub"),
    ({"decl": [["node", 1, "n"]]}, "a DeclareNode has 3 fields \\(wire_id, name, namespace\\), got 2"),
    ({"decl": [["node", 1, "n", None]]}, "DeclareNode.namespace must be a string, got NoneType None"),
    ({"decl": [["pub", 2, 1, "/t", "pkg/msg/T", "10", None]]}, "DeclarePublisher.depth must be an integer, got str '10'"),
    ({"decl": [["pub", 2, 1, "/t", "pkg/msg/T", 10, [1, 2]]]}, "DeclarePublisher.qos must be null or QoS policies"),
    ({"decl": [["sub", 2, 1, "/t", "pkg/msg/T", 10, 5, None, False]]}, "DeclareSubscription.label must be a string"),
    ({"decl": [["sub", 2, 1, "/t", "pkg/msg/T", 10, "cb", None, 1]]}, "DeclareSubscription.message_info must be true or false"),
    ({"decl": [["rmrecord", "turtle", 1, "/t"]]}, "RemoveRecord.kind must be one of service, client, action_client, action_server"),
    ({"served": [["accept", 1, "won"]]}, r"served\[0\]: AcceptServedGoal.status must be one of accepted, executing, got str 'won'"),
    ({"served": [["cancel", 1, 0, 1]]}, "AnswerServedCancel.canceling must be true or false"),
    ({"served": [["teleport", 1]]}, "unknown served-goal event str 'teleport'"),
    ({"decl": [["param", 1, "p", {"a": 1}, False]]}, "SetParameter.value must be a value a ROS parameter can hold"),
    ({"decl": [["param", 1, "p", [[1]], False]]}, "SetParameter.value must be a value a ROS parameter can hold"),
    ({"decl": [["param", 1, "p", 1, 0]]}, "SetParameter.remove must be true or false, got int 0"),
    ({"wake": "soon"}, "wake: must be an integer or null, got str 'soon'"),
    ({"wake": 1.5}, "wake: must be an integer or null, got float 1.5"),
    ({"done": 1}, "done: must be true or false"),
    ({"logs_dropped": -1}, "logs_dropped: must be a count"),
    ({"logs_dropped": "7"}, "logs_dropped: must be a count"),
    ({"crash": {"kind": "x"}}, "crash: a Crash must be an array of its fields, got dict"),
    ({"crash": ["x", "m", "frames"]}, "Crash.frames must be a list of strings, got str 'frames'"),
    ({"crash": ["x", "m", [1]]}, "Crash.frames must be a list of strings"),
]


@pytest.mark.parametrize(("entries", "says"), REFUSED, ids=[says[:40] for _, says in REFUSED])
def test_a_report_of_the_wrong_shape_is_refused_naming_the_record_and_field(entries, says):
    with pytest.raises(protocol.ProtocolError, match=says):
        protocol.decode_report(json.dumps(entries).encode())


def test_a_long_forged_value_is_shown_cut_short():
    with pytest.raises(protocol.ProtocolError) as caught:
        protocol.decode_report(json.dumps({"log": [["x" * 10_000, "n", "m", True, 0]]}).encode())
    assert len(str(caught.value)) < 200


def test_mutated_reports_never_raise_anything_but_wire_errors():
    """Whatever a child makes of a real report (fields swapped, dropped, retyped,
    nested), decoding gives a Report or a WireError: never a TypeError,
    IndexError or KeyError from turtletui's own code."""
    rng = random.Random(17)
    base = json.loads(protocol.encode_report(full_report()))
    oddities = [None, True, 0, -1, 2**70, 1.5, float("inf"), "", "x", [], {}, [[]], [None], {"a": []}]

    def mutate(value, depth=0):
        if isinstance(value, list) and value and rng.random() < 0.7:
            value = list(value)
            i = rng.randrange(len(value))
            roll = rng.random()
            if roll < 0.2:
                del value[i]
            elif roll < 0.3:
                value.append(rng.choice(oddities))
            else:
                value[i] = mutate(value[i], depth + 1)
            return value
        if isinstance(value, dict) and value and rng.random() < 0.8:
            value = dict(value)
            key = rng.choice(list(value))
            value[key] = mutate(value[key], depth + 1)
            return value
        return rng.choice(oddities)

    outcomes = {"report": 0, "refused": 0}
    for _ in range(3000):
        payload = json.dumps(mutate(base)).encode()
        try:
            protocol.decode_report(payload)
            outcomes["report"] += 1
        except wire.WireError as err:
            assert str(err)
            outcomes["refused"] += 1
    assert outcomes["refused"] > 1000 and outcomes["report"] > 0


# -- the frame reader ---------------------------------------------------------------------------


@pytest.fixture
def pipe():
    r, w = os.pipe()
    yield r, w
    for fd in (r, w):
        try:
            os.close(fd)
        except OSError:
            pass


@pytest.mark.parametrize("blocking", [True, False], ids=["blocking", "polling"])
def test_the_reader_takes_frames_whole_however_they_arrive(pipe, blocking):
    r, w = pipe
    reader = wire.FrameReader(r, spin=0.0 if blocking else 0.0002, blocking=blocking)
    payloads = [b"", b"x" * 70_000, protocol.encode_report(full_report())]
    data = b"".join(struct.pack(">I", len(p)) + p for p in payloads)

    def send() -> None:
        os.write(w, data[:3])  # a header cut in two
        time.sleep(0.01)
        os.write(w, data[3:])  # more than a pipe holds: written as it is read

    writer = threading.Thread(target=send)
    writer.start()
    try:
        assert [reader.read_frame() for _ in payloads] == payloads
    finally:
        writer.join()


def test_the_parent_refuses_a_frame_over_its_limit(pipe):
    r, w = pipe
    reader = wire.FrameReader(r, max_size=wire.MAX_REPLY_BYTES)
    os.write(w, struct.pack(">I", wire.MAX_REPLY_BYTES + 1) + b"{}")
    with pytest.raises(wire.FrameTooLarge, match=f"sent {wire.MAX_REPLY_BYTES + 1} bytes in one step"):
        reader.read_frame(time.monotonic() + 60)


def test_a_frame_half_sent_times_out_and_keeps_what_came(pipe):
    r, w = pipe
    reader = wire.FrameReader(r)
    os.write(w, struct.pack(">I", 10) + b"abc")
    with pytest.raises(wire.WireTimeout):
        reader.read_frame(time.monotonic() + 0.05)
    os.write(w, b"defghij")
    assert reader.read_frame(time.monotonic() + 60) == b"abcdefghij"


def test_a_closed_pipe_is_said_so(pipe):
    r, w = pipe
    reader = wire.FrameReader(r)
    os.write(w, struct.pack(">I", 10) + b"abc")
    os.close(w)
    with pytest.raises(wire.WireClosed):
        reader.read_frame(time.monotonic() + 60)


def test_frame_ready_reads_without_waiting(pipe):
    r, w = pipe
    seen = []
    reader = wire.FrameReader(r, max_size=100, on_data=lambda: seen.append(True))
    assert not reader.frame_ready()
    os.write(w, struct.pack(">I", 4) + b"ab")
    assert not reader.frame_ready()
    os.write(w, b"cd")
    assert reader.frame_ready()
    assert reader.read_frame(time.monotonic() + 60) == b"abcd"
    assert seen
    os.write(w, struct.pack(">I", 101))
    with pytest.raises(wire.FrameTooLarge):
        reader.frame_ready()


def test_the_wait_hook_may_give_up(pipe):
    """The parent's hook watches its child while it waits; what it raises ends the read."""
    r, _ = pipe

    class ChildGone(Exception):
        pass

    def wait(fd, remaining):
        assert remaining is not None and remaining > 0
        raise ChildGone

    reader = wire.FrameReader(r, wait=wait)
    with pytest.raises(ChildGone):
        reader.read_frame(time.monotonic() + 60)


def test_a_reports_json_is_what_json_dumps_writes() -> None:
    # the C encoder built once (protocol._json_encoder) must write what json.dumps does
    values = {
        "log": [protocol.Log(20, "n\u00e9", 'a "quoted"\nline \u2713', True)],
        "pub": [protocol.Publish("/x", [[1.5, -0.0, 1e300], [float("inf"), float("-inf"), float("nan")]], 3, False)],
        "wake": 2**70,
        "done": None,
    }
    encoded = protocol._ENCODE_JSON(values)
    assert encoded == json.dumps(values, separators=(",", ":"), allow_nan=True)
    with pytest.raises(TypeError, match="not JSON serializable"):
        protocol._ENCODE_JSON({"x": {1, 2}})
