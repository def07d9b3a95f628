"""turtletui's rclpy behaves as the real rclpy does where course code can tell.

Every expectation here was observed with the real rclpy (ros-rclpy 9.1.2 wheels, the ones
make_rclpy_surface.py is run with), without a running ROS graph: init/shutdown, loggers
and their filters, Duration/Time/Clock arithmetic, Parameter types and messages, QoS
profiles and Futures. The tests that need no turtletui host (Duration, Time, Clock,
Parameter, QoS, Future) were also run unchanged against the real rclpy and pass there, as do
the host-based init/shutdown, logging-filter, level and parameter-callback ones (with a
fixture doing rclpy.init/try_shutdown, and without the checks of captured log records).

The host-based ones run as a controller's main() (run_body) under both hosts, in-process
and sandboxed, and must behave the same in each.
"""

from __future__ import annotations

import inspect
import json
import textwrap
import warnings
from pathlib import Path

import pytest
from support.hosts import node_logs

from turtletui import compat
from turtletui.api import RunResult

SURFACE = json.loads(Path(__file__).with_name("rclpy_surface.json").read_text(encoding="utf-8"))

compat.install()

import rclpy  # noqa: E402
from rclpy.clock import Clock, ClockType, ROSClock  # noqa: E402
from rclpy.duration import Duration  # noqa: E402
from rclpy.logging import LoggingSeverity  # noqa: E402
from rclpy.parameter import Parameter  # noqa: E402
from rclpy.qos import (  # noqa: E402
    HistoryPolicy,
    InvalidQoSProfileException,
    QoSProfile,
    ReliabilityPolicy,
    qos_profile_sensor_data,
    qos_profile_system_default,
)
from rclpy.task import Future  # noqa: E402
from rclpy.time import Time  # noqa: E402


def run_body(controller_host, body, *, duration: float = 2.0, **options) -> RunResult:
    """Run ``body`` (a function of this module, no arguments) as a controller's
    main() under ``controller_host``; an assertion failing in it is a crash."""
    source = "\n".join(
        [
            BODY_HEADER,
            f"SURFACE = {SURFACE!r}",
            *(inspect.getsource(helper) for helper in (beh_node, calls)),
            textwrap.dedent(inspect.getsource(body)),
            f"def main():\n    {body.__name__}()\n",
        ]
    )
    result = controller_host.run(source, duration=duration, **options)
    assert result.ok, result.crashes
    return result


BODY_HEADER = """
import pytest
import rclpy
from rclpy.clock import Clock, ClockType
from rclpy.duration import Duration
from rclpy.logging import LoggingSeverity
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile, qos_profile_sensor_data, qos_profile_system_default
from rclpy.task import Future
"""
"""What the bodies run by run_body may use besides SURFACE."""


def calls(log, n=3):
    return [log() for _ in range(n)]


def beh_node():
    """The node most bodies log with (as a fixture of the host would make it)."""
    rclpy.init(args=[])
    return rclpy.create_node("beh")


# -- init and shutdown ---------------------------------------------------------------------------


def ok_is_false_before_init():
    assert rclpy.ok() is False


def test_ok_is_false_before_init(controller_host):
    run_body(controller_host, ok_is_false_before_init)


def shutdown_before_init_raises_and_try_shutdown_does_not():
    with pytest.raises(RuntimeError, match="Context must be initialized before it can be shutdown"):
        rclpy.shutdown()
    assert rclpy.try_shutdown() is None


def test_shutdown_before_init_raises_and_try_shutdown_does_not(controller_host):
    run_body(controller_host, shutdown_before_init_raises_and_try_shutdown_does_not)


def init_twice_raises():
    rclpy.init(args=[])
    with pytest.raises(RuntimeError, match="must only be called once"):
        rclpy.init(args=[])
    assert rclpy.ok() is True


def test_init_twice_raises(controller_host):
    run_body(controller_host, init_twice_raises)


def shutdown_twice_raises_then_init_works_again():
    rclpy.init(args=[])
    assert rclpy.shutdown() is None
    assert rclpy.ok() is False
    with pytest.raises(RuntimeError, match="Context must be initialized before it can be shutdown"):
        rclpy.shutdown()
    rclpy.try_shutdown()
    rclpy.init(args=[])
    assert rclpy.ok() is True
    rclpy.shutdown()


