"""What rclpy does with a node, publisher, timer... once it is destroyed."""

from __future__ import annotations

from turtletui.compat.exceptions import InvalidHandle

_DESTROYED = "cannot use Destroyable because destruction was requested"


class Destroyable:
    """An rclpy entity that refuses to be used once destroyed, as rclpy's do."""

    _destroyed = False

    def _require_alive(self) -> None:
        if self._destroyed:
            raise InvalidHandle(_DESTROYED)
