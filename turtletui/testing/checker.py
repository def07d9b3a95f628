"""``check_controller``: prove a controller file is deterministic, as
Gymnasium's ``check_env`` proves an environment is.

It runs the file headless in lockstep five times and compares what the
trusted simulation saw (every pose turtlesim published, bit for bit, and the
log):

1. sandboxed with ``seed``, twice: the same seed must give the same run;
2. in this process with ``seed``: the host students use (sandboxed) and the
   host tests use (in-process) must agree;
3. in this process again: nothing may survive from one run to the next;
4. sandboxed with another seed: reported as changing the trajectory or not
   (a controller that draws no random numbers, in a world that draws none,
   cannot differ; nor can one that seeds its own generators).

The in-process runs come only after the sandboxed runs ended cleanly, so a
controller that loops forever is stopped by the sandbox first.
"""

from __future__ import annotations

import contextlib
import io
import struct
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from turtletui.api import run
from turtletui.errors import TurtletuiError, UsageError
from turtletui.graph.logs import PRINTED_SUFFIXES, LogRecord
from turtletui.lessons.loader import display_path
from turtletui.plugins.manager import Plugins, plugin_manager
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.report import CrashReport
from turtletui.sim.constants import DT

if TYPE_CHECKING:
    from turtletui.grading.engine import GradingPlan, ScenarioRun
    from turtletui.lessons.model import Lesson
    from turtletui.runtime.sandbox import Limits
    from turtletui.worlds import WorldSpec

DEFAULT_SECONDS = 10.0
"""Simulated seconds each run lasts without a lesson (with one: its scenario's duration)."""

HINTS = {
    "reproducible": "something besides the seed changes what it does: random numbers from an "
    "unseeded generator (random.Random(), numpy.random.default_rng(), os.urandom, uuid.uuid4) "
    "or real time (time.process_time, threads racing)",
    "hosts": "it depends on the process it runs in (os.getpid, the order of a set of strings, "
    "the environment, files it writes) or on state an earlier run left in this process",
    "fresh": "state survives from the previous run in this process: a module-level global it "
    "changes in a module it imports, a class attribute, a cache",
}


class ControllerCheckError(TurtletuiError, AssertionError):
    """A controller that is not deterministic (or could not be checked).

    The message is one line naming the file, which runs differ, and the first
    difference: tick, simulated time, turtle and the pose values (or the log
    line). An AssertionError too, so a pytest test calling
    :func:`check_controller` fails rather than errors.
    """

    __module__ = "turtletui.testing"  # tracebacks name it where users import it from

    def __init__(
        self,
        message: str,
        *,
        check: str,
        t: float | None = None,
        turtle: str | None = None,
        first: tuple[float, ...] | LogRecord | None = None,
        second: tuple[float, ...] | LogRecord | None = None,
    ) -> None:
        super().__init__(message)
        self.check = check
        """Which comparison failed: "crash", "reproducible" (same seed twice),
        "hosts" (sandboxed against in-process) or "fresh" (in-process twice)."""
        self.t = t
        """Simulated seconds of the first difference."""
        self.turtle = turtle
        """The turtle whose poses differ first (None for a log difference)."""
        self.first = first
        """The pose row (or log record) in the first run; None where it has none."""
        self.second = second
        """The same in the second run."""

    @property
    def tick(self) -> int | None:
        """The 16 ms simulation tick of the first difference."""
        return None if self.t is None else round(self.t / DT)


@dataclass(frozen=True)
class ControllerCheck:
    """What :func:`check_controller` proved about a controller."""

    path: Path
    seed: int
    other_seed: int
    seconds: float
    """Simulated seconds of each run."""
    scenario: str | None
    """The lesson scenario it ran in; None: turtlesim's own start."""
    poses: dict[str, int]
    """Pose rows compared per turtle, in each run."""
    end_poses: dict[str, tuple[float, float, float]]
    """Where each turtle ended: (x, y, theta), metres and radians."""
    log_lines: int
    """Log lines compared, in each run."""
    seed_changes_trajectory: bool
    """Whether ``other_seed`` gave a different trajectory."""
    seed_note: str
    """Why the other seed changed the trajectory or could not."""

    def summary(self) -> str:
        """One line, as a test report or a terminal would show it."""
        poses = ", ".join(f"{n} of {turtle}" for turtle, n in self.poses.items()) or "none"
        where = f" in scenario {self.scenario}" if self.scenario else ""
        return (
            f"{display_path(self.path)}: deterministic over {self.seconds:g} s{where} "
            f"(poses: {poses}; {self.log_lines} log lines): seed {self.seed} twice bit for bit, "
            f"sandboxed = in-process, run after run; {self.seed_note}"
        )


