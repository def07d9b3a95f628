"""Write tests/compat/rclpy_surface.json: the part of the real rclpy's API that course code uses.

Run it with the Python of an environment where the REAL rclpy is importable, never with
turtletui's (turtletui's shim would shadow nothing here, but the point is to record ROS's API):

    python3 -m venv /tmp/rosvenv
    /tmp/rosvenv/bin/pip install ros-rclpy ros-geometry-msgs ros-rmw-fastrtps-cpp
    cd /tmp && /tmp/rosvenv/bin/python /path/to/turtletui/tests/compat/make_rclpy_surface.py

(The ros-* wheels import without sourcing a ROS setup file; a ROS 2 installation works too
after ``source /opt/ros/<distro>/setup.bash``.) Run it from outside the repository so that
nothing of turtletui is on sys.path. It rewrites the JSON next to this file; commit the
result. tests/compat/test_rclpy_surface.py compares turtletui's shim against it.

What is recorded, for each name in SURFACE below:
- functions, methods, classmethods, staticmethods and constructors: their parameters in
  order, each with its kind (POSITIONAL_ONLY, POSITIONAL_OR_KEYWORD, VAR_POSITIONAL,
  KEYWORD_ONLY, VAR_KEYWORD), whether it has a default, and the default's repr when it is a
  simple literal (None, bool, int, float, str, or an enum member as ``Enum.MEMBER``);
  methods are recorded without ``self``, classmethods without ``cls``, and a class's
  ``__init__`` is the signature of calling the class (``inspect.signature(cls)``);
- properties (kind ``property``) and dunders set to None (kind ``disabled``: e.g. an
  unhashable class has ``__hash__ = None``);
- enums: member names and values; aliases: names that are the same object as another;
- QoS presets: every field of the profile;
- the keyword arguments that RcutilsLogger's logging calls accept, per logging filter.
"""

from __future__ import annotations

import enum
import importlib
import inspect
import json
import sys
from pathlib import Path

OUT = Path(__file__).with_name("rclpy_surface.json")

FUNCTIONS = {
    "rclpy": [
        "init",
        "shutdown",
        "try_shutdown",
        "ok",
        "spin",
        "spin_once",
        "spin_until_future_complete",
        "create_node",
        "get_global_executor",
        "get_default_context",
    ],
    "rclpy.logging": ["get_logger", "set_logger_level", "get_logger_effective_level"],
    "rclpy.wait_for_message": ["wait_for_message"],
    "rclpy.signals": ["install_signal_handlers", "get_current_signal_handlers_options", "uninstall_signal_handlers"],
    "rclpy.serialization": ["serialize_message", "deserialize_message"],
    "rclpy.type_support": ["check_for_type_support"],
    "rclpy.utilities": ["ok", "shutdown", "try_shutdown", "get_default_context", "remove_ros_args", "timeout_sec_to_nsec"],
    "rclpy.validate_node_name": ["validate_node_name"],
    "rclpy.validate_namespace": ["validate_namespace"],
    "rclpy.validate_topic_name": ["validate_topic_name"],
    "rclpy.validate_full_topic_name": ["validate_full_topic_name"],
    "rclpy.expand_topic_name": ["expand_topic_name"],
    "rclpy.topic_or_service_is_hidden": ["topic_or_service_is_hidden"],
}

NODE_METHODS = [
    "create_publisher",
    "create_subscription",
    "create_timer",
    "create_client",
    "create_service",
    "create_rate",
    "get_logger",
    "get_clock",
    "get_name",
    "get_namespace",
    "get_fully_qualified_name",
    "declare_parameter",
    "declare_parameters",
    "get_parameter",
    "get_parameter_or",
    "get_parameters",
    "has_parameter",
    "set_parameters",
    "set_parameters_atomically",
    "undeclare_parameter",
    "add_on_set_parameters_callback",
    "describe_parameter",
    "describe_parameters",
    "get_parameter_type",
    "get_parameter_types",
    "list_parameters",
    "destroy_node",
    "destroy_publisher",
    "destroy_subscription",
    "destroy_timer",
    "destroy_client",
    "destroy_service",
    "count_publishers",
    "count_subscribers",
    "get_topic_names_and_types",
    "get_node_names",
    "get_service_names_and_types",
]

EXECUTOR_METHODS = [
    "__init__",
    "add_node",
    "remove_node",
    "spin",
    "spin_once",
    "spin_until_future_complete",
    "shutdown",
]

LOGGER_METHODS = [
    "__init__",
    "debug",
    "info",
    "warn",
    "warning",
    "error",
    "fatal",
    "log",
    "get_child",
    "set_level",
    "get_effective_level",
    "is_enabled_for",
]

