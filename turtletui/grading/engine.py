"""Grade controllers against a lesson: run its scenarios, judge its checks.

:func:`prepare` turns a lesson into a :class:`GradingPlan` (its checks resolved
against the registered ones, its scenario runs laid out with their start
poses), raising :class:`GradingError` with one line for anything that cannot
be graded. :func:`grade_controllers` runs the plan for one submission in the
grader's own trusted simulation and returns a :class:`SubmissionResult`.
"""

from __future__ import annotations

import math
import os
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from fnmatch import fnmatchcase
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.compat.distro import resolve_distro
from turtletui.errors import TurtletuiError, UsageError
from turtletui.grading.checks import Check, Verdict
from turtletui.grading.pictures import picture_of_trace
from turtletui.grading.results import FAILED, PASSED, Picture, SubmissionResult, TestResult
from turtletui.grading.trace import Trace, TraceCollector
from turtletui.graph.introspection import NEVER_MATCH, is_dangling_warning, is_qos_warning
from turtletui.graph.logs import PRINTED_SUFFIXES, LogRecord
from turtletui.lessons.loader import display_path
from turtletui.lessons.model import CheckSpec, Lesson, Scenario
from turtletui.messages import (
    ENDED_EARLY_ADVICE,
    LONG_TIMER_ADVICE,
    LONG_TIMER_SECONDS,
    LOST_GOAL_ADVICE,
    LOST_REQUEST_ADVICE,
    NEVER_SPUN_ADVICE,
    RESPONSE_WAITS_ADVICE,
    did_you_mean,
)
from turtletui.plugins.manager import Plugins, collect_checks, plugin_manager
from turtletui.runtime.loader import ControllerSpec
from turtletui.runtime.recorder import open_recorder
from turtletui.runtime.replica import ReplicableSetup, Step
from turtletui.runtime.report import CrashReport

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


class GradingError(TurtletuiError, ValueError):
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
    twin_start: tuple[float, float, float] = (0.0, 0.0, 0.0)
    """Where its twin run starts (:attr:`Check.twin`): see :func:`twin_start`."""

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
    distro: str | None = None
    """The grader's choice (``grade --distro``); None: ``$TURTLETUI_DISTRO``, else
    the lesson's, else what the files import."""

    @property
    def max_score(self) -> float:
        return sum(spec.weight for spec, _ in self.checks if self.runs_for(spec))

    def runs_for(self, spec: CheckSpec) -> list[ScenarioRun]:
        """The scenario runs a check judges."""
        return [r for r in self.runs if not spec.scenarios or r.scenario.name in spec.scenarios]

    @cached_property
    def gates(self) -> tuple[dict[str, tuple[int, ...]], ...]:
        """Per check, each name of its ``requires`` -> the indices of the checks it means."""
        specs = [spec for spec, _ in self.checks]
        return tuple(
            {name: tuple(j for j, other in enumerate(specs) if other.is_named(name)) for name in spec.requires}
            for spec in specs
        )

    @cached_property
    def order(self) -> tuple[int, ...]:
        """Check indices with every check after those it requires (the loader
        refused loops), otherwise in the lesson's order."""
        done: list[int] = []

        def visit(index: int) -> None:
            if index in done:
                return
            for needed in self.gates[index].values():
                for other in needed:
                    visit(other)
            done.append(index)

        for index in range(len(self.checks)):
            visit(index)
        return tuple(done)

    def twin_window(self, run: ScenarioRun) -> float | None:
        """Seconds of twin run the checks judging ``run`` need (None: no twin)."""
        windows = [
            window
            for spec, check in self.checks
            if run in self.runs_for(spec) and (window := check.twin_window(spec.thresholds)) is not None
        ]
        return min(max(windows), run.scenario.duration) if windows else None


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
            blocked = obstacles(scenario.world or lesson.world)
            if scenario.start == "random":
                start = random_start(seed, obstacles=blocked)
            else:
                pose = scenario.start
                start = (pose["x"], pose["y"], pose.get("theta", 0.0))
            runs.append(ScenarioRun(scenario, seed, label, start, twin_start(seed, start, blocked)))
    return runs


