from turtletui.interfaces.rosidl_definition import *  # noqa: F403