COMPARISONS = ["__eq__", "__ne__", "__lt__", "__le__", "__gt__", "__ge__", "__hash__"]

# Class (dotted path as course code imports it) -> members to record.
SURFACE = {
    "rclpy.node.Node": ["__init__", *NODE_METHODS],
    "rclpy.publisher.Publisher": ["publish", "get_subscription_count", "topic_name"],
    "rclpy.client.Client": ["call_async", "call", "wait_for_service", "service_is_ready", "configure_introspection"],
    "rclpy.service.Service": ["configure_introspection"],
    "rclpy.parameter_event_handler.ParameterEventHandler": [
        "__init__",
        "destroy",
        "get_parameter_from_event",
        "get_parameters_from_event",
        "add_parameter_callback",
        "remove_parameter_callback",
        "add_parameter_event_callback",
        "remove_parameter_event_callback",
    ],
    "rclpy.qos_overriding_options.QoSOverridingOptions": [
        "__init__",
        "with_default_policies",
        "policy_kinds",
        "callback",
        "entity_id",
    ],
    "rclpy.timer.Timer": ["cancel", "reset", "is_canceled"],
    "rclpy.task.Future": [
        "__init__",
        "done",
        "result",
        "exception",
        "add_done_callback",
        "remove_done_callback",
        "cancel",
        "cancelled",
        "set_result",
        "set_exception",
    ],
    "rclpy.action.ActionClient": [
        "__init__",
        "wait_for_server",
        "send_goal_async",
        "send_goal",
        "server_is_ready",
        "destroy",
    ],
    "rclpy.action.client.ClientGoalHandle": [
        "accepted",
        "status",
        "goal_id",
        "get_result_async",
        "get_result",
        "cancel_goal_async",
        "cancel_goal",
    ],
    "rclpy.action.ActionServer": [
        "__init__",
        "action_type",
        "register_handle_accepted_callback",
        "register_goal_callback",
        "register_cancel_callback",
        "register_execute_callback",
        "destroy",
    ],
    "rclpy.action.server.ServerGoalHandle": [
        "request",
        "goal_id",
        "is_active",
        "is_cancel_requested",
        "status",
        "execute",
        "publish_feedback",
        "succeed",
        "abort",
        "canceled",
        "destroy",
    ],
    "rclpy.parameter_client.AsyncParameterClient": [
        "__init__",
        "services_are_ready",
        "wait_for_services",
        "list_parameters",
        "get_parameters",
        "set_parameters",
        "describe_parameters",
        "get_parameter_types",
        "set_parameters_atomically",
        "delete_parameters",
        "load_parameter_file",
        "load_parameter_file_atomically",
        "on_parameter_event",
    ],
    "rclpy.qos.QoSProfile": [
        "__init__",
        "history",
        "depth",
        "reliability",
        "durability",
        "lifespan",
        "deadline",
        "liveliness",
        "liveliness_lease_duration",
        "avoid_ros_namespace_conventions",
    ],
    "rclpy.duration.Duration": [
        "__init__",
        "nanoseconds",
        "to_msg",
        "from_msg",
        "__add__",
        "__sub__",
        "__mul__",
        "__repr__",
        "__str__",
        *COMPARISONS,
    ],
    "rclpy.time.Time": [
        "__init__",
        "nanoseconds",
        "seconds_nanoseconds",
        "clock_type",
        "to_msg",
        "from_msg",
        "__add__",
        "__radd__",
        "__sub__",
        "__repr__",
        *COMPARISONS,
    ],
    "rclpy.clock.Clock": ["__init__", "now", "clock_type", "sleep_for", "sleep_until"],
    "rclpy.executors.SingleThreadedExecutor": EXECUTOR_METHODS,
    "rclpy.executors.MultiThreadedExecutor": EXECUTOR_METHODS,
    "rclpy.callback_groups.CallbackGroup": ["__init__"],
    "rclpy.callback_groups.MutuallyExclusiveCallbackGroup": ["__init__"],
    "rclpy.callback_groups.ReentrantCallbackGroup": ["__init__"],
    "rclpy.parameter.Parameter": [
        "__init__",
        "name",
        "type_",
        "value",
        "get_parameter_value",
        "to_parameter_msg",
        "from_parameter_msg",
    ],
    "rclpy.parameter.Parameter.Type": ["from_parameter_value", "check"],
    "rclpy.logging.RcutilsLogger": LOGGER_METHODS,
    "rclpy.lifecycle.LifecycleNode": [
        "__init__",
        "trigger_configure",
        "trigger_cleanup",
        "trigger_activate",
        "trigger_deactivate",
        "trigger_shutdown",
        "on_configure",
        "on_cleanup",
        "on_activate",
        "on_deactivate",
        "on_shutdown",
        "on_error",
        "create_lifecycle_publisher",
        "destroy_lifecycle_publisher",
        "add_managed_entity",
    ],
    "rclpy.lifecycle.LifecyclePublisher": ["publish", "is_activated"],
    "rclpy.lifecycle.SimpleManagedEntity": ["__init__", "on_activate", "on_deactivate", "is_activated"],
    "rclpy.lifecycle.LifecycleState": ["__init__"],
    "rclpy.time_source.TimeSource": ["__init__", "attach_node", "detach_node", "attach_clock", "clock_callback"],
    "rclpy.event_handler.SubscriptionEventCallbacks": ["__init__"],
    "rclpy.event_handler.PublisherEventCallbacks": ["__init__"],
}

