"""Sandboxed runs without a round trip per exchange.

In lockstep (turtletui.runtime.sandbox) the parent sends a Tick and waits for
the child's Report at every exchange. On the fast path the child answers its
own Ticks: :class:`Loopback` runs the parent's side of the exchange (the
same SandboxHost code, GraphProxy and Simulation) against the child's own
copy of the simulation (turtletui.runtime.replica), and streams every Report
the controller sent, stamped with the simulated instant it answered, in
batches. :class:`FastHost`, in the parent, replays them through the trusted
simulation at the same instants, through the same code that applies a
lockstep Report, and judges only its replay. Every few exchanges the child
also sends its copy's state; a copy that differs from the parent's, or a
Report stamped with another instant than the replay's, means the
controller tampered with its copy: the run ends as ``tampered``.

A batch is a frame (turtletui.runtime.wire) of records, each:
``<q now_ns><d seconds><q stdout bytes><q stderr bytes><I digest length><I report length>``,
then the digest (empty most of the time) and the Report's JSON
(turtletui.runtime.protocol). ``seconds`` is the wall time the controller
took to answer (the parent's budget.Pace charges it); ``stdout bytes`` and
``stderr bytes`` count what the child had written to each by then, so that
the parent shows each line at the instant it was printed, as in lockstep.
"""

from __future__ import annotations

import io
import mmap
import os
import struct
from collections import deque
from pathlib import Path
from time import perf_counter as _perf_counter
from time import sleep as _real_sleep  # bound at import: the child simulates time.sleep
from typing import Any

from turtletui.interfaces import trusted_from_values
from turtletui.runtime import protocol, replica, wire
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.sandbox import Limits, SandboxHost, _Stop
from turtletui.runtime.sandbox_process import ChildFailed
from turtletui.runtime.simulation import Simulation

_HEADER = struct.Struct("<qq")
"""A batch's (and the journal's) head: the batch's number, the bytes of records after it."""
_RECORD = struct.Struct("<qdqqII")
DIGEST_EVERY = 16
"""Every this many exchanges (counted from the first), the record carries the copy's digest."""
_BATCH_RECORDS = 512
"""Records the child sends in one frame at most."""
_FLUSH_SECONDS = 0.02
"""Wall seconds a record may wait in the child before it is sent anyway."""
JOURNAL_BYTES = wire.MAX_REPLY_BYTES + (1 << 20)
"""The journal holds one batch: the largest Report and then some."""
_HOLD_SECONDS = 10.0
"""How long a child whose copy ended the run waits for the parent to end it."""
TAMPERED = "tampered"


# -- the child's side --------------------------------------------------------------------------------
class _CountedOutput(io.RawIOBase):
    """The child's stdout or stderr: counts the bytes written through it."""

    def __init__(self, fd: int) -> None:
        super().__init__()
        self.fd = fd
        self.count = 0

    def writable(self) -> bool:
        return True

    def fileno(self) -> int:
        return self.fd

    def write(self, data: Any) -> int:
        view = memoryview(data).cast("B")
        done = 0
        while done < len(view):
            done += os.write(self.fd, view[done:])
        self.count += done
        return done


def count_output() -> tuple[_CountedOutput, _CountedOutput]:
    """Route sys.stdout and sys.stderr (the child's fd 1 and 2, two pipes)
    through a counter each."""
    import sys

    counters = []
    for fd, name in ((1, "stdout"), (2, "stderr")):
        counted = _CountedOutput(fd)
        stream = getattr(sys, name)
        text = io.TextIOWrapper(
            counted, encoding=stream.encoding, errors=stream.errors, write_through=True, line_buffering=False
        )
        setattr(sys, name, text)
        counters.append(counted)
    return counters[0], counters[1]


