"""What a shell adds around ``ros2``, for a console that has one prompt.

One command runs in the foreground and its output follows it; Ctrl+C
(:meth:`Terminal.interrupt`) stops it; a new command stops it too, so output
never mixes with later commands. A ``ros2 topic pub`` that repeats is the
exception: its work is its effect, so a new command sends it to the
background instead (or ``&`` starts it there), where it goes on publishing
quietly. ``jobs`` lists the background publishers, ``kill %N`` stops one and
``kill all`` stops every one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

from turtletui.ros2cli.cli import Ros2Cli
from turtletui.ros2cli.streams import Stream


class Line(NamedTuple):
    """One line a terminal shows."""

    text: str
    kind: str = "out"
    """``prompt`` (the command typed), ``out``, ``error`` or ``note`` (what the
    terminal itself says: ^C, jobs going to the background or ending)."""


@dataclass
class Job:
    """A publisher running in the background."""

    number: int
    stream: Stream

    def describe(self, state: str) -> str:
        count = getattr(self.stream, "count", None)
        published = "" if count is None else f"  ({count} published)"
        return f"[{self.number}]  {state:<8} {self.stream.command}{published}"


class Terminal:
    """A ``ros2`` console with one foreground command and background publishers."""

    def __init__(self, cli: Ros2Cli) -> None:
        self.cli = cli
        self.foreground: Stream | None = None
        """The command whose output the console shows now."""
        self.jobs: list[Job] = []
        """Publishers running in the background, by job number."""

    def run(self, line: str) -> list[Line]:
        """Run one line: ``jobs``, ``kill ...`` or a ros2 command (``&`` at the
        end starts a publisher in the background)."""
        text = line.strip()
        if not text:
            return []
        out = self._leave_foreground()
        out.append(Line(f"$ {text}", "prompt"))
        words = text.split()
        if words[0] == "jobs":
            return out + self._jobs(words[1:])
        if words[0] == "kill":
            return out + self._kill(words[1:])
        background = text.endswith("&") and not text.endswith("&&")
        if background:
            text = text[:-1].rstrip()
        result = self.cli.run(text)
        kind = "error" if result.error else "out"
        stream = result.stream
        if stream is None:
            return out + [Line(t, kind) for t in result.lines]
        if not background:
            self.foreground = stream
            return out + [Line(t, kind) for t in result.lines]
        if not stream.publishes:
            stream.close()
            return out + [Line("only ros2 topic pub runs in the background here (the output of"
                               " other commands would mix with later ones)", "error")]
        job = self._add_job(stream)
        return out + [Line(t, kind) for t in result.lines] + [
            Line(f"[{job.number}] in the background: jobs lists it, kill %{job.number} stops it",
                 "note")]

    def interrupt(self) -> list[Line]:
        """Ctrl+C: stop the foreground command. Nothing happens (and nothing is
        returned) when none runs."""
        if self.foreground is None:
            return []
        self.foreground.close()
        self.foreground = None
        return [Line("^C", "note")]

    def poll(self) -> list[Line]:
        """What the foreground command printed since the last poll, and notices
        of background publishers that ended (``-t N``)."""
        out: list[Line] = []
        stream = self.foreground
        if stream is not None:
            out += [Line(text) for text in stream.poll()]
            if stream.done:
                self.foreground = None
        for job in list(self.jobs):
            job.stream.poll()  # output of the background is not shown
            if job.stream.done:
                self.jobs.remove(job)
                out.append(Line(job.describe("Done"), "note"))
        return out

    def close(self) -> None:
        """Stop everything (the console closes)."""
        if self.foreground is not None:
            self.foreground.close()
            self.foreground = None
        for job in self.jobs:
            job.stream.close()
        self.jobs.clear()

    # -- internals --------------------------------------------------------------------
    def _leave_foreground(self) -> list[Line]:
        """A new command comes: a repeating publisher goes to the background,
        anything else stops."""
        stream, self.foreground = self.foreground, None
        if stream is None:
            return []
        out = [Line(text) for text in stream.poll()]  # printed before the new command
        if stream.done:
            return out
        if stream.publishes:
            job = self._add_job(stream)
            return out + [Line(f"[{job.number}] {stream.command}: goes on in the background"
                               f" (jobs lists it, kill %{job.number} stops it)", "note")]
        stream.close()
        return out + [Line("^C", "note")]

    def _add_job(self, stream: Stream) -> Job:
        number = max((job.number for job in self.jobs), default=0) + 1
        job = Job(number, stream)
        self.jobs.append(job)
        return job

    def _jobs(self, args: list[str]) -> list[Line]:
        if args:
            return [Line("jobs: takes no arguments", "error")]
        for job in list(self.jobs):
            if job.stream.done:
                self.jobs.remove(job)
        if not self.jobs:
            return [Line("no publishers in the background", "note")]
        return [Line(job.describe("Running")) for job in self.jobs]

    def _kill(self, args: list[str]) -> list[Line]:
        if not args:
            return [Line("kill: usage: kill %N (a job number from jobs) | kill all", "error")]
        if args == ["all"]:
            stopped = [Line(job.describe("Stopped"), "note") for job in self.jobs]
            for job in self.jobs:
                job.stream.close()
            self.jobs.clear()
            return stopped or [Line("no publishers in the background", "note")]
        out = []
        for arg in args:
            job = next((j for j in self.jobs if arg in (f"%{j.number}", str(j.number))), None)
            if job is None:
                out.append(Line(f"kill: {arg}: no such job (jobs lists them)", "error"))
                continue
            job.stream.close()
            self.jobs.remove(job)
            out.append(Line(job.describe("Stopped"), "note"))
        return out
