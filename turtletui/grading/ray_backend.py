"""Grade on a Ray cluster: ``turtletui grade CLASS --lesson ID --backend ray
[--address ADDR]``, with the optional extra ``pip install 'turtletui[ray]'``.

Each scenario run of each submission is one Ray task that runs it as a worker
of the local pool does (:func:`~turtletui.grading.batch.run_task`, in its
sandbox, under the same limits), while this process (the driver) does what the
pool's parent does: it hands out the runs, keeps each submission's time limit,
prints the progress lines and assembles the report, so that the report is the
local pool's.

The workers may be other machines. The lesson (with its starter and the world
files it names by a relative path), the ``--plugin`` files and each submission
are sent with the tasks through Ray's object store, packed once each, and
unpacked in a private folder of the worker that mirrors the driver's paths
(what a run reports names the files as the driver would). Workers need the same
turtletui (and installed plugins) as the driver: a worker whose lesson, checks
or version differ refuses to grade.

The driver is the only writer of the results folder: each task returns its
outcome and the recording of a failed run as bytes, and the driver signs and
saves them, so no shared filesystem is needed and the results key never
leaves the driver's machine (the workers run student code). A worker that dies
during a run (a controller that kills it, a node lost) is retried once by Ray,
then that run fails as in the local pool.
"""

from __future__ import annotations

import logging
import os
import shutil
import sys
import tempfile
from collections.abc import Callable, Iterator
from contextlib import ExitStack, contextmanager, redirect_stdout
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from turtletui.errors import TurtletuiError
from turtletui.grading import batch
from turtletui.grading.bundles import BundleError, digest, pack, unpack
from turtletui.grading.engine import GradingPlan, RunOutcome, failed_run
from turtletui.grading.store import store_key
from turtletui.grading.submissions import Submission
from turtletui.messages import one_line
from turtletui.plugins.manager import Plugins, extra_paths
from turtletui.runtime.sandbox import Limits

RAY_EXTRA = "pip install 'turtletui[ray]'"


class RayBackendError(TurtletuiError, ValueError):
    """Grading on Ray cannot start or go on (no Ray, no cluster, workers that
    differ from the driver); one line saying why."""


def import_ray() -> Any:
    """The ``ray`` module, or RayBackendError naming the extra that installs it."""
    try:
        import ray
    except ImportError:
        raise RayBackendError(f"--backend ray needs Ray, which is not installed: {RAY_EXTRA}") from None
    return ray


@dataclass(frozen=True)
class LessonBundle:
    """What a worker needs to grade a lesson as the driver does."""

    files: bytes
    """lesson/ (the lesson file, its starter), plugins/N/ (each --plugin) and
    cwd/ (world files named by a path relative to the driver's folder)."""
    lesson: str
    plugins: tuple[str, ...]
    key: str
    """The driver's :func:`~turtletui.grading.store.store_key` of the plan."""
    version: str
    distro: str | None = None
    """The grader's ``--distro`` (None: the lesson's, else the files' imports)."""


@dataclass(frozen=True)
class SubmissionBundle:
    """One submission's files, and where the driver has them."""

    files: bytes
    root: str
    """The driver's absolute path of the submission (file or folder)."""
    cwd: str
    """The driver's working folder (relative controller paths start there)."""