def test_shutdown_twice_raises_then_init_works_again(controller_host):
    run_body(controller_host, shutdown_twice_raises_then_init_works_again)


def init_is_a_context_manager_that_shuts_down():
    with rclpy.init(args=[]) as manager:
        inside = rclpy.ok()
    assert inside is True
    assert rclpy.ok() is False
    assert manager.context is not None
    with rclpy.init(args=[]):
        rclpy.shutdown()  # shutting down inside the block is fine too
    assert rclpy.ok() is False


def test_init_is_a_context_manager_that_shuts_down(controller_host):
    run_body(controller_host, init_is_a_context_manager_that_shuts_down)


# -- loggers --------------------------------------------------------------------------------------


def logging_calls_return_whether_they_logged():
    logger = beh_node().get_logger()
    assert logger.info("x") is True
    assert logger.debug("x") is False


def test_logging_calls_return_whether_they_logged(controller_host):
    result = run_body(controller_host, logging_calls_return_whether_they_logged)
    assert node_logs(result, "beh") == ["x"]


def non_string_messages_are_handled_as_rclpy_does():
    logger = beh_node().get_logger()
    with pytest.raises(TypeError):
        logger.info(5)
    assert logger.debug(5) is False  # below the level: never converted, no error
    assert logger.info(None) is True
    assert logger.info(b"ab") is True


def test_non_string_messages_are_handled_as_rclpy_does(controller_host):
    result = run_body(controller_host, non_string_messages_are_handled_as_rclpy_does)
    assert node_logs(result, "beh") == ["(null)", "ab"]


def unknown_logging_keyword_is_a_type_error():
    with pytest.raises(TypeError, match='parameter "foo" is not one of the recognized logging options'):
        beh_node().get_logger().info("x", foo=1)


def test_unknown_logging_keyword_is_a_type_error(controller_host):
    run_body(controller_host, unknown_logging_keyword_is_a_type_error)


def name_keyword_logs_under_another_name():
    assert beh_node().get_logger().info("x", name="other") is True


def test_name_keyword_logs_under_another_name(controller_host):
    result = run_body(controller_host, name_keyword_logs_under_another_name)
    assert [(r.node, r.msg) for r in result.logs if r.node in ("beh", "other")] == [("other", "x")]


def every_recorded_logging_keyword_is_accepted():
    node = beh_node()
    values = {
        "name": "beh",
        "once": True,
        "skip_first": True,
        "throttle_duration_sec": 1.0,
        "throttle_time_source_type": node.get_clock(),
    }
    for keyword in SURFACE["logging_keywords"]["severity_methods"]:
        kwargs = {keyword: values[keyword]}
        if keyword == "throttle_time_source_type":
            kwargs["throttle_duration_sec"] = 1.0
        # a new logger object for each: one call site may not change its filters
        logged = rclpy.logging.get_logger("kw").info(f"with {keyword}", **kwargs)
        assert logged is (keyword != "skip_first")
    for keyword in SURFACE["logging_keywords"]["log"]:
        kwargs = {keyword: values[keyword]}
        if keyword == "throttle_time_source_type":
            kwargs["throttle_duration_sec"] = 1.0
        logged = rclpy.logging.get_logger("kw").log(f"log {keyword}", LoggingSeverity.INFO, **kwargs)
        assert logged is (keyword != "skip_first")


def test_every_recorded_logging_keyword_is_accepted(controller_host):
    result = run_body(controller_host, every_recorded_logging_keyword_is_accepted)
    assert node_logs(result, "beh") == ["with name"]


def once_skip_first_and_their_combination():
    logger = beh_node().get_logger()
    assert calls(lambda: logger.info("once", once=True)) == [True, False, False]
    assert calls(lambda: logger.info("skip", skip_first=True)) == [False, True, True]
    assert calls(lambda: logger.info("so", skip_first=True, once=True)) == [False, True, False]
    assert calls(lambda: logger.info("of", once=False), 2) == [True, True]


def test_once_skip_first_and_their_combination(controller_host):
    result = run_body(controller_host, once_skip_first_and_their_combination)
    assert node_logs(result, "beh") == ["once", "skip", "skip", "so", "of", "of"]


def throttle_logs_first_then_once_per_period_of_simulated_time():
    node = beh_node()
    logger = node.get_logger()

    def tick():
        return logger.info("th", throttle_duration_sec=1.0)

    assert calls(tick) == [True, False, False]
    node.get_clock().sleep_for(Duration(seconds=0.5))
    assert tick() is False
    node.get_clock().sleep_for(Duration(seconds=0.6))
    assert tick() is True


