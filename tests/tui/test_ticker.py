"""The app's tick schedule (turtletui.tui.ticker): deadlines on a fixed grid."""

from __future__ import annotations

import threading

import pytest

from turtletui.tui.ticker import CATCH_UP, MAX_BEHIND, Schedule, Ticker

PERIOD = 0.016


def run(schedule: Schedule, delays: dict[int, float], ticks: int) -> list[float]:
    """Tick ``ticks`` times, each when due plus delays[k] (a busy machine); the gaps."""
    gaps = []
    for k in range(ticks):
        now = schedule.wake_at() + delays.get(k, 0.0)
        gap = schedule.ticked(now)
        if gap is not None:
            gaps.append(gap)
    return gaps


def test_on_time_ticks_are_exactly_one_period_apart():
    gaps = run(Schedule(PERIOD, 100.0), {}, 200)
    assert gaps == pytest.approx([PERIOD] * 199)


def test_a_late_tick_is_made_up_without_a_short_gap():
    gaps = run(Schedule(PERIOD, 100.0), {50: 0.008}, 200)
    assert max(gaps) == pytest.approx(PERIOD + 0.008)
    # Made up a little at a time: no gap shorter than the period less CATCH_UP ...
    assert min(gaps) >= PERIOD - CATCH_UP - 1e-12
    assert sum(1 for gap in gaps if gap < PERIOD - 1e-9) == 3
    # ... and the mean is exact again once it is made up (no tick lost).
    assert sum(gaps) == pytest.approx(199 * PERIOD)


def test_a_long_stall_starts_the_schedule_afresh_instead_of_a_burst():
    schedule = Schedule(PERIOD, 100.0)
    gaps = run(schedule, {10: MAX_BEHIND + 1.0}, 40)
    assert max(gaps) > 1.0
    after = gaps[gaps.index(max(gaps)) + 1 :]
    assert after == pytest.approx([PERIOD] * len(after))


def test_the_ticker_calls_its_tick_holding_the_lock_and_stops():
    lock = threading.Lock()
    held = []
    enough = threading.Event()

    def tick(now: float) -> None:
        held.append(lock.locked())
        if len(held) >= 5:
            enough.set()

    ticker = Ticker(0.001, tick, lock)
    ticker.start()
    assert enough.wait(10.0)
    ticker.stop()
    assert not ticker.running
    count = len(held)
    assert all(held) and len(ticker.gaps) >= 4
    assert enough.wait(0.05) and len(held) == count  # no tick after stop


def test_an_error_in_the_tick_is_handed_over_and_stops_the_ticker():
    seen = []
    done = threading.Event()

    def tick(now: float) -> None:
        raise ValueError("boom")

    ticker = Ticker(0.001, tick, threading.Lock(), on_error=lambda err: (seen.append(err), done.set()))
    ticker.start()
    assert done.wait(10.0)
    ticker.stop()
    assert isinstance(seen[0], ValueError) and not ticker.running
