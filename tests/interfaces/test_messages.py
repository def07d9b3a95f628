"""Tests for turtletui.interfaces: rclpy-compatible messages in pure Python.

Expected strings marked "ROS" were observed with the real rclpy message
classes (ros-rclpy 9.1 wheels, ROS_PYTHON_CHECK_FIELDS=1).
"""

from __future__ import annotations

import array
import copy
import json
import math
import pickle
import re
import subprocess
import sys

import pytest

import turtletui.interfaces as I
from turtletui.interfaces import (
    action_msgs,
    builtin_interfaces,
    example_interfaces,
    geometry_msgs,
    lifecycle_msgs,
    nav_msgs,
    rcl_interfaces,
    rosgraph_msgs,
    sensor_msgs,
    std_msgs,
    std_srvs,
    tf2_msgs,
    turtlesim,
    unique_identifier_msgs,
    visualization_msgs,
)
from turtletui.interfaces.geometry_msgs import (
    Point32,
    Pose,
    Quaternion,
    Twist,
    TwistStamped,
    Vector3,
)
from turtletui.interfaces.rcl_interfaces import Log, ParameterDescriptor, ParameterValue
from turtletui.interfaces.sensor_msgs import LaserScan
from turtletui.interfaces.std_msgs import Bool, Empty, Header, String, UInt8
from turtletui.interfaces.turtlesim import Color, RotateAbsolute, SetPen, Spawn


@pytest.fixture(autouse=True)
def _turtlesim_shown_as_itself():
    """turtlesim's classes print as ``turtlesim.*`` here. An in-process run of
    Kilted or later, earlier in the same test process, renames them for that
    process (turtletui.compat.distro.show_types_as): undo it."""
    I.show_package_as('turtlesim', 'turtlesim')


TURTLE_POSE = turtlesim.Pose

MODULES = [action_msgs, builtin_interfaces, example_interfaces, geometry_msgs, lifecycle_msgs, nav_msgs, rcl_interfaces, rosgraph_msgs,
           sensor_msgs,
           std_msgs, std_srvs, tf2_msgs, turtlesim, unique_identifier_msgs,
           visualization_msgs]


def message_classes() -> list[type]:
    """Every message class, including Request/Response/Goal/... parts."""
    classes = []
    for name in sorted(I._message._REGISTRY):
        cls = I._message._REGISTRY[name]
        if issubclass(cls, I.Message):
            classes.append(cls)
    return classes


ALL_MESSAGES = message_classes()


def raises_assert(func, *args, **kwargs) -> str:
    with pytest.raises(AssertionError) as info:
        func(*args, **kwargs)
    return str(info.value)


def set_field(msg, name, value):
    setattr(msg, name, value)


# ---------------------------------------------------------------------------
# construction and defaults
# ---------------------------------------------------------------------------

def test_keyword_construction_and_defaults():
    t = Twist(linear=Vector3(x=2.0), angular=Vector3(z=-1.5))
    assert (t.linear.x, t.linear.y, t.linear.z) == (2.0, 0.0, 0.0)
    assert t.angular.z == -1.5
    d = Twist()
    assert d.linear == Vector3() and d.angular == Vector3()
    assert d.linear is not d.angular
    assert Twist().linear is not Twist().linear  # fresh nested defaults
    assert Quaternion().w == 1.0 and Quaternion.W__DEFAULT == 1.0
    assert (Quaternion().x, Quaternion().y, Quaternion().z) == (0.0, 0.0, 0.0)
    p = TURTLE_POSE(x=5.5, theta=1.0)
    assert (p.x, p.y, p.theta, p.linear_velocity, p.angular_velocity) == (5.5, 0.0, 1.0, 0.0, 0.0)
    assert Color() == Color(r=0, g=0, b=0)
    assert String().data == '' and Bool().data is False and UInt8().data == 0
    assert Header().stamp == builtin_interfaces.Time(sec=0, nanosec=0)
    assert ParameterDescriptor().read_only is False
    assert ParameterDescriptor().floating_point_range == []
    req = SetPen.Request(r=255, width=3)
    assert (req.r, req.g, req.b, req.width, req.off) == (255, 0, 0, 3, 0)
    assert Spawn.Request(name='leo').name == 'leo' and Spawn.Response().name == ''
    assert RotateAbsolute.Goal(theta=1.5).theta == 1.5
    assert RotateAbsolute.Feedback().remaining == 0.0
    assert RotateAbsolute.Result().delta == 0.0


def test_array_fields_match_ros_storage():
    scan = LaserScan()
    assert scan.ranges == array.array('f') and isinstance(scan.ranges, array.array)
    scan.ranges = [1.0, 0.1]
    assert scan.ranges.typecode == 'f'
    assert scan.ranges.tolist() == [1.0, pytest.approx(0.1)]
    assert scan.ranges[1] != 0.1  # stored as float32, like ROS
    scan.ranges = (2.0,)
    assert scan.ranges == array.array('f', [2.0])
    same = array.array('f', [3.0])
    scan.intensities = same
    assert scan.intensities is same  # ROS keeps an array('f') as is
    # the ROS constructor converts with array.array() first, so ints work there
    assert LaserScan(ranges=[1, 2]).ranges == array.array('f', [1.0, 2.0])
    pv = ParameterValue(integer_array_value=[1, 2], string_array_value=('a',))
    assert pv.integer_array_value == array.array('q', [1, 2])
    assert pv.string_array_value == ('a',)  # non-numeric sequences are kept as given
    assert pv.double_array_value == array.array('d')
    uuid = unique_identifier_msgs.UUID()
    assert uuid.uuid == [0] * 16
    uuid.uuid = list(range(16))
    assert bytes(uuid.uuid) == bytes(range(16))


def test_constants():
    assert (Log.DEBUG, Log.INFO, Log.WARN, Log.ERROR, Log.FATAL) == (10, 20, 30, 40, 50)
    assert Log().INFO == 20
    assert action_msgs.GoalStatus.STATUS_SUCCEEDED == 4
    assert action_msgs.CancelGoal.Response.ERROR_REJECTED == 1
    assert rcl_interfaces.ParameterType.PARAMETER_DOUBLE == 3
    with pytest.raises(AttributeError):
        Log().INFO = 3  # read-only on instances, like ROS


def test_unknown_keyword_and_positional():
    text = raises_assert(Twist, linerr=Vector3(), foo=1)
    assert text.startswith('Invalid arguments passed to constructor: foo, linerr (')  # ROS
    assert "did you mean 'linear' instead of 'linerr'?" in text
    assert raises_assert(Empty, x=1).startswith('Invalid arguments passed to constructor: x')
    with pytest.raises(TypeError, match='positional'):
        Vector3(1.0)
    Twist(check_fields=True)  # accepted like Iron+ (checks are always on here)


