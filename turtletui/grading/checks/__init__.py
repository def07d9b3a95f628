"""The checks a lesson can name: the built-in ones, registered as their modules
are imported, and what a check is (:mod:`turtletui.grading.checks.base`).

A check judges behaviour, not one student's numbers: ``min_clearance`` asks
for room to spare from the walls, not for particular turn rates. A lesson
names checks in its ``[[checks]]`` tables with their ``thresholds``; every
threshold a built-in check takes is listed in its :class:`Check` ``params``,
so a misspelt one is an error when the lesson is prepared for grading.
Plugins add checks through ``turtletui_register_checks``.
"""

from turtletui.grading.checks import logs, motion, safety, services
from turtletui.grading.checks.base import BUILTIN_CHECKS, Check, CheckFunction, Verdict, check
from turtletui.grading.checks.motion import fit_circle

__all__ = ["BUILTIN_CHECKS", "Check", "CheckFunction", "Verdict", "check", "fit_circle", "logs", "motion", "safety", "services"]
