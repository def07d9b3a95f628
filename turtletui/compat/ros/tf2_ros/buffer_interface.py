from turtletui.compat.tf2.buffer_interface import (  # noqa: F401
    BufferInterface,
    NotImplementedException,
    TypeException,
)
