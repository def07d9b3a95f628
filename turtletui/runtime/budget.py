"""What a sandboxed controller may spend: wall time and output.

In lockstep the simulation waits for the controller, so a controller too
slow for a real robot still gets every message in time, only the run takes
longer (a 30 ms callback on a 16 ms pose: twice as long; a wait of half a
second per callback: hours). :class:`Pace` measures, on the trusted side,
the wall time the controller takes to answer and what it was answering,
and says when it has fallen so far behind real time that a robot would have
left it behind. :class:`OutputBudget` keeps a flood of ``print()`` output
from reaching the terminal: what is over the budget is counted, not shown.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

WAKE = "wake"
"""The cause of an exchange that delivered nothing: a timer or a sleep was due."""
CALLS = "calls"
"""...one that delivered service responses, requests, goal events or parameters."""


@dataclass(slots=True)
class _Cost:
    exchanges: int
    seconds: float
    first_ns: int
    last_ns: int


@dataclass(slots=True)
class Pace:
    """Wall time a controller took to answer, against the simulated time it covered.

    ``charge(cause, seconds, now_ns)`` after each exchange; the cause is the
    subscription (its wire id) whose messages the exchange delivered, a tuple
    of them, :data:`WAKE` or :data:`CALLS`. On a busy machine some of that
    time was spent waiting for a CPU: :meth:`excuse` takes it off.
    """

    start_ns: int
    """Simulated time when metering began (after start-up)."""
    busy: float = 0.0
    """Wall seconds the controller took to answer since then."""
    excused: float = 0.0
    """Of those, seconds the machine kept the processes waiting for a CPU."""
    costs: dict[Any, _Cost] = field(default_factory=dict)
    subscriptions: dict[int, tuple[str, str]] = field(default_factory=dict)
    """Wire id -> (callback name, topic), as the controller declared them."""
    timers: list[tuple[int, str]] = field(default_factory=list)
    """(period ns, callback name) of the controller's timers."""

    def charge(self, cause: Any, seconds: float, now_ns: int) -> float:
        """Count one exchange; returns how many wall seconds the controller is
        behind real time (negative: ahead)."""
        self.busy += seconds
        cost = self.costs.get(cause)
        if cost is None:
            self.costs[cause] = _Cost(1, seconds, now_ns, now_ns)
        else:
            cost.exchanges += 1
            cost.seconds += seconds
            cost.last_ns = now_ns
        return self.busy - self.excused - (now_ns - self.start_ns) / 1e9

    def excuse(self, waited: float, now_ns: int) -> float:
        """Take off the ``waited`` seconds (since metering began) the machine
        kept the controller, or the grader waiting for it, from a CPU; returns
        how far behind real time it is then."""
        self.excused = min(max(self.excused, waited), self.busy)
        return self.busy - self.excused - (now_ns - self.start_ns) / 1e9

    def report(self, now_ns: int) -> str:
        """Why the controller is too slow, in the words of a robot."""
        simulated = (now_ns - self.start_ns) / 1e9
        own = self.busy - self.excused
        head = f"could not keep up with real time ({own:.1f} s of wall time for {simulated:.1f} s of simulated time"
        if self.excused >= 0.1:
            head += f", not counting {self.excused:.1f} s this machine kept it waiting for a CPU"
        head += ")"
        if not self.costs:
            return head
        share = own / self.busy if self.busy > 0 else 1.0
        cause, cost = max(self.costs.items(), key=lambda item: item[1].seconds)
        average = _ms(cost.seconds * share / cost.exchanges)
        every = None
        if cost.exchanges > 1 and cost.last_ns > cost.first_ns:
            every = _ms((cost.last_ns - cost.first_ns) / (cost.exchanges - 1) / 1e9)
        if isinstance(cause, int):
            label, topic = self.subscriptions.get(cause, ("", "a topic"))
            who = f"your {label}" if label else f"your callback for {topic}"
            text = f"{who} takes {average} on average"
            if every:
                text += f"; a message on {topic} arrives every {every}"
        elif isinstance(cause, tuple):
            topics = sorted({self.subscriptions.get(c, ("", "?"))[1] for c in cause})
            text = f"your callbacks for {', '.join(topics)} take {average} on average"
            if every:
                text += f"; their messages arrive every {every}"
        elif cause == CALLS:
            text = f"your callbacks for service and action answers take {average} on average"
        else:
            text = f"your {self._waking()} take {average} on average"
            if every:
                text += f", and are due every {every}"
        return f"{head}: {text}: on a real robot this node falls behind"

    def _waking(self) -> str:
        names = sorted({label or "timer callback" for _, label in self.timers})
        if len(names) == 1 and len(self.timers) == 1:
            return f"{names[0]} (a timer) and loops between sleeps"
        if names:
            return f"timer callbacks ({', '.join(names)}) and loops between sleeps"
        return "loops between sleeps"


def _ms(seconds: float) -> str:
    ms = seconds * 1000
    return f"{ms:.0f} ms" if ms >= 10 else f"{ms:.1f} ms"


def size_text(size: int) -> str:
    """``size`` bytes for people: 512 bytes, 12.3 kB, 59.0 MB."""
    if size < 1000:
        return f"{size} byte{'s' if size != 1 else ''}"
    if size < 1_000_000:
        return f"{size / 1000:.1f} kB"
    return f"{size / 1_000_000:.1f} MB"


