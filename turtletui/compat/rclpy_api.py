"""The top-level ``rclpy`` functions: init, spin, shutdown and friends."""

from __future__ import annotations

from typing import Any

from turtletui.compat import logging as _logging
from turtletui.compat.context import Context, get_default_context
from turtletui.compat.executors import Executor, get_global_executor
from turtletui.compat.node import Node
from turtletui.compat.parameter import Parameter
from turtletui.compat.qos import QoSProfile, qos_profile_rosout_default
from turtletui.compat.signals import (
    SignalHandlerOptions,
    install_signal_handlers,
    uninstall_signal_handlers,
)
from turtletui.compat.task import Future


class InitContextManager:
    """What ``rclpy.init()`` returns: ``with rclpy.init(): ...`` shuts down at the end."""

    def __init__(
        self,
        args: list[str] | None,
        context: Context | None,
        domain_id: int | None,
        signal_handler_options: Any,
    ) -> None:
        self.context = get_default_context() if context is None else context
        if signal_handler_options is None:  # rclpy's: the default context's init handles both signals
            default = context is None or context is get_default_context()
            signal_handler_options = SignalHandlerOptions.ALL if default else SignalHandlerOptions.NO
        self.installed_signal_handlers = signal_handler_options != SignalHandlerOptions.NO
        self.context.init(args, domain_id=domain_id)
        _logging.apply_log_level(self.context.ros_args.log_level, self.context.ros_args.log_levels)
        install_signal_handlers(signal_handler_options)

    def __enter__(self) -> InitContextManager:
        return self

    def __exit__(self, exc_type: Any, exc_val: Any, exc_tb: Any) -> None:
        try_shutdown(
            context=None if self.context is get_default_context() else self.context,
            uninstall_handlers=self.installed_signal_handlers,
        )


def init(
    *,
    args: list[str] | None = None,
    context: Context | None = None,
    domain_id: int | None = None,
    signal_handler_options: Any = None,
) -> InitContextManager:
    """Initialise the context (reads ``--ros-args`` from ``args`` or sys.argv).

    ``signal_handler_options`` is recorded (``rclpy.signals``), not acted on:
    turtletui ends the run itself, Ctrl-C included."""
    return InitContextManager(args, context, domain_id, signal_handler_options)


def shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut the context down; RuntimeError if it is not initialised (or already shut down)."""
    utilities_shutdown(context=context)
    _uninstall_handlers(context, uninstall_handlers)


def try_shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut the context down if it is initialised."""
    utilities_try_shutdown(context=context)
    _uninstall_handlers(context, uninstall_handlers)


def utilities_shutdown(*, context: Context | None = None) -> None:
    """rclpy.utilities.shutdown: rclpy.shutdown without removing the signal handlers."""
    (get_default_context(shutting_down=True) if context is None else context).shutdown()


def utilities_try_shutdown(*, context: Context | None = None) -> None:
    """rclpy.utilities.try_shutdown: rclpy.try_shutdown without removing the signal handlers."""
    if context is None:
        context = get_default_context()
        context.try_shutdown()
        if not context.ok() and context is get_default_context():
            get_default_context(shutting_down=True)
    else:
        context.try_shutdown()


def _uninstall_handlers(context: Context | None, uninstall_handlers: bool | None) -> None:
    """rclpy's rule: shutting the default context down removes the signal
    handlers unless ``uninstall_handlers`` says otherwise."""
    if uninstall_handlers or (uninstall_handlers is None and (context is None or context is get_default_context())):
        uninstall_signal_handlers()


def ok(*, context: Context | None = None) -> bool:
    return (context or get_default_context()).ok()


def create_node(
    node_name: str,
    *,
    context: Context | None = None,
    cli_args: list[str] | None = None,
    namespace: str | None = None,
    use_global_arguments: bool = True,
    enable_rosout: bool = True,
    rosout_qos_profile: QoSProfile | int = qos_profile_rosout_default,
    start_parameter_services: bool = True,
    parameter_overrides: list[Parameter] | None = None,
    allow_undeclared_parameters: bool = False,
    automatically_declare_parameters_from_overrides: bool = False,
    enable_logger_service: bool = False,
) -> Node:
    return Node(
        node_name,
        context=context,
        cli_args=cli_args,
        namespace=namespace,
        use_global_arguments=use_global_arguments,
        enable_rosout=enable_rosout,
        rosout_qos_profile=rosout_qos_profile,
        start_parameter_services=start_parameter_services,
        parameter_overrides=parameter_overrides,
        allow_undeclared_parameters=allow_undeclared_parameters,
        automatically_declare_parameters_from_overrides=automatically_declare_parameters_from_overrides,
        enable_logger_service=enable_logger_service,
    )


def spin(node: Node, executor: Executor | None = None) -> None:
    """Run the node's callbacks until the context shuts down (the run ends)."""
    executor = get_global_executor() if executor is None else executor
    try:
        executor.add_node(node)
        if getattr(executor, "_spins_itself", True):
            executor.spin()
        else:
            # rclpy's loop, which a custom executor's spin_once drives (its spin() is not called)
            while executor.context.ok():
                executor.spin_once()
    finally:
        executor.remove_node(node)


def spin_once(node: Node, *, executor: Executor | None = None, timeout_sec: float | None = None) -> None:
    executor = get_global_executor() if executor is None else executor
    node_was_added = False
    try:
        node_was_added = executor.add_node(node)
        executor.spin_once(timeout_sec=timeout_sec)
    finally:
        if node_was_added:
            executor.remove_node(node)


def spin_until_future_complete(
    node: Node, future: Future, executor: Executor | None = None, timeout_sec: float | None = None
) -> None:
    executor = get_global_executor() if executor is None else executor
    node_added = False
    try:
        node_added = executor.add_node(node)
        executor.spin_until_future_complete(future, timeout_sec)
    finally:
        if node_added:
            executor.remove_node(node)


def timeout_sec_to_nsec(timeout_sec: float | None) -> int:
    """rclpy.utilities': a timeout in seconds as rcl_wait's nanoseconds (-1: for ever)."""
    if timeout_sec is None or timeout_sec < 0:
        return -1
    return int(float(timeout_sec) * 1_000_000_000)


def utilities_remove_ros_args(args: list[str] | None = None) -> list[str]:
    import sys

    from turtletui.compat.ros_args import parse_ros_args

    return parse_ros_args(sys.argv if args is None else list(args)).user_args
