"""A class graded in parts (`turtletui grade --shard K/N`) and put together
again (`turtletui grade merge DIR...`): the same report as one machine
grading it all, and nothing merged that the parts did not sign, grade the
same way, or grade at all."""

from __future__ import annotations

import json
import re
import shutil
from dataclasses import dataclass
from pathlib import Path

import pytest
from support.grading import (
    CRASH_WITH_POSE,
    HONEST,
    SYNTAX_ERROR,
    WALL_HITTER,
    grade_cli,
    make_class,
    one_line_error,
    write_lesson,
)
from typer.testing import CliRunner

from turtletui.cli import app
from turtletui.grading.engine import prepare
from turtletui.grading.shards import MANIFEST, ClassManifest, Shard, write_manifest
from turtletui.grading.store import KEY_ENV, ResultStore, read_signed, signing_key
from turtletui.grading.submissions import find_submissions
from turtletui.lessons.loader import load_lesson

KEY = "the class's CI secret"
ENV = {KEY_ENV: KEY, "SOURCE_DATE_EPOCH": "1700000000"}
STUDENTS = {"ann": HONEST, "ben": WALL_HITTER, "cat": CRASH_WITH_POSE, "dan": SYNTAX_ERROR, "eve": HONEST}
PARTS = 3


@dataclass
class Graded:
    lesson: Path
    klass: Path
    whole: Path
    """One machine's results folder."""
    parts: list[Path]
    """The results folder of each part, part 1 first."""
    part_reports: list[dict]


def grade(klass: Path, lesson: Path, results: Path, *args: str, env: dict[str, str] = ENV):
    done = grade_cli(klass, "--lesson", lesson, "--results", results, "--same-user", "-j", "2", *args, env=env)
    assert done.exit_code == 0, done.stderr
    return done


@pytest.fixture
def secret(monkeypatch: pytest.MonkeyPatch) -> bytes:
    """The key the parts signed with."""
    monkeypatch.setenv(KEY_ENV, KEY)
    return signing_key()


def merge(*args: str | Path, env: dict[str, str | None] = ENV):
    return CliRunner().invoke(app, ["grade", "merge", *map(str, args)], env=env)


@pytest.fixture(scope="module")
def graded(tmp_path_factory: pytest.TempPathFactory) -> Graded:
    root = tmp_path_factory.mktemp("sharded")
    lesson = write_lesson(root)
    klass = make_class(root / "class", STUDENTS)
    whole = root / "whole"
    grade(klass, lesson, whole, "-q")
    parts, reports = [], []
    for k in range(1, PARTS + 1):
        parts.append(root / f"part{k}")
        done = grade(klass, lesson, parts[-1], "--shard", f"{k}/{PARTS}", "--format", "json")
        reports.append(json.loads(done.stdout))
    return Graded(lesson, klass, whole, parts, reports)


def comparable_json(text: str, folders: list[Path]) -> dict:
    """A JSON report without wall times, each recording named from the results
    folder (one of ``folders``) that holds it, which must have it."""
    data = json.loads(text)
    for sub in data["submissions"]:
        sub.pop("execution_time")
        kept = [Path(r) for r in sub["recordings"]]
        assert all(r.is_file() for r in kept)
        sub["recordings"] = [str(r.relative_to(next(f for f in folders if r.is_relative_to(f)))) for r in kept]
    return data


def one_machine(graded: Graded, fmt: str) -> str:
    """The report of the one machine that graded the whole class (its kept results)."""
    return grade(graded.klass, graded.lesson, graded.whole, "--format", fmt, "-q").stdout


# -- the same report ----------------------------------------------------------------------


def test_parts_merged_give_the_report_of_one_machine_grading_the_class(graded: Graded):
    merged = merge(*graded.parts, "--format", "json")
    assert merged.exit_code == 0, merged.stderr
    assert merged.stderr == "merged parts 1/3, 2/3, 3/3: 5 of 5 students\n"
    whole = comparable_json(one_machine(graded, "json"), [graded.whole])
    assert [s["student"] for s in whole["submissions"]] == list(STUDENTS)
    assert comparable_json(merged.stdout, graded.parts) == whole  # recordings: where each part kept them
    scores = {s["student"]: s["score"] for s in whole["submissions"]}
    assert scores == {"ann": 3.0, "ben": 1.0, "cat": 0.0, "dan": 0.0, "eve": 3.0}
    # the formats without paths or wall times are the same byte for byte (the folders in any order)
    for fmt in ("csv", "table", "moodle"):
        assert merge(*reversed(graded.parts), "--format", fmt).stdout == one_machine(graded, fmt), fmt
    # junit: the same but for each test's share of the wall time
    no_times = re.compile(r' time="[0-9.]+"')
    junit = merge(*graded.parts, "--format", "junit").stdout
    assert no_times.sub("", junit) == no_times.sub("", one_machine(graded, "junit"))


