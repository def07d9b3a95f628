from turtletui.compat.tf2.broadcasters import TransformBroadcaster  # noqa: F401
