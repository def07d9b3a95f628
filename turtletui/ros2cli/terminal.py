"""What a shell adds around ``ros2``, for a console that has one prompt.

One command runs in the foreground and its output follows it; Ctrl+C
(:meth:`Terminal.interrupt`) stops it; a new command stops it too, so output
never mixes with later commands. A ``ros2 topic pub`` that repeats, a
``ros2 bag record`` and a ``ros2 bag play`` are the exception: their work is
their effect, so a new command sends them to the background instead (or
``&`` starts them there), where they go on quietly. ``jobs`` lists them,
``kill %N`` stops one and ``kill all`` stops every one (a recording stopped
says so and is written, as after Ctrl+C).
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
    """A command running in the background (a publisher, a recording...)."""

    number: int
    stream: Stream

    def describe(self, state: str) -> str:
        progress = self.stream.progress
        return f"[{self.number}]  {state:<8} {self.stream.command}" + (f"  ({progress})" if progress else "")


class Terminal:
    """A ``ros2`` console with one foreground command and background jobs."""

    def __init__(self, cli: Ros2Cli) -> None:
        self.cli = cli
        self.foreground: Stream | None = None
        """The command whose output the console shows now."""
        self.jobs: list[Job] = []
        """Commands running in the background, by job number."""

    def run(self, line: str) -> list[Line]:
        """Run one line: ``jobs``, ``kill ...`` or a ros2 command (``&`` at the
        end starts a publisher or a recording in the background)."""
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
        if not stream.runs_in_background:
            stream.close()
            return out + [Line("only ros2 topic pub and ros2 bag record|play run in the background here"
                               " (the output of other commands would mix with later ones)", "error")]
        job = self._add_job(stream)
        return out + [Line(t, kind) for t in result.lines] + [
            Line(f"[{job.number}] in the background: jobs lists it, kill %{job.number} stops it",
                 "note")]

    def interrupt(self) -> list[Line]:
        """Ctrl+C: stop the foreground command. Nothing happens (and nothing is
        returned) when none runs."""
        stream, self.foreground = self.foreground, None
        if stream is None:
            return []
        printed = [Line(text) for text in stream.poll()]  # before the ^C, as in a terminal
        return [*printed, Line("^C", "note"), *_last_words(stream)]

    def poll(self) -> list[Line]:
        """What the foreground command printed since the last poll, and notices
        of background jobs that ended (``pub -t N``, a bag played to its end)."""
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
        if stream.runs_in_background:
            job = self._add_job(stream)
            return out + [Line(f"[{job.number}] {stream.command}: goes on in the background"
                               f" (jobs lists it, kill %{job.number} stops it)", "note")]
        return [*out, Line("^C", "note"), *_last_words(stream)]

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
            return [Line("nothing runs in the background", "note")]
        return [Line(job.describe("Running")) for job in self.jobs]

    def _kill(self, args: list[str]) -> list[Line]:
        if not args:
            return [Line("kill: usage: kill %N (a job number from jobs) | kill all", "error")]
        if args == ["all"]:
            stopped = [line for job in self.jobs for line in self._stop_job(job)]
            self.jobs.clear()
            return stopped or [Line("nothing runs in the background", "note")]
        out = []
        for arg in args:
            job = next((j for j in self.jobs if arg in (f"%{j.number}", str(j.number))), None)
            if job is None:
                out.append(Line(f"kill: {arg}: no such job (jobs lists them)", "error"))
                continue
            self.jobs.remove(job)
            out += self._stop_job(job)
        return out

    @staticmethod
    def _stop_job(job: Job) -> list[Line]:
        job.stream.poll()  # what it printed in the background is not shown
        return [Line(job.describe("Stopped"), "note"), *_last_words(job.stream)]


def _last_words(stream: Stream) -> list[Line]:
    """Stop a stream (its earlier output taken), and what it says as it stops
    (a recorder's last lines)."""
    stream.close()
    return [Line(text) for text in stream.poll()]
