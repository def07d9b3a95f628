"""Grade many submissions: in parallel, each result saved the moment it is
known, so that an interrupted batch resumes where it stopped.

Every scenario run of every submission is one task; ``jobs`` worker processes
take tasks (so one submission's scenarios spread over the cores too). A
submission's result is assembled when its last run finishes and written to the
:class:`ResultStore` atomically. A rerun reuses a stored result when the
student's files, the lesson and turtletui are the same (``force`` regrades).
"""

from __future__ import annotations

import gc
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Protocol

from turtletui.grading.engine import (
    GradingPlan,
    RunOutcome,
    assemble,
    failed_run,
    grade_run,
    prepare,
)
from turtletui.grading.results import GradeReport, SubmissionResult
from turtletui.grading.store import ResultStore, store_key  # noqa: F401 - where callers found them
from turtletui.grading.submissions import Submission
from turtletui.lessons.loader import load_lesson
from turtletui.plugins.manager import Plugins, extra_paths
from turtletui.runtime import forkserver, wire
from turtletui.runtime.loader import ControllerError, ControllerSpec, check_source
from turtletui.runtime.sandbox import Limits

DEFAULT_TIME_LIMIT = 300.0
"""Wall-clock seconds all the runs of one submission may take together, unless
the lesson (``time_limit``) or the grader (``--time-limit``) says otherwise.
An honest controller needs a few seconds; a run of each scenario may besides
take at most its own simulated duration and :data:`RUN_GRACE` more."""
RUN_GRACE = 3.0
"""Wall seconds a run may take beyond its simulated duration: the pace rule's
default lag (``Limits.realtime_lag``), so that a controller the pace rule lets
fall that far behind real time (on a busy grading machine, with start-up) is
not stopped first by its run's limit."""
PROGRESS_EVERY = 10.0
"""Seconds between progress lines about a submission still being graded."""
KILLED_RUN = "not judged: the process grading this run was killed (by the controller?)"
"""What the tests of a run say when the process running it died twice."""

Task = tuple[Any, ...]
"""One scenario run of one submission: the first arguments of :func:`run_task`."""


class RunBackend(Protocol):
    """Runs a batch's scenario runs somewhere else than in this machine's pool
    of workers (:mod:`turtletui.grading.ray_backend`)."""

    def run(
        self,
        plan: GradingPlan,
        tasks: list[Task],
        submissions: dict[str, Submission],
        limits: Limits | None,
        start: Callable[[Task], Task | None],
        done: Callable[[str, RunOutcome, float], None],
        tick: Callable[[], None],
    ) -> None:
        """Run every task of the ``submissions`` (student -> submission) through
        :func:`run_task`: ``start(task)`` gives its arguments (None: it is not
        run), ``done(*answer)`` takes each answer, ``tick()`` is called about
        once a second."""


@dataclass
class _Pending:
    submission: Submission
    outcomes: list[RunOutcome] = field(default_factory=list)
    seconds: float = 0.0
    """Wall seconds its finished runs took (what its time limit counts)."""
    started: float | None = None
    """When its first run started (time.monotonic), for progress lines."""
    reported: float = 0.0
    """When a progress line last spoke of it."""


# -- worker side ------------------------------------------------------------------

@dataclass(frozen=True)
class WorkerSetup:
    """What :func:`set_up_worker` made ready for the runs of this worker process."""

    plan: GradingPlan
    limits: Limits


_worker: WorkerSetup | None = None
"""This process's setup. Held here rather than passed: tasks reach a worker (of
the pool, or of a Ray cluster) as a few strings and numbers, and the plan is
prepared once per worker, not pickled with every run."""

_in_task = False
"""Whether a run is under way (read by the SIGTERM handler, which gets no arguments)."""


class _GraderGone(BaseException):
    """The grader stopped this worker (or died): end the run, closing its sandbox."""


_leaving = False
"""Whether this worker is closing its run's sandbox because it was told to stop."""


def _on_sigterm(signum: int, frame: Any) -> None:
    global _leaving
    if _leaving:
        # A second SIGTERM (a broken pool terminates its workers, and so does
        # the grader) must not cut short the closing of the sandbox: that could
        # leave the child stopped, half-killed, forever.
        return
    if _in_task:
        _leaving = True
        raise _GraderGone  # the run's sandbox is closed on the way out (runner's finally)
    os._exit(1)


