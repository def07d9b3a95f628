"""Build a wheel of the turtletui that is running, to ship inside an autograder:
grading containers then install exactly this version (its dependencies come
from the package index) whether or not it was ever published.

Two ways, by where turtletui was installed from:

- a source checkout (a plain or editable install: ``pyproject.toml`` next to
  the package): ``pip wheel --no-deps`` builds it, as a release would;
- an installed wheel (site-packages, no source anywhere): the installed files
  listed in the distribution's RECORD are packed again into a wheel with the
  same metadata and entry points. pip keeps no reliable copy of the wheel it
  installed (its cache may be off, pruned or elsewhere), the installed files
  are always there.
"""

from __future__ import annotations

import base64
import hashlib
import importlib.metadata as metadata
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

from turtletui.errors import TurtletuiError

DISTRIBUTION = "turtletui"
_NOT_PACKED = {"RECORD", "INSTALLER", "REQUESTED", "direct_url.json"}
"""dist-info files that describe one installation, not the distribution."""


class WheelError(TurtletuiError, ValueError):
    """The wheel cannot be built; one line saying why."""


def source_tree() -> Path | None:
    """The checkout turtletui is imported from, or None when it is installed."""
    import turtletui

    root = Path(turtletui.__file__).resolve().parents[1]
    pyproject = root / "pyproject.toml"
    try:
        text = pyproject.read_text(encoding="utf-8")
    except OSError:
        return None
    return root if re.search(r'^name\s*=\s*"turtletui"', text, re.MULTILINE) else None


def build_wheel(dest: Path) -> Path:
    """A wheel of the running turtletui, written into ``dest``; returns its path."""
    dest.mkdir(parents=True, exist_ok=True)
    root = source_tree()
    return _pip_wheel(root, dest) if root is not None else repack_installed(dest)


def _pip_wheel(root: Path, dest: Path) -> Path:
    with tempfile.TemporaryDirectory(prefix="turtletui-wheel-") as tmp:
        # A copy of the checkout: building writes build/ and *.egg-info into the
        # source folder, and the checkout may be read-only or belong to someone else.
        source = Path(tmp) / "src"
        shutil.copytree(
            root, source,
            ignore=shutil.ignore_patterns(".git", ".venv", "*.egg-info", "build", "dist", "__pycache__", "tests"),
        )
        out = Path(tmp) / "out"
        command = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "--wheel-dir", str(out), str(source)]
        # Isolated first, as a release is built (pip fetches the build backend);
        # offline, with the setuptools installed here.
        last = "no wheel was written"
        for extra in ([], ["--no-build-isolation"]):
            proc = subprocess.run([*command, *extra], capture_output=True, text=True)
            wheels = sorted(out.glob("turtletui-*.whl"))
            if proc.returncode == 0 and wheels:
                target = dest / wheels[0].name
                shutil.copyfile(wheels[0], target)
                return target
            lines = [line.strip() for line in proc.stderr.splitlines() if line.strip().startswith(("error", "ERROR"))]
            last = lines[-1] if lines else last
        raise WheelError(f"cannot build a wheel of turtletui from {root}: {last}")


def _record_hash(data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode("ascii")
    return f"sha256={digest}"


def repack_installed(dest: Path, distribution: str = DISTRIBUTION) -> Path:
    """Pack the installed files of ``distribution`` into a wheel in ``dest``."""
    try:
        dist = metadata.distribution(distribution)
    except metadata.PackageNotFoundError:
        raise WheelError(f"{distribution} is not installed, and not run from a checkout") from None
    files = dist.files or []
    info = next((f.parts[0] for f in files if f.parts and f.parts[0].endswith(".dist-info")), None)
    if info is None:
        raise WheelError(f"{distribution}'s installation lists no .dist-info folder")
    dest.mkdir(parents=True, exist_ok=True)
    name = re.sub(r"[-_.]+", "_", dist.metadata["Name"]).lower()
    version = dist.version
    target = dest / f"{name}-{version}-py3-none-any.whl"
    records = []
    with zipfile.ZipFile(target, "w", zipfile.ZIP_DEFLATED) as wheel:
        for file in sorted(files, key=str):
            parts = file.parts
            if not parts or parts[0] == ".." or "__pycache__" in parts or file.suffix == ".pyc":
                continue  # console scripts (in bin/) are made again from entry_points.txt
            if parts[0] == info and parts[-1] in _NOT_PACKED:
                continue
            data = Path(file.locate()).read_bytes()
            arcname = "/".join(parts)
            wheel.writestr(arcname, data)
            records.append(f"{arcname},{_record_hash(data)},{len(data)}")
        if f"{info}/WHEEL" not in {r.split(",")[0] for r in records}:
            data = b"Wheel-Version: 1.0\nGenerator: turtletui\nRoot-Is-Purelib: true\nTag: py3-none-any\n"
            wheel.writestr(f"{info}/WHEEL", data)
            records.append(f"{info}/WHEEL,{_record_hash(data)},{len(data)}")
        records.append(f"{info}/RECORD,,")
        wheel.writestr(f"{info}/RECORD", "\n".join(records) + "\n")
    return target