@dataclass(frozen=True)
class _Run:
    """One run as the checks compare it."""

    label: str
    columns: tuple[str, ...]
    poses: dict[str, list[tuple[float, ...]]]
    logs: list[LogRecord]
    crashes: list[CrashReport]


def check_controller(
    path: str | Path,
    *,
    lesson: str | Path | Lesson | None = None,
    scenario: str | None = None,
    seconds: float | None = None,
    seed: int = 0,
    other_seed: int | None = None,
    ros_args: Sequence[str] = (),
    world: str | Path | None = None,
    distro: str | None = None,
    limits: Limits | None = None,
    plugins: Plugins = (),
) -> ControllerCheck:
    """Check that a controller file runs deterministically; raise
    :class:`ControllerCheckError` naming the first difference otherwise.

    ``lesson`` (an id or a lesson file) runs it as the grader does, in the
    lesson's ``scenario`` (its first when None): start pose, world, drive,
    ``--ros-args`` and distro. ``seconds`` is each run's simulated length
    (the scenario's duration, else 10 s); ``other_seed`` defaults to
    ``seed + 1``. ``world`` (a registered world's name or a ``.toml`` file),
    ``ros_args``, ``distro`` and ``limits`` are as for
    :func:`turtletui.api.run`. The file also runs in this process (trusted):
    check only code you would run yourself. Bad input raises the library's
    usual one-line TurtletuiError (a missing file, an unknown lesson...).
    """
    __tracebackhide__ = True  # pytest shows the caller's line, not this module's
    path = Path(path)
    other = seed + 1 if other_seed is None else other_seed
    if other == seed:
        raise UsageError(f"other_seed must differ from seed, both are {seed}")
    if lesson is not None or world is not None:
        plugins = plugin_manager(plugins)  # built once for the lesson, its worlds and checks
    if lesson is not None:
        if world is not None:
            raise UsageError("give a lesson or a world, not both: a lesson's scenario names its world")
        runner, scenario_name, seconds, seeded = _lesson_runner(
            path, lesson, scenario, seconds, (seed, other), ros_args, distro, limits, plugins
        )
    else:
        if scenario is not None:
            raise UsageError(f"scenario {scenario!r} needs a lesson")
        seconds = DEFAULT_SECONDS if seconds is None else seconds
        runner, seeded = _plain_runner(path, seconds, ros_args, world, distro, limits, plugins)
        scenario_name = None
    shown = display_path(path)

    first = runner(True, seed)
    if first.crashes:
        crash = first.crashes[0]
        raise ControllerCheckError(
            f"{crash.summary()} ({first.label}); only a controller that runs cleanly can be checked",
            check="crash",
            t=crash.t,
        )
    _compare(shown, "reproducible", first, runner(True, seed))
    in_process = runner(False, seed)
    _compare(shown, "hosts", first, in_process)
    _compare(shown, "fresh", in_process, runner(False, seed))

    reseeded = runner(True, other)
    differs = _first_pose_difference(first, reseeded) is not None
    if differs:
        note = f"seed {other} gives another trajectory"
    elif seeded:
        note = f"seed {other} gives the same trajectory although {seeded} (the controller does not depend on it)"
    else:
        note = (
            f"seed {other} gives the same trajectory: nothing in the run draws on the seed "
            "(the controller takes no numbers from random or numpy.random, or seeds them itself)"
        )
    return ControllerCheck(
        path=path,
        seed=seed,
        other_seed=other,
        seconds=seconds,
        scenario=scenario_name,
        poses={turtle: len(rows) for turtle, rows in first.poses.items()},
        end_poses={turtle: tuple(rows[-1][1:4]) for turtle, rows in first.poses.items() if rows},
        log_lines=len(first.logs),
        seed_changes_trajectory=differs,
        seed_note=note,
    )


