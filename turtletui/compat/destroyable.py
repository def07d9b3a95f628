"""What rclpy does with a node, publisher, timer... once it is destroyed."""

from __future__ import annotations

from typing import TypeVar

from turtletui.compat.exceptions import InvalidHandle

_Entity = TypeVar("_Entity", bound="Destroyable")
_DESTROYED = "cannot use Destroyable because destruction was requested"


class Destroyable:
    """An rclpy entity that refuses to be used once destroyed, as rclpy's do."""

    _destroyed = False

    def _require_alive(self) -> None:
        if self._destroyed:
            raise InvalidHandle(_DESTROYED)

    def __enter__(self: _Entity) -> _Entity:
        return self

    def __exit__(self, *exc_info: object) -> None:
        """Leaving a ``with`` block destroys the entity, as rclpy's entities do."""
        self.destroy()  # type: ignore[attr-defined]  # each entity has its own