class Loopback(SandboxHost):
    """The parent's side of every exchange, run in the child against its own
    copy of the simulation; records what the controller answered for the parent."""

    def __init__(
        self, sim: Simulation, spec: ControllerSpec, limits: Limits, end_ns: int, fd_out: int, fd_journal: int
    ) -> None:
        super().__init__(sim, spec, limits)
        sim.remotes.append(self)
        # The parent checks every value; where it refuses one the run ends there,
        # so the copy builds what it accepts, the same messages, without checks.
        self.proxy.build = _trusted_build
        self.end_ns = end_ns
        self.fd_out = fd_out
        self.output, self.errors = count_output()
        self._index = 0
        self._digest = b""
        self._tick_ns = 0
        self._asked = 0.0
        self.journal = mmap.mmap(fd_journal, JOURNAL_BYTES)
        os.close(fd_journal)
        self._seq = 0
        self._length = 0
        self._records = 0
        self._last_flush = _perf_counter()
        self._begun = False

    def ask(self, report: protocol.Report) -> protocol.Tick | protocol.End:
        """What ChildHost.ask does in lockstep: the answer to ``report``."""
        if self._begun:
            tick = self.answer(report)
        else:
            # The first report goes to the parent as in lockstep (it says the
            # child started; nobody reads it). Then the copy's first Tick.
            self._begun = True
            wire.write_frame(self.fd_out, protocol.encode_report(report))
            tick = self._next_tick()
        # The Tick as the controller would have read it from the pipe. The pipe's
        # encoding (marshal) gives back the same values; only the graph's
        # mirror, which the copy's GraphProxy keeps to compare with the next
        # one, goes through it, so that the child has its own.
        if type(tick) is protocol.Tick and tick.graph is not None:
            return protocol.decode_from_parent(protocol.encode_tick(tick))
        return tick

    def answer(self, report: protocol.Report) -> protocol.Tick | protocol.End:
        """Record the controller's answer, apply it to the copy, run the copy to
        the next exchange: its Tick (End once the run is over)."""
        self._record(protocol.encode_report(report))
        try:
            # As the parent will apply it once decoded (the same values). A
            # report the parent refuses ends the run at this record: the
            # copy's state after it never counts.
            self._apply(report)
        except _Stop:
            self._hold()
        sim = self.sim
        if sim.pump(None, self.end_ns, until=self._wants) == "limit":
            self._tick_ns = sim.graph.now_ns
            self._asked = _perf_counter()
            self._digest = replica.digest(sim)  # the parent's close() checks the end
            return protocol.End()
        return self._next_tick()

    def finish(self, report: protocol.Report) -> None:
        """The controller's last report: sent with everything still held."""
        self._record(protocol.encode_report(report))
        self.flush()

    def _wants(self) -> bool:
        return self.wants_exchange(self.sim.graph.now_ns)

    def _next_tick(self) -> protocol.Tick:
        self._rounds += 1
        if self._index % DIGEST_EVERY == 0:
            self._digest = replica.digest(self.sim)
        tick, _ = self.proxy.tick()
        self._tick_ns = tick.now_ns
        self._asked = _perf_counter()
        return tick

    def _record(self, payload: bytes) -> None:
        now = _perf_counter()
        seconds = now - self._asked
        digest, self._digest = self._digest, b""
        if len(payload) > wire.MAX_REPLY_BYTES:
            # the parent says what lockstep says of a step this large
            payload = b"\0" + str(len(payload)).encode()
        journal = self.journal
        size = _RECORD.size + len(digest) + len(payload)
        if self._length + size > len(journal) - _HEADER.size:
            self.flush()
        at = _HEADER.size + self._length
        _RECORD.pack_into(
            journal, at, self._tick_ns, seconds, self.output.count, self.errors.count, len(digest), len(payload)
        )
        at += _RECORD.size
        journal[at : at + len(digest)] = digest
        journal[at + len(digest) : at + size - _RECORD.size] = payload
        self._length += size
        _HEADER.pack_into(journal, 0, self._seq, self._length)  # after the record: the parent may read it now
        self._records += 1
        self._index += 1
        if (
            self._records >= _BATCH_RECORDS
            or now - self._last_flush > _FLUSH_SECONDS
            or self._seq == 0  # the answer that ends the start: the parent waits for it with the start's timeout
        ):
            self.flush()

    def flush(self) -> None:
        """Send the journal's records to the parent as one batch, and start the next."""
        self._last_flush = _perf_counter()
        if not self._length:
            return
        journal = self.journal
        try:
            wire.write_frame(self.fd_out, journal[: _HEADER.size + self._length])
        except (OSError, wire.WireError):
            pass  # the parent went away: it ends this process
        self._seq += 1
        self._length = self._records = 0
        _HEADER.pack_into(journal, 0, self._seq, 0)

    def _hold(self) -> None:
        """The copy ended the run (the parent will, replaying the same record):
        send everything and wait to be ended (or for the parent to be gone)."""
        self.flush()
        _real_sleep(_HOLD_SECONDS)
        os._exit(0)


