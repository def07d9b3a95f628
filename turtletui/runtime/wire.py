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
from select import select as _select
from time import monotonic as _monotonic
from time import perf_counter as _perf_counter

# Bound at import: a sandboxed child replaces time's clocks and select.select
# with simulated ones for the controller, never for its own pipe to the parent.

_HEADER = struct.Struct(">I")
MAX_REPLY_BYTES = 8 * 1024 * 1024
"""Largest answer the parent accepts from a child in one exchange."""


SPIN_ENV = "TURTLETUI_SPIN_SECONDS"
"""Overrides :func:`default_spin_seconds` on this machine (seconds, 0 for none)."""


def available_cpus() -> int:
    """CPUs this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def default_spin_seconds() -> float:
    """How long a reader polls for the other side's answer before it sleeps in the
    kernel, unless told otherwise (``Limits.spin_seconds``). Lockstep exchanges are
    short; with two or more CPUs a brief poll saves the cross-CPU wake-up of a
    sleeping reader (tens of microseconds per exchange on virtual machines). Zero
    on a single CPU, where polling would only steal time from the side being
    waited for; ``$TURTLETUI_SPIN_SECONDS`` overrides it."""
    override = os.environ.get(SPIN_ENV)
    if override:
        try:
            return max(0.0, float(override))
        except ValueError:
            pass
    return 0.0002 if available_cpus() > 1 else 0.0


def spin_read(fd: int, size: int, spin: float) -> bytes | None:
    """Read up to ``size`` bytes from the non-blocking ``fd`` within ``spin``
    seconds of polling; None if nothing came (b"" if the pipe is closed)."""
    try:
        return os.read(fd, size)
    except BlockingIOError:
        pass
    if spin <= 0:
        return None
    clock = _perf_counter
    end = clock() + spin
    read = os.read
    while clock() < end:
        try:
            return read(fd, size)
        except BlockingIOError:
            pass
    return None


class WireError(Exception):
    """The other side closed the pipe or sent something malformed."""


class WireTimeout(WireError):
    """The other side did not take a frame in time (it is not reading)."""


def _read_exact(fd: int, size: int) -> bytes:
    chunks = []
    while size:
        chunk = os.read(fd, size)
        if not chunk:
            raise WireError("pipe closed")
        chunks.append(chunk)
        size -= len(chunk)
    return b"".join(chunks)


def _write_all(fd: int, data: bytes | memoryview, deadline: float | None = None) -> None:
    view = memoryview(data)
    while view:
        try:
            written = os.write(fd, view)
        except BlockingIOError:  # a non-blocking fd with a full pipe: wait, up to deadline
            remaining = None if deadline is None else deadline - _monotonic()
            if remaining is not None and remaining <= 0:
                raise WireTimeout("the other side did not read what was sent") from None
            _select([], [fd], [], remaining)
            continue
        view = view[written:]


_pack = _HEADER.pack
_unpack_from = _HEADER.unpack_from
_ENCODE = json.JSONEncoder(separators=(",", ":"), allow_nan=True).encode
"""``json.dumps(obj, separators=(",", ":"), allow_nan=True)`` without building an encoder each call."""


def _write_frame(fd: int, payload: bytes, deadline: float | None = None) -> None:
    # Header and payload in one write: one system call (one wake-up) per frame.
    data = _pack(len(payload)) + payload
    try:
        written = os.write(fd, data)
    except BlockingIOError:
        written = 0
    if written != len(data):
        _write_all(fd, memoryview(data)[written:], deadline)


def send_to_child(fd: int, obj: object, deadline: float | None = None) -> None:
    """Send ``obj``; on a non-blocking ``fd``, raise WireTimeout if the child has
    not taken it by ``deadline`` (time.monotonic), instead of waiting for ever."""
    _write_frame(fd, marshal.dumps(obj), deadline)


class FrameReader:
    """Reads frames from a pipe with few system calls: a frame sent in one write
    (header and payload) usually arrives in one read. With ``spin`` seconds
    the descriptor is made non-blocking and waiting polls that long, then sleeps
    in select; with 0, a plain blocking read waits (one system call)."""

    __slots__ = ("fd", "buffer", "spin")

    def __init__(self, fd: int, spin: float) -> None:
        self.fd = fd
        self.buffer = b""
        self.spin = spin
        os.set_blocking(fd, self.spin <= 0)

    def _chunk(self, size: int) -> bytes:
        fd = self.fd
        if self.spin <= 0:
            chunk = os.read(fd, size)
        else:
            chunk = spin_read(fd, size, self.spin)
        while chunk is None:
            _select([fd], [], [])
            try:
                chunk = os.read(fd, size)
            except BlockingIOError:
                chunk = None
        if not chunk:
            raise WireError("pipe closed")
        return chunk

    def read_frame(self) -> bytes:
        buffer = self.buffer
        while len(buffer) < 4:
            buffer += self._chunk(1 << 16)
        (size,) = _unpack_from(buffer)
        end = 4 + size
        if len(buffer) < end:
            chunks = [buffer]
            have = len(buffer)
            while have < end:
                chunk = self._chunk(max(end - have, 1 << 16))
                chunks.append(chunk)
                have += len(chunk)
            buffer = b"".join(chunks)
        self.buffer = buffer[end:]
        return buffer[4:end]


_readers: dict[int, FrameReader] = {}


def read_from_parent(fd: int, spin: float) -> object:
    """The next message from the parent; ``spin`` as for :class:`FrameReader`
    (the first read from ``fd`` sets it)."""
    reader = _readers.get(fd)
    if reader is None:
        reader = _readers[fd] = FrameReader(fd, spin)
    return marshal.loads(reader.read_frame())


def send_to_parent(fd: int, obj: object) -> None:
    _write_frame(fd, _ENCODE(obj).encode())


def read_header(data: bytes) -> int:
    (size,) = _HEADER.unpack(data)
    if size > MAX_REPLY_BYTES:
        raise WireError(f"sent {size} bytes in one step (limit {MAX_REPLY_BYTES})")
    return size


_SCAN = json.JSONDecoder().scan_once
"""What json.loads does past its checks for encodings and white space: the
child sends UTF-8 without white space, and anything else is malformed."""


def parse_reply(payload: bytes) -> dict:
    try:
        text = payload.decode()
        reply, end = _SCAN(text, 0)
    except StopIteration as stop:
        raise WireError(f"sent a malformed reply (no JSON value at char {stop.value})") from None
    except ValueError as err:  # also UnicodeDecodeError
        raise WireError(f"sent a malformed reply ({err})") from None
    except RecursionError:
        raise WireError("sent a malformed reply (nested too deeply)") from None
    if end != len(text):
        raise WireError(f"sent a malformed reply (more after the JSON value at char {end})")
    if not isinstance(reply, dict):
        raise WireError("sent a malformed reply (not an object)")
    return reply