class RayBackend:
    """Runs a batch's scenario runs as Ray tasks (a :class:`~turtletui.grading.batch.RunBackend`).

    Use it as a context manager: entering connects to the cluster at
    ``address`` (Ray's: ``auto``, ``local``, ``ray://HOST:10001``, ``HOST:6379``;
    None: ``$RAY_ADDRESS``, else a cluster on this machine, else a new one),
    leaving disconnects (and stops a cluster it started)."""

    def __init__(
        self,
        address: str | None = None,
        *,
        plugins: Plugins = (),
        same_user: bool = False,
        jobs: int = 0,
    ) -> None:
        self.address = address
        self.plugins = [Path(p) for p in extra_paths(plugins)]
        """The plugin files and folders each worker loads again."""
        self.same_user = same_user
        """Run student code as the worker's user even when it is root."""
        self.jobs = jobs
        """Runs under way at once (0: two per CPU of the cluster)."""
        self._ray: Any = None
        self._leave = ExitStack()

    def __enter__(self) -> RayBackend:
        ray = import_ray()
        with ExitStack() as stack:
            # Ray's driver prints what the cluster reports (a worker that
            # died...) on stdout, where the report goes: on stderr instead.
            stack.enter_context(redirect_stdout(sys.stderr))
            if not ray.is_initialized():
                where = f" at {self.address}" if self.address else ""
                try:
                    ray.init(address=self.address, log_to_driver=False, logging_level=logging.ERROR)
                except Exception as err:  # noqa: BLE001 - Ray raises many kinds; each is one line here
                    raise RayBackendError(f"cannot connect to a Ray cluster{where}: {one_line(str(err))}") from None
                stack.callback(ray.shutdown)  # and stops a cluster it started
            self._leave = stack.pop_all()
        self._ray = ray
        return self

    def __exit__(self, *exc: object) -> None:
        self._leave.close()
        self._ray = None

    def run(
        self,
        plan: GradingPlan,
        tasks: list[batch.Task],
        submissions: dict[str, Submission],
        limits: Limits | None,
        start: Callable[[batch.Task], batch.Task | None],
        done: Callable[[str, RunOutcome, float], None],
        tick: Callable[[], None],
    ) -> None:
        """See :meth:`turtletui.grading.batch.RunBackend.run`."""
        ray = self._ray
        if ray is None:
            raise RuntimeError("RayBackend.run outside its with block")
        remote = ray.remote(num_cpus=1, max_retries=1)(grade_remotely)
        lesson = ray.put(self._lesson_bundle(plan))
        bundles: dict[str, Any] = {}
        window = 2 * (self.jobs or max(1, int(ray.cluster_resources().get("CPU", 1))))
        queue = list(reversed(tasks))
        running: dict[Any, batch.Task] = {}
        try:
            while queue or running:
                while queue and len(running) < window:
                    task = queue.pop()
                    started = start(task)
                    if started is None:
                        continue
                    student, controller, index, recordings, fmt, function, run_seconds, why = started
                    bundle = bundles.get(student)
                    if bundle is None:
                        bundle = bundles[student] = self._submission_bundle(ray, submissions[student])
                    if isinstance(bundle, str):  # too big to send: this student's runs fail
                        done(student, failed_run(plan, index, bundle), 0.0)
                        continue
                    running[
                        remote.remote(
                            lesson, bundle, student, controller, index, recordings is not None, fmt, function,
                            run_seconds, why, limits, self.same_user,
                        )
                    ] = started
                if not running:
                    continue
                ready, rest = ray.wait(list(running), num_returns=1, timeout=1.0)
                if ready and rest:
                    more, _ = ray.wait(rest, num_returns=len(rest), timeout=0)
                    ready += more
                tick()
                for ref in ready:
                    done(*self._answer(ref, running.pop(ref), plan))
        except BaseException:
            for ref in running:
                ray.cancel(ref, force=True)
            raise

    def _answer(self, ref: Any, task: batch.Task, plan: GradingPlan) -> tuple[str, RunOutcome, float]:
        """A task's answer, its recording saved where the local pool saves it."""
        ray = self._ray
        student, index, recordings = task[0], task[2], task[3]
        try:
            student, outcome, seconds, recording = ray.get(ref)
        except ray.exceptions.RayTaskError as err:
            cause = getattr(err, "cause", None)
            if isinstance(cause, ValueError):  # the worker cannot grade this lesson as the driver does
                raise RayBackendError(f"a Ray worker cannot grade: {one_line(str(cause))}") from None
            raise RuntimeError(f"a Ray worker failed: {err}") from err
        except ray.exceptions.RayError:  # the worker or its node died, twice
            return student, failed_run(plan, index, batch.KILLED_RUN), 0.0
        if recording is not None and outcome.recording is not None and recordings is not None:
            target = Path(recordings) / outcome.recording
            _write_bytes_atomic(target, recording)
            outcome = replace(outcome, recording=str(target))
        return student, outcome, seconds

    def _lesson_bundle(self, plan: GradingPlan) -> LessonBundle:
        from turtletui import __version__
        from turtletui.worlds.registry import is_world_path

        lesson = plan.lesson
        entries = [(lesson.path, f"lesson/{lesson.path.name}")]
        if lesson.starter is not None:
            entries.append((lesson.path.parent / lesson.starter, f"lesson/{lesson.starter}"))
        plugins = []
        for number, plugin in enumerate(self.plugins):
            plugins.append(f"plugins/{number}/{plugin.name}")
            entries.append((plugin, plugins[-1]))
        for world in {s.world or lesson.world for s in lesson.scenarios} | {lesson.world}:
            path = Path(world)
            if is_world_path(world) and not path.is_absolute() and ".." not in path.parts and path.is_file():
                entries.append((path, f"cwd/{path.as_posix()}"))
        return LessonBundle(
            files=pack(entries),
            lesson=f"lesson/{lesson.path.name}",
            plugins=tuple(plugins),
            key=store_key(plan, plugins=self.plugins),
            version=__version__,
            distro=plan.distro,
        )

    @staticmethod
    def _submission_bundle(ray: Any, submission: Submission) -> Any:
        """The submission's files in the object store, or why they cannot go there."""
        # the paths as the driver names them (not resolved): what a controller
        # named relative to the working folder is found at
        root = os.path.abspath(submission.path)
        try:
            files = pack([(submission.path, Path(root).name)])
        except (BundleError, OSError) as err:
            return f"not judged: the submission cannot be sent to the Ray cluster: {one_line(str(err))}"
        return ray.put(SubmissionBundle(files, root, os.getcwd()))