def _trusted_build(cls: Any, values: list) -> Any:
    return trusted_from_values(cls)(values)


# -- the parent's side ---------------------------------------------------------------------------------
def _unread(msg: Any) -> None:
    return None


class FastHost(SandboxHost):
    """Parent-side host of a fast-path child: replays the Reports it streams."""

    def __init__(self, sim: Simulation, spec: ControllerSpec, limits: Limits, recipe: replica.Recipe) -> None:
        super().__init__(sim, spec, limits)
        self.recipe = recipe
        self.proxy.values = _unread  # the child's own copy sent it its messages
        self.process.max_frame = JOURNAL_BYTES
        self.process.hold_output()
        fd = os.memfd_create("turtletui-journal")
        os.ftruncate(fd, JOURNAL_BYTES)
        self.journal = mmap.mmap(fd, JOURNAL_BYTES)
        self.process.journal_fd = fd
        self._records: deque[tuple[int, float, int, int, bytes, bytes]] = deque()
        self._index = 0
        self._seq = 0
        """The number of the next batch."""
        self._read_ahead = 0
        """Bytes of the batch numbered ``_seq`` already taken from the journal."""
        self._failure: ChildFailed | None = None
        """Why the child is gone, said once what it wrote before is replayed."""
        self._ending = False
        """The run is over: the next record is the child's answer to its end."""

    def _terminate(self) -> None:
        super()._terminate()
        fd, self.process.journal_fd = self.process.journal_fd, None
        if fd is not None:
            os.close(fd)
            self.journal.close()

    def _config(self, ros_args: list[str], seed: int) -> dict[str, Any]:
        return {**super()._config(ros_args, seed), "fast": self.recipe.to_config()}

    def exchange(self, timeout: float | None = None, *, wait: bool = False) -> bool:
        if self.finished:
            return False
        self._rounds += 1
        due = self._index % DIGEST_EVERY == 0
        ours = replica.digest(self.sim) if due else b""
        _, cause = self.proxy.tick()  # what the child's copy sent it
        try:
            seconds = self._replay(timeout or self.limits.step_timeout, ours, due)
        except _Stop:
            return True
        if self._metering:
            self._meter(cause, seconds, _perf_counter())
        return True

    def _queued(self) -> float:
        # The child times its own answers while this process replays beside it:
        # only the child's waits for a CPU are in them.
        return self.process.queued_seconds(own=False)

    def close(self) -> Any:
        if not self.finished and self.graph.now_ns >= self.recipe.end_ns:
            # the copy ended the run at the same instant: its answer to End is next
            self._ending = True
            try:
                self._replay(1.0, replica.digest(self.sim), True)
            except _Stop:
                pass
        self._terminate()
        return self.crash

    def _replay(self, timeout: float, ours: bytes, due: bool) -> float:
        """Check and apply the child's next record; the wall seconds it took to
        answer. Raises _Stop when the run ended here."""
        now_ns, seconds, printed, errors, digest, payload = self._next_record(timeout)
        self._index += 1
        if now_ns != self.graph.now_ns:
            self._tampered(
                f"its copy of the simulator answered at t={now_ns / 1e9:.3f} s where turtletui was at "
                f"t={self.sim.t:.3f} s"
            )
        if due and digest != ours:
            self._tampered(replica.describe_difference(digest, ours) if digest else "it did not say where its turtles were")
        self.process.show_output_until(printed, errors)
        if payload[:1] == b"\0":
            self._fail("flood", f"sent {payload[1:20].decode(errors='replace')} bytes in one step (limit {wire.MAX_REPLY_BYTES})")
            raise _Stop
        self._apply(self._decode(payload))
        # measured by the child's clock: a time no answer takes (negative, NaN) counts as none
        return seconds if seconds >= 0.0 else 0.0

    def _tampered(self, why: str) -> None:
        self._fail(TAMPERED, f"tampered with the simulator: {why}; the run is not graded")
        raise _Stop

    def _next_record(self, timeout: float) -> tuple[int, float, int, int, bytes, bytes]:
        """The child's next record, within ``timeout`` seconds of wall time;
        raises _Stop when the child is gone (or stuck) and every record it
        wrote is replayed."""
        records = self._records
        while not records:
            failure = self._failure
            if failure is None:
                try:
                    self._take(self.process.receive(timeout))
                    continue
                except ChildFailed as failed:
                    failure = failed
            # The child died or is stuck: what it answered before is in the journal.
            if self._from_journal():
                if failure.kind != "timeout":
                    self._failure = failure  # said when the replay gets there
                continue  # a timeout with new records: it is slow, not stuck
            if self._ending:
                self._no_last_report(failure)  # its answer to the run's end never came
            else:
                self._failed(failure)
            raise _Stop
        return records.popleft()

    def _take(self, payload: bytes) -> None:
        """One batch from the pipe."""
        try:
            seq, length = _HEADER.unpack_from(payload)
        except struct.error:
            seq = length = -1
        if seq != self._seq or length != len(payload) - _HEADER.size:
            self._tampered("it sent a batch of answers out of order")
        try:
            self._records.extend(_records(payload, _HEADER.size + self._read_ahead))
        except ValueError:
            self._tampered("it sent a batch of answers turtletui cannot read")
        self._seq += 1
        self._read_ahead = 0

    def _from_journal(self) -> bool:
        """Take the records of the batch the child had not sent yet; whether there were any."""
        try:
            seq, length = _HEADER.unpack_from(self.journal)
        except (struct.error, ValueError):
            return False
        if seq != self._seq or not self._read_ahead < length <= JOURNAL_BYTES - _HEADER.size:
            return False
        try:
            records = _records(self.journal[: _HEADER.size + length], _HEADER.size + self._read_ahead)
        except ValueError:
            return False
        self._records.extend(records)
        self._read_ahead = length
        return True