def test_trusted_constructor():
    p = TURTLE_POSE._trusted(1.0, 2.0, 3.0, 0.5, -0.5)
    assert isinstance(p, TURTLE_POSE)
    assert p == TURTLE_POSE(x=1.0, y=2.0, theta=3.0, linear_velocity=0.5, angular_velocity=-0.5)
    c = Color._trusted(1, 2, 3)
    assert (c.r, c.g, c.b) == (1, 2, 3)
    v = Vector3._trusted(1, 2, 3)  # no checks at all: ints stay ints
    assert v.x == 1 and type(v.x) is int
    t = Twist._trusted(Vector3(x=1.0), Vector3())
    assert t.linear.x == 1.0
    with pytest.raises(TypeError):
        TURTLE_POSE._trusted(1.0, 2.0)


def test_copier_copies_everything_mutable_and_nothing_more():
    scan = LaserScan(ranges=[1.0, 2.0], intensities=[0.5])
    scan.header.frame_id = "turtle1"
    scan.header.stamp.sec = 7
    twin = I.copier(LaserScan)(scan)
    assert twin == scan and type(twin) is LaserScan
    assert twin.header is not scan.header and twin.header.stamp is not scan.header.stamp
    assert twin.ranges is not scan.ranges and twin.ranges.typecode == "f"
    scan.ranges[0] = 9.0
    scan.header.stamp.sec = 8
    twist = Twist(linear=Vector3(x=2.0))
    copied = I.copier(Twist)(twist)
    twist.linear.x = 0.0
    assert (twin.ranges[0], twin.header.stamp.sec, copied.linear.x) == (1.0, 7, 2.0)
    log = Log(name="n", msg="m")
    assert I.copier(Log)(log) == log
    with pytest.raises(I.InterfaceError, match="needs a message class"):
        I.copier(int)


def test_float32_rounder_rounds_float32_fields_as_cdr_carries_them():
    from turtletui.interfaces.geometry_msgs import Point32, Polygon, PolygonStamped

    stamped = PolygonStamped(polygon=Polygon(points=[Point32(x=0.1), Point32(y=1 / 3, z=3.4e38)]))
    I.float32_rounder(PolygonStamped)(stamped)
    assert [(p.x, p.y, p.z) for p in stamped.polygon.points] == [
        (0.10000000149011612, 0.0, 0.0),
        (0.0, 0.3333333432674408, 3.3999999521443642e38),
    ]
    assert I.float32_rounder(Twist) is None  # float64 only: nothing to do
    pose = I.get_interface("turtlesim/msg/Pose")(x=0.1, y=2.5, theta=float("nan"), angular_velocity=float("-inf"))
    pose._linear_velocity = 1e39  # beyond float32, as only a trusted builder could set it: an infinity, as C casts
    I.float32_rounder(type(pose))(pose)
    assert repr((pose.x, pose.y, pose.theta, pose.linear_velocity, pose.angular_velocity)) == repr(
        (0.10000000149011612, 2.5, float("nan"), float("inf"), float("-inf"))
    )
    assert I.float32_rounder(LaserScan) is not None  # angle_min ... (its ranges are array('f') already)
    with pytest.raises(I.InterfaceError, match="needs a message class"):
        I.float32_rounder(int)


def test_fields_getter_reads_the_named_fields_as_a_tuple():
    twist = Twist(linear=Vector3(x=1.5, y=-2.0), angular=Vector3(z=0.25))
    assert I.fields_getter(Twist, "linear.x", "linear.y", "angular.z")(twist) == (1.5, -2.0, 0.25)
    assert I.fields_getter(Twist, "angular.z")(twist) == (0.25,)
    assert I.fields_getter(Twist, "linear")(twist) == (twist.linear,)
    scan = LaserScan(range_max=10.0)
    assert I.fields_getter(LaserScan, "range_max", "header.stamp.sec")(scan) == (10.0, 0)
    for path in ("linear.w", "ranges", "speed"):
        with pytest.raises(I.InterfaceError, match=f"no scalar field '{path}'"):
            I.fields_getter(LaserScan if path == "ranges" else Twist, path)
    with pytest.raises(I.InterfaceError, match="needs a message class"):
        I.fields_getter(dict, "x")


# ---------------------------------------------------------------------------
# type checks on assignment and construction
# ---------------------------------------------------------------------------

def test_float_field_refuses_int_with_hint():
    t = Twist()
    text = raises_assert(set_field, t.linear, 'x', 2)
    assert text == ("The 'x' field must be of type 'float' "
                    '(got int 2; ROS 2 wants a float here: write 2.0)')
    assert raises_assert(Vector3, x=2).startswith("The 'x' field must be of type 'float' (")
    text = raises_assert(set_field, TURTLE_POSE(), 'theta', 'a')
    assert text.startswith("The 'theta' field must be of type 'float' (got str 'a';")
    assert raises_assert(set_field, Vector3(), 'x', True).startswith(
        "The 'x' field must be of type 'float' (got bool True")
    assert raises_assert(set_field, Vector3(), 'x', None).startswith(
        "The 'x' field must be of type 'float' (got None")
    assert t.linear.x == 0.0  # failed assignment left the value alone


def test_float_ranges_nan_inf_and_no_rounding():
    p = Point32()
    p.x = 0.1
    assert p.x == 0.1  # ROS python does not round float32 on assignment
    for value in (math.inf, -math.inf):
        p.y = value
        assert p.y == value
    p.z = math.nan
    assert math.isnan(p.z)
    text = raises_assert(set_field, p, 'x', 1e39)
    assert text.startswith(  # ROS
        "The 'x' field must be a float in [-3.402823466e+38, 3.402823466e+38] (got float 1e+39")
    v = Vector3(x=1e300)
    v.y = math.nan
    assert v.x == 1e300


