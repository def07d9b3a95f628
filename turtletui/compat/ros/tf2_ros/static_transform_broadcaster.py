from turtletui.compat.tf2.broadcasters import StaticTransformBroadcaster  # noqa: F401
