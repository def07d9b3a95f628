"""Keep each student's result between runs, and never believe one that could
have been touched.

A stored result is a JSON file signed with HMAC-SHA256 under a key that lives
outside every submission: ``$TURTLETUI_RESULTS_KEY`` when set (a CI secret, or
a key made for one job), else ``$XDG_DATA_HOME/turtletui/results.key``, made
with mode 0600 on first use. A result is reused only when its signature holds,
its student's files are the same, and so are the lesson, its checks, the
plugins, the limits and turtletui's version (:func:`store_key`). A store
folder inside a submission, or inside the checkout a submission comes from, is
never read: whoever committed the submission could have written it.
"""

from __future__ import annotations

import hashlib
import hmac
import inspect
import json
import os
import secrets
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from turtletui.errors import TurtletuiError
from turtletui.files import cannot_write_in
from turtletui.grading.reports import ReportError, write_text_atomic
from turtletui.grading.results import SubmissionResult
from turtletui.grading.submissions import Submission
from turtletui.plugins.manager import Plugins, extra_paths

if TYPE_CHECKING:
    from turtletui.grading.engine import GradingPlan

STORE_VERSION = 2
KEY_ENV = "TURTLETUI_RESULTS_KEY"
"""A secret to sign stored results with, instead of the key file."""
KEY_FILE = "results.key"


def data_home() -> Path:
    """``$XDG_DATA_HOME/turtletui`` (``~/.local/share/turtletui`` by default)."""
    base = os.environ.get("XDG_DATA_HOME") or os.path.join(os.path.expanduser("~"), ".local", "share")
    return Path(base) / "turtletui"


def signing_key() -> bytes:
    """The key stored results are signed with (see the module's docstring). A
    key file that cannot be made gives a key for this process only: results
    are then kept for the run but not reused by the next one."""
    try:
        existing = existing_signing_key()
    except OSError:
        return secrets.token_bytes(32)
    if existing is not None:
        return existing
    path = data_home() / KEY_FILE
    try:
        path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except FileExistsError:  # another grader made it just now
        return _read_key(path)
    except OSError:
        return secrets.token_bytes(32)
    key = secrets.token_bytes(32)
    with os.fdopen(fd, "wb") as file:
        file.write(key.hex().encode())
    return key


def existing_signing_key() -> bytes | None:
    """The key from ``$TURTLETUI_RESULTS_KEY`` or the key file, None when
    there is neither (nothing is made); OSError for a key file that cannot be
    trusted or read."""
    secret = os.environ.get(KEY_ENV)
    if secret:
        return hashlib.sha256(secret.encode("utf-8")).digest()
    try:
        return _read_key(data_home() / KEY_FILE)
    except FileNotFoundError:
        return None


def _read_key(path: Path) -> bytes:
    if path.stat().st_mode & 0o077:
        raise OSError(f"{path} is readable by others")  # not a key to trust
    key = bytes.fromhex(path.read_text(encoding="ascii").strip())
    if len(key) < 16:
        raise OSError(f"{path} is too short to be a key")
    return key


def signature(secret: bytes, data: dict[str, Any]) -> str:
    """The HMAC-SHA256 every stored file carries: of ``data`` as canonical JSON."""
    body = json.dumps(data, sort_keys=True, separators=(",", ":")).encode("utf-8")
    return hmac.new(secret, body, hashlib.sha256).hexdigest()


class SignatureError(TurtletuiError, ValueError):
    """A stored file that is not as the grader signed it; one line naming it."""


def read_signed(path: Path, secret: bytes) -> dict[str, Any]:
    """The data of a signed file (its signature taken off). OSError when it
    cannot be read, :class:`SignatureError` when it is not JSON or its
    signature is not ``secret``'s: edited, forged, or signed with another key."""
    return parse_signed(path.read_text(encoding="utf-8"), secret, path)


def parse_signed(raw: str, secret: bytes, path: Path) -> dict[str, Any]:
    """:func:`read_signed` of the text ``raw`` read from ``path``."""
    try:
        data = json.loads(raw)
        given = data.pop("signature")
    except (ValueError, TypeError, KeyError, AttributeError):
        raise SignatureError(f"{path}: not a signed turtletui results file") from None
    if not hmac.compare_digest(str(given), signature(secret, data)):
        raise SignatureError(f"{path}: its signature does not match the results key")
    return data


def result_path(folder: Path, student: str) -> Path:
    """Where a results folder keeps ``student``'s result."""
    return folder / f"{_safe(student)}.json"


def recordings_folder(folder: Path, student: str) -> Path:
    """Where a results folder keeps the recordings of ``student``'s failed runs."""
    return folder / "recordings" / _safe(student)


def checkout_of(path: Path) -> Path:
    """The version-control checkout ``path`` is in (the folder holding ``.git``),
    or ``path`` itself when it is in none."""
    path = path.resolve()
    for folder in (path, *path.parents):
        if (folder / ".git").exists():
            return folder
    return path


