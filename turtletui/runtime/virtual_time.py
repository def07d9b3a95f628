"""Simulated sleeps for controller code in lockstep.

In lockstep, wall time means nothing to the simulation: a controller's main()
that does ``publish(); time.sleep(0.5)`` must let half a simulated second
pass, as it would let half a second of turtlesim pass on a real robot. While
the controller runs, ``time.sleep`` becomes a sleep in simulated time: time
advances, the node's own callbacks stay queued (as a sleeping thread would
leave them), and the rest of the world goes on.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

_real_sleep = time.sleep


def _simulated_sleep(host: Any):
    pid = os.getpid()

    def sleep(seconds: float) -> None:
        if os.getpid() != pid:
            # A process the controller forked has no simulated clock.
            _real_sleep(seconds)
            return
        if isinstance(seconds, bool) or not isinstance(seconds, (int, float)):
            raise TypeError(f"'{type(seconds).__name__}' object cannot be interpreted as an integer or float")
        if seconds < 0:
            raise ValueError("sleep length must be non-negative")
        if math.isnan(seconds):
            raise ValueError("Invalid value NaN (not a number)")
        if not host.running:
            # The run is over: do not stall the program on its way out.
            return
        host.sleep_until(host.graph.now_ns + int(min(seconds, 1e9) * 1_000_000_000))

    sleep.__doc__ = _real_sleep.__doc__
    return sleep


@contextmanager
def simulated_sleep(host: Any) -> Iterator[None]:
    """Within the block, ``time.sleep`` sleeps in ``host``'s simulated time."""
    time.sleep = _simulated_sleep(host)
    try:
        yield
    finally:
        time.sleep = _real_sleep


def install_simulated_sleep(host: Any) -> None:
    """For a process that exists to run one controller (the sandbox child)."""
    time.sleep = _simulated_sleep(host)
