"""Turn errors into one-line messages and exit codes.

A :class:`~turtletui.errors.TurtletuiError` is the user's to fix: its one
line and exit status 2. Anything else escaping a command is a bug in
turtletui: one line saying so, the traceback saved to a file whose path the
line gives, and exit status 3.
"""

from __future__ import annotations

import os
import sys
import time
import traceback
from pathlib import Path
from typing import NoReturn

EXIT_BAD_INPUT = 2
EXIT_INTERNAL = 3


def fail(message: str, code: int = EXIT_BAD_INPUT) -> NoReturn:
    """Print ``turtletui: error: message`` on stderr and exit."""
    sys.stderr.write(f"turtletui: error: {message}\n")
    raise SystemExit(code)


def internal_error(err: BaseException) -> NoReturn:
    """Report a bug in one line, its traceback in a file, and exit with status 3."""
    where = save_traceback(err)
    text = " ".join(str(err).split())
    what = f"{type(err).__name__}: {text}" if text else type(err).__name__
    sys.stderr.write(f"turtletui: internal error: {what} (details in {where})\n")
    raise SystemExit(EXIT_INTERNAL)


def save_traceback(err: BaseException) -> Path:
    """Write ``err``'s traceback to a new file in the user's cache
    (``$XDG_CACHE_HOME/turtletui/errors``), or the temporary folder if that
    cannot be written; returns its path."""
    details = "".join(traceback.format_exception(type(err), err, err.__traceback__))
    name = f"error-{time.strftime('%Y%m%d-%H%M%S')}-{os.getpid()}.txt"
    for folder in (_cache_dir() / "errors", Path(_temporary_folder())):
        try:
            folder.mkdir(parents=True, exist_ok=True)
            path = folder / name
            path.write_text(details, encoding="utf-8")
            return path
        except OSError:
            continue
    return Path(os.devnull)


def _cache_dir() -> Path:
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "turtletui"


def _temporary_folder() -> str:
    import tempfile

    return tempfile.gettempdir()
