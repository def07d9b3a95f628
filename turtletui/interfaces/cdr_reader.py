"""Reading CDR back into turtletui's messages: the inverse of turtletui.interfaces.cdr.

The layout is the writer's (see its docstring); the encapsulation header says
the byte order (``00 01`` little-endian, ``00 00`` big-endian). Bytes after the
message are ignored, as Fast CDR ignores them; bytes missing, a sequence longer
than its bound or text that is not UTF-8 raise CdrError. Used where speed does
not matter (``rclpy.serialization``), so it walks the field specs.
"""

from __future__ import annotations

import struct
from typing import Any

from turtletui.interfaces import FieldSpec, build_from_values
from turtletui.interfaces.cdr import CODES, SIZES


class CdrError(ValueError):
    """Bytes that are not a CDR message of the type they were read as."""


def deserialize(data: bytes, cls: type) -> Any:
    """The message of class ``cls`` that the CDR payload ``data`` (header included) holds."""
    if len(data) < 4:
        raise CdrError(f"{len(data)} bytes: no CDR encapsulation header")
    reader = _Reader(data, little=data[1] & 1 == 1)
    return build_from_values(cls, reader.message(cls))


class _Reader:
    def __init__(self, data: bytes, little: bool) -> None:
        self.data = data
        self.order = "<" if little else ">"
        self.pos = 4

    def take(self, code: str, count: int = 1) -> tuple[Any, ...]:
        """``count`` primitives of struct code ``code``, aligned to their size from the header's end."""
        if count == 0:
            return ()  # not even aligned, as Fast CDR reads an empty array
        size = SIZES[code]
        self.pos += -(self.pos - 4) % size
        end = self.pos + size * count
        if end > len(self.data):
            raise CdrError(f"the data ends at byte {len(self.data)}, before byte {end}")
        values = struct.unpack_from(f"{self.order}{count}{code}", self.data, self.pos)
        self.pos = end
        return values

    def text(self) -> str:
        (length,) = self.take("I")
        end = self.pos + length
        if end > len(self.data):
            raise CdrError(f"a string of {length} bytes at byte {self.pos} runs past the end")
        raw = self.data[self.pos : end]
        self.pos = end
        try:
            return raw.removesuffix(b"\0").decode()
        except UnicodeDecodeError as err:
            raise CdrError(f"a string that is not UTF-8: {err}") from None

    def message(self, cls: type) -> list[Any]:
        fields: tuple[FieldSpec, ...] = cls._FIELDS
        if not fields:
            self.take("B")  # rosidl's structure_needs_at_least_one_member
            return []
        return [self.field(spec) for spec in fields]

    def one(self, spec: FieldSpec, code: str | None) -> Any:
        if spec.kind == "msg":
            return self.message(spec.msg_cls)
        if code is None:
            return self.text()
        return self.take(code)[0]

    def field(self, spec: FieldSpec) -> Any:
        code = None if spec.strlen is not None else CODES.get(spec.base)
        if code == "c":
            code = "B"  # a byte's plain value is its int
        if spec.array == 0:
            return self.one(spec, code)
        if spec.array == 3:
            count = spec.size
        else:
            (count,) = self.take("I")
            if spec.size is not None and count > spec.size:
                raise CdrError(f"{count} elements in a sequence of {spec.size} at most")
        if code is None or spec.kind == "msg":
            return [self.one(spec, code) for _ in range(count)]
        return list(self.take(code, count))
