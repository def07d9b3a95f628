"""The controller file the editor pane edits, without Textual: read it, save it
atomically, tell whether it changed on disk and whether it still compiles."""

from __future__ import annotations

import os
import stat
from pathlib import Path

from turtletui.runtime.loader import ControllerError, check_source


class SourceFile:
    """A text file on disk and the version of it last read or written."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.saved_text = ""
        """The text as it is on disk, as far as this object knows."""
        self._mtime_ns: int | None = None

    def load(self) -> str:
        """The file's text; OSError or UnicodeDecodeError if it cannot be read as UTF-8."""
        data = self.path.read_bytes()
        if b"\0" in data[:8192]:
            raise UnicodeDecodeError("utf-8", data[:1], 0, 1, "a binary file, not Python source")
        self.saved_text = data.decode("utf-8")
        self._mtime_ns = _mtime_ns(self.path)
        return self.saved_text

    def save(self, text: str) -> str | None:
        """Write ``text`` in one step (a reader never sees half a file); OSError
        if it cannot be written, nothing changed then. Returns why the saved
        code cannot run (a one-line syntax error naming the line), or None."""
        target = self.path.resolve()  # write through a symlink, never over it
        temporary = target.with_name(f".{target.name}.{os.getpid()}.tmp")
        try:
            mode = stat.S_IMODE(os.stat(target).st_mode)
        except FileNotFoundError:
            mode = 0o644
        try:
            with open(temporary, "w", encoding="utf-8", newline="") as out:
                out.write(text)
            os.chmod(temporary, mode)
            os.replace(temporary, target)
        except OSError:
            temporary.unlink(missing_ok=True)
            raise
        self.saved_text = text
        self._mtime_ns = _mtime_ns(self.path)
        try:
            check_source(self.path)
        except ControllerError as err:
            return str(err)
        return None

    def changed_on_disk(self) -> bool:
        """Whether something else wrote the file since it was last loaded or saved."""
        mtime = _mtime_ns(self.path)
        return mtime is not None and mtime != self._mtime_ns

    def seen_on_disk(self) -> None:
        """Take the version on disk as known without reading it (a change was reported)."""
        self._mtime_ns = _mtime_ns(self.path)


def _mtime_ns(path: Path) -> int | None:
    try:
        return os.stat(path).st_mtime_ns
    except OSError:
        return None
