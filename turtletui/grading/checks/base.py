"""What a check is: a function that turns a :class:`~turtletui.grading.trace.Trace`
into a :class:`Verdict` (passed or not, and what was measured), registered
with the thresholds it takes; and the helpers the built-in checks share.

Plugins add checks through ``turtletui_register_checks``: ``register(name,
function, description)`` where ``function(trace, thresholds) -> Verdict``
(or a ``(passed, message)`` pair, or a bool).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from turtletui.grading.trace import Trace

CheckFunction = Callable[[Trace, Mapping[str, Any]], "Verdict"]

TWIN_WINDOW = 10.0
"""Simulated seconds of a twin run (:attr:`Check.twin`) unless a lesson says otherwise."""


@dataclass(frozen=True)
class Verdict:
    """A check's judgement of one run."""

    passed: bool
    measured: str
    """What was measured and what was asked, e.g. ``closest to a wall 0.31 m (needs >= 0.5 m)``."""
    judged: bool = True
    """False when the check was not judged at all (the controller crashed, or a
    check it requires failed): feedback then gives the reason, never advice."""


@dataclass(frozen=True)
class Check:
    """A check the lessons can name."""

    name: str
    function: Callable[..., Any]
    description: str = ""
    params: Mapping[str, str] | None = None
    """Threshold name -> kind ("number", "integer", "text", "point", "colour",
    "pattern"); None when unknown (a plugin's check: thresholds are passed as given)."""
    required: tuple[str, ...] = ()
    twin: bool = False
    """Whether it compares the run with a *twin run*: the same scenario and
    seed from another start, for ``window`` seconds (threshold, default
    :data:`TWIN_WINDOW`); the engine then sets ``trace.twin``."""

    def twin_window(self, thresholds: Mapping[str, Any]) -> float | None:
        """Seconds of twin run this check needs with these thresholds; None: none."""
        return float(thresholds.get("window", TWIN_WINDOW)) if self.twin else None

    def __call__(self, trace: Trace, thresholds: Mapping[str, Any]) -> Any:
        """What the function answers (a plugin may register a Check object itself,
        with the thresholds it takes)."""
        return self.function(trace, thresholds)

    def judge(self, trace: Trace, thresholds: Mapping[str, Any]) -> Verdict:
        """Run the check; a plugin's answer is normalised to a Verdict."""
        answer = self.function(trace, thresholds)
        if isinstance(answer, Verdict):
            return answer
        if isinstance(answer, bool):
            return Verdict(answer, "")
        if isinstance(answer, tuple) and len(answer) == 2:
            return Verdict(bool(answer[0]), str(answer[1]))
        raise TypeError(f"check {self.name!r} returned {type(answer).__name__}, not a Verdict")

    def problem(self, thresholds: Mapping[str, Any]) -> str | None:
        """Why these thresholds cannot be used, or None."""
        if self.params is None:
            return None
        for key in thresholds:
            if key not in self.params:
                known = ", ".join(self.params) or "none"
                return f"check {self.name!r} takes no threshold {key!r} (it takes: {known})"
        for key in self.required:
            if key not in thresholds:
                return f"check {self.name!r} needs the threshold {key!r}"
        for key, value in thresholds.items():
            reason = kind_problem(self.params[key], value)
            if reason:
                return f"check {self.name!r}: threshold {key!r} {reason}, got {value!r}"
        return None