# -- running ------------------------------------------------------------------


def _label(sandboxed: bool, seed: int) -> str:
    return f"{'sandboxed' if sandboxed else 'in-process'}, seed {seed}"


@contextlib.contextmanager
def _quiet(sandboxed: bool):
    """In-process, what the controller prints would land on this process's
    terminal (sandboxed it becomes log lines): keep it out."""
    if sandboxed:
        yield
        return
    sink = io.StringIO()
    with contextlib.redirect_stdout(sink), contextlib.redirect_stderr(sink):
        yield


def _seeded(world: WorldSpec | None) -> str | None:
    """What in a world is drawn from the seed, or None."""
    lidar = world.lidar if world is not None else None
    drawn = [] if lidar is None else [
        what for what, used in (("noise", lidar.noise_std > 0), ("dropped readings", lidar.dropout > 0)) if used
    ]
    if drawn:
        return f"the LiDAR's {' and '.join(drawn)} {'is' if len(drawn) == 1 else 'are'} drawn from the seed"
    return None


def _plain_runner(path, seconds, ros_args, world, distro, limits, plugins):
    """A runner of plain runs (turtlesim's start, ``world`` or its empty arena),
    and what in the world draws on the seed."""
    spec: WorldSpec | None = None
    if world is not None:
        from turtletui.worlds import resolve_world

        spec = resolve_world(world, plugins)

    def runner(sandboxed: bool, seed: int) -> _Run:
        with _quiet(sandboxed):
            result = run(
                [path],
                duration=seconds,
                seed=seed,
                sandbox=sandboxed,
                ros_args=ros_args,
                keep_poses=True,
                keep_calls=False,
                limits=limits,
                world=None if spec is None else spec.build(seed),
                distro=distro,
            )
        if result.interrupted:
            raise KeyboardInterrupt
        return _Run(_label(sandboxed, seed), ("t", "x", "y", "theta"), result.poses, result.logs, result.crashes)

    return runner, _seeded(spec)


def _lesson_runner(path, lesson, scenario, seconds, seeds, ros_args, distro, limits, plugins):
    """A runner of the grader's own scenario runs, and the scenario's name,
    duration and what in it draws on the seed."""
    from turtletui.grading.engine import prepare, run_scenario, validate
    from turtletui.grading.trace import POSE_COLUMNS
    from turtletui.lessons.loader import find_lesson

    if isinstance(lesson, (str, Path)):
        lesson = find_lesson(lesson, plugins=plugins)
    chosen = _scenario(lesson, scenario)
    changes = {"seeds": seeds}
    if seconds is not None:
        changes["duration"] = seconds
    if ros_args:
        changes["ros_args"] = tuple(ros_args)
    chosen = replace(chosen, **changes)
    lesson = replace(lesson, scenarios=(chosen,), distro=distro or lesson.distro)
    plan: GradingPlan = prepare(lesson, plugins=plugins)
    runs: dict[int, ScenarioRun] = {r.seed: r for r in plan.runs}
    _, worlds = validate(lesson, plugins=plugins)
    if chosen.start == "random":
        seeded = "the start pose is drawn from the seed"
    else:
        seeded = _seeded(worlds[chosen.world or lesson.world])

    def runner(sandboxed: bool, seed: int) -> _Run:
        spec = ControllerSpec(name=path.stem, path=path, trusted=not sandboxed)
        with _quiet(sandboxed):
            trace, _ = run_scenario(plan, runs[seed], [spec], limits=limits)
        poses = {turtle: [tuple(row) for row in rows.tolist()] for turtle, rows in trace.poses.items()}
        return _Run(_label(sandboxed, seed), POSE_COLUMNS, poses, trace.logs, trace.crashes)

    return runner, chosen.name, chosen.duration, seeded


