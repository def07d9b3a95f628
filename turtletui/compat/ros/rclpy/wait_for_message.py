from turtletui.compat.wait_for_message import wait_for_message  # noqa: F401