def test_integer_fields():
    req = SetPen.Request()
    text = raises_assert(set_field, req, 'r', 256)
    assert text.startswith("The 'r' field must be an unsigned integer in [0, 255] (")  # ROS
    assert 'from 0 to 255' in text
    assert raises_assert(set_field, req, 'g', -1).startswith(
        "The 'g' field must be an unsigned integer in [0, 255]")
    text = raises_assert(set_field, req, 'b', 2.0)
    assert text == ("The 'b' field must be of type 'int' (got float 2.0; ROS 2 wants a whole "
                    'number (int) for this uint8 field: write 2)')
    assert 'round(' in raises_assert(SetPen.Request, width=2.5)
    assert raises_assert(builtin_interfaces.Time, sec=2 ** 31).startswith(
        "The 'sec' field must be an integer in [-2147483648, 2147483647]")  # ROS
    req.off = True  # bool is an int subclass; ROS accepts it too
    assert req.off is True
    assert raises_assert(SetPen.Request, r=300).startswith("The 'r' field must be an unsigned")


def test_string_bool_and_nested_fields():
    assert raises_assert(set_field, String(), 'data', 5) == (
        "The 'data' field must be of type 'str' "
        '(got int 5; ROS 2 wants a str here: convert it with str(...))')
    assert raises_assert(set_field, Bool(), 'data', 1).startswith(
        "The 'data' field must be of type 'bool' (got int 1; ROS 2 wants True or False")
    text = raises_assert(set_field, Twist(), 'linear', {'x': 1.0})
    assert text.startswith("The 'linear' field must be a sub message of type 'Vector3' (")
    assert 'Vector3(x=..., y=..., z=...)' in text and 'from geometry_msgs.msg import' in text
    text = raises_assert(set_field, Twist(), 'angular', Quaternion())
    assert 'geometry_msgs/msg/Quaternion' in text
    text = raises_assert(set_field, RotateAbsolute.Impl.SendGoalService.Request(), 'goal', 1)
    assert 'RotateAbsolute.Goal(theta=...)' in text


def test_sequence_checks():
    scan = LaserScan()
    text = raises_assert(set_field, scan, 'ranges', [1, 2])
    assert text.startswith(  # ROS
        "The 'ranges' field must be a set or sequence and each value of type 'float' and each "
        'float in [-340282346600000016151267322115014000640.000000, '
        '340282346600000016151267322115014000640.000000] (')
    assert 'item [0] is int 1: write 1.0' in text
    assert raises_assert(set_field, scan, 'ranges', array.array('d', [1.0])).startswith(
        "The 'ranges' array.array() must have the type code of 'f'")
    assert 'list of float' in raises_assert(set_field, scan, 'ranges', 'abc')
    raises_assert(set_field, scan, 'ranges', [1e39])
    text = raises_assert(set_field, ParameterDescriptor(), 'floating_point_range',
                         [rcl_interfaces.FloatingPointRange()] * 2)
    assert text.startswith("The 'floating_point_range' field must be a set or sequence with "
                           "length <= 1 and each value of type 'FloatingPointRange'")
    text = raises_assert(set_field, unique_identifier_msgs.UUID(), 'uuid', [1, 2])
    assert text.startswith("The 'uuid' field must be a set or sequence with length 16")
    raises_assert(set_field, unique_identifier_msgs.UUID(), 'uuid', [256] * 16)
    raises_assert(set_field, action_msgs.GoalStatusArray(), 'status_list',
                  [action_msgs.GoalInfo()])


def test_no_new_attributes():
    t = Twist()
    with pytest.raises(AttributeError):
        t.linearr = Vector3()
    assert not hasattr(t, '__dict__')


# ---------------------------------------------------------------------------
# equality, hashing, repr, fields dict, slots, copy and pickle
# ---------------------------------------------------------------------------

def test_equality_and_hash():
    assert Twist() == Twist()
    assert Twist(linear=Vector3(x=1.0)) != Twist()
    assert Vector3() != geometry_msgs.Point()  # same fields, other class
    assert Vector3() != None  # noqa: E711
    assert LaserScan(ranges=[1.0]) == LaserScan(ranges=[1.0])
    assert LaserScan(ranges=[1.0]) != LaserScan(ranges=[2.0])
    nan = Vector3(x=math.nan)
    assert nan != nan  # compared field by field like ROS
    with pytest.raises(TypeError, match='unhashable'):
        hash(Twist())


def test_repr_like_ros():
    assert repr(Twist(linear=Vector3(x=5.0))) == (  # ROS
        'geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=5.0, y=0.0, z=0.0), '
        'angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0))')
    assert repr(TwistStamped()) == (  # ROS
        'geometry_msgs.msg.TwistStamped(header=std_msgs.msg.Header(stamp='
        "builtin_interfaces.msg.Time(sec=0, nanosec=0), frame_id=''), "
        'twist=geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0), '
        'angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0)))')
    assert repr(String(data='it\'s "x"')) == 'std_msgs.msg.String(data=\'it\\\'s "x"\')'
    assert repr(Empty()) == 'std_msgs.msg.Empty()'
    assert repr(SetPen.Request(r=3)) == (
        'turtlesim.srv.SetPen_Request(r=3, g=0, b=0, width=0, off=0)')
    assert repr(RotateAbsolute.Goal()) == 'turtlesim.action.RotateAbsolute_Goal(theta=0.0)'
    assert repr(LaserScan(ranges=[1.0, 2.5])).endswith(  # ROS
        'range_max=0.0, ranges=[1.0, 2.5], intensities=[])')
    assert repr(ParameterValue(integer_array_value=[1, 2])).endswith(
        'integer_array_value=[1, 2], double_array_value=[], string_array_value=[])')
    assert repr(Log()) == (  # ROS
        'rcl_interfaces.msg.Log(stamp=builtin_interfaces.msg.Time(sec=0, nanosec=0), '
        "level=0, name='', msg='', file='', function='', line=0)")


def test_fields_and_field_types_like_ros():
    assert Twist.get_fields_and_field_types() == {
        'linear': 'geometry_msgs/Vector3', 'angular': 'geometry_msgs/Vector3'}
    assert Vector3.get_fields_and_field_types() == {'x': 'double', 'y': 'double', 'z': 'double'}
    assert TURTLE_POSE.get_fields_and_field_types() == {
        'x': 'float', 'y': 'float', 'theta': 'float', 'linear_velocity': 'float',
        'angular_velocity': 'float'}
    assert LaserScan.get_fields_and_field_types() == {
        'header': 'std_msgs/Header', 'angle_min': 'float', 'angle_max': 'float',
        'angle_increment': 'float', 'time_increment': 'float', 'scan_time': 'float',
        'range_min': 'float', 'range_max': 'float', 'ranges': 'sequence<float>',
        'intensities': 'sequence<float>'}
    assert Log.get_fields_and_field_types() == {
        'stamp': 'builtin_interfaces/Time', 'level': 'uint8', 'name': 'string',
        'msg': 'string', 'file': 'string', 'function': 'string', 'line': 'uint32'}
    assert Bool.get_fields_and_field_types() == {'data': 'boolean'}
    assert ParameterDescriptor.get_fields_and_field_types()['floating_point_range'] == \
        'sequence<rcl_interfaces/FloatingPointRange, 1>'
    assert ParameterValue.get_fields_and_field_types()['byte_array_value'] == 'sequence<octet>'
    assert unique_identifier_msgs.UUID.get_fields_and_field_types() == {'uuid': 'uint8[16]'}
    assert SetPen.Request.get_fields_and_field_types() == {
        'r': 'uint8', 'g': 'uint8', 'b': 'uint8', 'width': 'uint8', 'off': 'uint8'}
    assert RotateAbsolute.Impl.SendGoalService.Request.get_fields_and_field_types() == {
        'goal_id': 'unique_identifier_msgs/UUID', 'goal': 'turtlesim/RotateAbsolute_Goal'}
    fields = Twist.get_fields_and_field_types()
    fields['extra'] = 'x'
    assert 'extra' not in Twist.get_fields_and_field_types()  # a copy each time