def _scenario(lesson: Lesson, name: str | None):
    if not lesson.scenarios:
        raise UsageError(f"{display_path(lesson.path)}: lesson {lesson.id!r} has no [[scenarios]]")
    if name is None:
        return lesson.scenarios[0]
    for scenario in lesson.scenarios:
        if scenario.name == name:
            return scenario
    known = ", ".join(s.name for s in lesson.scenarios)
    raise UsageError(f"{display_path(lesson.path)}: no scenario {name!r}; its scenarios: {known}")


# -- comparing ------------------------------------------------------------------


def _bits(rows: Sequence[tuple[float, ...]]) -> bytes:
    """The rows' floats as IEEE 754 bytes: -0.0 is not 0.0, a NaN equals itself."""
    flat = [value for row in rows for value in row]
    return struct.pack(f"<{len(flat)}d", *flat)


def _first_pose_difference(a: _Run, b: _Run):
    """(t, turtle, row in a, row in b) of the earliest differing pose, or None."""
    found = None
    for turtle in sorted(a.poses.keys() | b.poses.keys()):
        rows_a, rows_b = a.poses.get(turtle, []), b.poses.get(turtle, [])
        if _bits(rows_a) == _bits(rows_b):
            continue
        index = next(
            (i for i, (ra, rb) in enumerate(zip(rows_a, rows_b, strict=False)) if _bits([ra]) != _bits([rb])),
            min(len(rows_a), len(rows_b)),
        )
        row_a = rows_a[index] if index < len(rows_a) else None
        row_b = rows_b[index] if index < len(rows_b) else None
        t = min(row[0] for row in (row_a, row_b) if row is not None)
        if found is None or t < found[0]:
            found = (t, turtle, row_a, row_b)
    return found


def _describe_poses(columns, turtle, a: _Run, b: _Run, row_a, row_b) -> str:
    if row_a is None or row_b is None:
        has, lacks = (a, b) if row_b is None else (b, a)
        return f"{turtle} has a pose in the {has.label} run and none in the {lacks.label} run"
    fields = [
        f"{name} {va!r} vs {vb!r}"
        for name, va, vb in zip(columns, row_a, row_b, strict=True)
        if _bits([(va,)]) != _bits([(vb,)])
    ]
    return f"{turtle} " + ", ".join(fields)


def _comparable_logs(logs: list[LogRecord], across_hosts: bool) -> list[LogRecord]:
    # What a sandboxed controller prints becomes log lines; in this process it
    # goes to stdout, so between hosts only the log proper is compared.
    if not across_hosts:
        return logs
    return [record for record in logs if not record.node.endswith(PRINTED_SUFFIXES)]


def _compare(shown: str, check: str, a: _Run, b: _Run) -> None:
    __tracebackhide__ = True
    what = {
        "reproducible": f"two runs ({a.label}) differ",
        "hosts": f"the {a.label} and {b.label} runs differ",
        "fresh": f"a second run ({b.label}) differs from the first",
    }[check]
    found = _first_pose_difference(a, b)
    if found is not None:
        t, turtle, row_a, row_b = found
        detail = _describe_poses(a.columns, turtle, a, b, row_a, row_b)
        raise ControllerCheckError(
            f"{shown}: {what}: first at tick {round(t / DT)} (t={t:.3f} s), {detail}; {HINTS[check]}",
            check=check,
            t=t,
            turtle=turtle,
            first=row_a,
            second=row_b,
        )
    logs_a = _comparable_logs(a.logs, check == "hosts")
    logs_b = _comparable_logs(b.logs, check == "hosts")
    for index in range(max(len(logs_a), len(logs_b))):
        rec_a = logs_a[index] if index < len(logs_a) else None
        rec_b = logs_b[index] if index < len(logs_b) else None
        if rec_a == rec_b:
            continue
        t = min(r.t for r in (rec_a, rec_b) if r is not None)
        text_a = "(none)" if rec_a is None else repr(rec_a.format())
        text_b = "(none)" if rec_b is None else repr(rec_b.format())
        raise ControllerCheckError(
            f"{shown}: {what}: same trajectory, but log line {index + 1} (t={t:.3f} s) is "
            f"{text_a} vs {text_b}; {HINTS[check]}",
            check=check,
            t=t,
            first=rec_a,
            second=rec_b,
        )