TWIN_APART = 2.0
"""Metres at least between a run's start and its twin's."""
TWIN_WALL_DISTANCE = 1.0
"""Metres from a wall at which a twin run starts, facing it."""
TWIN_HEADING_SPREAD = math.pi / 6
"""Radians either side of straight at the wall that a twin's heading is drawn from."""


def twin_start(
    seed: int, start: tuple[float, float, float], obstacles: Sequence[Any] = ()
) -> tuple[float, float, float]:
    """Where the twin of a run with this seed and start begins: drawn from the
    seed, :data:`TWIN_WALL_DISTANCE` from one of the walls and facing it, at
    least :data:`TWIN_APART` metres from ``start`` (and clear of obstacles).

    There any loop that watches the pose or the scan must react at once,
    whatever its rate, gains or margins; from a start in the open, a slow loop
    that sends one of two fixed Twists (a 1 Hz timer: ten commands in the
    window) can happen to send the same ones and be called an open loop.
    An open loop sends the same commands from anywhere."""
    from turtletui.sim.constants import ARENA_SIZE
    from turtletui.sim.obstacles import nearest_distance

    rng = random.Random(seed * 1_000_003)
    near, far = TWIN_WALL_DISTANCE, ARENA_SIZE - TWIN_WALL_DISTANCE
    for _ in range(1000):
        along = rng.uniform(RANDOM_START_MARGIN, ARENA_SIZE - RANDOM_START_MARGIN)
        x, y, facing = rng.choice(
            [(near, along, math.pi), (far, along, 0.0), (along, near, -math.pi / 2), (along, far, math.pi / 2)]
        )
        theta = math.remainder(facing + rng.uniform(-TWIN_HEADING_SPREAD, TWIN_HEADING_SPREAD), math.tau)
        if math.hypot(x - start[0], y - start[1]) >= TWIN_APART and (
            not obstacles or nearest_distance(obstacles, x, y) >= OBSTACLE_START_CLEARANCE
        ):
            return (x, y, theta)
    raise GradingError(f"no start {TWIN_APART} m from ({start[0]:.2f}, {start[1]:.2f}) for a twin run (seed {seed})")


def available_checks(plugins: Plugins = ()) -> dict[str, Check]:
    """The checks plugins register, the built-in plugin's among them (a later
    plugin's wins); ``plugins`` is the plugin manager, or extra plugin paths."""
    checks = {}
    for name, entry in collect_checks(plugin_manager(plugins)).items():
        if isinstance(entry.object, Check):
            description = entry.description or entry.object.description
            checks[name] = replace(entry.object, name=name, description=description)
        else:
            checks[name] = Check(name, entry.object, entry.description)
    return checks


def prepare(
    lesson: Lesson, *, plugins: Plugins = (), checks: dict[str, Check] | None = None, distro: str | None = None
) -> GradingPlan:
    """Check that every check a lesson names exists and takes its thresholds,
    and lay out its scenario runs; ``distro`` overrides the lesson's (a known
    name: see turtletui.compat.distro.check_distro)."""
    shown = display_path(lesson.path)
    if not lesson.scenarios:
        raise GradingError(f"{shown}: lesson {lesson.id!r} has no [[scenarios]] to grade")
    if not lesson.checks:
        raise GradingError(f"{shown}: lesson {lesson.id!r} has no [[checks]] to grade")
    plugins = plugin_manager(plugins)
    resolved, specs = validate(lesson, plugins=plugins, checks=checks)
    worlds = {name: (lambda seed: None) if spec is None else spec.build for name, spec in specs.items()}
    runs = scenario_runs(lesson, lambda name: () if specs[name] is None else specs[name].obstacles)
    return GradingPlan(lesson, resolved, tuple(runs), worlds, distro)


