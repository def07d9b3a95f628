from turtletui.interfaces.turtlesim import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative  # noqa: F401
