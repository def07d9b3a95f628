"""How a class is split between machines (turtletui.grading.shards): parts
that are balanced, the same on every machine whatever the order of the folder
listing, and that keep their students when one is added late."""

from __future__ import annotations

import random

import pytest

from turtletui.grading.shards import Shard, ShardError, parse_shard, split


def names(count: int, seed: int = 0) -> list[str]:
    rng = random.Random(seed)
    return [f"{rng.choice(['ann', 'ben', 'late-cat', 'dan_2', 'Émile'])}-{i}" for i in range(count)]


@pytest.mark.parametrize("count", [1, 2, 3, 4, 7])
def test_parts_cover_the_class_once_and_differ_in_size_by_at_most_one(count: int):
    for size in (0, 1, 5, 30, 31, 200):
        students = names(size)
        parts = split(students, count)
        assert len(parts) == count
        assert sorted(s for part in parts for s in part) == sorted(students)
        sizes = [len(part) for part in parts]
        assert max(sizes) - min(sizes) <= 1, (size, sizes)
        # each part keeps the class's order
        for part in parts:
            assert part == [s for s in students if s in part]


def test_the_split_depends_on_the_names_only_not_on_their_order():
    students = names(40)
    parts = split(students, 4)
    shuffled = students[:]
    random.Random(1).shuffle(shuffled)
    assert [sorted(p) for p in split(shuffled, 4)] == [sorted(p) for p in parts]


def test_the_split_is_the_same_on_every_machine():
    """A SHA-256 order of the names: no hash seed, locale or platform in it.
    (These parts were computed once; a change here splits running classes differently.)"""
    students = ["ann", "ben", "cat", "dan", "eve", "fay", "gus"]  # in SHA-256 order: ann ben gus cat eve fay dan
    assert split(students, 3) == [["ann", "ben"], ["cat", "gus"], ["dan", "eve", "fay"]]
    assert split(students[::-1], 3) == [["ben", "ann"], ["gus", "cat"], ["fay", "eve", "dan"]]


@pytest.mark.parametrize("count", [2, 3, 5])
def test_a_student_added_late_moves_at_most_one_student_across_each_boundary(count: int):
    for seed in range(20):
        students = names(25, seed)
        before = split(students, count)
        late = f"late-{seed}"
        after = split([*students, late], count)
        moved = sum(len(set(b) - set(a)) for a, b in zip(before, after, strict=True)) - 1  # minus the new one
        assert 0 <= moved <= count - 1, (seed, moved)
        for a, b in zip(before, after, strict=True):
            assert len(set(a) - set(b)) <= 1  # each part loses at most one (its results stay useful)


def test_shard_k_of_n_is_counted_from_1():
    assert parse_shard("2/4") == Shard(2, 4)
    assert parse_shard(" 1 / 1 ") == Shard(1, 1)
    assert str(parse_shard("3/8")) == "3/8"


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("0/4", "JOB_COMPLETION_INDEX"),
        ("5/4", "only 4 parts"),
        ("1/0", "at least 1"),
        ("3", "write K/N"),
        ("a/b", "write K/N"),
        ("-1/4", "write K/N"),
    ],
)
def test_a_bad_shard_is_a_one_line_error_saying_what_to_write(text: str, said: str):
    with pytest.raises(ShardError) as err:
        parse_shard(text)
    assert said in str(err.value) and "\n" not in str(err.value)
