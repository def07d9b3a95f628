"""Framing between the simulator and a sandboxed controller.

Each frame is a 4-byte big-endian length and a payload; what the payloads
hold is turtletui.runtime.protocol's business. Both sides read with one
:class:`FrameReader`: the child with no deadline, the parent with deadlines,
a size limit and a hook that watches the child while it waits.
"""

from __future__ import annotations

import os
import struct
from collections.abc import Callable
from select import select as _select
from time import monotonic as _monotonic
from time import perf_counter as _perf_counter

# Bound at import: a sandboxed child replaces time's clocks and select.select
# with simulated ones for the controller, never for its own pipe to the parent.

_HEADER = struct.Struct(">I")
_pack = _HEADER.pack
_unpack_from = _HEADER.unpack_from

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


class WireClosed(WireError):
    """The other side closed its end of the pipe."""


class WireTimeout(WireError):
    """The other side did not take a frame, or send one, in time."""


class FrameTooLarge(WireError):
    """The other side announced a frame over the reader's limit."""


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


def write_frame(fd: int, payload: bytes, deadline: float | None = None) -> None:
    """Send one frame; on a non-blocking ``fd``, raise WireTimeout if the other
    side has not taken it by ``deadline`` (time.monotonic), instead of waiting
    for ever."""
    # Header and payload in one write: one system call (one wake-up) per frame.
    data = _pack(len(payload)) + payload
    try:
        written = os.write(fd, data)
    except BlockingIOError:
        written = 0
    if written != len(data):
        _write_all(fd, memoryview(data)[written:], deadline)


def _select_readable(fd: int, timeout: float | None) -> None:
    _select([fd], [], [], timeout)


class FrameReader:
    """Reads frames from a pipe with few system calls: a frame sent in one write
    (header and payload) usually arrives in one read.

    ``blocking``: a plain blocking read waits (one system call; no deadlines).
    Otherwise the descriptor is made non-blocking, waiting polls ``spin``
    seconds and then calls ``wait(fd, timeout)``, which returns when ``fd``
    may be readable or ``timeout`` seconds passed (None: no limit); a parent's
    ``wait`` also watches its child and may raise to give up. ``on_data()`` is
    called after a chunk that came while polling or by :meth:`frame_ready`.
    A frame larger than ``max_size`` raises FrameTooLarge; a closed pipe
    WireClosed; a deadline passed WireTimeout (what came so far is kept).
    """

    __slots__ = ("fd", "buffer", "spin", "max_size", "wait", "on_data", "_blocking")

    def __init__(
        self,
        fd: int,
        *,
        spin: float = 0.0,
        blocking: bool = False,
        max_size: int | None = None,
        wait: Callable[[int, float | None], object] = _select_readable,
        on_data: Callable[[], object] | None = None,
    ) -> None:
        self.fd = fd
        self.buffer = b""
        self.spin = spin
        self.max_size = max_size
        self.wait = wait
        self.on_data = on_data
        self._blocking = blocking
        os.set_blocking(fd, blocking)

    def read_frame(self, deadline: float | None = None) -> bytes:
        """The next frame's payload; waits until ``deadline`` (time.monotonic)."""
        buffer = self.buffer
        if len(buffer) < 4:
            buffer = self._fill(buffer, 4, deadline)
        end = 4 + self._size(buffer)
        if len(buffer) < end:
            buffer = self._fill(buffer, end, deadline)
        self.buffer = buffer[end:]
        return buffer[4:end]

    def frame_ready(self) -> bool:
        """Read what has come without waiting: is a whole frame in?"""
        buffer = self.buffer
        limit = (self.max_size or 1 << 62) + 4
        fd = self.fd
        while True:
            try:
                chunk = os.read(fd, 1 << 16)
            except BlockingIOError:
                break
            if not chunk:
                self.buffer = buffer
                raise WireClosed("pipe closed")
            buffer += chunk
            if len(buffer) > limit:
                break
        self.buffer = buffer
        if self.on_data is not None:
            self.on_data()
        return len(buffer) >= 4 and len(buffer) >= 4 + self._size(buffer)

    def _size(self, buffer: bytes) -> int:
        (size,) = _unpack_from(buffer)
        if self.max_size is not None and size > self.max_size:
            raise FrameTooLarge(f"sent {size} bytes in one step (limit {self.max_size})")
        return size

    def _fill(self, buffer: bytes, total: int, deadline: float | None) -> bytes:
        """``buffer`` extended with what comes until it holds ``total`` bytes: one
        read per chunk the pipe has, not per field."""
        chunks = [buffer]
        have = len(buffer)
        try:
            while have < total:
                chunk = self._chunk(max(min(total - have, 1 << 20), 1 << 16), deadline)
                chunks.append(chunk)
                have += len(chunk)
        except BaseException:
            self.buffer = b"".join(chunks)  # kept for whoever reads on
            raise
        return b"".join(chunks)

    def _chunk(self, size: int, deadline: float | None) -> bytes:
        fd = self.fd
        if self._blocking:
            chunk = os.read(fd, size)
        else:
            if deadline is not None and deadline <= _monotonic():
                raise WireTimeout("no answer in time")
            chunk = spin_read(fd, size, self.spin)
            if chunk is None:
                while chunk is None:
                    if deadline is None:
                        remaining = None
                    else:
                        remaining = deadline - _monotonic()
                        if remaining <= 0:
                            raise WireTimeout("no answer in time")
                    self.wait(fd, remaining)
                    try:
                        chunk = os.read(fd, size)
                    except BlockingIOError:
                        chunk = None
            elif self.on_data is not None:
                self.on_data()
        if not chunk:
            raise WireClosed("pipe closed")
        return chunk