def test_throttle_logs_first_then_once_per_period_of_simulated_time(controller_host):
    result = run_body(controller_host, throttle_logs_first_then_once_per_period_of_simulated_time)
    assert [r.t for r in result.logs if r.node == "beh"] == [0.0, 1.1]


def throttle_parameters_are_checked():
    logger = beh_node().get_logger()
    with pytest.raises(TypeError, match="throttle_duration_sec"):
        logger.info("x", throttle_time_source_type=Clock())
    with pytest.raises(ValueError, match="is not a clock instance"):
        logger.info("x", throttle_duration_sec=1, throttle_time_source_type=5)


def test_throttle_parameters_are_checked(controller_host):
    run_body(controller_host, throttle_parameters_are_checked)


def one_call_site_keeps_its_severity_and_filters():
    logger = beh_node().get_logger()
    with pytest.raises(ValueError, match="Logger severity cannot be changed between calls"):
        for severity in (LoggingSeverity.INFO, LoggingSeverity.WARN):
            logger.log("x", severity)
    with pytest.raises(ValueError, match="Logging filter parameters cannot be changed between calls"):
        for period in (1, 2):
            logger.info("t", throttle_duration_sec=period)
    for i in range(2):  # two calls on one line are two call sites
        logger.info("a") if i else logger.warning("b")


def test_one_call_site_keeps_its_severity_and_filters(controller_host):
    result = run_body(controller_host, one_call_site_keeps_its_severity_and_filters)
    assert node_logs(result, "beh") == ["x", "t", "b", "a"]


def levels_belong_to_names_and_are_validated():
    logger = beh_node().get_logger()
    assert logger.set_level(LoggingSeverity.DEBUG) is None
    assert logger.get_effective_level() is LoggingSeverity.DEBUG
    assert rclpy.logging.get_logger("beh").get_effective_level() is LoggingSeverity.DEBUG
    assert logger.get_child("c").name == "beh.c"
    assert logger.get_child("c").get_effective_level() is LoggingSeverity.DEBUG
    assert logger.debug("now shown") is True
    with pytest.raises(ValueError, match="15 is not a valid LoggingSeverity"):
        logger.set_level(15)
    with pytest.raises(ValueError):
        logger.is_enabled_for(15)
    with pytest.raises(ValueError):
        logger.log("y", 25)
    assert logger.log("y", 20) is True


def test_levels_belong_to_names_and_are_validated(controller_host):
    result = run_body(controller_host, levels_belong_to_names_and_are_validated)
    assert node_logs(result, "beh") == ["now shown", "y"]


def module_level_logging_functions():
    assert rclpy.logging.get_logger("a") is not rclpy.logging.get_logger("a")  # new object per call
    with pytest.raises(ValueError, match="Logger name must not be empty"):
        rclpy.logging.get_logger("")
    assert rclpy.logging.set_logger_level("a", LoggingSeverity.DEBUG) is None
    assert rclpy.logging.get_logger_effective_level("a") is LoggingSeverity.DEBUG
    assert rclpy.logging.get_logger_effective_level("a.b") is LoggingSeverity.DEBUG
    assert rclpy.logging.get_logger_effective_level("z") is LoggingSeverity.INFO
    assert rclpy.logging.get_logger("a").debug("shown") is True


def test_module_level_logging_functions(controller_host):
    result = run_body(controller_host, module_level_logging_functions)
    assert node_logs(result, "a") == ["shown"]


# -- Duration, Time, Clock --------------------------------------------------------------------------


def test_duration_arithmetic_and_comparisons():
    d1, d2 = Duration(seconds=1.5), Duration(nanoseconds=500_000_000)
    assert d1 + d2 == Duration(nanoseconds=2_000_000_000)
    assert (d2 - d1).nanoseconds == -1_000_000_000
    assert (d1 * 2).nanoseconds == 3_000_000_000
    assert (d1 * 0.5).nanoseconds == 750_000_000
    assert Duration(nanoseconds=1.7).nanoseconds == 1
    assert Duration(seconds=0.1).nanoseconds == 100_000_000
    assert Duration(seconds=-1).nanoseconds == -1_000_000_000
    assert d2 < d1 and d1 >= d2 and d1 != d2
    assert (Duration(seconds=1) == 1) is False
    assert (Duration(seconds=1) != 1) is True
    for bad in (lambda: 2 * d1, lambda: d1 * d2, lambda: d1 + 1, lambda: d2 < 1, lambda: hash(d1)):
        with pytest.raises(TypeError):
            bad()
    with pytest.raises(TypeError):
        Duration(1)
    with pytest.raises(OverflowError):
        Duration(seconds=2**63)


