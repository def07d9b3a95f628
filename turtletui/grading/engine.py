"""Grade controllers against a lesson: run its scenarios, judge its checks.

:func:`prepare` turns a lesson into a :class:`GradingPlan` (its checks resolved
against the registered ones, its scenario runs laid out with their start
poses), raising :class:`GradingError` with one line for anything that cannot
be graded. :func:`grade_controllers` runs the plan for one submission in the
grader's own trusted simulation and returns a :class:`SubmissionResult`.
"""

from __future__ import annotations

import math
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.compat.distro import resolve_distro
from turtletui.grading.checks import BUILTIN_CHECKS, Check, Verdict
from turtletui.grading.pictures import picture_of_trace
from turtletui.grading.results import FAILED, PASSED, Picture, SubmissionResult, TestResult
from turtletui.grading.trace import Trace, TraceCollector
from turtletui.graph.logs import INFO, LogRecord
from turtletui.lessons.loader import display_path
from turtletui.lessons.model import CheckSpec, Lesson, Scenario
from turtletui.messages import did_you_mean
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.recorder import open_recorder

if TYPE_CHECKING:
    from turtletui.runtime.sandbox import Limits
    from turtletui.runtime.simulation import Simulation
    from turtletui.sim import World
    from turtletui.worlds import WorldSpec

RANDOM_START_MARGIN = 2.0
"""Random starts keep this many metres from every wall: inside the 2..9 m box
the course's controllers treat as safe."""
OBSTACLE_START_CLEARANCE = 0.5
"""...and this many from every obstacle."""


class GradingError(ValueError):
    """A lesson that cannot be graded; the message is one line naming the file."""


RECORDING_FORMATS = ("mcap", "jsonl")
"""How failed runs are kept: MCAP (the default: replay, Foxglove, PlotJuggler
and ros2 bag open it, and it is a quarter of the size) or JSON Lines."""


@dataclass(frozen=True)
class ScenarioRun:
    """One scenario with one seed: what a single simulated run is."""

    scenario: Scenario
    seed: int
    label: str
    """How results name it: the scenario's name (and seed), or ``hidden N``."""
    start: tuple[float, float, float]

    @property
    def hidden(self) -> bool:
        return self.scenario.hidden


@dataclass(frozen=True)
class GradingPlan:
    """A lesson made ready to grade."""

    lesson: Lesson
    checks: tuple[tuple[CheckSpec, Check], ...]
    runs: tuple[ScenarioRun, ...]
    worlds: dict[str, Callable[[int], World | None]] = field(default_factory=dict)
    """Scenario world name -> builder of a fresh World for a seed (None: turtlesim's own)."""

    @property
    def max_score(self) -> float:
        return sum(spec.weight for spec, _ in self.checks if self.runs_for(spec))

    def runs_for(self, spec: CheckSpec) -> list[ScenarioRun]:
        """The scenario runs a check judges."""
        return [r for r in self.runs if not spec.scenarios or r.scenario.name in spec.scenarios]


def random_start(
    seed: int, margin: float = RANDOM_START_MARGIN, obstacles: Sequence[Any] = ()
) -> tuple[float, float, float]:
    """A start pose drawn from ``seed`` (the same on every machine): x and y
    uniform at least ``margin`` metres from the walls and, in a world with
    obstacles, at least :data:`OBSTACLE_START_CLEARANCE` from them (drawn
    again until so), any heading."""
    from turtletui.sim.constants import ARENA_SIZE
    from turtletui.sim.obstacles import nearest_distance

    rng = random.Random(seed)
    for _ in range(1000):
        x = rng.uniform(margin, ARENA_SIZE - margin)
        y = rng.uniform(margin, ARENA_SIZE - margin)
        theta = rng.uniform(-math.pi, math.pi)
        if not obstacles or nearest_distance(obstacles, x, y) >= OBSTACLE_START_CLEARANCE:
            return (x, y, theta)
    raise GradingError(f"no random start {OBSTACLE_START_CLEARANCE} m clear of the obstacles (seed {seed})")


