"""Checks of the controller's log lines."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from turtletui.grading.checks.base import MINMAX, Verdict, bounds, check, measured, number_text
from turtletui.grading.trace import Trace
from turtletui.graph.logs import LEVEL_NAMES

_LOG = {"pattern": "pattern", "node": "text", "level": "text"}


def _matching_logs(trace: Trace, th: Mapping[str, Any]) -> list[Any]:
    pattern = re.compile(th.get("pattern", ""))
    node = th.get("node")
    level = th.get("level", "").upper()
    return [
        r
        for r in trace.logs
        if r.node != "turtlesim"
        and r.node != "turtletui"
        and (node is None or r.node == node.lstrip("/"))
        and (not level or r.level_name == level)
        and pattern.search(r.msg)
    ]


@check(
    "log_lines",
    "Log lines of the controller's nodes matching `pattern` (optionally from `node`, at `level`): "
    "thresholds min and max, or min_rate and max_rate in lines per simulated second.",
    {**MINMAX, **_LOG, "min_rate": "number", "max_rate": "number"},
)
def log_lines(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    level = th.get("level", "").upper()
    if level and level not in LEVEL_NAMES.values():
        return Verdict(False, f"unknown log level {level!r}")
    lines = _matching_logs(trace, th)
    what = f"log lines matching {th['pattern']!r}" if "pattern" in th else "log lines"
    verdict = bounds(len(lines), th)
    if "min_rate" in th or "max_rate" in th:
        rate = len(lines) / trace.sim_time if trace.sim_time > 0 else 0.0
        by_rate = bounds(rate, {"min": th.get("min_rate"), "max": th.get("max_rate")}, " per s")
        return Verdict(verdict.passed and by_rate.passed, f"{what}: {len(lines)}, {by_rate.measured}")
    return measured(f"{what}:", verdict)


@check(
    "log_counter",
    "The matching log lines carry a counter that goes up by one each line (at least `min` lines).",
    {**_LOG, "min": "number"},
)
def log_counter(trace: Trace, th: Mapping[str, Any]) -> Verdict:
    numbers = []
    for record in _matching_logs(trace, th):
        found = re.search(r"-?\d+", record.msg)
        if found:
            numbers.append(int(found.group()))
    need = th.get("min", 3)
    if len(numbers) < need:
        return Verdict(False, f"{len(numbers)} log lines with a number (needs >= {number_text(need)})")
    steps = [b - a for a, b in zip(numbers, numbers[1:], strict=False)]
    if any(step != 1 for step in steps):
        bad = next(i for i, step in enumerate(steps) if step != 1)
        return Verdict(False, f"the counter went from {numbers[bad]} to {numbers[bad + 1]}: it should go up by one")
    return Verdict(True, f"counter logged {len(numbers)} times, {numbers[0]} to {numbers[-1]}")