ENUMS = [
    "rclpy.qos.HistoryPolicy",
    "rclpy.qos.ReliabilityPolicy",
    "rclpy.qos.DurabilityPolicy",
    "rclpy.qos.LivelinessPolicy",
    "rclpy.parameter.Parameter.Type",
    "rclpy.logging.LoggingSeverity",
    "rclpy.clock.ClockType",
    "rclpy.action.GoalResponse",
    "rclpy.action.CancelResponse",
    "rclpy.lifecycle.TransitionCallbackReturn",
    "rclpy.qos.QoSPolicyKind",
    "rclpy.signals.SignalHandlerOptions",
    "rclpy.service_introspection.ServiceIntrospectionState",
]

ALIASES = {
    "rclpy.qos.QoSHistoryPolicy": "rclpy.qos.HistoryPolicy",
    "rclpy.qos.QoSReliabilityPolicy": "rclpy.qos.ReliabilityPolicy",
    "rclpy.qos.QoSDurabilityPolicy": "rclpy.qos.DurabilityPolicy",
    "rclpy.qos.QoSLivelinessPolicy": "rclpy.qos.LivelinessPolicy",
    "rclpy.action.client.ActionClient": "rclpy.action.ActionClient",
    "rclpy.action.server.ActionServer": "rclpy.action.ActionServer",
    "rclpy.action.server.GoalResponse": "rclpy.action.GoalResponse",
    "rclpy.action.server.CancelResponse": "rclpy.action.CancelResponse",
    "rclpy.node.Parameter": "rclpy.parameter.Parameter",
    "rclpy.lifecycle.Node": "rclpy.lifecycle.LifecycleNode",
    "rclpy.lifecycle.State": "rclpy.lifecycle.LifecycleState",
    "rclpy.lifecycle.Publisher": "rclpy.lifecycle.LifecyclePublisher",
    "rclpy.lifecycle.node.LifecycleNode": "rclpy.lifecycle.LifecycleNode",
}

# Other names course code imports, recorded as existing (kind "class" or "exception").
NAMES = [
    "rclpy.executors.Executor",
    "rclpy.executors.ExternalShutdownException",
    "rclpy.qos.InvalidQoSProfileException",
    "rclpy.context.Context",
    "rclpy.exceptions.ParameterNotDeclaredException",
    "rclpy.exceptions.ParameterAlreadyDeclaredException",
    "rclpy.exceptions.InvalidParameterTypeException",
    "rclpy.impl.rcutils_logger.RcutilsLogger",
    "rclpy.subscription.Subscription",
    "rclpy.service.Service",
    "rclpy.timer.Rate",
    "rclpy.lifecycle.LifecycleNodeMixin",
    "rclpy.lifecycle.ManagedEntity",
    "rclpy.event_handler.UnsupportedEventTypeError",
]

QOS_PRESETS = [
    "qos_profile_default",
    "qos_profile_rosout_default",
    "qos_profile_sensor_data",
    "qos_profile_system_default",
    "qos_profile_services_default",
    "qos_profile_parameters",
    "qos_profile_parameter_events",
    "qos_profile_action_status_default",
]


def resolve(dotted: str) -> object:
    """Import the longest module prefix of ``dotted`` and getattr the rest."""
    parts = dotted.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for name in parts[cut:]:
            obj = getattr(obj, name)
        return obj
    raise ImportError(dotted)


def default_repr(value: object) -> str | None:
    if value is None or isinstance(value, (bool, int, float, str)) and not isinstance(value, enum.Enum):
        return repr(value)
    if isinstance(value, enum.Enum) or type(type(value)).__name__ == "pybind11_type" and hasattr(value, "name"):
        return f"{type(value).__name__}.{value.name}"
    return None