def test_slots_names_and_type_names():
    assert Twist.__slots__ == ('_linear', '_angular')
    assert Empty.__slots__ == ()
    assert Twist.__name__ == 'Twist' and SetPen.Request.__name__ == 'SetPen_Request'
    assert Twist._TYPE_NAME == 'geometry_msgs/msg/Twist'
    assert TURTLE_POSE._TYPE_NAME == 'turtlesim/msg/Pose'
    assert SetPen.Request._TYPE_NAME == 'turtlesim/srv/SetPen_Request'
    assert SetPen._TYPE_NAME == 'turtlesim/srv/SetPen'
    assert RotateAbsolute._TYPE_NAME == 'turtlesim/action/RotateAbsolute'
    assert RotateAbsolute.Feedback._TYPE_NAME == 'turtlesim/action/RotateAbsolute_Feedback'


@pytest.mark.parametrize('cls', ALL_MESSAGES, ids=lambda c: c._TYPE_NAME)
def test_copy_and_pickle_every_type(cls):
    msg = I.from_dict(cls, sample_dict(cls))
    for clone in (copy.copy(msg), copy.deepcopy(msg), pickle.loads(pickle.dumps(msg))):
        assert type(clone) is cls
        assert clone == msg
    default = cls()
    assert pickle.loads(pickle.dumps(default, protocol=2)) == default


def test_copy_is_shallow_deepcopy_is_deep():
    t = Twist(linear=Vector3(x=1.0))
    assert copy.copy(t).linear is t.linear
    deep = copy.deepcopy(t)
    assert deep.linear is not t.linear and deep == t


# ---------------------------------------------------------------------------
# services and actions
# ---------------------------------------------------------------------------

def test_service_and_action_classes():
    with pytest.raises(NotImplementedError, match='Service classes can not be instantiated'):
        SetPen()
    with pytest.raises(NotImplementedError, match='Action classes can not be instantiated'):
        RotateAbsolute()
    assert std_srvs.SetBool.Request().data is False
    assert std_srvs.Trigger.Response(success=True, message='ok').message == 'ok'
    assert std_srvs.Empty.Request() == std_srvs.Empty.Request()
    assert turtlesim.SetPen_Request is SetPen.Request  # module-level, as in ROS
    impl = RotateAbsolute.Impl
    assert impl.CancelGoalService is action_msgs.CancelGoal
    assert impl.GoalStatusMessage is action_msgs.GoalStatusArray
    resp = impl.GetResultService.Response(status=4, result=RotateAbsolute.Result(delta=0.5))
    assert resp.result.delta == 0.5
    fb = impl.FeedbackMessage(feedback=RotateAbsolute.Feedback(remaining=1.0))
    assert fb.feedback.remaining == 1.0 and fb.goal_id.uuid == [0] * 16
    assert impl.SendGoalService.Response().stamp == builtin_interfaces.Time()


# ---------------------------------------------------------------------------
# to_dict / from_dict
# ---------------------------------------------------------------------------

def _sample_scalar(spec):
    if spec.kind == 'float':
        return 1.5
    if spec.kind == 'int':
        return 7
    if spec.kind == 'bool':
        return True
    if spec.kind == 'str':
        return 'abc'
    if spec.kind == 'byte':
        return 65
    return sample_dict(spec.msg_cls)


def sample_dict(cls) -> dict:
    """A non-default value for every field, in to_dict form."""
    out = {}
    for spec in cls._FIELDS:
        if spec.array == 0:
            out[spec.name] = _sample_scalar(spec)
        else:
            n = spec.size if spec.array == 3 else min(2, spec.size or 2)
            out[spec.name] = [_sample_scalar(spec) for _ in range(n)]
    return out


def test_to_dict_shape():
    assert I.to_dict(Twist(linear=Vector3(x=5.0))) == {
        'linear': {'x': 5.0, 'y': 0.0, 'z': 0.0}, 'angular': {'x': 0.0, 'y': 0.0, 'z': 0.0}}
    d = I.to_dict(LaserScan(ranges=[1.0, 2.0]))
    assert d['ranges'] == [1.0, 2.0] and type(d['ranges']) is list
    assert d['header'] == {'stamp': {'sec': 0, 'nanosec': 0}, 'frame_id': ''}
    assert I.to_dict(ParameterValue(byte_array_value=[b'a'])) ['byte_array_value'] == [97]
    assert I.to_dict(Empty()) == {}
    with pytest.raises(I.InterfaceError):
        I.to_dict({'x': 1.0})


@pytest.mark.parametrize('cls', ALL_MESSAGES, ids=lambda c: c._TYPE_NAME)
def test_round_trip_every_type(cls):
    default = cls()
    assert I.from_dict(cls, I.to_dict(default)) == default
    data = sample_dict(cls)
    msg = I.from_dict(cls, data)
    assert I.to_dict(msg) == data
    assert json.loads(json.dumps(I.to_dict(msg))) == data
    assert I.from_dict(cls._TYPE_NAME, json.loads(json.dumps(data))) == msg
    if data:
        assert msg != default
    # what from_dict builds passes the normal checks too
    assert cls(**{s.name: s.get(msg) for s in cls._FIELDS}) == msg


