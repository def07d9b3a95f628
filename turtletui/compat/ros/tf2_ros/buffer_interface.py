from turtletui.compat.tf2.buffer_interface import (  # noqa: F401
    BufferInterface,
    ConvertRegistration,
    NotImplementedException,
    Stamped,
    TransformRegistration,
    TypeException,
    convert,
)