def test_each_part_grades_keeps_and_reports_only_its_own_students(graded: Graded, secret: bytes):
    graded_by = [[s["student"] for s in report["submissions"]] for report in graded.part_reports]
    assert sorted(s for part in graded_by for s in part) == sorted(STUDENTS)
    assert max(map(len, graded_by)) - min(map(len, graded_by)) <= 1
    for part, students in zip(graded.parts, graded_by, strict=True):
        assert sorted(p.stem for p in part.glob("*.json")) == sorted(students)
        manifest = ClassManifest.from_dict(read_signed(part / MANIFEST, secret))
        assert manifest.students == list(STUDENTS)  # the whole class, in its order
    again = grade(graded.klass, graded.lesson, graded.parts[1], "--shard", "2/3")
    assert f"part 2/3 of the class: {len(graded_by[1])} of 5 students" in again.stderr
    assert "kept from an earlier run" in again.stderr


# -- nothing merged that should not be ------------------------------------------------------


def copy_parts(graded: Graded, tmp_path: Path) -> list[Path]:
    copies = [tmp_path / part.name for part in graded.parts]
    for part, copy in zip(graded.parts, copies, strict=True):
        shutil.copytree(part, copy)
    return copies


def test_an_edited_or_forged_part_is_refused(graded: Graded, tmp_path: Path):
    parts = copy_parts(graded, tmp_path)
    [edited] = [p / "ben.json" for p in parts if (p / "ben.json").exists()]
    data = json.loads(edited.read_text())
    data["result"]["score"] = 3.0  # full marks, written by whoever could reach the folder
    edited.write_text(json.dumps(data))
    error = one_line_error(merge(*parts))
    assert f"{edited}: its signature does not match the results key" in error
    assert KEY_ENV in error

    parts = copy_parts(graded, tmp_path / "again")
    manifest = parts[0] / MANIFEST
    data = json.loads(manifest.read_text())
    data["members"] = data["members"][1:]  # a student left out of the class
    manifest.write_text(json.dumps(data))
    assert f"{manifest}: its signature" in one_line_error(merge(*parts))

    # a part signed with another key is refused, and so is every part for a merge
    # that has not the parts' key
    assert "signature does not match" in one_line_error(merge(*graded.parts, env={KEY_ENV: "another secret"}))
    assert f"no results key here: set {KEY_ENV}" in one_line_error(merge(*graded.parts, env={KEY_ENV: None}))


def test_students_of_a_missing_or_unfinished_part_are_named_and_fail_the_merge(graded: Graded, tmp_path: Path):
    second = [s["student"] for s in graded.part_reports[1]["submissions"]]
    error = one_line_error(merge(graded.parts[0], graded.parts[2]))
    assert f"{len(second)} students of 5 have no result: {', '.join(second)} (part 2/3: no results folder given)" in error
    assert "--allow-missing" in error

    allowed = merge(graded.parts[0], graded.parts[2], "--allow-missing", "--format", "csv")
    assert allowed.exit_code == 0
    rows = [line.split(",")[0] for line in allowed.stdout.splitlines()[1:]]
    assert rows == [s for s in STUDENTS if s not in second]
    assert f"warning: {len(second)} students of 5 have no result: {', '.join(second)}" in allowed.stderr

    # a part that stopped before its last student: that student is named
    parts = copy_parts(graded, tmp_path)
    last = graded.part_reports[2]["submissions"][-1]["student"]
    (parts[2] / f"{last}.json").unlink()
    error = one_line_error(merge(*parts))
    assert f"1 student of 5 has no result: {last} (part 3/3 in {parts[2]}: not graded (did it stop?))" in error


