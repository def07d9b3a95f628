from turtletui.compat.lifecycle import LifecyclePublisher  # noqa: F401
