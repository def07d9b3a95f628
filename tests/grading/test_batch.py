"""Grading a class (turtletui.grading.batch, `turtletui grade`): what counts as a
submission, parallel runs that give the same report as serial ones, results
kept as each student finishes and reused by a rerun, recordings of failed
scenarios, hidden scenarios, and a batch stopped by Ctrl-C or SIGKILL."""

from __future__ import annotations

import gc
import json
import os
import re
import signal
import time
from pathlib import Path

import pytest
from support.controllers import spin_in_a_thread
from support.grading import (
    CRASH_WITH_POSE,
    HIDDEN_NAME,
    HIDDEN_START,
    HONEST,
    MAX_SCORE,
    WALL_HITTER,
    grade_cli,
    grade_subprocess,
    make_class,
    sleeper,
    stored_results,
    wait_until_gone,
)

from turtletui.grading.batch import ResultStore, grade_submissions, store_key
from turtletui.grading.engine import prepare
from turtletui.grading.reports import render_report
from turtletui.grading.submissions import find_submissions
from turtletui.lessons.loader import load_lesson
from turtletui.runtime.sandbox import Limits


def plan_of(lesson: Path):
    return prepare(load_lesson(lesson))


def comparable(report) -> dict:
    """A report's JSON without what may differ between two gradings of the same
    work: wall times, and where the recordings went."""
    data = json.loads(render_report(report, "json"))
    for sub in data["submissions"]:
        sub.pop("execution_time")
        sub.pop("recordings")
    return data


# -- what a submission is ------------------------------------------------------------


def test_a_submission_is_a_file_a_student_folder_or_a_class_of_folders(tmp_path: Path, lesson: Path):
    solo = tmp_path / "solo.py"
    solo.write_text(HONEST)
    student = tmp_path / "bea"
    student.mkdir()
    (student / "helpers.py").write_text("SPEED = 5.0\n")
    (student / "my_node.py").write_text(HONEST)
    klass = make_class(tmp_path / "class", {"carl": HONEST, "dora": WALL_HITTER})

    found = find_submissions([solo, student, klass])
    assert [(s.student, s.controller.name if s.controller else None, s.error) for s in found] == [
        ("solo", "solo.py", None),
        ("bea", "my_node.py", None),  # the one file with a main()
        ("carl", "controller.py", None),
        ("dora", "controller.py", None),
    ]

    result = grade_cli(
        solo, student, klass, "--lesson", lesson, "--results", tmp_path / "res", "--format", "json",
        "--same-user", "-j", "2",
    )
    assert result.exit_code == 0, result.stderr
    report = json.loads(result.stdout)
    scores = {s["student"]: s["score"] for s in report["submissions"]}
    assert scores == {"solo": MAX_SCORE, "bea": MAX_SCORE, "carl": MAX_SCORE, "dora": 1.0}
    assert [s["submission"] for s in report["submissions"]] == [
        str(solo), str(student), str(klass / "carl"), str(klass / "dora")
    ]


# -- parallel and deterministic -----------------------------------------------------------


def test_jobs_2_gives_exactly_the_report_of_jobs_1(tmp_path: Path, lesson: Path):
    klass = make_class(
        tmp_path / "class", {"ann": HONEST, "ben": WALL_HITTER, "cat": CRASH_WITH_POSE, "dan": HONEST}
    )
    plan = plan_of(lesson)
    subs = find_submissions([klass])
    serial = grade_submissions(plan, subs, jobs=1, store=ResultStore(tmp_path / "one", store_key(plan)))
    parallel = grade_submissions(plan, subs, jobs=2, store=ResultStore(tmp_path / "two", store_key(plan)))
    assert comparable(parallel) == comparable(serial)
    assert [s.score for s in serial.submissions] == [MAX_SCORE, 1.0, 0.0, MAX_SCORE]
    # the same failed scenario is recorded by both, under each store's folder
    assert [[Path(r).relative_to(tmp_path / "one") for r in s.recordings] for s in serial.submissions] == [
        [Path(r).relative_to(tmp_path / "two") for r in s.recordings] for s in parallel.submissions
    ]
    # and a third grading of the same work (no store) scores the same again
    again = grade_submissions(plan, subs, jobs=2)
    assert comparable(again) == comparable(serial)