def default_jobs() -> int:
    """Runs side by side by default: one per CPU."""
    return wire.available_cpus()


def _init_worker(
    lesson_path: str,
    plugins: Sequence[str],
    limits: Limits | None,
    distro: str | None,
    parent: int | None = None,
    next_cpu: Any = None,
) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C
    # A grader killed outright (SIGKILL) must not leave its workers waiting for
    # tasks forever, holding its output pipes: they get SIGTERM when it dies (Linux).
    signal.signal(signal.SIGTERM, _on_sigterm)
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM, 0, 0, 0)  # PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass
    if parent is not None and os.getppid() != parent:
        os._exit(1)  # it died before the line above
    if next_cpu is not None:
        _pin_to_one_cpu(next_cpu)
    set_up_worker(lesson_path, plugins, limits, shared_cpus=next_cpu is not None, distro=distro)


@contextmanager
def _as_worker(plan: GradingPlan, limits: Limits | None) -> Iterator[None]:
    """This process as a worker of ``plan`` for the block: for its own runs
    (one job), or for the workers it forks, which start with it."""
    global _worker
    _worker = WorkerSetup(plan, limits or Limits())
    try:
        yield
    finally:
        _worker = None


def set_up_worker(
    lesson_path: str,
    plugins: Sequence[str | Path],
    limits: Limits | None,
    *,
    shared_cpus: bool = False,
    distro: str | None = None,
) -> GradingPlan:
    """Make this process ready to :func:`run_task` the runs of a lesson (a
    worker of the local pool, or of a cluster): its plan (kept while the
    lesson file and ``distro``, the grader's choice, are the same), the
    sandbox's limits, fork servers. ``shared_cpus``: more runs than pairs of
    CPUs run side by side."""
    global _worker
    limits = limits or Limits()
    if shared_cpus:
        # A reader polling for its child's answer would take the CPU that child needs.
        limits = replace(limits, spin_seconds=0.0)
    forkserver.enable()
    if _worker is not None and str(_worker.plan.lesson.path) == lesson_path and _worker.plan.distro == distro:
        plan = _worker.plan
    else:
        plan = prepare(load_lesson(lesson_path), plugins=plugins, distro=distro)
    _worker = WorkerSetup(plan, limits)
    return plan