def _distro(plan: GradingPlan) -> str | None:
    """The distro of the plan's runs; None: the files' imports choose (turtletui.api.run)."""
    if plan.distro is not None:
        return plan.distro
    return None if plan.lesson.distro is None else resolve_distro(None, plan.lesson.distro)


def validate(
    lesson: Lesson, *, plugins: Plugins = (), checks: dict[str, Check] | None = None
) -> tuple[tuple[tuple[CheckSpec, Check], ...], dict[str, WorldSpec | None]]:
    """The lesson's checks resolved against the registered ones, and the worlds
    its scenarios name; GradingError (one line, file:line) for an unknown check,
    a threshold it does not take, or an unknown world."""
    plugins = plugin_manager(plugins)
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


def _world_spec(name: str, plugins: Plugins, shown: str) -> WorldSpec | None:
    """The named world's description; None for turtlesim's own empty arena."""
    if name == "empty":
        return None
    from turtletui.worlds import WorldError, resolve_world

    try:
        return resolve_world(name, plugins)
    except WorldError as err:
        raise GradingError(f"{shown}: {err}") from None


def run_scenario(
    plan: GradingPlan,
    run: ScenarioRun,
    controllers: Sequence[ControllerSpec],
    *,
    limits: Limits | None = None,
    record: str | Path | None = None,
    start: tuple[float, float, float] | None = None,
    duration: float | None = None,
) -> tuple[Trace, Any]:
    """Run one scenario in the grader's own simulation: its trace and, with
    ``record``, its recording in memory (the caller closes it, keeping the
    file or not). ``start`` and ``duration`` replace the run's own (a twin
    run). Raises KeyboardInterrupt if Ctrl-C cut the run short."""
    from turtletui.api import run as run_controllers

    scenario = run.scenario
    start = run.start if start is None else start
    duration = scenario.duration if duration is None else duration
    world_name = scenario.world or plan.lesson.world
    collector: list[TraceCollector] = []
    recorder: list[Any] = []
    start_logs: list[LogRecord] = []

    steps = [Step("turtletui.grading.scenario_steps:place_turtle", (tuple(start), run.label))]
    if scenario.drive is not None:
        steps.append(Step("turtletui.grading.scenario_steps:ScenarioDriver", (tuple(scenario.drive),)))
    if scenario.teleport is not None:
        steps.append(Step("turtletui.grading.scenario_steps:ScenarioTeleport", (tuple(scenario.teleport), run.label)))

    def observe(sim: Simulation) -> None:
        # the sandboxed child's copy redoes the steps; what observes stays here
        if record is not None:
            header = {
                "lesson": plan.lesson.id,
                "scenario": run.label,
                "seed": run.seed,
                "duration": duration,
                "world": world_name,
                "start": list(start),
                "ros_args": list(scenario.ros_args),
            }
            recorder.append(open_recorder(sim, record, start_logs, header, buffered=True))
        driver = setup.results[1] if scenario.drive is not None else None
        collector.append(
            TraceCollector(
                sim, scenario=run.label, seed=run.seed, duration=duration, scripted=driver and driver.msg
            )
        )
        if scenario.teleport is not None:
            setup.results[-1].on_jump.append(collector[-1].teleported)

    setup = ReplicableSetup(steps, observe)
    try:
        result = run_controllers(
            controllers,
            duration=duration,
            seed=run.seed,
            ros_args=scenario.ros_args,
            setup=setup,
            limits=limits,
            keep_calls=False,
            world=plan.worlds[world_name](run.seed),
            on_log=start_logs.append if record is not None else None,
            distro=_distro(plan),
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


def _output(spec: CheckSpec, verdict: Verdict, hidden: bool, warnings: Sequence[str] = ()) -> str:
    # a check that was not judged says why (never with a number in a hidden
    # run), and gives no advice about what it judges; what was measured in a
    # hidden run could tell where it starts
    if not verdict.judged:
        return verdict.measured
    lines = [verdict.measured] if verdict.measured and not hidden else []
    if not verdict.passed:
        lines += warnings  # the likely cause, said by turtletui during the run: before the general advice
    if not verdict.passed and spec.feedback:
        lines.append(spec.feedback)
    return "\n".join(lines)


def _likely_causes(trace: Trace, *, hidden: bool = False) -> list[str]:
    """turtletui's warnings in a run, each said once, of what ROS 2 does silently:
    endpoints whose types never match another's
    (turtletui.graph.introspection.mistyped_endpoints), the reason a turtle
    neither moves nor is heard; service requests sent before the client had
    discovered the server, lost (a node that skips wait_for_service), and
    action goals the same way (wait_for_server); topics a node subscribes to that
    nothing publishes, or publishes on that nothing subscribes to, with the
    name it may have meant (dangling_endpoints: /scan for /turtle1/scan);
    endpoints whose QoS never match (mismatched_qos: a reliable subscription
    of a best-effort scan); a node no executor has, whose callbacks wait; a
    timer of 10 s or more (milliseconds meant?); a wait inside a callback
    that ran out its timeout, the response stuck behind the callback's own
    group; and
    a program that ended by itself before the run did (a main() that never
    spins). Also rclpy's own warning that a done callback raised (printed,
    not raised: the node runs on, and whatever that callback was to start
    never happens). In a hidden run each kind is told in fixed words: a
    sandboxed node can log under turtletui's name, and its own text (or the
    names and times of an honest warning) might carry where the run starts."""
    causes = []
    for r in trace.logs:
        kind = _cause_kind(r) if r.node == "turtletui" else None
        if kind is not None:
            causes.append(_HIDDEN_CAUSES[kind] if hidden else r.msg)
        elif r.node.endswith(PRINTED_SUFFIXES) and DONE_CALLBACK_FAILED in r.msg:
            error = "" if hidden else f" The error: {r.msg.split(DONE_CALLBACK_FAILED, 1)[1].strip()}"
            causes.append(
                "A done callback of your node raised an error, which rclpy only prints as a warning "
                f"('{DONE_CALLBACK_FAILED.strip()} ...'): the node runs on, but what that callback "
                f"should have done next never happens.{error}"
            )
    return list(dict.fromkeys(causes))


_HIDDEN_CAUSES = {
    "mistyped": "A topic your node uses has endpoints of another type at its other end: " + NEVER_MATCH + ".",
    "lost request": "A service request of your node was sent before its client had found the server, and was lost. "
    + LOST_REQUEST_ADVICE,
    "lost goal": "An action goal of your node was sent before its client had found the server, and was lost. "
    + LOST_GOAL_ADVICE,
    "ended": "Your program ended by itself before the run did, and its nodes stopped with it: " + ENDED_EARLY_ADVICE,
    "dangling": "A topic, service or action your node uses has nothing at its other end (a misspelt name?).",
    "never spun": "A node of your program has callbacks that never ran, because no executor has the node. "
    + NEVER_SPUN_ADVICE,
    "long timer": f"A timer of your node has a period of {LONG_TIMER_SECONDS:g} s or more: it first fires that "
    "long after it is made. " + LONG_TIMER_ADVICE,
    "response waits": "Your node waited inside a callback, with spin_until_future_complete(), for a service's "
    "response that could only be handled after that callback returned: each wait lasted its whole timeout, and "
    "the node handled nothing else meanwhile. " + RESPONSE_WAITS_ADVICE,
    "qos": "A topic your node uses has an endpoint at its other end whose QoS never matches your node's, so "
    "nothing passes between them: a reliable subscription hears no best-effort publisher (subscribe with "
    "qos_profile_sensor_data), and a best-effort publisher reaches no reliable subscription (publish with a plain "
    "depth such as 10).",
}
"""What a hidden run says of each kind of likely cause, whatever the warning's text."""


def _cause_kind(record: LogRecord) -> str | None:
    """Which of the likely causes turtletui's warning ``record`` is, or None."""
    msg = record.msg
    for kind, ending in (
        ("mistyped", NEVER_MATCH),
        ("lost request", LOST_REQUEST_ADVICE),
        ("lost goal", LOST_GOAL_ADVICE),
        ("ended", ENDED_EARLY_ADVICE),
        ("never spun", NEVER_SPUN_ADVICE),
        ("long timer", LONG_TIMER_ADVICE),
        ("response waits", RESPONSE_WAITS_ADVICE),
    ):
        if msg.endswith(ending):
            return kind
    if is_qos_warning(msg):
        return "qos"
    return "dangling" if is_dangling_warning(msg) else None


DONE_CALLBACK_FAILED = "Unhandled exception in done callback: "
"""How rclpy's warning of a Future's done callback that raised begins (rclpy.task)."""


def forbidden_call(plan: GradingPlan, trace: Trace, *, hidden: bool = False) -> str | None:
    """Why the run broke the lesson's rules (its first call of a forbidden service), or None."""
    patterns = plan.lesson.forbidden_services
    for call in trace.service_calls if patterns else ():
        if any(fnmatchcase(call.service, pattern) for pattern in patterns):
            when = "" if hidden else f" at t={call.t:.3f} s"
            return f"the controller called {call.service}{when}, a service this lesson forbids"
    return None


def as_the_student_sees_it(crash: CrashReport, controllers: Sequence[ControllerSpec]) -> CrashReport:
    """The crash with the controller's file named as the student knows it: by
    its name (and files beside it by their paths from its folder), never by
    the folder the grader ran it from (a private copy when grading as root)."""
    text = [crash.controller, crash.message, *crash.frames]
    for spec in controllers:
        # the absolute path first: the path as given may be part of it
        for path in dict.fromkeys([spec.path.resolve(), spec.path]) if spec.path is not None else ():
            folder = str(path.parent) + os.sep
            text = [line.replace(str(path), path.name).replace(folder, "") for line in text]
    return replace(crash, controller=text[0], message=text[1], frames=text[2:])


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
    from turtletui.runtime.sandbox import Limits

    if recording_format not in RECORDING_FORMATS:
        raise UsageError(f"recording format {recording_format!r}: choose one of {', '.join(RECORDING_FORMATS)}")
    # a submission's relative paths (a file it handed in beside it) are its own
    limits = replace(limits or Limits(), file_folder=True)
    run = plan.runs[run_index]
    # hidden runs are not recorded: a recording would show where they start
    name = f"{_file_name(run.label)}.{recording_format}"
    path = None if recordings is None or run.hidden else recordings / name
    trace, recorder = run_scenario(plan, run, controllers, limits=limits, record=path)
    if _killed_from_outside(trace):
        # SIGKILL that none of the run's own limits sent (the machine's OOM
        # killer, an operator, a busy machine's accident) is no verdict on the
        # student: the deterministic run is run again, once. A controller that
        # kills itself is killed again, the same way, and marked so.
        if recorder is not None:
            recorder.close(keep=False)
        trace, recorder = run_scenario(plan, run, controllers, limits=limits, record=path)
    trace.crashes = [as_the_student_sees_it(crash, controllers) for crash in trace.crashes]
    broken = forbidden_call(plan, trace, hidden=run.hidden)

    def problem(check: Check) -> Verdict | None:
        """Why this run judges no check (a broken rule, a crash: then only
        no_crash is judged), or None."""
        if broken is not None:
            return Verdict(False, f"not judged: {broken}", judged=False)
        if trace.crashes and check.name != "no_crash":
            # a turtle that stopped with its node cannot hit a wall: not a pass
            crash = trace.crashes[0]
            when = "before the end of the run" if run.hidden else f"at t={crash.t:.3f} s"
            return Verdict(False, f"not judged: the controller stopped {when} ({crash.kind})", judged=False)
        return None

    def verdict_of(check: Check, thresholds: dict[str, Any]) -> Verdict:
        if check.twin and trace.twin is None:
            # run only when a check that compares with it is judged
            window = plan.twin_window(run)
            trace.twin, _ = run_scenario(plan, run, controllers, limits=limits, start=run.twin_start, duration=window)
        return judge(check, trace, thresholds)

    tests = _judge_run(plan, run, verdict_of, problem, _likely_causes(trace, hidden=run.hidden))
    failed = not all(test.passed for _, test in tests)
    if recorder is not None:
        if failed:  # buffered: the file is written now, and only a failed run's
            recordings.mkdir(parents=True, exist_ok=True)
        recorder.close(keep=failed)
    picture = picture_of_trace(trace, run.label) if failed and not run.hidden else None
    return RunOutcome(run_index, tests, str(path) if recorder is not None and failed else None, picture)


def _killed_from_outside(trace: Trace) -> bool:
    return any(crash.kind == "killed" and "(SIGKILL)" in crash.message for crash in trace.crashes)


def _judge_run(
    plan: GradingPlan,
    run: ScenarioRun,
    verdict_of: Callable[[Check, dict[str, Any]], Verdict],
    problem: Callable[[Check], Verdict | None] = lambda check: None,
    warnings: Sequence[str] = (),
) -> list[tuple[int, TestResult]]:
    """The tests of one run, each with the index of its check in the lesson.
    ``problem`` gives the verdict of a check the run itself cannot judge (a
    crash, a broken rule). A check that passed while a check it requires
    did not pass in this run earns nothing and is shown as not judged; one
    that failed shows its own failure and advice. A check that compares with
    a twin run is not judged at all then (the twin would be a run for
    nothing)."""
    verdicts: dict[int, Verdict] = {}
    run_level: set[int] = set()
    for index in plan.order:
        spec, check = plan.checks[index]
        if run not in plan.runs_for(spec):
            continue
        verdict = problem(check)
        if verdict is not None:
            run_level.add(index)
            verdicts[index] = verdict
            continue
        # requirements that failed for the run's own problem do not gate:
        # no_crash still reports the crash
        failed = [
            name
            for name, needed in plan.gates[index].items()
            if not all(verdicts[j].passed or j in run_level for j in needed if j in verdicts)
        ]
        if failed and check.twin:
            verdict = _gated(spec, failed)
        else:
            verdict = verdict_of(check, spec.thresholds)
            if verdict.passed and failed:
                verdict = _gated(spec, failed)
        verdicts[index] = verdict
    tests = []
    for index, verdict in sorted(verdicts.items()):
        spec, _ = plan.checks[index]
        points = spec.weight / len(plan.runs_for(spec))
        test = TestResult(
            name=f"{spec.title} [{run.label}]",
            check=spec.title,
            scenario=run.label,
            score=points if verdict.passed else 0.0,
            max_score=points,
            status=PASSED if verdict.passed else FAILED,
            output=_output(spec, verdict, run.hidden, warnings),
            hidden=run.hidden,
        )
        tests.append((index, test))
    return tests


def _gated(spec: CheckSpec, failed: Sequence[str]) -> Verdict:
    """The verdict of a check whose required checks ``failed`` in this run."""
    needs = " and ".join(spec.requires)
    verb = "passes" if len(spec.requires) == 1 else "pass"
    which = "it" if len(spec.requires) == 1 else " and ".join(failed)
    return Verdict(
        False, f"not judged: {spec.title} counts only in runs where {needs} {verb}; here {which} did not", judged=False
    )


def failed_run(plan: GradingPlan, run_index: int, reason: str) -> RunOutcome:
    """Every test of a run failed for ``reason`` (the run could not be judged)."""
    failure = Verdict(False, reason, judged=False)
    return RunOutcome(run_index, _judge_run(plan, plan.runs[run_index], lambda check, th: failure, lambda check: failure))


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