def test_duration_text_and_messages():
    d = Duration(seconds=1.5)
    assert str(d) == "1500000000 nanoseconds"
    assert repr(d) == "Duration(nanoseconds=1500000000)"
    msg = d.to_msg()
    assert (msg.sec, msg.nanosec) == (1, 500_000_000)
    negative = Duration(nanoseconds=-1).to_msg()
    assert (negative.sec, negative.nanosec) == (-1, 999_999_999)
    assert Duration.from_msg(msg) == d
    with pytest.raises(TypeError):
        Duration.from_msg(5)


def test_time_arithmetic_and_comparisons():
    a = Time(seconds=10, clock_type=ClockType.ROS_TIME)
    b = Time(seconds=4, nanoseconds=5, clock_type=ClockType.ROS_TIME)
    system = Time(seconds=4)
    assert Time().clock_type == ClockType.SYSTEM_TIME
    assert a - b == Duration(nanoseconds=5_999_999_995)
    assert a - Duration(seconds=1) == Time(seconds=9, clock_type=ClockType.ROS_TIME)
    assert a + Duration(seconds=1) == Duration(seconds=1) + a
    assert (a + Duration(seconds=1)).nanoseconds == 11_000_000_000
    assert b < a and a >= b
    assert (a == 5) is False
    with pytest.raises(TypeError):
        a + b
    with pytest.raises(TypeError, match="Can't subtract times with different clock types"):
        a - system
    with pytest.raises(TypeError, match="Can't compare times with different clock types"):
        system < a  # noqa: B015
    with pytest.raises(TypeError, match="Can't compare times with different clock types"):
        system == Time(seconds=4, clock_type=ClockType.ROS_TIME)  # noqa: B015
    with pytest.raises(TypeError):
        a < 5  # noqa: B015
    with pytest.raises(TypeError):
        hash(a)
    with pytest.raises(ValueError, match="Subtraction leads to negative time"):
        b - Duration(seconds=100)
    with pytest.raises(ValueError, match="Seconds value must not be negative"):
        Time(seconds=-1)
    with pytest.raises(OverflowError):
        Time(seconds=2**64)
    assert Time(seconds=1.5, nanoseconds=0.5).nanoseconds == 1_500_000_000


def test_time_text_and_messages():
    b = Time(seconds=4, nanoseconds=5, clock_type=ClockType.ROS_TIME)
    assert repr(b) == str(b) == "Time(nanoseconds=4000000005, clock_type=ROS_TIME)"
    assert b.seconds_nanoseconds() == (4, 5)
    msg = b.to_msg()
    assert (msg.sec, msg.nanosec) == (4, 5)
    assert Time.from_msg(msg) == b  # from_msg defaults to ROS time
    with pytest.raises(TypeError):
        Time.from_msg(Duration().to_msg())


def test_clock_types():
    assert Clock().clock_type == ClockType.SYSTEM_TIME
    assert repr(Clock()) == "Clock(clock_type=SYSTEM_TIME)"
    ros = Clock(clock_type=ClockType.ROS_TIME)
    assert isinstance(ros, ROSClock) and ros.clock_type == ClockType.ROS_TIME
    assert isinstance(ROSClock(), ROSClock)
    with pytest.raises(TypeError):
        Clock(clock_type=1)


def node_clock_reads_simulated_ros_time():
    node = beh_node()
    now = node.get_clock().now()
    assert now.clock_type == ClockType.ROS_TIME
    assert Clock().now().clock_type == ClockType.SYSTEM_TIME
    assert node.get_clock().sleep_for(Duration(seconds=2)) is True
    assert node.get_clock().now() - now == Duration(seconds=2)


def test_node_clock_reads_simulated_ros_time(controller_host):
    run_body(controller_host, node_clock_reads_simulated_ros_time, duration=3.0)


