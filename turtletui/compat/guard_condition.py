"""``rclpy.guard_condition.GuardCondition``: a condition the program triggers by hand.

``trigger()`` wakes the executor spinning its node, which then runs the
callback once; triggers made before it runs count as one, as in rclpy (the
executor takes the condition, not each trigger).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from turtletui.compat.destroyable import Destroyable
from turtletui.compat.identity import as_rclpy

if TYPE_CHECKING:
    from turtletui.compat.callback_groups import CallbackGroup
    from turtletui.compat.node import Node


class GuardCondition(Destroyable):
    """Runs ``callback()`` (if any) in the node's executor after each ``trigger()``."""

    def __init__(self, node: Node, callback: Callable[[], Any] | None, callback_group: CallbackGroup, run: Callable) -> None:
        self._node = node
        self.callback = callback
        self.callback_group = callback_group
        self._run = run
        self._pending = False
        """Whether a trigger waits for the executor to take it."""

    def trigger(self) -> None:
        """Wake the executor: it runs the callback once, however many triggers came first."""
        self._require_alive()
        if self._pending:
            return
        self._pending = True
        host = self._node.context.host
        host.graph.ready.append((host.owner, self._take))

    def _take(self) -> None:
        self._pending = False
        if self._destroyed or self._node._destroyed or self.callback is None:
            return
        self._run()

    def destroy(self) -> None:
        """As rclpy's: the guard condition stays in ``node.guards`` until ``destroy_guard_condition``."""
        self._destroyed = True

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.guard_condition", GuardCondition)
