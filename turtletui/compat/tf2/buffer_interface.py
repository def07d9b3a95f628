"""tf2_ros's BufferInterface: the lookups every tf2 buffer offers, and its exceptions."""

from __future__ import annotations


class TypeException(Exception):
    """A type tf2 has no conversion for."""

    def __init__(self, errstr: str) -> None:
        super().__init__(errstr)
        self.errstr = errstr


class NotImplementedException(Exception):
    """A BufferInterface method its subclass does not provide."""

    def __init__(self) -> None:
        super().__init__("function not implemented")
        self.errstr = "function not implemented"


class BufferInterface:
    """What a buffer of transforms answers; Buffer implements it."""

    def lookup_transform(self, target_frame, source_frame, time, timeout=None):  # noqa: ANN001, ANN201
        raise NotImplementedException()

    def lookup_transform_full(self, target_frame, target_time, source_frame, source_time, fixed_frame, timeout=None):  # noqa: ANN001, ANN201, E501
        raise NotImplementedException()

    def can_transform(self, target_frame, source_frame, time, timeout=None):  # noqa: ANN001, ANN201
        raise NotImplementedException()

    def can_transform_full(self, target_frame, target_time, source_frame, source_time, fixed_frame, timeout=None):  # noqa: ANN001, ANN201, E501
        raise NotImplementedException()
