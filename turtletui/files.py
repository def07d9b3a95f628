"""What the file system allows, asked before work that would be lost otherwise."""

from __future__ import annotations

import tempfile
from pathlib import Path


def cannot_write_in(folder: Path) -> str | None:
    """Why no file can be made in ``folder`` (the system's reason), or None
    when one can: a probe file is made and removed. It tells what access()
    cannot (root; a read-only or special file system such as /proc)."""
    try:
        with tempfile.NamedTemporaryFile(dir=folder, prefix=".turtletui-", suffix=".probe"):
            return None
    except OSError as err:
        return err.strerror or str(err)
