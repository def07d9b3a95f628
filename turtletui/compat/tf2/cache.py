"""A frame's transforms over time (tf2's TimeCache) or for all time (StaticCache).

``get`` answers for a time in ns (0: the latest) with the stored transform,
or an interpolation of the two around it, or an error text as cache.cpp
words it. Stamps print as tf2's displayTimePoint does (seconds, 6 decimals)."""

from __future__ import annotations

from bisect import bisect_left, bisect_right

from turtletui.compat.tf2.transform import Stored, lerp, slerp

DEFAULT_CACHE_TIME_NS = 10_000_000_000
"""tf2's BufferCore::DEFAULT_CACHE_TIME: 10 s."""


def show_time(t_ns: int) -> str:
    return f"{t_ns / 1e9:.6f}"


class TimeCache:
    """The transforms of one frame, oldest first, kept ``cache_time_ns`` behind the newest."""

    static = False

    def __init__(self, cache_time_ns: int = DEFAULT_CACHE_TIME_NS) -> None:
        self.cache_time_ns = cache_time_ns
        self.items: list[Stored] = []

    def insert(self, item: Stored) -> bool:
        """Store ``item``; False (tf2's TF_OLD_DATA) when it is older than the cache keeps."""
        items = self.items
        if items:
            latest = items[-1].stamp_ns
            cut = 0
            while cut < len(items) and items[cut].stamp_ns + self.cache_time_ns < latest:
                cut += 1
            del items[:cut]
            if item.stamp_ns < latest - self.cache_time_ns:
                return False
        stamps = [i.stamp_ns for i in items]
        at = bisect_right(stamps, item.stamp_ns)
        if item not in items[bisect_left(stamps, item.stamp_ns):at]:  # the same data again: once
            items.insert(at, item)
        return True

    def get(self, t_ns: int) -> Stored | str:
        """The transform at ``t_ns`` (0: the newest), or why there is none."""
        items = self.items
        if not items:
            return f"Lookup would require extrapolation at time {show_time(t_ns)}, but only time 0.000000 is in the buffer"
        if t_ns == 0:
            return items[-1]
        if len(items) == 1:
            if items[0].stamp_ns == t_ns:
                return items[0]
            return (
                f"Lookup would require extrapolation at time {show_time(t_ns)}, "
                f"but only time {show_time(items[0].stamp_ns)} is in the buffer"
            )
        newest, oldest = items[-1], items[0]
        if t_ns == newest.stamp_ns:
            return newest
        if t_ns == oldest.stamp_ns:
            return oldest
        if t_ns > newest.stamp_ns:
            return (
                f"Lookup would require extrapolation into the future.  Requested time {show_time(t_ns)} "
                f"but the latest data is at time {show_time(newest.stamp_ns)}"
            )
        if t_ns < oldest.stamp_ns:
            return (
                f"Lookup would require extrapolation into the past.  Requested time {show_time(t_ns)} "
                f"but the earliest data is at time {show_time(oldest.stamp_ns)}"
            )
        i = bisect_right([i.stamp_ns for i in items], t_ns) - 1
        older, newer = items[i], items[i + 1]
        if older.parent != newer.parent:
            return older
        ratio = (t_ns - older.stamp_ns) / (newer.stamp_ns - older.stamp_ns)
        return Stored(
            older.stamp_ns, older.parent,
            lerp(older.translation, newer.translation, ratio), slerp(older.rotation, newer.rotation, ratio),
        )

    def latest(self) -> tuple[int, str | None]:
        """(the newest stamp, its parent); (0, None) when empty."""
        return (self.items[-1].stamp_ns, self.items[-1].parent) if self.items else (0, None)

    def oldest_ns(self) -> int:
        return self.items[0].stamp_ns if self.items else 0

    def __len__(self) -> int:
        return len(self.items)


class StaticCache:
    """The one transform of a static frame: the same at every time."""

    static = True

    def __init__(self) -> None:
        self.item: Stored | None = None

    def insert(self, item: Stored) -> bool:
        self.item = item
        return True

    def get(self, t_ns: int) -> Stored | str:
        assert self.item is not None
        return self.item

    def latest(self) -> tuple[int, str | None]:
        return (0, self.item.parent if self.item else None)

    def oldest_ns(self) -> int:
        return 0

    def __len__(self) -> int:
        return 1