class OutputBudget:
    """Turns a controller's raw output into lines to show, within a budget of
    bytes and lines per run; a line longer than ``line_chars`` is cut. What is
    over is counted: :meth:`dropped` says how much at the end. The budget is
    shared by stdout and stderr (``feed(..., stderr=True)``, shown by
    ``show_stderr``), each stream cut into lines of its own."""

    def __init__(
        self,
        show: Callable[[str], None],
        *,
        max_bytes: int,
        max_lines: int,
        line_chars: int,
        show_stderr: Callable[[str], None] | None = None,
        lines_per_second: int | None = None,
        clock: Callable[[], float] = time.monotonic,
        note: Callable[[int], None] | None = None,
    ) -> None:
        """``lines_per_second``: besides the run's budget, show at most that many
        lines a second of ``clock`` (the app's, where a run has no budget but the
        screen and the simulation share one process); ``note(count)`` is told,
        at the start of a second, how many the seconds before could not show."""
        self._shows = (show, show_stderr or show)
        self.lines_per_second = lines_per_second
        self._rate = None if lines_per_second is None else RateCap(lines_per_second, clock, note)
        self.max_bytes = max_bytes
        self.max_lines = max_lines
        self.line_chars = line_chars
        self._buffers = [b"", b""]
        """Each stream's line not ended yet (stdout, stderr)."""
        self._skipping = [False, False]
        """Past the cut of a long line: drop until its end (each stream)."""
        self.over = False
        """The budget is spent: everything from now on is dropped."""
        self.shown_bytes = 0
        self.shown_lines = 0
        self.dropped_bytes = 0
        self.dropped_lines = 0
        self.cut_lines = 0

    def feed(self, data: bytes, final: bool = False, *, stderr: bool = False) -> bool:
        """Show the complete lines of ``data`` (all of it when ``final``),
        written to stdout (or ``stderr``). Returns True when this call used up the budget."""
        if self.over:
            self._drop(data)
            return False
        stream = int(stderr)
        if self._skipping[stream]:
            rest, newline, data = data.partition(b"\n")
            self.dropped_bytes += len(rest)
            if not newline:
                return False
            self._skipping[stream] = False
        *lines, buffer = (self._buffers[stream] + data).split(b"\n")
        if final and buffer:
            lines.append(buffer)
            buffer = b""
        elif len(buffer) > 4 * self.line_chars:  # a line without end yet: show its start
            lines.append(buffer)
            buffer = b""
            self._skipping[stream] = True
        self._buffers[stream] = buffer
        if self._rate is not None and lines:
            room = self._rate.allow(len(lines))
            if room < len(lines):
                over = lines[room:]
                self.dropped_lines += len(over)
                self.dropped_bytes += sum(map(len, over)) + len(over)
                lines = lines[:room]
        show = self._shows[stream]
        for index, line in enumerate(lines):
            text, cut = self._cut(line)
            size = len(line) - cut + 1
            if self.shown_lines >= self.max_lines or self.shown_bytes + size > self.max_bytes:
                self.over = True
                rest = lines[index:]
                self.dropped_lines += len(rest)
                self.dropped_bytes += sum(len(item) + 1 for item in rest) + sum(map(len, self._buffers))
                self._buffers = [b"", b""]
                self._skipping = [False, False]
                return True
            self.shown_lines += 1
            self.shown_bytes += size
            if cut:
                self.dropped_bytes += cut
                self.cut_lines += 1
            show(text)
        return False

    def _cut(self, line: bytes) -> tuple[str, int]:
        """The line as shown, and how many of its bytes are cut off."""
        limit = self.line_chars
        text = line[: 4 * limit].decode("utf-8", "replace")
        if len(text) <= limit and len(line) <= 4 * limit:
            return text, 0
        kept = text[:limit]
        return f"{kept} [... cut]", max(0, len(line) - len(kept.encode("utf-8", "replace")))

    def _drop(self, data: bytes) -> None:
        self.dropped_bytes += len(data)
        self.dropped_lines += data.count(b"\n")

    def dropped(self) -> str | None:
        """One line saying how much output was not shown, or None."""
        if not (self.dropped_bytes or self.dropped_lines):
            return None
        why = []
        if self.over:
            why.append(
                f"{self.dropped_lines:,} lines over its budget of {size_text(self.max_bytes)} "
                f"or {self.max_lines:,} lines per run"
            )
        if self._rate is not None and self._rate.dropped:
            why.append(f"{self._rate.dropped:,} lines over {self.lines_per_second:,} a second")
        if self.cut_lines:
            why.append(f"{self.cut_lines:,} long line{'s' if self.cut_lines != 1 else ''} cut at {self.line_chars:,} characters")
        return f"{size_text(self.dropped_bytes)} of output dropped ({'; '.join(why)})"


class RateCap:
    """At most ``per_second`` items a second of ``clock``; ``note(count)`` is
    told, as a new second begins, how many the seconds before refused."""

    def __init__(self, per_second: int, clock: Callable[[], float], note: Callable[[int], None] | None) -> None:
        self.per_second = per_second
        self._clock = clock
        self._note = note
        self._second = -1.0
        """When the current second began."""
        self._taken = 0
        """Items allowed in it."""
        self._untold = 0
        """Items refused and not told to ``note`` yet."""
        self.dropped = 0
        """Items refused in all."""

    def allow(self, count: int) -> int:
        """How many of ``count`` items may pass now (the first ones); the rest are refused."""
        now = self._clock()
        if now - self._second >= 1.0:
            self._second, self._taken = now, 0
            untold, self._untold = self._untold, 0
            if untold and self._note is not None:
                self._note(untold)  # (which may take an item of the new second itself)
        room = min(max(self.per_second - self._taken, 0), count)
        self._taken += room
        self._untold += count - room
        self.dropped += count - room
        return room