def kind_problem(kind: str, value: Any) -> str | None:
    """Why ``value`` is not a threshold of ``kind`` ("number", "integer", "text",
    "pattern", "numbers", "point", "points", "colour", "boolean"), or None."""
    number = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    if kind == "boolean":
        return None if isinstance(value, bool) else "must be true or false"
    if kind == "number":
        return None if number else "must be a number"
    if kind == "integer":
        return None if isinstance(value, int) and not isinstance(value, bool) else "must be an integer"
    if kind == "text":
        return None if isinstance(value, str) and value else "must be a non-empty string"
    if kind == "pattern":
        if not isinstance(value, str):
            return "must be a regular expression string"
        try:
            re.compile(value)
        except re.error as err:
            return f"is not a valid regular expression ({err})"
        return None
    if kind == "numbers":
        ok = isinstance(value, list) and value and all(kind_problem("number", v) is None for v in value)
        return None if ok else "must be a non-empty list of numbers"
    if kind == "point":
        ok = isinstance(value, list) and len(value) == 2 and all(kind_problem("number", v) is None for v in value)
        return None if ok else "must be [x, y] in metres"
    if kind == "points":
        ok = isinstance(value, list) and value and all(kind_problem("point", v) is None for v in value)
        return None if ok else "must be a non-empty list of [x, y] points in metres"
    if kind == "colour":
        ok = (
            isinstance(value, list)
            and len(value) == 3
            and all(isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= 255 for v in value)
        )
        return None if ok else "must be [r, g, b] with integers 0..255"
    raise ValueError(f"unknown threshold kind {kind!r}")


BUILTIN_CHECKS: dict[str, Check] = {}


def check(
    name: str, description: str, params: Mapping[str, str], required: tuple[str, ...] = (), *, twin: bool = False
):
    """Register a function as a built-in check (``twin``: see :attr:`Check.twin`)."""

    def decorate(function: Callable[[Trace, Mapping[str, Any]], Verdict]) -> Callable[..., Verdict]:
        BUILTIN_CHECKS[name] = Check(name, function, description, dict(params), required, twin)
        return function

    return decorate


# -- helpers of the built-in checks --------------------------------------------------


def bounds(value: float, th: Mapping[str, Any], unit: str = "", *, default_max: float | None = None) -> Verdict:
    """Judge ``value`` against the thresholds ``min`` and ``max``."""
    low = th.get("min")
    high = th.get("max", default_max)
    passed = (low is None or value >= low) and (high is None or value <= high)
    wanted = []
    if low is not None:
        wanted.append(f">= {number_text(low)}{unit}")
    if high is not None:
        wanted.append(f"<= {number_text(high)}{unit}")
    need = f" (needs {' and '.join(wanted)})" if wanted else ""
    missed = [bound for bound, ok in ((low, low is None or value >= low), (high, high is None or value <= high)) if not ok]
    shown = _apart(value, missed[0]) if missed else number_text(value)
    return Verdict(passed, f"{shown}{unit}{need}")


def _apart(value: float, bound: float) -> str:
    """``value`` with the digits that tell it from the ``bound`` it missed: a
    clearance of 1.4996 m is "1.4996", not "1.50", beside "needs >= 1.50"."""
    if number_text(value) != number_text(bound) and f"{value:.2f}" != f"{bound:.2f}":
        return number_text(value)
    for digits in range(3, 7):
        if f"{value:.{digits}f}" != f"{bound:.{digits}f}":
            return f"{value:.{digits}f}"
    return repr(value)


def number_text(value: float) -> str:
    """A measured number as feedback shows it: whole numbers bare, else 2
    decimals (3 significant digits below 0.01); rounding noise (1.1e-16 m from
    a turtle held at a surface) reads 0."""
    if isinstance(value, int) or float(value).is_integer():
        return str(int(value))
    if abs(value) < 1e-9:
        return "0"
    return f"{value:.3g}" if abs(value) < 0.01 else f"{value:.2f}"


def turtle_of(th: Mapping[str, Any]) -> str:
    """The turtle a check looks at (threshold ``turtle``, default turtle1)."""
    return th.get("turtle", "turtle1")


def measured(label: str, verdict: Verdict) -> Verdict:
    """The verdict with ``label`` before what it measured."""
    return Verdict(verdict.passed, f"{label} {verdict.measured}")


MINMAX = {"min": "number", "max": "number"}
"""The thresholds of a check judged by :func:`bounds`."""
TURTLE = {"turtle": "text"}
"""The threshold of a check that looks at one turtle."""