def scenario_runs(
    lesson: Lesson, obstacles: Callable[[str], Sequence[Any]] = lambda world: ()
) -> list[ScenarioRun]:
    """Every (scenario, seed) of a lesson, with its label and start pose;
    ``obstacles(world name)`` keeps random starts clear of a world's obstacles."""
    runs = []
    hidden = 0
    for scenario in lesson.scenarios:
        for seed in scenario.seeds:
            if scenario.hidden:
                hidden += 1
                label = f"hidden {hidden}"
            elif len(scenario.seeds) > 1:
                label = f"{scenario.name}, seed {seed}"
            else:
                label = scenario.name
            if scenario.start == "random":
                start = random_start(seed, obstacles=obstacles(scenario.world or lesson.world))
            else:
                pose = scenario.start
                start = (pose["x"], pose["y"], pose.get("theta", 0.0))
            runs.append(ScenarioRun(scenario, seed, label, start))
    return runs


def available_checks(plugins: Sequence[str | Path] = ()) -> dict[str, Check]:
    """The built-in checks and those plugins register (a plugin's wins)."""
    from turtletui.plugins.manager import collect_checks, get_plugin_manager

    checks = dict(BUILTIN_CHECKS)
    for name, entry in collect_checks(get_plugin_manager(extra=plugins)).items():
        checks[name] = Check(name, entry.object, entry.description)
    return checks


def prepare(
    lesson: Lesson, *, plugins: Sequence[str | Path] = (), checks: dict[str, Check] | None = None
) -> GradingPlan:
    """Check that every check a lesson names exists and takes its thresholds,
    and lay out its scenario runs."""
    shown = display_path(lesson.path)
    if not lesson.scenarios:
        raise GradingError(f"{shown}: lesson {lesson.id!r} has no [[scenarios]] to grade")
    if not lesson.checks:
        raise GradingError(f"{shown}: lesson {lesson.id!r} has no [[checks]] to grade")
    resolved, specs = validate(lesson, plugins=plugins, checks=checks)
    worlds = {name: (lambda seed: None) if spec is None else spec.build for name, spec in specs.items()}
    runs = scenario_runs(lesson, lambda name: () if specs[name] is None else specs[name].obstacles)
    return GradingPlan(lesson, resolved, tuple(runs), worlds)


def validate(
    lesson: Lesson, *, plugins: Sequence[str | Path] = (), checks: dict[str, Check] | None = None
) -> tuple[tuple[tuple[CheckSpec, Check], ...], dict[str, WorldSpec | None]]:
    """The lesson's checks resolved against the registered ones, and the worlds
    its scenarios name; GradingError (one line, file:line) for an unknown check,
    a threshold it does not take, or an unknown world."""
    known = available_checks(plugins) if checks is None else checks
    shown = display_path(lesson.path)
    resolved = []
    for spec in lesson.checks:
        where = f"{shown}:{spec.line}" if spec.line else shown
        check = known.get(spec.name)
        if check is None:
            hint = did_you_mean(spec.name, known)
            raise GradingError(
                f"{where}: check {spec.name!r} is not a registered check{hint}; known: {', '.join(sorted(known))}"
            )
        problem = check.problem(spec.thresholds)
        if problem:
            raise GradingError(f"{where}: {problem}")
        resolved.append((spec, check))
    names = {s.world or lesson.world for s in lesson.scenarios} | {lesson.world}
    return tuple(resolved), {name: _world_spec(name, plugins, shown) for name in names}


def _world_spec(name: str, plugins: Sequence[str | Path], shown: str) -> WorldSpec | None:
    """The named world's description; None for turtlesim's own empty arena."""
    if name == "empty":
        return None
    from turtletui.worlds import WorldError, resolve_world

    try:
        return resolve_world(name, plugins)
    except WorldError as err:
        raise GradingError(f"{shown}: {err}") from None