def test_from_dict_lenient_numbers_and_defaults():
    t = I.from_dict('geometry_msgs/msg/Twist', {'linear': {'x': 2}})
    assert t.linear.x == 2.0 and type(t.linear.x) is float
    assert t.angular == Vector3()
    scan = I.from_dict(LaserScan, {'ranges': [1, 2.5, math.inf], 'angle_min': math.nan})
    assert scan.ranges.typecode == 'f' and scan.ranges.tolist() == [1.0, 2.5, math.inf]
    assert math.isnan(scan.angle_min)
    assert I.from_dict(Empty, {}) == Empty()


@pytest.mark.parametrize(('cls', 'data', 'message', 'path'), [
    (Twist, {'linear': {'x': 'a'}},
     "geometry_msgs/msg/Twist: field 'linear.x' must be a float, got str 'a'", 'linear.x'),
    (Twist, {'angular': {'z': True}},
     "geometry_msgs/msg/Twist: field 'angular.z' must be a float, got bool True", 'angular.z'),
    (Twist, {'linear': [1.0]},
     "geometry_msgs/msg/Twist: field 'linear' must be a dict (a geometry_msgs/msg/Vector3 "
     'message), got list [1.0]', 'linear'),
    (Twist, {'linear': {'w': 1.0}},
     "geometry_msgs/msg/Twist: unknown field 'linear.w' (geometry_msgs/msg/Vector3 has "
     'fields: x, y, z)', 'linear.w'),
    (Twist, {'lineer': {}},
     "geometry_msgs/msg/Twist: unknown field 'lineer' (geometry_msgs/msg/Twist has fields: "
     'linear, angular)', 'lineer'),
    (LaserScan, {'ranges': [1.0, 'x']},
     "sensor_msgs/msg/LaserScan: field 'ranges[1]' must be a float, got str 'x'", 'ranges[1]'),
    (LaserScan, {'ranges': [1e39]},
     "sensor_msgs/msg/LaserScan: field 'ranges[0]' must be a float32 in "
     '[-3.402823466e+38, 3.402823466e+38], got float 1e+39', 'ranges[0]'),
    (LaserScan, {'header': {'stamp': {'sec': 2 ** 40}}},
     "sensor_msgs/msg/LaserScan: field 'header.stamp.sec' must be an int in "
     '[-2147483648, 2147483647] (int32), got int 1099511627776', 'header.stamp.sec'),
    (SetPen.Request, {'r': 256},
     "turtlesim/srv/SetPen_Request: field 'r' must be an int in [0, 255] (uint8), got int 256",
     'r'),
    (SetPen.Request, {'r': 1.0},
     "turtlesim/srv/SetPen_Request: field 'r' must be an int in [0, 255] (uint8), "
     'got float 1.0', 'r'),
    (Spawn.Request, {'name': None},
     "turtlesim/srv/Spawn_Request: field 'name' must be a str, got None", 'name'),
    (std_srvs.SetBool.Request, {'data': 1},
     "std_srvs/srv/SetBool_Request: field 'data' must be a bool, got int 1", 'data'),
    (action_msgs.GoalStatusArray, {'status_list': [{'status': 1}, {'goal_info': 3}]},
     "action_msgs/msg/GoalStatusArray: field 'status_list[1].goal_info' must be a dict "
     '(a action_msgs/msg/GoalInfo message), got int 3', 'status_list[1].goal_info'),
    (unique_identifier_msgs.UUID, {'uuid': [1, 2]},
     "unique_identifier_msgs/msg/UUID: field 'uuid' must be a list of exactly 16 items, "
     'got list [1, 2]', 'uuid'),
    (ParameterDescriptor, {'integer_range': [{}, {}]},
     "rcl_interfaces/msg/ParameterDescriptor: field 'integer_range' must be a list of at "
     'most 1 items, got list [{}, {}]', 'integer_range'),
    (LaserScan, {'ranges': 'abc'},
     "sensor_msgs/msg/LaserScan: field 'ranges' must be a list, got str 'abc'", 'ranges'),
])
def test_from_dict_errors_name_type_and_path(cls, data, message, path):
    with pytest.raises(I.InterfaceError) as info:
        I.from_dict(cls, data)
    assert str(info.value) == message
    assert info.value.path == path
    assert info.value.type_name == cls._TYPE_NAME
    assert isinstance(info.value, ValueError)


def test_from_dict_other_errors():
    with pytest.raises(I.InterfaceError, match='message data must be a dict, got list'):
        I.from_dict(Twist, [1, 2])
    with pytest.raises(I.InterfaceError, match='unknown field'):
        I.from_dict(Twist, {1: 2})
    with pytest.raises(I.InterfaceError, match='not a message type'):
        I.from_dict(SetPen, {})
    with pytest.raises(I.InterfaceError, match='unknown interface'):
        I.from_dict('geometry_msgs/msg/Nope', {})
    long = 'x' * 10000
    with pytest.raises(I.InterfaceError) as info:
        I.from_dict(TURTLE_POSE, {'x': long})
    assert len(str(info.value)) < 200  # untrusted values are shortened


# ---------------------------------------------------------------------------
# registry
# ---------------------------------------------------------------------------

def test_get_interface_forms():
    assert I.get_interface('geometry_msgs/msg/Twist') is Twist
    assert I.get_interface('geometry_msgs/Twist') is Twist
    assert I.get_interface('geometry_msgs.msg.Twist') is Twist
    assert I.get_interface('turtlesim/srv/SetPen') is SetPen
    assert I.get_interface('turtlesim/SetPen') is SetPen
    assert I.get_interface('turtlesim/srv/SetPen_Request') is SetPen.Request
    assert I.get_interface('turtlesim/action/RotateAbsolute') is RotateAbsolute
    assert I.get_interface('turtlesim/msg/Pose') is TURTLE_POSE
    assert I.get_interface('turtlesim_msgs/msg/Pose') is TURTLE_POSE
    assert I.get_interface('std_srvs/srv/Empty') is std_srvs.Empty
    assert I.get_interface('std_msgs/Empty') is std_msgs.Empty
    assert I.get_interface(Twist) is Twist


def test_get_interface_unknown_lists_close_matches():
    with pytest.raises(I.InterfaceError) as info:
        I.get_interface('geometry_msgs/msg/Twst')
    assert str(info.value).startswith(
        "unknown interface type 'geometry_msgs/msg/Twst'; did you mean geometry_msgs/msg/Twist")
    with pytest.raises(I.InterfaceError, match='turtlesim/srv/SetPen'):
        I.get_interface('turtlesim/srv/SetPn')
    with pytest.raises(I.InterfaceError, match='the full name is geometry_msgs/msg/Twist'):
        I.get_interface('Twist')
    with pytest.raises(I.InterfaceError, match='geometry_msgs/msg/Twist'):
        I.get_interface('geometry_msgs/twist')
    with pytest.raises(I.InterfaceError, match='all_interfaces'):
        I.get_interface('nothing/at/all')
    with pytest.raises(I.InterfaceError):
        I.get_interface(42)


