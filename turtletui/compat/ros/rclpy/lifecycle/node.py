from turtletui.compat.lifecycle import (  # noqa: F401
    LifecycleNode,
    LifecycleNodeMixin,
    LifecycleState,
    TransitionCallbackReturn,
)