# -- parameters ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        (None, "NOT_SET"),
        (True, "BOOL"),
        (1, "INTEGER"),
        (1.0, "DOUBLE"),
        ("a", "STRING"),
        ([b"a"], "BYTE_ARRAY"),
        ([], "BYTE_ARRAY"),
        ((), "BYTE_ARRAY"),
        ([True], "BOOL_ARRAY"),
        ([1], "INTEGER_ARRAY"),
        ([True, 1], "INTEGER_ARRAY"),
        ([1.0], "DOUBLE_ARRAY"),
        (["a"], "STRING_ARRAY"),
        (b"a", TypeError),
        (bytearray(b"a"), TypeError),
        ([1, 1.0], TypeError),
        ({}, TypeError),
        (1j, TypeError),
    ],
)
def test_parameter_type_from_value(value, expected):
    if expected is TypeError:
        with pytest.raises(TypeError):
            Parameter.Type.from_parameter_value(value)
    else:
        assert Parameter.Type.from_parameter_value(value) is Parameter.Type[expected]


def test_parameter_type_is_an_int_enum_with_rclpy_checks():
    assert isinstance(Parameter.Type.BOOL, int) and Parameter.Type.DOUBLE == 3
    assert Parameter.Type.INTEGER.check(True) is True
    Parameter("p", Parameter.Type.INTEGER, True)
    with pytest.raises(ValueError, match="do not agree"):
        Parameter("p", Parameter.Type.DOUBLE, 1)
    with pytest.raises(ValueError, match="do not agree"):
        Parameter("p", Parameter.Type.INTEGER)
    assert Parameter("p", value=[]).type_ is Parameter.Type.BYTE_ARRAY
    assert Parameter("p", Parameter.Type.INTEGER_ARRAY, []).value == []


def test_parameter_values_are_rcl_interfaces_messages():
    from rcl_interfaces.msg import Parameter as ParameterMsg
    from rcl_interfaces.msg import ParameterValue

    value = Parameter("p", value=2.5).get_parameter_value()
    assert isinstance(value, ParameterValue)
    assert (value.type, value.double_value) == (3, 2.5)
    assert Parameter("p", value=2).get_parameter_value().integer_value == 2
    assert Parameter("p", value=True).get_parameter_value().bool_value is True
    assert Parameter("p", value="s").get_parameter_value().string_value == "s"
    assert list(Parameter("p", value=[1, 2]).get_parameter_value().integer_array_value) == [1, 2]
    assert list(Parameter("p", value=[0.5]).get_parameter_value().double_array_value) == [0.5]
    assert list(Parameter("p", value=("a", "b")).get_parameter_value().string_array_value) == ["a", "b"]
    assert list(Parameter("p", value=[b"a"]).get_parameter_value().byte_array_value) == [b"a"]
    assert Parameter("p").get_parameter_value().type == 0
    msg = Parameter("p", value=[1.0]).to_parameter_msg()
    assert isinstance(msg, ParameterMsg) and msg.name == "p"
    back = Parameter.from_parameter_msg(msg)
    assert back.type_ is Parameter.Type.DOUBLE_ARRAY and list(back.value) == [1.0]


def test_parameter_messages_come_from_turtletui_interfaces():
    import rcl_interfaces.msg

    from turtletui.compat import parameter
    from turtletui.interfaces import rcl_interfaces as interfaces

    for name in ("ParameterValue", "ParameterDescriptor", "SetParametersResult", "ParameterType"):
        assert getattr(rcl_interfaces.msg, name) is getattr(interfaces, name)
        assert getattr(parameter, name) is getattr(interfaces, name)


def on_set_callback_returning_the_rcl_interfaces_result():
    from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult

    node = beh_node()
    node.declare_parameter("speed", 1.0)
    node.declare_parameter("fixed", 2, ParameterDescriptor(read_only=True))

    def check(params):
        ok = all(p.value >= 0 for p in params if p.name == "speed")
        return SetParametersResult(successful=ok, reason="" if ok else "negative")

    node.add_on_set_parameters_callback(check)
    [good] = node.set_parameters([Parameter("speed", value=2.0)])
    [bad] = node.set_parameters([Parameter("speed", value=-1.0)])
    assert isinstance(good, SetParametersResult) and good.successful is True
    assert (bad.successful, bad.reason) == (False, "negative")
    assert node.get_parameter("speed").get_parameter_value().double_value == 2.0
    assert node.set_parameters([Parameter("fixed", value=3)])[0].successful is False