def params_of(signature: inspect.Signature, drop_first: bool) -> list[dict]:
    params = list(signature.parameters.values())
    if drop_first:
        params = params[1:]
    out = []
    for p in params:
        entry: dict = {"name": p.name, "kind": p.kind.name, "has_default": p.default is not p.empty}
        if p.default is not p.empty:
            entry["default"] = default_repr(p.default)
        out.append(entry)
    return out


def raw_attribute(cls: type, name: str) -> object:
    for klass in cls.__mro__:
        if name in vars(klass):
            return vars(klass)[name]
    raise AttributeError(f"{cls.__qualname__} has no {name}")


def member(cls: type, name: str) -> dict:
    if name == "__init__":
        return {"kind": "constructor", "params": params_of(inspect.signature(cls), False)}
    raw = raw_attribute(cls, name)
    if raw is None:
        return {"kind": "disabled"}
    if isinstance(raw, property):
        return {"kind": "property"}
    if isinstance(raw, classmethod):
        return {"kind": "classmethod", "params": params_of(inspect.signature(getattr(cls, name)), False)}
    if isinstance(raw, staticmethod):
        return {"kind": "staticmethod", "params": params_of(inspect.signature(raw.__func__), False)}
    if inspect.isfunction(raw):
        return {"kind": "method", "params": params_of(inspect.signature(raw), True)}
    raise TypeError(f"{cls.__qualname__}.{name} is a {type(raw).__name__}")


def enum_members(cls: type) -> dict[str, int]:
    return {name: int(getattr(value, "value", value)) for name, value in cls.__members__.items()}


def qos_fields(profile: object) -> dict:
    return {
        "history": profile.history.name,
        "depth": profile.depth,
        "reliability": profile.reliability.name,
        "durability": profile.durability.name,
        "lifespan_ns": profile.lifespan.nanoseconds,
        "deadline_ns": profile.deadline.nanoseconds,
        "liveliness": profile.liveliness.name,
        "liveliness_lease_duration_ns": profile.liveliness_lease_duration.nanoseconds,
        "avoid_ros_namespace_conventions": profile.avoid_ros_namespace_conventions,
    }


def logging_keywords() -> dict:
    from rclpy.impl import rcutils_logger

    filters = {
        name: {param: {"required": default is None} for param, default in cls.params.items()}
        for name, cls in rcutils_logger.supported_filters.items()
    }
    return {
        "filters": filters,
        # info()/warning()/... take LoggingArgs; log() takes LoggingFilterArgs (+ its name=).
        "severity_methods": sorted(rcutils_logger.LoggingArgs.__annotations__),
        "log": sorted(rcutils_logger.LoggingFilterArgs.__annotations__),
    }


def main() -> None:
    import rclpy

    if "/turtletui/compat/" in (getattr(rclpy, "__file__", "") or ""):
        sys.exit("this imported turtletui's rclpy shim: run it with the real rclpy's python")
    try:
        from importlib.metadata import version

        rclpy_version = version("ros-rclpy")
    except Exception:
        rclpy_version = "unknown"
    callables: dict[str, dict] = {}
    for module, names in FUNCTIONS.items():
        mod = importlib.import_module(module)
        for name in names:
            callables[f"{module}.{name}"] = {
                "kind": "function",
                "params": params_of(inspect.signature(getattr(mod, name)), False),
            }
    for cls_path, members in SURFACE.items():
        cls = resolve(cls_path)
        for name in members:
            callables[f"{cls_path}.{name}"] = member(cls, name)
    names = {}
    for path in NAMES:
        obj = resolve(path)
        names[path] = "exception" if isinstance(obj, type) and issubclass(obj, BaseException) else "class"
    for path, target in ALIASES.items():
        assert resolve(path) is resolve(target), path
    import rclpy.qos

    surface = {
        "_generated_by": "tests/compat/make_rclpy_surface.py (run with the real rclpy; see its docstring)",
        "rclpy_distribution": f"ros-rclpy {rclpy_version}",
        "python": ".".join(map(str, sys.version_info[:3])),
        "callables": callables,
        "names": names,
        "aliases": ALIASES,
        "enums": {path: enum_members(resolve(path)) for path in ENUMS},
        "qos_profiles": {f"rclpy.qos.{name}": qos_fields(getattr(rclpy.qos, name)) for name in QOS_PRESETS},
        "logging_keywords": logging_keywords(),
    }
    OUT.write_text(json.dumps(surface, indent=1, sort_keys=False) + "\n", encoding="utf-8")
    print(f"wrote {OUT} ({len(callables)} callables)")


if __name__ == "__main__":
    main()