def test_interface_name_and_lists():
    assert I.interface_name(Twist) == 'geometry_msgs/msg/Twist'
    assert I.interface_name(Twist()) == 'geometry_msgs/msg/Twist'
    assert I.interface_name(SetPen) == 'turtlesim/srv/SetPen'
    assert I.interface_name(SetPen.Request()) == 'turtlesim/srv/SetPen_Request'
    assert I.interface_name(RotateAbsolute) == 'turtlesim/action/RotateAbsolute'
    with pytest.raises(I.InterfaceError):
        I.interface_name(3)
    names = I.all_interfaces()
    assert names == sorted(names)
    required = [
        'geometry_msgs/msg/' + n for n in (
            'Vector3', 'Point', 'Point32', 'Quaternion', 'Pose', 'Pose2D', 'Twist', 'Accel',
            'Transform', 'TwistStamped')
    ] + ['std_msgs/msg/' + n for n in (
        'Header', 'String', 'Bool', 'Int32', 'Int64', 'Float32', 'Float64', 'Empty',
        'ColorRGBA', 'UInt8')
    ] + ['std_srvs/srv/Empty', 'std_srvs/srv/Trigger', 'std_srvs/srv/SetBool',
         'sensor_msgs/msg/LaserScan', 'turtlesim/msg/Pose', 'turtlesim/msg/Color',
         'turtlesim/srv/Spawn', 'turtlesim/srv/Kill', 'turtlesim/srv/SetPen',
         'turtlesim/srv/TeleportAbsolute', 'turtlesim/srv/TeleportRelative',
         'turtlesim/action/RotateAbsolute', 'rcl_interfaces/msg/Log',
         'builtin_interfaces/msg/Time', 'builtin_interfaces/msg/Duration']
    assert not set(required) - set(names)
    assert not [n for n in names if n.endswith(('_Request', '_Response', '_Goal'))]
    for name in names:
        assert I.interface_name(I.get_interface(name)) == name


def test_module_exports_for_shims():
    for module in MODULES:
        assert module.__all__ == sorted(module.__all__)
        for name in module.__all__:
            cls = getattr(module, name)
            assert cls.__name__ == name
            package, kind, _ = cls._TYPE_NAME.split('/')
            assert cls.__module__.rpartition('.')[0] == f'{package}.{kind}'  # as rosidl's: see below
            assert cls._TYPE_NAME in I.all_interfaces()
    assert 'SetPen_Request' not in turtlesim.__all__
    assert set(I.ros_module_members('turtlesim', 'srv')) == {  # as rosidl_generator_py's __init__.py
        f'{name}{part}' for name in ('Spawn', 'Kill', 'SetPen', 'TeleportAbsolute', 'TeleportRelative')
        for part in ('', '_Request', '_Response', '_Event')}
    assert I.ros_module_members('turtlesim_msgs', 'msg') == {'Pose': TURTLE_POSE, 'Color': Color}
    assert I.ros_module_members('turtlesim', 'action') == {
        'RotateAbsolute': RotateAbsolute,
        **{f'RotateAbsolute_{service}_{part}': getattr(getattr(RotateAbsolute.Impl, f'{service}Service'), part)
           for service in ('GetResult', 'SendGoal') for part in ('Event', 'Request', 'Response')}}
    with pytest.raises(I.InterfaceError):
        I.ros_module_members('turtlesim', 'nope')


# ---------------------------------------------------------------------------
# class identities: what type(msg) prints (rosidl_generator_py's modules)
# ---------------------------------------------------------------------------

@pytest.mark.parametrize(('cls', 'module', 'qualname'), [
    (Twist, 'geometry_msgs.msg._twist', 'Twist'),
    (std_msgs.Float64MultiArray, 'std_msgs.msg._float64_multi_array', 'Float64MultiArray'),
    (geometry_msgs.PoseWithCovarianceStamped, 'geometry_msgs.msg._pose_with_covariance_stamped',
     'PoseWithCovarianceStamped'),
    (geometry_msgs.Point32, 'geometry_msgs.msg._point32', 'Point32'),
    (unique_identifier_msgs.UUID, 'unique_identifier_msgs.msg._uuid', 'UUID'),
    (rcl_interfaces.SetParametersAtomically, 'rcl_interfaces.srv._set_parameters_atomically',
     'SetParametersAtomically'),
    (std_srvs.SetBool.Request, 'std_srvs.srv._set_bool', 'SetBool_Request'),
    (std_srvs.SetBool.Event, 'std_srvs.srv._set_bool', 'SetBool_Event'),
    (SetPen.Response, 'turtlesim.srv._set_pen', 'SetPen_Response'),
    (RotateAbsolute, 'turtlesim.action._rotate_absolute', 'RotateAbsolute'),
    (RotateAbsolute.Feedback, 'turtlesim.action._rotate_absolute', 'RotateAbsolute_Feedback'),
    (RotateAbsolute.Impl, 'turtlesim.action._rotate_absolute', 'RotateAbsolute.Impl'),
    (RotateAbsolute.Impl.SendGoalService.Request, 'turtlesim.action._rotate_absolute',
     'RotateAbsolute_SendGoal_Request'),
    (RotateAbsolute.Impl.CancelGoalService, 'action_msgs.srv._cancel_goal', 'CancelGoal'),
], ids=lambda value: value if isinstance(value, str) else value.__qualname__)
def test_classes_are_named_as_rosidl_names_them(cls, module, qualname):
    """As ROS 2 Kilted's (measured): <class 'geometry_msgs.msg._twist.Twist'>."""
    assert (cls.__module__, cls.__qualname__) == (module, qualname)
    assert cls.__name__ == qualname.rpartition('.')[2]
    assert repr(cls) == str(cls) == f"<class '{module}.{qualname}'>"
    if qualname.endswith('Impl'):
        assert type(cls) is type
    else:
        assert repr(type(cls)) == f"<class '{module}.Metaclass_{qualname}'>"


