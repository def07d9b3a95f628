"""Framing between the simulator and a sandboxed controller.

Each frame is a 4-byte big-endian length and a payload. The parent sends
``marshal`` payloads (the child trusts it); the child answers in JSON, which
the parent can parse safely whatever the child's code has done.
"""

from __future__ import annotations

import json
import marshal
import os
import struct

_HEADER = struct.Struct(">I")
MAX_REPLY_BYTES = 8 * 1024 * 1024
"""Largest answer the parent accepts from a child in one exchange."""


class WireError(Exception):
    """The other side closed the pipe or sent something malformed."""


def _read_exact(fd: int, size: int) -> bytes:
    chunks = []
    while size:
        chunk = os.read(fd, size)
        if not chunk:
            raise WireError("pipe closed")
        chunks.append(chunk)
        size -= len(chunk)
    return b"".join(chunks)


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        written = os.write(fd, view)
        view = view[written:]


def send_to_child(fd: int, obj: object) -> None:
    payload = marshal.dumps(obj)
    _write_all(fd, _HEADER.pack(len(payload)) + payload)


def read_from_parent(fd: int) -> object:
    (size,) = _HEADER.unpack(_read_exact(fd, 4))
    return marshal.loads(_read_exact(fd, size))


def send_to_parent(fd: int, obj: object) -> None:
    payload = json.dumps(obj, separators=(",", ":"), allow_nan=True).encode()
    _write_all(fd, _HEADER.pack(len(payload)) + payload)


def read_header(data: bytes) -> int:
    (size,) = _HEADER.unpack(data)
    if size > MAX_REPLY_BYTES:
        raise WireError(f"sent {size} bytes in one step (limit {MAX_REPLY_BYTES})")
    return size


def parse_reply(payload: bytes) -> dict:
    try:
        reply = json.loads(payload)
    except ValueError as err:
        raise WireError(f"sent a malformed reply ({err})") from None
    if not isinstance(reply, dict):
        raise WireError("sent a malformed reply (not an object)")
    return reply
