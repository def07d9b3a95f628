"""Pieces of the one-line messages turtletui answers bad input with."""

from __future__ import annotations

import difflib
from collections.abc import Iterable

LOST_REQUEST_ADVICE = "Wait with client.wait_for_service() before the first call."
"""How turtletui's warning of a service request sent before discovery ends
(turtletui.compat.node); the grader shows the warning as a likely cause."""
LOST_GOAL_ADVICE = "Wait with action_client.wait_for_server() before the first goal."
"""The same for an action goal (turtletui.compat.action)."""
ENDED_EARLY_ADVICE = (
    "a callback runs only while something spins its node (rclpy.spin(node) at the end of main() keeps it running)."
)
"""How turtletui's note of a controller whose program ended before the run did
ends (turtletui.runtime.report.log_ended_early); the grader shows it as a
likely cause."""

NEVER_SPUN_ADVICE = "Spin it: rclpy.spin(node), or executor.add_node(node) for each node of an executor you spin."
"""How turtletui's note of a node whose callbacks wait for an executor that
never had it ends (turtletui.compat.dispatch); a likely cause in grading."""
LONG_TIMER_SECONDS = 10.0
"""A timer period from which turtletui asks whether milliseconds were meant."""
LONG_TIMER_ADVICE = (
    "If you meant milliseconds: create_timer() takes seconds, not milliseconds (0.1 is 100 ms); "
    "a timer meant to be slow is fine."
)
"""How turtletui's note of a timer of LONG_TIMER_SECONDS or more ends
(turtletui.compat.node); a likely cause in grading."""
RESPONSE_WAITS_ADVICE = (
    "Use call_async() with add_done_callback(), or give the client a callback group of its own."
)
"""How turtletui's note of a wait inside a callback that ran out its timeout,
the response stuck behind the callback's own group, ends (turtletui.compat.node);
a likely cause in grading."""


def one_line(value: object) -> str:
    """``value``'s text with every run of whitespace, newlines included, made one space."""
    return " ".join(str(value).split())


def did_you_mean(word: str, known: Iterable[str], cutoff: float = 0.6) -> str:
    """`` (did you mean 'x'?)`` for the closest of ``known``, or "" when none is close."""
    close = difflib.get_close_matches(word, list(known), n=1, cutoff=cutoff)
    return f" (did you mean {close[0]!r}?)" if close else ""


def plural(count: int, noun: str) -> str:
    """``1 check``, ``2 checks``, ``0 runs``: a count with its noun."""
    return f"{count} {noun}" if count == 1 else f"{count} {noun}s"