def _records(payload: bytes, at: int) -> list[tuple[int, float, int, int, bytes, bytes]]:
    """The records of one batch from byte ``at``; ValueError if they are malformed."""
    out = []
    view = memoryview(payload)
    end, size = len(payload), _RECORD.size
    unpack = _RECORD.unpack_from
    while at < end:
        if at + size > end:
            raise ValueError("short record")
        now_ns, seconds, printed, errors, digest_len, report_len = unpack(view, at)
        at += size
        stop = at + digest_len + report_len
        if stop > end:
            raise ValueError("short record")
        digest = bytes(view[at : at + digest_len])
        out.append((now_ns, seconds, printed, errors, digest, bytes(view[at + digest_len : stop])))
        at = stop
    return out


def start_loopback(host: Any, config: dict[str, Any]) -> Loopback:
    """Build the child's copy from the config's recipe and let it answer the
    child's host (turtletui.runtime.child.ChildHost) instead of the parent."""
    recipe = replica.Recipe.from_config(config["fast"])
    sim = replica.build_copy(recipe)
    path = config.get("path")
    spec = ControllerSpec(name=config["name"], path=None if path is None else Path(path), module=config.get("module"))
    loopback = Loopback(sim, spec, Limits(), recipe.end_ns, config["fd_out"], config["fd_journal"])
    host.ask = loopback.ask
    return loopback