def test_services_have_rosidl_s_event_message():
    """Service introspection's Event (Iron on), also of an action's services."""
    event = SetPen.Event
    assert event.get_fields_and_field_types() == {
        'info': 'service_msgs/ServiceEventInfo',
        'request': 'sequence<turtlesim/SetPen_Request, 1>',
        'response': 'sequence<turtlesim/SetPen_Response, 1>'}
    assert repr(std_srvs.Empty.Event()).startswith('std_srvs.srv.Empty_Event(info=service_msgs.msg.ServiceEventInfo(')
    assert turtlesim.SetPen_Event is event
    assert RotateAbsolute.Impl.GetResultService.Event.__qualname__ == 'RotateAbsolute_GetResult_Event'
    with pytest.raises(AssertionError):
        std_srvs.SetBool.Event(request=[std_srvs.SetBool.Request()] * 2)  # at most one


def test_a_distro_renames_turtlesim_s_classes_and_back():
    try:
        I.show_package_as('turtlesim', 'turtlesim_msgs')
        assert repr(Spawn.Request) == "<class 'turtlesim_msgs.srv._spawn.Spawn_Request'>"
        assert repr(type(TURTLE_POSE)) == "<class 'turtlesim_msgs.msg._pose.Metaclass_Pose'>"
        assert RotateAbsolute.Impl.__module__ == 'turtlesim_msgs.action._rotate_absolute'
        assert RotateAbsolute.Impl.FeedbackMessage.get_fields_and_field_types()['feedback'] == \
            'turtlesim_msgs/RotateAbsolute_Feedback'
        assert Spawn.Event.get_fields_and_field_types()['request'] == 'sequence<turtlesim_msgs/Spawn_Request, 1>'
        assert Spawn.Event.SLOT_TYPES[1].value_type.namespaces == ['turtlesim_msgs', 'srv']
        assert repr(Spawn.Request()) == "turtlesim_msgs.srv.Spawn_Request(x=0.0, y=0.0, theta=0.0, name='')"
        assert I.interface_name(Spawn.Request) == 'turtlesim/srv/Spawn_Request'  # the registry's name stays
    finally:
        I.show_package_as('turtlesim', 'turtlesim')
    assert repr(Spawn.Request) == "<class 'turtlesim.srv._spawn.Spawn_Request'>"
    assert RotateAbsolute.Impl.FeedbackMessage.get_fields_and_field_types()['feedback'] == \
        'turtlesim/RotateAbsolute_Feedback'
    assert Spawn.Event.SLOT_TYPES[1].value_type.namespaces == ['turtlesim', 'srv']


def test_slot_types_are_the_fields_types_as_rosidl_parser_describes_them():
    from turtletui.interfaces import rosidl_definition as d

    # no shipped message has every kind of field: one made from text, for this test only
    text = ('string<=5 a\nwstring b\nwstring<=3 c\nchar d\nbyte e\n'
            'float64[3] f\nint16[<=4] g\ngeometry_msgs/Vector3[] h\nbool i\n')
    cls = I._message._create_message('test_msgs/msg/SlotKinds', text, 'test_msgs.msg._slot_kinds')
    del I._message._REGISTRY['test_msgs/msg/SlotKinds']
    assert cls.SLOT_TYPES == (
        d.BoundedString(5), d.UnboundedWString(), d.BoundedWString(3), d.BasicType('uint8'), d.BasicType('octet'),
        d.Array(d.BasicType('double'), 3), d.BoundedSequence(d.BasicType('int16'), 4),
        d.UnboundedSequence(d.NamespacedType(['geometry_msgs', 'msg'], 'Vector3')), d.BasicType('boolean'),
    )
    assert cls().SLOT_TYPES is cls.SLOT_TYPES
    assert repr(cls.SLOT_TYPES[0]).startswith('<rosidl_parser.definition.BoundedString object at 0x')
    with pytest.raises(TypeError):
        hash(cls.SLOT_TYPES[0])


@pytest.mark.parametrize('protocol', range(2, pickle.HIGHEST_PROTOCOL + 1))
def test_classes_pickle_by_their_names_where_no_ros_module_exists(protocol):
    """Classes and messages pickle by their full names, so they need no module
    geometry_msgs.msg._twist (only controllers' processes have those)."""
    for cls in (Twist, SetPen, SetPen.Request, SetPen.Event, RotateAbsolute, RotateAbsolute.Impl.FeedbackMessage):
        assert pickle.loads(pickle.dumps(cls, protocol)) is cls
    msg = RotateAbsolute.Impl.FeedbackMessage(feedback=RotateAbsolute.Feedback(remaining=1.5))
    data = pickle.dumps([msg, type(msg)], protocol)
    assert b'turtlesim.action._rotate_absolute' not in data and b'turtlesim/action/RotateAbsolute_FeedbackMessage' in data
    assert pickle.loads(data) == [msg, type(msg)]


def test_like_ros_s_slotted_messages_do_not_pickle_with_protocols_0_and_1():
    for protocol in (0, 1):
        with pytest.raises(TypeError):
            pickle.dumps(Twist(), protocol)


# ---------------------------------------------------------------------------
# definition_text (`ros2 interface show`)
# ---------------------------------------------------------------------------

def test_definition_text_twist():
    assert I.definition_text('geometry_msgs/msg/Twist') == (
        '# This expresses velocity in free space broken into its linear and angular parts.\n'
        '\n'
        'Vector3  linear\n'
        '\tfloat64 x\n'
        '\tfloat64 y\n'
        '\tfloat64 z\n'
        'Vector3  angular\n'
        '\tfloat64 x\n'
        '\tfloat64 y\n'
        '\tfloat64 z')


def test_definition_text_services_and_action():
    assert I.definition_text('turtlesim/srv/SetPen') == (
        'uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off\n---')
    assert I.definition_text(Spawn) == (
        'float32 x\nfloat32 y\nfloat32 theta\n'
        'string name # Optional.  A unique name will be created and returned if this is empty\n'
        '---\nstring name')
    assert I.definition_text('turtlesim/srv/Kill') == 'string name\n---'
    assert I.definition_text('std_srvs/srv/Empty') == '---'
    assert I.definition_text(RotateAbsolute) == (
        '# The desired heading in radians\nfloat32 theta\n---\n'
        '# The angular displacement in radians to the starting position\nfloat32 delta\n---\n'
        '# The remaining rotation in radians\nfloat32 remaining')
    assert I.definition_text(TURTLE_POSE()) == (
        'float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\n'
        'float32 angular_velocity')