def _write_bytes_atomic(target: Path, data: bytes) -> None:
    """Write a recording as the recorder does: under a temporary name, renamed when complete."""
    target.parent.mkdir(parents=True, exist_ok=True)
    tmp = target.with_name(f".{target.name}.{os.getpid()}.tmp")
    try:
        with open(tmp, "wb") as file:
            file.write(data)
        os.replace(tmp, target)
    finally:
        tmp.unlink(missing_ok=True)


# -- on a worker ----------------------------------------------------------------------


class WorkerMismatch(TurtletuiError, ValueError):
    """This worker would not grade as the driver does; one line saying how."""


_lesson_keys: dict[str, str] = {}
"""The key of each lesson bundle's plan in this worker (by digest)."""
_RUN_FOLDER = "turtletui-ray-run-"
"""Each run's files are in a temporary folder ``turtletui-ray-run-PID-...``,
removed when it ends, or by the next run on the machine if its worker died."""


def grade_remotely(
    lesson: LessonBundle,
    submission: SubmissionBundle,
    student: str,
    controller: str,
    run_index: int,
    record: bool,
    recording_format: str,
    function: str | None,
    run_seconds: float | None,
    why: str,
    limits: Limits | None,
    same_user: bool,
) -> tuple[str, RunOutcome, float, bytes | None]:
    """A Ray task: one scenario run of one submission, as the local pool runs
    it. Returns what :func:`~turtletui.grading.batch.run_task` returns, the
    recording's file name in place of its path, and the recording's bytes."""
    run_as = _run_as(same_user)
    limits = replace(limits or Limits(), run_as=run_as)
    _set_up(lesson, limits)
    _remove_left_over()
    with tempfile.TemporaryDirectory(prefix=f"{_RUN_FOLDER}{os.getpid()}-") as folder:
        base = Path(folder).resolve()
        _unpack_submission(submission, base, readable=run_as is not None)
        recordings = base / "recordings" if record else None
        with _working_folder(base, submission.cwd):
            path = str(_mirror(base, controller)) if Path(controller).is_absolute() else controller
            student, outcome, seconds = batch.run_task(
                student, path, run_index, str(recordings) if recordings else None, recording_format, function,
                run_seconds, why,
            )
        data = None
        if outcome.recording is not None:
            data = Path(outcome.recording).read_bytes()
            outcome = replace(outcome, recording=Path(outcome.recording).name)
        return student, _as_on_the_driver(outcome, base), seconds, data


def _run_as(same_user: bool) -> tuple[int, int] | None:
    """Whom student code runs as on this worker: as locally, ``nobody`` when
    the worker is root (unless ``same_user``)."""
    from turtletui.grading.integrity import check_runtime_readable, unprivileged_ids

    if same_user:
        return None
    ids = unprivileged_ids()
    if ids is not None:
        check_runtime_readable()
    return ids


