"""Files sent to the machines of a cluster: a submission, or a lesson with what
it needs, packed in memory as one gzip'd tar and unpacked into a fresh folder
there.

A student's folder is sent without what holds no source of theirs (hidden
folders, caches, colcon's build, install and log folders, environments: see
:func:`~turtletui.grading.submissions.ignored`); links are sent as links only
when they stay inside it.
"""

from __future__ import annotations

import hashlib
import io
import os
import tarfile
from collections.abc import Iterator, Sequence
from pathlib import Path

from turtletui.errors import TurtletuiError
from turtletui.grading.submissions import ignored

MAX_BUNDLE_BYTES = 64 * 1024**2
"""Bytes of files one bundle may hold (a submission is a few source files)."""


class BundleError(TurtletuiError, ValueError):
    """Files that cannot be sent; one line naming them."""


def pack(entries: Sequence[tuple[Path, str]], limit: int = MAX_BUNDLE_BYTES) -> bytes:
    """A tar.gz of each ``(path, name)``: the file or folder at ``path``,
    stored as ``name``. BundleError above ``limit`` bytes of files."""
    buffer = io.BytesIO()
    size = 0
    with tarfile.open(fileobj=buffer, mode="w:gz", compresslevel=1) as tar:
        for path, name in entries:
            for source, arcname in _files(path, name):
                info = tar.gettarinfo(str(source), arcname)
                info.uid = info.gid = 0
                info.uname = info.gname = ""
                if info.isreg():
                    size += info.size
                    if size > limit:
                        raise BundleError(f"{path}: more than {limit // 1024**2} MB of files to send")
                    with open(source, "rb") as file:
                        tar.addfile(info, file)
                elif info.issym():
                    # relative, so that it still points inside where it is unpacked
                    info.linkname = os.path.relpath(source.resolve(), source.parent.resolve())
                    tar.addfile(info)
                elif info.isdir():
                    tar.addfile(info)
    return buffer.getvalue()


def _files(path: Path, name: str) -> Iterator[tuple[Path, str]]:
    """What of ``path`` is sent, with its names in the bundle."""
    if not path.is_dir():
        yield path, name
        return
    root = path.resolve()
    yield path, name
    for folder, dirs, files in os.walk(path):
        here = Path(folder)
        dirs[:] = sorted(d for d in dirs if not ignored(here / d) and _inside(here / d, root))
        inside = here.relative_to(path)
        for entry in sorted(dirs):
            yield here / entry, f"{name}/{(inside / entry).as_posix()}"
        for entry in sorted(files):
            file = here / entry
            if _inside(file, root) and (file.is_symlink() or file.is_file()):
                yield file, f"{name}/{(inside / entry).as_posix()}"


def _inside(path: Path, root: Path) -> bool:
    """Not a link, or a link to something inside ``root``."""
    if not path.is_symlink():
        return True
    target = path.resolve()
    return target == root or root in target.parents


def unpack(data: bytes, into: Path) -> None:
    """Unpack a :func:`pack` bundle into the folder ``into``; nothing is
    written outside it."""
    with tarfile.open(fileobj=io.BytesIO(data), mode="r:gz") as tar:
        if hasattr(tarfile, "data_filter"):
            tar.extractall(into, filter="data")
            return
        root = into.resolve()
        for member in tar.getmembers():  # Pythons without extraction filters (3.10 before 3.10.12)
            target = (into / member.name).resolve()
            link = (target.parent / member.linkname).resolve() if member.issym() else target
            if not (member.isreg() or member.isdir() or member.issym()) or not all(
                p == root or root in p.parents for p in (target, link)
            ):
                raise BundleError(f"bundle member {member.name!r} would be unpacked outside {into}")
        tar.extractall(into)  # noqa: S202 - every member checked above


def digest(data: bytes) -> str:
    """A name for a bundle's content."""
    return hashlib.sha256(data).hexdigest()[:32]
