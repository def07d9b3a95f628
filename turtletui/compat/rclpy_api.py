"""The top-level ``rclpy`` functions: init, spin, shutdown and friends."""

from __future__ import annotations

from typing import Any

from turtletui.compat import logging as _logging
from turtletui.compat.context import Context, get_default_context
from turtletui.compat.executors import Executor, get_global_executor
from turtletui.compat.node import Node
from turtletui.compat.task import Future


def init(
    *,
    args: list[str] | None = None,
    context: Context | None = None,
    domain_id: int | None = None,
    signal_handler_options: Any = None,
) -> None:
    """Initialise the context (reads ``--ros-args`` from ``args`` or sys.argv)."""
    context = context or get_default_context()
    context.init(args, domain_id=domain_id)
    _logging.apply_log_level(context.ros_args.log_level)


def shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    (context or get_default_context()).shutdown()


def try_shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    (context or get_default_context()).try_shutdown()


def ok(*, context: Context | None = None) -> bool:
    return (context or get_default_context()).ok()


def create_node(node_name: str, **kwargs: Any) -> Node:
    return Node(node_name, **kwargs)


def _executor_for(node: Node | None, executor: Executor | None) -> Executor:
    executor = executor or get_global_executor()
    if node is not None:
        executor.add_node(node)
    return executor


def spin(node: Node, executor: Executor | None = None) -> None:
    """Run the node's callbacks until the context shuts down (the run ends)."""
    _executor_for(node, executor).spin()


def spin_once(node: Node, *, executor: Executor | None = None, timeout_sec: float | None = None) -> None:
    _executor_for(node, executor).spin_once(timeout_sec=timeout_sec)


def spin_until_future_complete(
    node: Node, future: Future, executor: Executor | None = None, timeout_sec: float | None = None
) -> None:
    _executor_for(node, executor).spin_until_future_complete(future, timeout_sec=timeout_sec)


def get_global_executor_() -> Executor:
    return get_global_executor()


def utilities_remove_ros_args(args: list[str] | None = None) -> list[str]:
    import sys

    from turtletui.compat.ros_args import parse_ros_args

    return parse_ros_args(sys.argv if args is None else list(args)).user_args
