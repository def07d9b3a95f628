"""What the grader does when it runs as root (as in Gradescope's containers):
the student's code runs as an unprivileged user, from a private copy of the
submission, and cannot read the lessons or the results."""

from __future__ import annotations

import os
import pwd
import shutil
import stat
import sys
import tempfile
from dataclasses import replace
from pathlib import Path

from turtletui.errors import TurtletuiError
from turtletui.grading.submissions import Submission

UNPRIVILEGED_USER = "nobody"


class IntegrityError(TurtletuiError, ValueError):
    """The grader cannot run student code safely here; one line saying why."""


def unprivileged_ids() -> tuple[int, int] | None:
    """(uid, gid) to run student code as: ``nobody`` when the grader is root, else None."""
    if not hasattr(os, "geteuid") or os.geteuid() != 0:
        return None
    try:
        entry = pwd.getpwnam(UNPRIVILEGED_USER)
    except KeyError:
        raise IntegrityError(
            f"grading as root needs the user {UNPRIVILEGED_USER!r} to run student code; "
            "create it or grade as an ordinary user"
        ) from None
    return entry.pw_uid, entry.pw_gid


def unreadable_by_others(path: Path) -> Path | None:
    """The first folder or file on the way to ``path`` that other users cannot
    search or read (None if they can reach and read it)."""
    path = path.resolve()
    for folder in reversed(path.parents):
        if not folder.stat().st_mode & stat.S_IXOTH:
            return folder
    mode = path.stat().st_mode
    need = stat.S_IROTH | (stat.S_IXOTH if path.is_dir() else 0)
    return None if mode & need == need else path


def check_runtime_readable() -> None:
    """Student code runs this Python and imports turtletui: the unprivileged
    user must be able to read both."""
    import turtletui

    for path in (Path(sys.executable), Path(turtletui.__file__).parent):
        blocked = unreadable_by_others(path)
        if blocked is not None:
            raise IntegrityError(
                f"grading as root runs student code as user {UNPRIVILEGED_USER!r}, who cannot read {blocked} "
                f"(needed for {path}): install turtletui where every user can read it (the Gradescope "
                "autograder uses /opt/turtletui), or grade as an ordinary user"
            )


def readable_not_writable(root: Path) -> None:
    """Let every user read ``root`` and what is in it, and only its owner write."""
    for folder, _dirs, files in os.walk(root):
        os.chmod(folder, 0o755)
        for name in files:
            file = os.path.join(folder, name)
            if not os.path.islink(file):
                os.chmod(file, 0o644)


class PrivateCopies:
    """Copies of submissions in a fresh folder the student's user can read but
    not write: one student's code cannot touch another's files or the originals."""

    def __init__(self) -> None:
        self.root = Path(tempfile.mkdtemp(prefix="turtletui-grade-"))
        os.chmod(self.root, 0o755)

    def __call__(self, submission: Submission) -> Submission:
        assert submission.controller is not None
        target = self.root / f"{len(os.listdir(self.root)):05d}"
        if submission.path.is_dir():
            # links are copied as links: following them as root could expose a
            # file the student may not read (a link to /etc/shadow)
            shutil.copytree(submission.path, target, symlinks=True)
            controller = target / submission.controller.relative_to(submission.path)
        else:
            target.mkdir()
            controller = target / submission.controller.name
            shutil.copy2(submission.controller, controller, follow_symlinks=False)
        readable_not_writable(target)
        return replace(submission, path=target, controller=controller)

    def close(self) -> None:
        shutil.rmtree(self.root, ignore_errors=True)