def place_turtle(sim: Simulation, start: tuple[float, float, float], label: str) -> None:
    """Put turtle1 at a scenario's start before anything has run (nothing drawn)."""
    sim.world.place("turtle1", *start)
    turtle = sim.world.turtles["turtle1"]
    sim.graph.log(
        "turtletui",
        INFO,
        f"scenario {label}: turtle1 starts at x=[{turtle.x:f}], y=[{turtle.y:f}], theta=[{turtle.theta:f}]",
    )


def run_scenario(
    plan: GradingPlan,
    run: ScenarioRun,
    controllers: Sequence[ControllerSpec],
    *,
    limits: Limits | None = None,
    record: str | Path | None = None,
) -> tuple[Trace, Any]:
    """Run one scenario in the grader's own simulation: its trace and, with
    ``record``, its recording in memory (the caller closes it, keeping the
    file or not). Raises KeyboardInterrupt if Ctrl-C cut the run short."""
    from turtletui.api import run as run_controllers

    scenario = run.scenario
    world_name = scenario.world or plan.lesson.world
    collector: list[TraceCollector] = []
    recorder: list[Any] = []
    start_logs: list[LogRecord] = []

    def setup(sim: Simulation) -> None:
        if record is not None:
            header = {
                "lesson": plan.lesson.id,
                "scenario": run.label,
                "seed": run.seed,
                "duration": scenario.duration,
                "world": world_name,
                "start": list(run.start),
                "ros_args": list(scenario.ros_args),
            }
            recorder.append(open_recorder(sim, record, start_logs, header, buffered=True))
        place_turtle(sim, run.start, run.label)
        collector.append(TraceCollector(sim, scenario=run.label, seed=run.seed, duration=scenario.duration))

    try:
        result = run_controllers(
            controllers,
            duration=scenario.duration,
            seed=run.seed,
            ros_args=scenario.ros_args,
            setup=setup,
            limits=limits,
            keep_calls=False,
            world=plan.worlds[world_name](run.seed),
            on_log=start_logs.append if record is not None else None,
            distro=resolve_distro(None, plan.lesson.distro),
        )
        if result.interrupted:
            raise KeyboardInterrupt
    except BaseException:
        for item in recorder:
            item.close(keep=False)
        raise
    return collector[0].finish(logs=result.logs, crashes=result.crashes), (recorder[0] if recorder else None)


def judge(check: Check, trace: Trace, thresholds: dict[str, Any]) -> Verdict:
    """A check's verdict; a check that fails with an exception fails the test with its message."""
    try:
        return check.judge(trace, thresholds)
    except Exception as err:  # a plugin's check must not stop the grading of a class
        return Verdict(False, f"the check itself failed: {type(err).__name__}: {err}")


def _output(spec: CheckSpec, verdict: Verdict, hidden: bool) -> str:
    # what was measured in a hidden run could tell where it starts
    lines = [verdict.measured] if verdict.measured and not hidden else []
    if not verdict.passed and spec.feedback:
        lines.append(spec.feedback)
    return "\n".join(lines)


@dataclass
class RunOutcome:
    """The tests of one scenario run (with each test's check index) and its recording."""

    run_index: int
    tests: list[tuple[int, TestResult]]
    recording: str | None = None
    picture: Picture | None = None
    """The run drawn from above, when it is visible and failed a check."""