def test_definition_text_nested_levels_and_comment_flags():
    text = I.definition_text('geometry_msgs/msg/TwistStamped')
    assert text.startswith('# A twist with reference coordinate frame and timestamp\n\n'
                           'std_msgs/Header header\n'
                           '\tbuiltin_interfaces/Time stamp\n'
                           '\t\tint32 sec\n'
                           '\t\tuint32 nanosec\n'
                           '\tstring frame_id\n'
                           'Twist twist\n'
                           '\tVector3  linear\n'
                           '\t\tfloat64 x\n')
    assert '#' not in I.definition_text(Pose, no_comments=True)
    assert I.definition_text(Pose, no_comments=True).startswith('Point position\n\tfloat64 x')
    full = I.definition_text(Pose, all_comments=True)
    assert '\t# This contains the position of a point in free space' in full
    # ros2cli keeps the '#' of a trailing comment when it strips the comment
    assert I.definition_text('std_srvs/srv/SetBool', no_comments=True) == (
        'bool data #\n---\nbool success   #\nstring message #')


# ---------------------------------------------------------------------------
# start-up and speed
# ---------------------------------------------------------------------------

def test_import_is_stdlib_only():
    # (how long it takes is bench/bench_messages.py's to say)
    code = 'import sys; import turtletui.interfaces; print("numpy" in sys.modules)'
    out = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                         check=True).stdout
    assert out.split() == ['False']


# -- to_values / from_values: the sandbox's positional wire format ------------------------------

def test_values_round_trip_for_every_registered_message() -> None:
    from turtletui.interfaces import from_values, to_values, trusted_from_values

    for name in I.all_interfaces():
        cls = I.get_interface(name)
        if not issubclass(cls, I.Message):
            continue
        msg = cls()
        values = to_values(msg)
        assert from_values(cls, values) == msg, name
        assert trusted_from_values(cls)(values) == msg, name


def test_values_are_positional_and_nested() -> None:
    from turtletui.interfaces import from_values, to_values

    twist = Twist(linear=Vector3(x=5.0), angular=Vector3(z=1.5))
    assert to_values(twist) == [[5.0, 0.0, 0.0], [0.0, 0.0, 1.5]]
    assert from_values("geometry_msgs/msg/Twist", [[5.0, 0.0, 0.0], [0.0, 0.0, 1.5]]) == twist


@pytest.mark.parametrize(
    ("values", "message"),
    [
        ([[5.0, "a", 0.0], [0.0, 0.0, 0.0]], "field 'linear.y' must be a float, got str 'a'"),
        ([[5.0]], "the message must be a list of 2 field values"),
        ({"linear": {}}, "message values must be a list"),
        ([[5.0, 0.0, 0.0], {"x": 1.0}], "field 'angular' must be a list of the geometry_msgs/msg/Vector3 field values"),
    ],
)
def test_from_values_names_what_is_wrong(values, message) -> None:
    from turtletui.interfaces import from_values

    with pytest.raises(I.InterfaceError, match=re.escape(message)):
        from_values(Twist, values)


def test_from_values_refuses_a_service_class_like_from_dict() -> None:
    from turtletui.interfaces import from_dict, from_values

    for build, data in ((from_dict, {}), (from_values, [])):
        with pytest.raises(I.InterfaceError, match="turtlesim/srv/SetPen is not a message type"):
            build("turtlesim/srv/SetPen", data)



_ODD_VALUES = [
    0, 1, -1, 2**31, 2**64, True, False, 0.5, -0.0, 1e39, -1e39, math.inf, -math.inf, math.nan,
    "", "x", "x" * 300, None, [], [0.0], {"x": 1.0}, b"\x01",
]
"""Values put in every place of a message's values: right, convertible or wrong."""


def _outcome(build, cls, values):
    try:
        msg = build(cls, values)
    except I.InterfaceError as err:
        return ("error", str(err))
    return ("ok", type(msg), I.to_dict(msg), [type(v) for v in _leaves(I.to_values(msg))])


def _leaves(values):
    for value in values:
        if isinstance(value, list):
            yield from _leaves(value)
        else:
            yield value


def _places(values, path=()):
    for i, value in enumerate(values):
        if isinstance(value, list):
            yield from _places(value, (*path, i))
        yield (*path, i)


def _replaced(values, place, new):
    values = copy.deepcopy(values)
    target = values
    for i in place[:-1]:
        target = target[i]
    target[place[-1]] = new
    return values


def test_compiled_values_functions_agree_with_the_generic_ones() -> None:
    """Messages of plain fields get compiled to_values/from_values
    (turtletui.interfaces._values): same messages, same conversions (an int
    where a float is due) and the same errors as the generic path, whatever
    is put wherever."""
    from turtletui.interfaces import _from_values, _to_values_generic, from_values
    from turtletui.interfaces._values import plain_fields

    def generic(cls, values):
        try:
            return _from_values(cls, values)
        except I._Bad as bad:
            raise I._interface_error(cls._TYPE_NAME, bad) from None

    compiled = 0
    for name in I.all_interfaces():
        cls = I.get_interface(name)
        if not issubclass(cls, I.Message) or not plain_fields(cls):
            continue
        compiled += 1
        good = I.to_values(cls())
        assert good == _to_values_generic(cls()), name
        tries = [good, [*good, 0.0], good[:-1]] if good else [good, [0.0]]
        tries += [_replaced(good, place, odd) for place in _places(good) for odd in _ODD_VALUES]
        for values in tries:
            assert _outcome(from_values, cls, values) == _outcome(generic, cls, values), (name, values)
    assert compiled > 50  # Twist, Pose, Color, Vector3, Time ... (not sequences)


def test_to_values_makes_plain_python_of_float_subclasses() -> None:
    class Float(float):
        pass

    twist = Twist(linear=Vector3(x=Float(2.5)))
    values = I.to_values(twist)
    assert values == [[2.5, 0.0, 0.0], [0.0, 0.0, 0.0]]
    assert type(values[0][0]) is float


def test_a_message_unpickled_before_its_class_was_used_still_checks_assignments() -> None:
    """A class's setters are compiled on first use; a message that arrives by
    pickle in a fresh process (no constructor ran) checks the same way."""
    code = (
        "import pickle, sys\n"
        "from turtletui.interfaces.geometry_msgs import Vector3\n"
        "msg = pickle.loads(sys.stdin.buffer.read())\n"
        "msg.x = 2.0\n"
        "try:\n"
        "    msg.y = 1\n"
        "except AssertionError as err:\n"
        "    print(err)\n"
        "print(msg)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], input=pickle.dumps(Vector3(x=1.0)),
                         capture_output=True, check=True).stdout.decode().splitlines()
    assert out == [
        "The 'y' field must be of type 'float' (got int 1; ROS 2 wants a float here: write 1.0)",
        "geometry_msgs.msg.Vector3(x=2.0, y=0.0, z=0.0)",
    ]