def test_parts_given_twice_split_otherwise_or_graded_differently_are_refused(
    graded: Graded, tmp_path: Path, secret: bytes
):
    twice = tmp_path / "part2-again"
    shutil.copytree(graded.parts[1], twice)
    second = ", ".join(s["student"] for s in graded.part_reports[1]["submissions"])
    error = one_line_error(merge(*graded.parts, twice))
    assert f"part 2/3 is in both {graded.parts[1]} and {twice}: {second} would be counted twice" in error
    # the same folder named twice is one folder
    assert merge(*graded.parts, graded.parts[1], "-q").exit_code == 0

    error = one_line_error(merge(graded.whole, *graded.parts))
    assert "parts of different splits (1/3 and 1/1)" in error

    # part 3 graded against another version of the lesson (a weight changed)
    lesson = tmp_path / "lesson" / graded.lesson.name
    lesson.parent.mkdir()
    lesson.write_text(graded.lesson.read_text().replace("weight = 1.0", "weight = 1.5"))
    other = tmp_path / "part3-new-lesson"
    grade(graded.klass, lesson, other, "--shard", "3/3", "-q")
    error = one_line_error(merge(*graded.parts[:2], other))
    assert f"{other} and {graded.parts[0]} were graded differently: lesson file" in error

    # part 3 graded on a class that has one student more
    klass = tmp_path / "class"
    shutil.copytree(graded.klass, klass)
    make_class(klass, {"fay": HONEST})
    bigger = _manifest_only(graded, secret, klass, tmp_path / "bigger", Shard(3, 3))
    error = one_line_error(merge(*graded.parts[:2], bigger))
    assert "graded different classes: only the first has fay" in error
    # ...or on the same class in another folder (the reports would name it otherwise)
    moved = tmp_path / "moved"
    shutil.copytree(graded.klass, moved)
    elsewhere = _manifest_only(graded, secret, moved, tmp_path / "elsewhere", Shard(3, 3))
    error = one_line_error(merge(*graded.parts[:2], elsewhere))
    assert f"ann's submission is {moved / 'ann'} in the first and {graded.klass / 'ann'} in the second" in error


def _manifest_only(graded: Graded, secret: bytes, klass: Path, folder: Path, shard: Shard) -> Path:
    """A results folder whose manifest says it grades ``shard`` of ``klass``
    (under the key of the real parts), with no results yet."""
    manifest = ClassManifest.from_dict(read_signed(graded.parts[0] / MANIFEST, secret))
    plan = prepare(load_lesson(graded.lesson))
    store = ResultStore(folder, manifest.key, secret=secret)
    write_manifest(store, plan, find_submissions([klass]), shard, manifest.conditions)
    return folder


def test_a_result_kept_for_other_files_counts_as_missing(graded: Graded, tmp_path: Path, secret: bytes):
    """A part's folder from an earlier grading, whose student changed their
    file since, and whose grading stopped before that student: the old result
    is not merged."""
    parts = copy_parts(graded, tmp_path)
    klass = tmp_path / "class"
    shutil.copytree(graded.klass, klass)
    (klass / "ann" / "controller.py").write_text(HONEST.replace("5.0", "4.0"))
    for number, part in enumerate(parts, 1):  # each part started grading the new class...
        _manifest_only(graded, secret, klass, part, Shard(number, PARTS))
    [index] = [i for i, p in enumerate(parts) if (p / "ann.json").exists()]  # ...and ann's stopped early
    error = one_line_error(merge(*parts))
    assert f"ann (part {index + 1}/3 in {parts[index]}: only a result of other files is there)" in error


# -- bad options ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (["--shard", "0/3"], "counted from 1"),
        (["--shard", "4/3"], "only 3 parts"),
        (["--shard", "2/3", "--format", "gradescope"], "--shard splits a class"),
        (["--address", "auto"], "--address is the Ray cluster's"),
        (["--backend", "spark"], "--backend 'spark': choose local or ray"),
    ],
)
def test_bad_shard_and_backend_options_are_one_line_errors(tmp_path: Path, args: list[str], said: str):
    lesson = write_lesson(tmp_path)
    klass = make_class(tmp_path / "class", {"ann": HONEST})
    done = grade_cli(klass, "--lesson", lesson, "--results", tmp_path / "res", *args)
    assert said in one_line_error(done)


def test_merge_names_what_it_cannot_use(tmp_path: Path):
    assert f"{tmp_path / 'nowhere'}: no such results folder" in one_line_error(merge(tmp_path / "nowhere"))
    assert f"no {MANIFEST}: not a results folder" in one_line_error(merge(tmp_path))
    said = one_line_error(CliRunner().invoke(app, ["grade", "merge", "--lesson", "x", "class"], env=ENV))
    assert "to grade a folder named merge, write ./merge" in said