def _pin_to_one_cpu(counter: Any) -> None:
    """Keep this worker, and the sandboxed children it starts (they inherit it),
    on one CPU of its own, the next one ``counter`` hands out. A lockstep
    exchange then passes from simulator to controller and back on the same CPU
    (a few microseconds) instead of waking the other side on another CPU (tens
    of microseconds on a virtual machine, 3,750 times per simulated minute)."""
    try:
        cpus = sorted(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not on Linux: let the system place them
        return
    with counter.get_lock():
        index = counter.value
        counter.value += 1
    try:
        os.sched_setaffinity(0, {cpus[index % len(cpus)]})
    except OSError:
        pass


def run_task(
    student: str,
    controller: str,
    run_index: int,
    recordings: str | None,
    recording_format: str,
    function: str | None = None,
    run_seconds: float | None = None,
    why: str = "",
) -> tuple[str, RunOutcome, float]:
    """Run ``run_index`` of the plan :func:`set_up_worker` prepared with one
    submission's controller, in its sandbox (at most ``run_seconds`` of wall
    time, for the reason ``why``); its failed visible run recorded in the
    folder ``recordings``. Returns the student, the outcome and the wall
    seconds it took. Every backend runs every run through this."""
    global _in_task
    assert _worker is not None
    started = time.perf_counter()
    limits = replace(_worker.limits, run_seconds=run_seconds, run_seconds_reason=why)
    _in_task = True
    try:
        outcome = grade_run(
            _worker.plan,
            run_index,
            [ControllerSpec(name=Path(controller).stem, path=Path(controller), function=function)],
            limits=limits,
            recordings=Path(recordings) if recordings else None,
            recording_format=recording_format,
        )
    except _GraderGone:
        os._exit(1)
    finally:
        _in_task = False
        servers = forkserver.servers()
        if servers is not None:
            servers.end_of_run()
    return student, outcome, time.perf_counter() - started


# -- parent side ------------------------------------------------------------------


def grade_submissions(
    plan: GradingPlan,
    submissions: Sequence[Submission],
    *,
    store: ResultStore | None = None,
    jobs: int = 1,
    force: bool = False,
    limits: Limits | None = None,
    plugins: Plugins = (),
    on_result: Callable[[SubmissionResult, bool], None] | None = None,
    workdir: Callable[[Submission], Submission] | None = None,
    recording_format: str = "mcap",
    on_run: Callable[[str, RunOutcome], None] | None = None,
    time_limit: float | None = None,
    on_progress: Callable[[str, str], None] | None = None,
    progress_every: float = PROGRESS_EVERY,
    backend: RunBackend | None = None,
    sole_parent: bool = False,
) -> GradeReport:
    """Grade every submission (reusing stored results unless ``force``).

    ``plugins`` is the plugin manager the plan was prepared with (or extra
    plugin paths): workers started afresh load the same plugin files once.
    Failed visible runs are recorded in ``recording_format`` ("mcap" or
    "jsonl") in the store's recordings folder.
    ``on_result(result, reused)`` is called as each submission's result is known,
    ``on_run(student, outcome)`` as each scenario run finishes (for progress).
    ``workdir`` may map a submission to a private copy to run (see integrity).
    ``time_limit``: wall seconds all the runs of one submission may take
    (default: the lesson's ``time_limit``, else :data:`DEFAULT_TIME_LIMIT`);
    each run besides may take its simulated duration and :data:`RUN_GRACE`
    more. ``on_progress(student, text)`` is told every ``progress_every``
    seconds about a submission still being graded. ``backend`` runs the runs
    instead of ``jobs`` local workers. KeyboardInterrupt propagates after the
    workers are stopped; every result finished before it is already saved.
    ``sole_parent``: this process starts no children of its own meanwhile (the
    command line), so runs graded here (``jobs`` 1) are followed by killing
    every child of it but the fork servers, as a worker does after each run:
    nothing a run left behind outlives it. A library caller's own children
    (the app's live run) are left alone, and with them such leftovers.
    """
    results: dict[str, SubmissionResult] = {}
    pending: dict[str, _Pending] = {}
    for sub in submissions:
        reused = None if force or store is None else store.load(sub)
        if reused is not None:
            results[sub.student] = reused
            if on_result:
                on_result(reused, True)
            continue
        error = sub.error
        if error is None:
            assert sub.controller is not None
            try:
                check_source(sub.controller)
            except ControllerError as err:
                error = str(err)
        if error is not None:
            result = SubmissionResult(
                submission=str(sub.path), student=sub.student, max_score=round(plan.max_score, 6), error=error
            )
            _finish(store, sub, result, results, on_result)
            continue
        pending[sub.student] = _Pending(workdir(sub) if workdir else sub)

    def done(student: str, outcome: RunOutcome, seconds: float) -> None:
        item = pending[student]
        item.outcomes.append(outcome)
        if on_run:
            on_run(student, outcome)
        item.seconds += seconds
        if len(item.outcomes) == len(plan.runs):
            original = next(s for s in submissions if s.student == student)
            result = assemble(
                plan, item.outcomes, submission=str(original.path), student=student, seconds=item.seconds
            )
            _finish(store, original, result, results, on_result)

    limit = time_limit if time_limit is not None else plan.lesson.time_limit or DEFAULT_TIME_LIMIT
    clock = _SubmissionClock(plan, pending, limit, on_progress, progress_every)

    def start(task: tuple[Any, ...]) -> tuple[Any, ...] | None:
        """``task`` with the wall time its run may take, or None (then judged
        at once) when its submission has used up its time."""
        student, index = task[0], task[2]
        allowed = clock.allowed(student, index)
        if allowed is None:
            done(student, failed_run(plan, index, clock.spent(student)), 0.0)
            return None
        return (*task, *allowed)

    tasks = [
        (
            student,
            str(item.submission.controller),
            index,
            str(store.recordings(student)) if store is not None else None,
            recording_format,
            item.submission.function,
        )
        for student, item in pending.items()
        for index in range(len(plan.runs))
    ]
    # What is built so far (modules, the plan) lives through the runs: frozen,
    # the garbage collector does not walk it during them, and forked workers
    # do not copy the pages it would touch.
    with _as_worker(plan, limits):  # before the freeze: frozen too, and forked workers start with it
        frozen_before = gc.get_freeze_count()
        gc.freeze()
        try:
            if backend is not None:
                submitted = {student: item.submission for student, item in pending.items()}
                backend.run(plan, tasks, submitted, limits, start, done, clock.tick)
            elif jobs <= 1 or len(tasks) <= 1:
                with forkserver.serving(sole_parent=sole_parent), clock.ticking():
                    for task in tasks:
                        started = start(task)
                        if started is not None:
                            done(*run_task(*started))
            else:
                _run_parallel(plan, tasks, jobs, limits, plugins, start, done, clock.tick)
        finally:
            if not frozen_before:  # a caller's own frozen heap (the app freezes its start-up) stays so
                gc.unfreeze()
            if store is not None:
                store.restore()
    order = {s.student: i for i, s in enumerate(submissions)}
    ordered = sorted(results.values(), key=lambda r: order[r.student])
    return GradeReport(lesson=plan.lesson.id, submissions=ordered, max_score=round(plan.max_score, 6))


class _SubmissionClock:
    """Each submission's time limit (how long each of its runs may take) and
    progress lines about submissions that are slow to grade."""

    def __init__(
        self,
        plan: GradingPlan,
        pending: dict[str, _Pending],
        limit: float,
        on_progress: Callable[[str, str], None] | None,
        every: float,
    ) -> None:
        self.plan = plan
        self.pending = pending
        self.limit = limit
        self.on_progress = on_progress
        self.every = every

    def allowed(self, student: str, index: int) -> tuple[float, str] | None:
        """Wall seconds run ``index`` of ``student`` may take and why that
        much; None if the submission has none left."""
        item = self.pending[student]
        if item.started is None:
            item.started = item.reported = time.monotonic()
        left = self.limit - item.seconds
        if left <= 0:
            return None
        duration = self.plan.runs[index].scenario.duration
        if left < duration + RUN_GRACE:
            return left, f"the submission's runs may take {self.limit:g} s of wall time in all (its time limit)"
        return duration + RUN_GRACE, (
            f"a run may take its simulated duration ({duration:g} s) and {RUN_GRACE:g} s more in wall time"
        )

    def spent(self, student: str) -> str:
        """Why a run of ``student`` was not run."""
        used = self.pending[student].seconds
        return (
            f"not judged: the submission used up its time limit ({used:.0f} s of wall time, "
            f"{self.limit:g} s allowed for all its runs; slow code is stopped)"
        )

    def tick(self) -> None:
        """Tell of each submission under way for :attr:`every` seconds since
        it started or was last told of."""
        if self.on_progress is None:
            return
        now = time.monotonic()
        total = len(self.plan.runs)
        for student, item in self.pending.items():
            if item.started is None or len(item.outcomes) == total or now - item.reported < self.every:
                continue
            item.reported = now
            self.on_progress(
                student,
                f"still grading: {len(item.outcomes)} of {total} runs done, {now - item.started:.0f} s so far",
            )

    @contextmanager
    def ticking(self) -> Iterator[None]:
        """:meth:`tick` every second from a thread of its own while the block
        runs the submissions here (no worker processes are forked meanwhile)."""
        if self.on_progress is None:
            yield
            return
        stop = threading.Event()

        def loop() -> None:
            while not stop.wait(1.0):
                self.tick()

        ticker = threading.Thread(target=loop, name="turtletui-progress", daemon=True)
        ticker.start()
        try:
            yield
        finally:
            stop.set()
            ticker.join()


def _finish(
    store: ResultStore | None,
    sub: Submission,
    result: SubmissionResult,
    results: dict[str, SubmissionResult],
    on_result: Callable[[SubmissionResult, bool], None] | None,
) -> None:
    result.graded = sub.graded
    if store is not None:
        store.save(sub, result)
    results[sub.student] = result
    if on_result:
        on_result(result, False)


def _run_parallel(
    plan: GradingPlan,
    tasks: list[tuple[Any, ...]],
    jobs: int,
    limits: Limits | None,
    plugins: Plugins,
    start: Callable[[tuple[Any, ...]], tuple[Any, ...] | None],
    done: Callable[[str, RunOutcome, float], None],
    tick: Callable[[], None],
) -> None:
    # a few tasks queued per worker: results come back in order of the
    # submissions, so early students are saved early
    queue = list(reversed(tasks))
    while queue:
        # A controller may kill the worker running it (its parent): that breaks
        # the pool. The runs under way then are run again one at a time, alone,
        # so that only the one that kills its worker again is failed for it.
        for task in _run_pool(plan, queue, jobs, limits, plugins, start, done, tick):
            if _run_pool(plan, [task], 1, limits, plugins, start, done, tick):
                lost = failed_run(plan, task[2], KILLED_RUN)
                done(task[0], lost, 0.0)


def _run_pool(
    plan: GradingPlan,
    queue: list[tuple[Any, ...]],
    jobs: int,
    limits: Limits | None,
    plugins: Plugins,
    start: Callable[[tuple[Any, ...]], tuple[Any, ...] | None],
    done: Callable[[str, RunOutcome, float], None],
    tick: Callable[[], None],
) -> list[tuple[Any, ...]]:
    """Run the tasks of ``queue`` (taken from its end) in a pool of workers:
    ``start(task)`` gives a task's arguments (or None: it is not run), ``tick()``
    is called about once a second. Returns the tasks that were under way when
    a worker died (the pool is broken then, and the tasks not started yet stay
    in ``queue``)."""
    # fork: workers start at once with the plan already prepared (_as_worker)
    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    # A run whose simulator and controller each have a CPU to themselves polls
    # for answers; when runs outnumber pairs of CPUs, each worker keeps to one CPU.
    next_cpu = context.Value("i", 0) if 2 * jobs > default_jobs() else None
    executor = ProcessPoolExecutor(
        max_workers=min(jobs, len(queue)),
        mp_context=context,
        initializer=_init_worker,
        # a worker started afresh (no fork) builds its own plugin manager once, from these
        initargs=(str(plan.lesson.path), extra_paths(plugins), limits, plan.distro, os.getpid(), next_cpu),
    )
    lost: list[tuple[Any, ...]] = []
    try:
        running: dict[Future, tuple[Any, ...]] = {}
        broken = False
        while (queue or running) and not broken:
            while queue and len(running) < 2 * jobs:
                task = queue.pop()
                started = start(task)
                if started is None:
                    continue
                try:
                    running[executor.submit(run_task, *started)] = task
                except BrokenProcessPool:
                    queue.append(task)
                    broken = True
                    break
            if not running:
                continue
            finished, _ = wait(running, timeout=1.0, return_when=FIRST_COMPLETED)
            tick()
            for future in finished:
                task = running.pop(future)
                try:
                    answer = future.result()
                except BrokenProcessPool:
                    lost.append(task)
                    broken = True
                    continue
                done(*answer)
            if broken:  # a broken pool fails every task under way at once
                for future in wait(running).done:
                    task = running.pop(future)
                    if isinstance(future.exception(), BrokenProcessPool):
                        lost.append(task)
                    else:
                        done(*future.result())
    except KeyboardInterrupt:
        # The workers got the Ctrl-C too: their runs stop like an interrupted
        # `turtletui run`, closing their sandboxes. A second Ctrl-C kills them.
        try:
            executor.shutdown(wait=True, cancel_futures=True)
        except KeyboardInterrupt:
            _stop_workers(executor)
        raise
    except BaseException:
        _stop_workers(executor)
        raise
    if lost:
        _stop_workers(executor)
    else:
        executor.shutdown(wait=True)
    return lost


def _stop_workers(executor: ProcessPoolExecutor) -> None:
    processes = getattr(executor, "_processes", None) or {}
    for process in list(processes.values()):
        process.terminate()
    executor.shutdown(wait=True, cancel_futures=True)
