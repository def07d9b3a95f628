from turtletui.compat.lifecycle import ManagedEntity, SimpleManagedEntity, TransitionCallbackReturn  # noqa: F401
