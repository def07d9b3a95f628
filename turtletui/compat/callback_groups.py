"""``rclpy.callback_groups``: which of a node's callbacks may run at the same time.

A MutuallyExclusiveCallbackGroup runs one of its callbacks at a time (every
node's default group is one); a ReentrantCallbackGroup runs any number. Only a
MultiThreadedExecutor runs callbacks at the same time at all
(turtletui.compat.dispatch)."""

from __future__ import annotations

from typing import Any

from turtletui.compat.identity import as_rclpy


class CallbackGroup:
    """The base of the two groups: what rclpy's executors ask of them."""

    def __init__(self) -> None:
        self.entities: set = set()
        self._deferred: list[tuple[str, Any]] = []
        """Callbacks that became ready while the group was busy: they run
        (first, in the order they came) once it is free again."""

    def add_entity(self, entity: Any) -> None:
        self.entities.add(entity)

    def has_entity(self, entity: Any) -> bool:
        return entity in self.entities

    def can_execute(self, entity: Any) -> bool:
        return True

    def beginning_execution(self, entity: Any) -> bool:
        return True

    def ending_execution(self, entity: Any) -> None:
        pass


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """One callback of the group at a time."""

    def __init__(self) -> None:
        super().__init__()
        self._active_entity: Any = None

    def can_execute(self, entity: Any) -> bool:
        return self._active_entity is None

    def beginning_execution(self, entity: Any) -> bool:
        if self._active_entity is None:
            self._active_entity = entity
            return True
        return False

    def ending_execution(self, entity: Any) -> None:
        self._active_entity = None


class ReentrantCallbackGroup(CallbackGroup):
    """Any number of the group's callbacks at a time."""

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.callback_groups", CallbackGroup, MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup)