def test_grading_leaves_the_garbage_collectors_frozen_heap_as_it_found_it(tmp_path: Path, lesson: Path):
    """The batch freezes the heap during its runs; a caller that froze its own
    (as the app does after start-up) keeps it frozen, one that did not gets it back."""
    plan = plan_of(lesson)
    subs = find_submissions([make_class(tmp_path / "class", {"ann": HONEST})])
    gc.unfreeze()  # whatever an earlier test froze (the app freezes its start-up heap)
    grade_submissions(plan, subs, jobs=1)
    assert gc.get_freeze_count() == 0
    callers_own: list = []  # frozen objects may still die during grading: follow one kept alive
    gc.freeze()
    try:
        assert not is_collectable(callers_own)
        grade_submissions(plan, subs, jobs=1)
        assert not is_collectable(callers_own)
    finally:
        gc.unfreeze()
    assert is_collectable(callers_own)


def is_collectable(obj: object) -> bool:
    """Whether the collector tracks obj in a generation it collects (frozen objects are in none)."""
    return any(tracked is obj for tracked in gc.get_objects())


# -- results kept, reused, regraded ------------------------------------------------------


def without_times(json_report: str) -> dict:
    data = json.loads(json_report)
    for sub in data["submissions"]:
        sub.pop("execution_time")
        sub.pop("recordings")
    return data


def progress_of(stderr: str) -> dict[str, str]:
    """Student -> their progress line's status, from ``[i/n] student: status`` lines."""
    lines = [line for line in stderr.splitlines() if line.startswith("[")]
    return dict(line.split("] ", 1)[1].split(": ", 1) for line in lines)


def counted(source: str, log: Path) -> str:
    """``source`` (a controller) noting each run it starts in ``log``."""
    return source.replace("    rclpy.init()\n", f"    open({str(log)!r}, 'a').write('run\\n')\n    rclpy.init()\n", 1)


def test_a_rerun_keeps_results_regrades_changes_and_force_regrades_all(tmp_path: Path, lesson: Path):
    runs = tmp_path / "runs.log"
    klass = make_class(tmp_path / "class", {"ann": counted(HONEST, runs), "ben": counted(WALL_HITTER, runs)})
    results = tmp_path / "results"
    args = (klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "2", "--format", "csv")

    def runs_since(before: int) -> int:
        return len(runs.read_text().splitlines()) - before

    first = grade_cli(*args)
    assert first.exit_code == 0, first.stderr
    assert all("kept" not in status for status in progress_of(first.stderr).values())
    assert sorted(stored_results(results)) == ["ann", "ben"]
    assert runs_since(0) == 4  # two students, two scenarios each

    # nothing changed: both kept, nothing run, the same report
    second = grade_cli(*args)
    assert second.exit_code == 0, second.stderr
    assert progress_of(second.stderr) == {
        "ann": "3/3 (kept from an earlier run)",
        "ben": "1/3 (kept from an earlier run)",
    }
    assert second.stdout == first.stdout
    assert runs_since(4) == 0

    # ann's file changed (even by a comment): only ann is graded again
    (klass / "ann" / "controller.py").write_text(counted(HONEST, runs) + "# fixed a typo\n")
    third = grade_cli(*args)
    status = progress_of(third.stderr)
    assert "kept" not in status["ann"] and status["ann"].startswith("3/3 (")
    assert status["ben"] == "1/3 (kept from an earlier run)"
    assert runs_since(4) == 2

    # --force grades everyone again
    forced = grade_cli(*args, "--force")
    assert forced.exit_code == 0, forced.stderr
    assert all("kept" not in s for s in progress_of(forced.stderr).values())
    assert forced.stdout == first.stdout
    assert runs_since(6) == 4


