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
