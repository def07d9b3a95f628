"""``rclpy.logging_service.LoggingService``: a node's logger level services.

``Node(..., enable_logger_service=True)`` serves ``<node name>/get_logger_levels``
and ``<node name>/set_logger_levels`` (demo_nodes_py's use_logger_service), as
rclpy 9's: levels read and set through ``rclpy.logging``, by logger name.
"""

from __future__ import annotations

from typing import Any

from turtletui.compat import logging
from turtletui.compat.qos import qos_profile_services_default
from turtletui.interfaces.rcl_interfaces import (
    GetLoggerLevels,
    LoggerLevel,
    SetLoggerLevels,
    SetLoggerLevelsResult,
)


class LoggingService:
    """Serves the levels of the process's loggers on ``node``'s behalf."""

    def __init__(self, node: Any) -> None:
        name = node.get_name()
        node.create_service(
            GetLoggerLevels, f"{name}/get_logger_levels", self._get_logger_levels, qos_profile=qos_profile_services_default
        )
        node.create_service(
            SetLoggerLevels, f"{name}/set_logger_levels", self._set_logger_levels, qos_profile=qos_profile_services_default
        )

    def _get_logger_levels(self, request: Any, response: Any) -> Any:
        for name in request.names:
            response.levels.append(LoggerLevel(name=name, level=logging.get_logger_level(name)))
        return response

    def _set_logger_levels(self, request: Any, response: Any) -> Any:
        for level in request.levels:
            result = SetLoggerLevelsResult(successful=False)
            try:
                logging.set_logger_level(level.name, level.level, detailed_error=True)
                result.successful = True
            except ValueError:
                result.reason = "Failed reason: Invalid logger level."
            response.results.append(result)
        return response
