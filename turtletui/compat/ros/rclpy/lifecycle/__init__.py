from rclpy.lifecycle import managed_entity, node, publisher  # noqa: E402,F401  (as rclpy's __init__ imports them)
from turtletui.compat.lifecycle import (  # noqa: F401
    LifecycleNode,
    LifecycleNodeMixin,
    LifecyclePublisher,
    LifecycleState,
    ManagedEntity,
    SimpleManagedEntity,
    TransitionCallbackReturn,
)

# as rclpy: ``from rclpy.lifecycle import Node, State, Publisher`` work too
Node = LifecycleNode
NodeMixin = LifecycleNodeMixin
State = LifecycleState
Publisher = LifecyclePublisher

__all__ = [
    "LifecycleNodeMixin",
    "LifecycleNode",
    "LifecycleState",
    "LifecyclePublisher",
    "ManagedEntity",
    "SimpleManagedEntity",
]