def test_a_damaged_result_file_is_graded_again_not_trusted(tmp_path: Path, lesson: Path):
    klass = make_class(tmp_path / "class", {"ann": HONEST, "ben": WALL_HITTER})
    results = tmp_path / "results"
    args = (klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "1", "--format", "json")
    first = grade_cli(*args)
    assert first.exit_code == 0, first.stderr

    stored = results / "ben.json"
    text = stored.read_text()
    # a forged full score in a file cut short (as a crash mid-write would leave it)
    stored.write_text(text.replace('"score": 1.0', '"score": 3.0')[: len(text) // 2])
    second = grade_cli(*args)
    assert second.exit_code == 0, second.stderr
    status = progress_of(second.stderr)
    assert status["ann"].endswith("(kept from an earlier run)")
    assert status["ben"].startswith("1/3 (") and status["ben"].endswith(" s of runs)")
    assert without_times(second.stdout) == without_times(first.stdout)
    assert stored_results(results)["ben"]["score"] == 1.0  # whole and right again


def test_a_result_for_other_code_or_another_lesson_is_not_reused(tmp_path: Path, lesson: Path):
    klass = make_class(tmp_path / "class", {"ann": HONEST})
    results = tmp_path / "results"
    plan = plan_of(lesson)
    subs = find_submissions([klass])
    store = ResultStore(results, store_key(plan))
    grade_submissions(plan, subs, store=store, jobs=1)
    assert store.load(subs[0]) is not None

    # the same student file under a changed lesson: its key differs
    lesson.write_text(lesson.read_text().replace("weight = 2.0", "weight = 4.0"))
    changed = plan_of(lesson)
    reused = []
    report = grade_submissions(
        changed, subs, store=ResultStore(results, store_key(changed)), jobs=1,
        on_result=lambda result, kept: reused.append(kept),
    )
    assert reused == [False]
    assert report.submissions[0].score == report.max_score == 5.0


# -- recordings and hidden scenarios -----------------------------------------------------


def test_a_failed_visible_scenario_is_recorded_and_a_hidden_one_is_not(tmp_path: Path, lesson: Path):
    klass = make_class(tmp_path / "class", {"ann": HONEST, "ben": WALL_HITTER})
    plan = plan_of(lesson)
    store = ResultStore(tmp_path / "results", store_key(plan))
    report = grade_submissions(plan, find_submissions([klass]), store=store, jobs=1)
    ann, ben = report.submissions
    assert ann.recordings == []  # nothing failed: nothing to watch
    assert not store.recordings("ann").exists(), "and no empty folder for it"
    failed = {t.scenario for t in ben.tests if not t.passed}
    assert failed == {"centre", "hidden 1"}  # it fails the hidden run too...
    assert ben.recordings == [str(store.recordings("ben") / "centre.mcap")]  # ...which is not recorded
    recorded = sorted(p.name for p in (tmp_path / "results" / "recordings").rglob("*") if p.is_file())
    assert recorded == ["centre.mcap"]
    header = mcap_header(Path(ben.recordings[0]))
    assert header["scenario"] == "centre" and header["start"] == [5.5, 5.5, 0.0]
    # the stored result lists the recording for the student to replay
    assert stored_results(tmp_path / "results")["ben"]["recordings"] == ben.recordings


def test_hidden_scenarios_are_run_but_not_described_in_any_format(tmp_path: Path, lesson: Path):
    klass = make_class(tmp_path / "class", {"ann": HONEST, "ben": WALL_HITTER, "cat": CRASH_WITH_POSE})
    plan = plan_of(lesson)
    report = grade_submissions(plan, find_submissions([klass]), jobs=1)
    for sub in report.submissions:
        hidden = [t for t in sub.tests if t.hidden]
        assert [t.name for t in hidden] == ["wall_hits [hidden 1]", "no_crash [hidden 1]"]
    # they count: ben fails the hidden run too and loses its points
    ben = report.submissions[1]
    assert [t.score for t in ben.tests if t.hidden] == [0.0, 0.5]
    cat_hidden = [t for t in report.submissions[2].tests if t.hidden]
    assert not any(t.passed for t in cat_hidden)
    # cat's exception message carries the pose it was given: the visible run's
    # feedback shows it, the hidden run's must not
    visible_crash = next(t for t in report.submissions[2].tests if t.name == "no_crash [centre]")
    assert "x=5.5000" in visible_crash.output
    secrets = [HIDDEN_NAME, *(f"{v:.4f}" for v in HIDDEN_START), *(f"{v:g}" for v in HIDDEN_START)]
    for fmt in ("json", "junit", "csv", "table"):
        text = render_report(report, fmt)
        leaked = [s for s in secrets if s in text]
        assert not leaked, (fmt, leaked)
    for sub in report.submissions:
        for test in sub.tests:
            if test.hidden:
                assert not any(s in test.output for s in secrets), test.output


# -- interrupted batches ------------------------------------------------------------------


def wait_for_first_result(results: Path, proc, seconds: float = 30.0) -> None:
    deadline = time.monotonic() + seconds
    while not list(results.glob("*.json")):
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < deadline, "no result file appeared"
        time.sleep(0.02)


def slow_class(root: Path) -> Path:
    """Six students, each about 1 s to grade: time to stop the batch midway."""
    return make_class(root, {f"s{i}": sleeper(0.4) for i in range(6)})


def test_ctrl_c_keeps_finished_results_and_a_rerun_resumes(tmp_path: Path, lesson: Path):
    klass = slow_class(tmp_path / "class")
    results = tmp_path / "results"
    args = (klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "1", "--format", "csv")
    proc = grade_subprocess(*args)
    wait_for_first_result(results, proc)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert "Traceback" not in err
    assert err.rstrip().endswith("interrupted: finished results are kept; run the same command to resume")
    kept = stored_results(results)  # every file there parses whole
    assert 1 <= len(kept) < 6, kept.keys()
    assert all(r["score"] == 3.0 for r in kept.values())
    assert not [p for p in tmp_path.rglob("*") if p.name.endswith(".tmp")]
    assert wait_until_gone([klass]) == []

    rerun = grade_subprocess(*args)
    out, err = rerun.communicate(timeout=60)
    assert rerun.returncode == 0, err
    status = progress_of(err)
    assert sorted(status) == [f"s{i}" for i in range(6)]
    assert {s for s, line in status.items() if line.endswith("(kept from an earlier run)")} == set(kept)
    assert len(out.splitlines()) == 7  # the csv: a header and one row per student
    assert sorted(stored_results(results)) == sorted(status)


def test_a_killed_grader_leaves_finished_results_and_no_student_processes(tmp_path: Path, lesson: Path):
    klass = slow_class(tmp_path / "class")
    results = tmp_path / "results"
    args = (klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "2", "--format", "csv")
    proc = grade_subprocess(*args)
    wait_for_first_result(results, proc)
    proc.send_signal(signal.SIGKILL)
    proc.communicate(timeout=120)
    assert proc.returncode == -signal.SIGKILL
    kept = stored_results(results)
    assert 1 <= len(kept) < 6 and all(r["score"] == 3.0 for r in kept.values())
    # the sandboxes of the runs it was doing notice their parent is gone and end
    assert wait_until_gone([klass], seconds=60) == []

    rerun = grade_subprocess(*args)
    out, err = rerun.communicate(timeout=60)
    assert rerun.returncode == 0, err
    status = progress_of(err)
    assert {s for s, line in status.items() if line.endswith("(kept from an earlier run)")} == set(kept)
    assert sorted(stored_results(results)) == [f"s{i}" for i in range(6)]
    assert wait_until_gone([klass]) == []


def mcap_header(path: Path) -> dict:
    """The run's header in an MCAP recording's "turtletui" metadata, read with mcap's own reader."""
    from mcap.reader import make_reader

    with path.open("rb") as stream:
        (record,) = [m for m in make_reader(stream).iter_metadata() if m.name == "turtletui"]
    return json.loads(record.metadata["header"])


def test_failed_runs_can_be_kept_as_json_lines(tmp_path: Path, lesson: Path):
    klass = make_class(tmp_path / "class", {"ben": WALL_HITTER})
    plan = plan_of(lesson)
    store = ResultStore(tmp_path / "results", store_key(plan))
    (ben,) = grade_submissions(plan, find_submissions([klass]), store=store, jobs=1, recording_format="jsonl").submissions
    assert ben.recordings == [str(store.recordings("ben") / "centre.jsonl")]
    header = json.loads(Path(ben.recordings[0]).read_text().splitlines()[0])
    assert header["scenario"] == "centre" and header["start"] == [5.5, 5.5, 0.0]


# -- time limits, progress -------------------------------------------------------------

# Blocks 12 ms of wall time per 16 ms pose (a socket's timeout is real): faster
# than real time, so no run stops it as too slow, but a 3 s run takes 2.25 s.
SLOWPOKE = HONEST.replace(
    "    def on_pose(self, pose):\n",
    "    def on_pose(self, pose):\n"
    "        waiting, _ = __import__('socket').socketpair()\n"
    "        waiting.settimeout(0.012)\n"
    "        try:\n            waiting.recv(1)\n        except OSError:\n            pass\n",
    1,
)


def test_a_submission_over_its_time_limit_is_stopped_and_says_why(tmp_path: Path, lesson: Path):
    lesson.write_text(lesson.read_text().replace("hidden = true", "hidden = false"))  # to read what it says
    klass = make_class(tmp_path / "class", {"slowpoke": SLOWPOKE})
    told: list[tuple[str, str]] = []
    report = grade_submissions(
        plan_of(lesson),
        find_submissions([klass]),
        jobs=1,
        time_limit=1.5,
        on_progress=lambda student, text: told.append((student, text)),
        progress_every=0.5,
    )
    [slowpoke] = report.submissions
    first, second = ([t for t in slowpoke.tests if t.scenario == label] for label in ("centre", HIDDEN_NAME))
    # its first run ran until the submission's 1.5 s were gone...
    [no_crash] = [t for t in first if t.check == "no_crash"]
    assert "ran out of time after 1." in no_crash.output
    assert "s of wall time: the submission's runs may take 1.5 s of wall time in all (its time limit)" in no_crash.output
    # ...and the second was not run at all
    assert all(not t.passed for t in second)
    assert all("not judged: the submission used up its time limit" in t.output for t in second)
    assert "1.5 s allowed for all its runs" in second[0].output
    assert slowpoke.score == 0.0
    # while it was being graded, the grader said so
    assert any(re.fullmatch(r"still grading: 0 of 2 runs done, [1-9]\d* s so far", text) for _, text in told), told
    assert {student for student, _ in told} == {"slowpoke"}


def test_a_lesson_sets_its_own_time_limit_and_the_grader_may_override_it(tmp_path: Path, lesson: Path):
    text = lesson.read_text().replace('world = "empty"\n', 'world = "empty"\ntime_limit = 1.5\n', 1)
    lesson.write_text(text)
    assert load_lesson(lesson).time_limit == 1.5
    klass = make_class(tmp_path / "class", {"slowpoke": SLOWPOKE})
    [limited] = grade_submissions(plan_of(lesson), find_submissions([klass]), jobs=1).submissions
    assert any("the submission's runs may take 1.5 s of wall time in all" in t.output for t in limited.tests)
    assert limited.score == 0.0
    # its 12 ms per pose is close to real time: on a busy machine the pace
    # rule could stop it, and that is not what this test is about
    [unlimited] = grade_submissions(plan_of(lesson), find_submissions([klass]), jobs=2, time_limit=60,
                                    limits=Limits(realtime_lag=None)).submissions
    assert unlimited.score == MAX_SCORE, [(t.check, t.output[:300]) for t in unlimited.tests if t.score < t.max_score]


def test_a_time_limit_that_is_not_a_positive_number_is_a_one_line_error(tmp_path: Path, lesson: Path):
    from support.grading import one_line_error

    from turtletui.lessons.loader import LessonError

    result = grade_cli(tmp_path, "--lesson", lesson, "--time-limit", "0")
    assert "--time-limit must be a positive number of seconds, got 0" in one_line_error(result)
    lesson.write_text(lesson.read_text().replace('world = "empty"\n', 'world = "empty"\ntime_limit = -5\n', 1))
    try:
        load_lesson(lesson)
    except LessonError as err:
        assert "field 'time_limit' must be a positive number of seconds, got -5" in str(err)
        assert str(err).startswith(f"{lesson}") or "tiny_walls.md" in str(err)
    else:
        raise AssertionError("a negative time_limit was accepted")


# A thread spins the node, main() drives from the latest pose: it heads for the
# north wall and hits it (so its visible run fails and leaves a recording).
THREADED = spin_in_a_thread(
    """
    cmd.linear.x = 3.0
    if pose is not None:
        cmd.angular.z = 1.0 * (1.5708 - pose.theta)
    """,
    rate=25,
)


def test_a_threaded_controller_gets_the_same_run_and_score_with_any_jobs(tmp_path: Path, lesson: Path):
    """"rclpy.spin in a thread, control loop in main": the same trajectory bit
    for bit and the same report on every grading, one job or two (five
    gradings scored 4.0, 4.0, 4.0, 0.5 and 1.25 before, crashed at random)."""
    klass = make_class(tmp_path / "class", {"threaded": THREADED, "honest": HONEST})
    reports, recordings = [], []
    for i, jobs in enumerate((1, 2, 2, 1)):
        store = ResultStore(tmp_path / f"results{i}", store_key(plan_of(lesson)))
        reports.append(
            grade_submissions(plan_of(lesson), find_submissions([klass]), store=store, jobs=jobs, recording_format="jsonl")
        )
        [recording] = (tmp_path / f"results{i}" / "recordings" / "threaded").glob("*.jsonl")
        recordings.append([line for line in recording.read_text().splitlines() if '"/turtle1/pose"' in line])
    assert all(comparable(report) == comparable(reports[0]) for report in reports)
    assert all(lines == recordings[0] for lines in recordings)
    threaded = reports[0].submissions[1]
    assert threaded.student == "threaded"
    assert {t.check for t in threaded.tests if not t.passed} == {"wall_hits"}  # it ran, and hit the wall
    assert len(recordings[0]) > 150


ESCAPER = HONEST.replace(
    "def main():\n    rclpy.init()",
    '''def escape():
    """Leave the sandbox's marks: no subreaper, a session of its own, the
    token overwritten where /proc shows it; note the pid once out."""
    import ctypes, os, signal
    ctypes.CDLL(None).prctl(36, 0, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER off
    noted, written = os.pipe()
    if os.fork() == 0:
        os.setsid()
        if os.fork() == 0:
            with open("/proc/self/stat", "rb") as f:
                fields = f.read().rpartition(b")")[2].split()
            start, end = int(fields[47]), int(fields[48])
            block = ctypes.string_at(start, end - start)
            at = block.find(b"TURTLETUI_SANDBOX=")
            if at >= 0:
                at += len(b"TURTLETUI_SANDBOX=")
                size = block.find(b"\\0", at) - at
                ctypes.memmove(start + at, b"x" * size, size)
            os.environ.pop("TURTLETUI_SANDBOX", None)
            with open("escaped", "a") as f:
                f.write(f"{os.getpid()}\\n")
            os.write(written, b"x")
            signal.pause()
        os._exit(0)
    os.read(noted, 1)


def main():
    escape()
    rclpy.init()''',
)


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rpartition(b")")[2].split()[0] not in (b"Z", b"X")
    except OSError:
        return False


@pytest.mark.parametrize("where", ["worker", "command"])
def test_a_process_that_escaped_its_sandbox_ends_with_its_run(tmp_path: Path, lesson: Path, where: str):
    """A run's process that left its session and its sandbox's marks is
    inherited by the grading process (a child subreaper): it is killed before
    that process's next run, so that it cannot stop another student's. So
    in a grading worker (``--jobs 2``) and in ``turtletui grade --jobs 1``,
    which grades in the command's own process."""
    klass = make_class(tmp_path / "class", {"ann": ESCAPER, "ben": HONEST})
    if where == "worker":
        report = grade_submissions(plan_of(lesson), find_submissions([klass]), jobs=2)
        scores = [s.score for s in report.submissions]
    else:
        args = (klass, "--lesson", lesson, "--results", tmp_path / "res", "--same-user", "-j", "1", "--format", "json")
        proc = grade_subprocess(*args)
        out, err = proc.communicate(timeout=300)
        assert proc.returncode == 0, err
        scores = [s["score"] for s in json.loads(out)["submissions"]]
    escaped = [int(pid) for pid in (klass / "ann" / "escaped").read_text().split()]
    try:
        assert len(escaped) == 2, "each of ann's runs escaped"
        assert scores == [MAX_SCORE, MAX_SCORE]
        deadline = time.monotonic() + 30  # a busy machine takes a while; the kill is at once
        while any(map(_alive, escaped)) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not any(map(_alive, escaped))
    finally:
        for pid in escaped:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
