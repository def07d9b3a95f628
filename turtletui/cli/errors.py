"""Turn domain errors into one-line messages and exit codes."""

from __future__ import annotations

import sys
from typing import NoReturn


def fail(message: str, code: int = 2) -> NoReturn:
    """Print ``turtletui: error: message`` on stderr and exit."""
    sys.stderr.write(f"turtletui: error: {message}\n")
    raise SystemExit(code)