def test_on_set_callback_returning_the_rcl_interfaces_result(controller_host):
    run_body(controller_host, on_set_callback_returning_the_rcl_interfaces_result)


# -- QoS --------------------------------------------------------------------------------------------


def test_qos_profile_needs_history_or_depth():
    with pytest.raises(InvalidQoSProfileException):
        QoSProfile()
    with pytest.raises(InvalidQoSProfileException):
        QoSProfile(history=HistoryPolicy.KEEP_LAST)
    keep_all = QoSProfile(history=HistoryPolicy.KEEP_ALL)
    assert keep_all.depth == 10


def test_qos_profile_fields_are_converted_and_checked():
    assert str(QoSProfile(1, 10)) == str(QoSProfile(depth=10)) == (
        "QoSProfile(history=1, depth=10, reliability=1, durability=2, lifespan=0 nanoseconds, "
        "deadline=0 nanoseconds, liveliness=0, liveliness_lease_duration=0 nanoseconds, "
        "avoid_ros_namespace_conventions=False)"
    )
    profile = QoSProfile(history=1, depth=3, reliability=2)
    assert profile.history is HistoryPolicy.KEEP_LAST
    assert profile.reliability is ReliabilityPolicy.BEST_EFFORT
    assert QoSProfile(depth=10) == QoSProfile(depth=10)
    assert (QoSProfile(depth=10) == 10) is False
    with pytest.raises(AssertionError):
        QoSProfile(depth=1.5)
    with pytest.raises(AssertionError):
        QoSProfile(depth="1")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        QoSProfile(depth=0)
    assert "zero depth with KEEP_LAST" in str(caught[0].message)


def test_qos_presets_print_as_rclpy_s():
    assert str(qos_profile_sensor_data).startswith("QoSProfile(history=1, depth=5, reliability=2, durability=2,")
    assert str(qos_profile_system_default).startswith("QoSProfile(history=0, depth=0, reliability=0, durability=0,")


def test_queue_length_for_each_history():
    from turtletui.compat.qos import KEEP_ALL_DEPTH, depth_of

    assert depth_of(7) == 7
    assert depth_of(QoSProfile(depth=3)) == 3
    assert depth_of(qos_profile_system_default) == 1  # the DDS default: keep last 1
    assert depth_of(QoSProfile(history=HistoryPolicy.KEEP_ALL)) == KEEP_ALL_DEPTH


# -- futures ------------------------------------------------------------------------------------------


def test_future_states():
    f = Future()
    assert f.result() is None and f.exception() is None
    f.cancel()
    assert (f.cancelled(), f.done()) == (True, False)  # cancelled is not done, as in rclpy
    assert f.result() is None
    failed = Future()
    failed.set_exception(ValueError("boom"))
    assert failed.done()
    with pytest.raises(ValueError, match="boom"):
        failed.result()
    assert isinstance(failed.exception(), ValueError)
    f3 = Future()
    f3.set_result(1)
    f3.set_result(2)
    assert f3.result() == 2
    f3.cancel()
    assert f3.cancelled() is False


def test_future_callbacks():
    seen = []
    f = Future()
    f.add_done_callback(seen.append)
    assert f.remove_done_callback(seen.append) is True
    assert f.remove_done_callback(print) is False
    f.add_done_callback(lambda fut: seen.append(fut.result()))
    f.set_result(1)
    f.add_done_callback(lambda fut: seen.append(fut.result() + 1))  # runs at once
    assert seen == [1, 2]
    cancelled = Future()
    cancelled.cancel()
    cancelled.add_done_callback(seen.append)
    assert seen[-1] is cancelled


def spin_until_future_complete_ends_on_cancel():
    node = beh_node()
    future = Future()
    node.create_timer(1.0, future.cancel)
    start = node.get_clock().now()
    rclpy.spin_until_future_complete(node, future, timeout_sec=10.0)
    assert future.cancelled() and not future.done()
    assert node.get_clock().now() - start == Duration(seconds=1)


def test_spin_until_future_complete_ends_on_cancel(controller_host):
    run_body(controller_host, spin_until_future_complete_ends_on_cancel, duration=3.0)


# -- parameters turtletui accepts and ignores ------------------------------------------------------