def store_key(plan: GradingPlan, *, plugins: Plugins = (), limits: Any = None) -> str:
    """What a stored result depends on besides the student's files: the lesson
    file, the code and thresholds of its checks, the plugins, the sandbox's
    limits, the distro the grader chose and turtletui's version."""
    from turtletui import __version__

    digest = hashlib.sha256(__version__.encode())
    digest.update(plan.lesson.path.read_bytes())
    for spec, check in plan.checks:
        digest.update(repr((spec.name, spec.weight, sorted(spec.thresholds.items(), key=str))).encode())
        digest.update(_code_of(check.function))
    for plugin in extra_paths(plugins):
        digest.update(_files_of(Path(plugin)))
    digest.update(repr(limits).encode())
    digest.update(repr(plan.distro).encode())
    return f"{plan.lesson.id}:{digest.hexdigest()[:32]}"


def _code_of(function: Any) -> bytes:
    try:
        return inspect.getsource(inspect.getmodule(function) or function).encode()
    except (OSError, TypeError):
        return repr(function).encode()


def _files_of(path: Path) -> bytes:
    files = sorted(p for p in path.rglob("*.py") if p.is_file()) if path.is_dir() else [path]
    digest = hashlib.sha256()
    for file in files:
        digest.update(str(file.relative_to(path) if path.is_dir() else file.name).encode())
        try:
            digest.update(file.read_bytes())
        except OSError:
            digest.update(b"<unreadable>")
    return digest.digest()


class ResultStore:
    """One signed JSON file per student in a folder only the grader can read."""

    def __init__(
        self,
        folder: Path,
        key: str,
        *,
        secret: bytes | None = None,
        untrusted: Sequence[Path] = (),
    ) -> None:
        self.folder = folder
        self.key = key
        """Identifies the lesson, checks, plugins, limits and turtletui version."""
        self._secret = secret if secret is not None else signing_key()
        try:
            folder.mkdir(parents=True, exist_ok=True, mode=0o700)
        except FileExistsError:
            raise ReportError(f"{folder}: cannot write results there (it is a file, not a folder)") from None
        except OSError as err:
            raise ReportError(f"{folder}: cannot write results there ({err.strerror or err})") from None
        why = cannot_write_in(folder)
        if why is not None:
            raise ReportError(f"{folder}: cannot write results there ({why})")
        here = folder.resolve()
        self.trusted = not any(
            here == place or place in here.parents for place in (Path(p).resolve() for p in untrusted)
        )
        """False for a folder inside one of the ``untrusted`` folders (the
        submissions, the checkouts they come from): nothing in it is reused."""
        self._kept: dict[Path, str] = {}
        """The text of every file this store wrote or reused, for :meth:`restore`."""

    def path(self, student: str) -> Path:
        return result_path(self.folder, student)

    def recordings(self, student: str) -> Path:
        return recordings_folder(self.folder, student)

    def load(self, submission: Submission) -> SubmissionResult | None:
        """The stored result of the same files under the same lesson, signed by
        this grader's key, or None."""
        if not self.trusted:
            return None
        path = self.path(submission.student)
        try:
            raw = path.read_text(encoding="utf-8")
            data = parse_signed(raw, self._secret, path)
            if data.get("store") != STORE_VERSION or data.get("key") != self.key:
                return None
            if data.get("student") != submission.student or data.get("fingerprint") != submission.fingerprint():
                return None
            result = SubmissionResult.from_dict(data["result"])
        except (OSError, ValueError, KeyError, TypeError, AttributeError):
            return None  # missing, damaged or forged: grade again
        self._kept[path] = raw
        return result

    def save(self, submission: Submission, result: SubmissionResult) -> None:
        """Write the signed result atomically: the file is complete or absent."""
        data = {
            "store": STORE_VERSION,
            "key": self.key,
            "student": submission.student,
            "fingerprint": submission.fingerprint(),
            "result": result.as_dict(),
        }
        self.write_signed(self.path(submission.student), data)

    def write_signed(self, target: Path, data: dict[str, Any]) -> None:
        """Sign ``data`` and write it to ``target`` (in this folder) atomically."""
        payload = json.dumps({**data, "signature": signature(self._secret, data)}, indent=1)
        write_text_atomic(target, payload)
        self._kept[target] = payload

    def restore(self) -> None:
        """Put back every result file this store wrote or reused that is not as
        it left it: student code running as the grader's own user (--same-user,
        or a grader that is not root) can write in the folder. Called once no
        student code runs any more."""
        for target, payload in self._kept.items():
            try:
                if target.read_text(encoding="utf-8") == payload:
                    continue
            except (OSError, ValueError):
                pass
            write_text_atomic(target, payload)


def _safe(name: str) -> str:
    """A file name for a student: their name, or a cleaned one with a hash of the
    name (so that "a b" and "a_b" get files of their own)."""
    safe = "".join(c if c.isalnum() or c in "-_." else "_" for c in name).lstrip(".") or "student"
    if safe == name:
        return safe
    return f"{safe}-{hashlib.sha256(name.encode()).hexdigest()[:8]}"
