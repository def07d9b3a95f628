"""The family of errors turtletui reports to its user.

Every error that is the user's to fix (a missing or broken file, a bad
option, a lesson that cannot be graded, a plugin's bad registration...)
derives from :class:`TurtletuiError` and says what is wrong in one line,
naming the file, field or value. The command line prints that line and exits
with status 2; any other exception is a bug in turtletui, reported as one.
Standard library only: every layer may import this module.
"""

from __future__ import annotations


class TurtletuiError(Exception):
    """Base of every error turtletui reports to its user as one line."""


class UsageError(TurtletuiError, ValueError):
    """A value turtletui was given that it cannot use (an option, an argument)."""