def accepted_but_ignored_arguments_change_nothing():
    from geometry_msgs.msg import Twist
    from rclpy.action import ActionClient
    from rclpy.callback_groups import ReentrantCallbackGroup
    from rclpy.executors import MultiThreadedExecutor
    from std_srvs.srv import Empty
    from turtlesim.action import RotateAbsolute

    rclpy.init(args=[], domain_id=7, signal_handler_options=None)
    node = rclpy.create_node("ignored", rosout_qos_profile=10, enable_rosout=False)
    group = ReentrantCallbackGroup()
    seen = []
    node.create_subscription(
        Twist, "/t", seen.append, qos_profile_sensor_data, callback_group=group, raw=False,
        content_filter_options=None,
    )
    pub = node.create_publisher(Twist, "/t", qos_profile_sensor_data, callback_group=group)
    node.create_client(Empty, "/e", qos_profile=qos_profile_system_default, callback_group=group)
    client = ActionClient(
        node,
        RotateAbsolute,
        "/turtle1/rotate_absolute",
        callback_group=group,
        goal_service_qos_profile=QoSProfile(depth=1),
        feedback_sub_qos_profile=QoSProfile(depth=1),
    )
    assert client.wait_for_server(timeout_sec=1.0) is True  # turtlesim serves it
    pub.publish(Twist())
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
    executor.spin_once(timeout_sec=0.1)
    assert len(seen) == 1
    assert executor.shutdown(wait_for_threads=False) is True
    rclpy.shutdown(uninstall_handlers=True)
    assert rclpy.ok() is False


def test_accepted_but_ignored_arguments_change_nothing(controller_host):
    run_body(controller_host, accepted_but_ignored_arguments_change_nothing)


# -- timers --------------------------------------------------------------------------------------


def a_zero_period_timer_fires_often_and_the_run_goes_on():
    node = beh_node()
    calls = []
    node.create_timer(0.0, lambda: calls.append(node.get_clock().now().nanoseconds))
    for _ in range(50):
        rclpy.spin_once(node, timeout_sec=1.0)
    # ready at every spin in rcl; here once a simulated millisecond, not once a
    # nanosecond (which made a run that spins on it never end)
    assert len(calls) == 50
    assert calls[-1] - calls[0] == 49 * 1_000_000
    rclpy.shutdown()


def test_a_zero_period_timer_fires_often_and_the_run_goes_on(controller_host):
    run_body(controller_host, a_zero_period_timer_fires_often_and_the_run_goes_on)


# -- QoS event callbacks ---------------------------------------------------------------------------


def event_callbacks_turtletui_never_calls():
    from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
    from std_msgs.msg import String

    node = beh_node()
    heard = []
    node.create_publisher(String, "a", 10, event_callbacks=PublisherEventCallbacks(deadline=heard.append))
    node.create_subscription(String, "a", heard.append, 10, event_callbacks=SubscriptionEventCallbacks(deadline=heard.append))
    rclpy.spin_once(node, timeout_sec=0.1)
    assert heard == []


def test_event_callbacks_turtletui_never_calls_are_named_once(controller_host):
    result = run_body(controller_host, event_callbacks_turtletui_never_calls)
    notes = [line for line in node_logs(result, "turtletui") if "never called in turtletui" in line]
    assert notes == [
        "/beh: the deadline callback of its publisher on '/a' is never called in turtletui (it has"
        " no such events: deadline and liveliness are not enforced, an endpoint of another type never matches);"
        " its incompatible_qos and matched callbacks are."
    ]


def matched_callbacks_count_matches():
    from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
    from std_msgs.msg import String

    node = beh_node()
    heard = []

    def said(side):
        return lambda s: heard.append((side, s.current_count, s.current_count_change, s.total_count, s.total_count_change))

    node.create_publisher(String, "a", 10, event_callbacks=PublisherEventCallbacks(matched=said("pub")))
    rclpy.spin_once(node, timeout_sec=0.1)
    assert heard == []
    sub = node.create_subscription(String, "a", print, 10, event_callbacks=SubscriptionEventCallbacks(matched=said("sub")))
    node.create_subscription(String, "a", print, 10)
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0.1)
    # the publisher's two matches before the executor ran: one call (rmw's status, taken once)
    assert heard == [("pub", 2, 2, 2, 2), ("sub", 1, 1, 1, 1)]
    heard.clear()
    node.destroy_subscription(sub)
    rclpy.spin_once(node, timeout_sec=0.1)
    assert heard == [("pub", 1, -1, 2, 0)]


def test_matched_callbacks_count_matches(controller_host):
    run_body(controller_host, matched_callbacks_count_matches)
