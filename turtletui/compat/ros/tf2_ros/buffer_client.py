from turtletui.compat.tf2.buffer_client import BufferClient  # noqa: F401