def _set_up(lesson: LessonBundle, limits: Limits) -> None:
    """This worker's plan for the lesson (prepared once), checked against the driver's."""
    from turtletui import __version__

    if lesson.version != __version__:
        raise WorkerMismatch(
            f"the Ray workers have turtletui {__version__}, the driver {lesson.version}: install the same on both"
        )
    name = digest(lesson.files)
    folder = _lesson_folder(lesson, name)
    worlds = folder / "cwd"
    with _working_folder(worlds if worlds.is_dir() else None, None):
        plan = batch.set_up_worker(
            str(folder / lesson.lesson),
            [str(folder / p) for p in lesson.plugins],
            limits,
            shared_cpus=True,
            distro=lesson.distro,
        )
    if name not in _lesson_keys:
        _lesson_keys[name] = store_key(plan, plugins=[folder / p for p in lesson.plugins])
    if _lesson_keys[name] != lesson.key:
        raise WorkerMismatch(
            "the Ray workers' checks or plugins differ from the driver's: install the same turtletui and plugins on both"
        )


def _lesson_folder(lesson: LessonBundle, name: str) -> Path:
    """The lesson bundle unpacked, once per machine and content, in a folder
    only this user can enter (student code run as ``nobody`` cannot read a
    lesson's hidden scenarios): kept between gradings, as a cache."""
    root = Path(tempfile.gettempdir()) / f"turtletui-ray-lessons-{os.getuid()}"
    try:
        root.mkdir(mode=0o700, exist_ok=True)
        mine = root.lstat()
        if mine.st_uid != os.getuid() or mine.st_mode & 0o077 or not root.is_dir():
            raise OSError(f"{root} is not this user's own")  # someone else made it: not to be trusted
    except OSError:
        root = Path(tempfile.mkdtemp(prefix="turtletui-ray-lessons-"))
    folder = root / name
    if not folder.is_dir():
        fresh = Path(tempfile.mkdtemp(dir=root))
        unpack(lesson.files, fresh)
        try:
            os.rename(fresh, folder)
        except OSError:  # another worker unpacked it meanwhile
            shutil.rmtree(fresh, ignore_errors=True)
    return folder.resolve()


def _remove_left_over() -> None:
    """Remove the run folders of this user's workers that died in a run."""
    for folder in Path(tempfile.gettempdir()).glob(f"{_RUN_FOLDER}*-*"):
        pid = folder.name[len(_RUN_FOLDER) :].split("-")[0]
        try:
            if not pid.isdigit() or folder.lstat().st_uid != os.getuid():
                continue
            os.kill(int(pid), 0)
        except ProcessLookupError:
            shutil.rmtree(folder, ignore_errors=True)
        except OSError:
            continue


def _unpack_submission(submission: SubmissionBundle, base: Path, *, readable: bool) -> None:
    """The submission under ``base`` at its driver's path, and the driver's
    working folder there (a relative controller path starts in it)."""
    from turtletui.grading.integrity import readable_not_writable

    target = _mirror(base, submission.root)
    target.parent.mkdir(parents=True, exist_ok=True)
    unpack(submission.files, target.parent)
    _mirror(base, submission.cwd).mkdir(parents=True, exist_ok=True)
    if readable:
        readable_not_writable(base)


def _mirror(base: Path, driver_path: str) -> Path:
    """Where the driver's absolute ``driver_path`` is under ``base``."""
    return base / Path(driver_path).relative_to(Path(driver_path).anchor)


@contextmanager
def _working_folder(base: Path | None, driver_cwd: str | None) -> Iterator[None]:
    """Work in ``base`` (or the driver's working folder mirrored under it)
    while the block runs: a Ray worker runs one task at a time."""
    if base is None:
        yield
        return
    before = os.getcwd()
    os.chdir(_mirror(base, driver_cwd) if driver_cwd else base)
    try:
        yield
    finally:
        os.chdir(before)


def _as_on_the_driver(outcome: RunOutcome, base: Path) -> RunOutcome:
    """The outcome with this worker's folders named as the driver's."""
    prefix = str(base)
    tests = [(index, replace(test, output=test.output.replace(prefix, ""))) for index, test in outcome.tests]
    return replace(outcome, tests=tests)