def grade_run(
    plan: GradingPlan,
    run_index: int,
    controllers: Sequence[ControllerSpec],
    *,
    limits: Limits | None = None,
    recordings: Path | None = None,
    recording_format: str = "mcap",
) -> RunOutcome:
    """Run one scenario of the plan and judge every check that applies to it.

    With ``recordings`` (a folder), a visible run that failed a check leaves
    its recording there as ``<label>.mcap`` (or ``.jsonl``, the
    ``recording_format``) for ``turtletui replay``, Foxglove or ros2 bag.
    """
    if recording_format not in RECORDING_FORMATS:
        raise ValueError(f"recording format {recording_format!r}: choose one of {', '.join(RECORDING_FORMATS)}")
    run = plan.runs[run_index]
    # hidden runs are not recorded: a recording would show where they start
    name = f"{_file_name(run.label)}.{recording_format}"
    path = None if recordings is None or run.hidden else recordings / name
    if path is not None:
        recordings.mkdir(parents=True, exist_ok=True)
    trace, recorder = run_scenario(plan, run, controllers, limits=limits, record=path)

    def verdict_of(check: Check, thresholds: dict[str, Any]) -> Verdict:
        if trace.crashes and check.name != "no_crash":
            # a turtle that stopped with its node cannot hit a wall: not a pass
            crash = trace.crashes[0]
            return Verdict(False, f"not judged: the controller stopped at t={crash.t:.3f} s ({crash.kind})")
        return judge(check, trace, thresholds)

    tests = _judge_run(plan, run, verdict_of)
    failed = not all(test.passed for _, test in tests)
    if recorder is not None:
        recorder.close(keep=failed)
    picture = picture_of_trace(trace, run.label) if failed and not run.hidden else None
    return RunOutcome(run_index, tests, str(path) if recorder is not None and failed else None, picture)


def _judge_run(
    plan: GradingPlan, run: ScenarioRun, verdict_of: Callable[[Check, dict[str, Any]], Verdict]
) -> list[tuple[int, TestResult]]:
    """The tests of one run, each with the index of its check in the lesson."""
    tests = []
    for index, (spec, check) in enumerate(plan.checks):
        runs = plan.runs_for(spec)
        if run not in runs:
            continue
        verdict = verdict_of(check, spec.thresholds)
        points = spec.weight / len(runs)
        test = TestResult(
            name=f"{spec.title} [{run.label}]",
            check=spec.title,
            scenario=run.label,
            score=points if verdict.passed else 0.0,
            max_score=points,
            status=PASSED if verdict.passed else FAILED,
            output=_output(spec, verdict, run.hidden),
            hidden=run.hidden,
        )
        tests.append((index, test))
    return tests


def failed_run(plan: GradingPlan, run_index: int, reason: str) -> RunOutcome:
    """Every test of a run failed for ``reason`` (the run could not be judged)."""
    return RunOutcome(run_index, _judge_run(plan, plan.runs[run_index], lambda check, th: Verdict(False, reason)))


def assemble(
    plan: GradingPlan, outcomes: Sequence[RunOutcome], *, submission: str, student: str, seconds: float
) -> SubmissionResult:
    """One submission's result from the outcomes of all its runs, tests in the
    lesson's check order and, within a check, in scenario order."""
    ordered = sorted(
        ((index, outcome.run_index, test) for outcome in outcomes for index, test in outcome.tests),
        key=lambda item: item[:2],
    )
    tests = [test for _, _, test in ordered]
    return SubmissionResult(
        submission=submission,
        student=student,
        score=round(sum(t.score for t in tests), 6),
        max_score=round(plan.max_score, 6),
        tests=tests,
        execution_time=seconds,
        recordings=[o.recording for o in sorted(outcomes, key=lambda o: o.run_index) if o.recording],
        pictures=[o.picture for o in sorted(outcomes, key=lambda o: o.run_index) if o.picture],
    )


def grade_controllers(
    plan: GradingPlan,
    controllers: Sequence[ControllerSpec],
    *,
    submission: str = "",
    student: str = "",
    limits: Limits | None = None,
    recordings: Path | None = None,
    recording_format: str = "mcap",
) -> SubmissionResult:
    """Run every scenario of the plan with these controllers, one after the
    other, and judge every check (:func:`grade_run` says what ``recordings``
    and ``recording_format`` do)."""
    started = time.perf_counter()
    outcomes = [
        grade_run(plan, i, controllers, limits=limits, recordings=recordings, recording_format=recording_format)
        for i in range(len(plan.runs))
    ]
    return assemble(plan, outcomes, submission=submission, student=student, seconds=time.perf_counter() - started)


def _file_name(label: str) -> str:
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in label).strip("_") or "run"
