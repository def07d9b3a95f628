"""The wheel an autograder bundle carries (turtletui.grading.wheel)."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

from turtletui.grading.wheel import repack_installed, source_tree


def fake_installation(site: Path) -> None:
    """An installed distribution as pip leaves it: files, dist-info, a script in bin/."""
    (site / "fakebot").mkdir(parents=True)
    (site / "fakebot" / "__init__.py").write_text("VERSION = '1.2'\n")
    (site / "fakebot" / "__pycache__").mkdir()
    (site / "fakebot" / "__pycache__" / "__init__.cpython-311.pyc").write_bytes(b"\0")
    info = site / "fakebot-1.2.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: fakebot\nVersion: 1.2\nRequires-Dist: pluggy\n")
    (info / "WHEEL").write_text("Wheel-Version: 1.0\nRoot-Is-Purelib: true\nTag: py3-none-any\n")
    (info / "entry_points.txt").write_text("[console_scripts]\nfakebot = fakebot:main\n")
    (info / "INSTALLER").write_text("pip\n")
    (info / "RECORD").write_text(
        "fakebot/__init__.py,,\nfakebot/__pycache__/__init__.cpython-311.pyc,,\n"
        "fakebot-1.2.dist-info/METADATA,,\nfakebot-1.2.dist-info/WHEEL,,\n"
        "fakebot-1.2.dist-info/entry_points.txt,,\nfakebot-1.2.dist-info/INSTALLER,,\n"
        "fakebot-1.2.dist-info/RECORD,,\n../../../bin/fakebot,,\n"
    )


def test_an_installed_distribution_is_packed_again_into_a_wheel_pip_installs(tmp_path: Path, monkeypatch):
    site = tmp_path / "site"
    fake_installation(site)
    monkeypatch.syspath_prepend(str(site))
    wheel = repack_installed(tmp_path / "out", "fakebot")
    assert wheel.name == "fakebot-1.2-py3-none-any.whl"
    names = zipfile.ZipFile(wheel).namelist()
    assert "fakebot/__init__.py" in names and "fakebot-1.2.dist-info/entry_points.txt" in names
    assert not any("__pycache__" in n or "INSTALLER" in n or n.startswith("..") for n in names)
    target = tmp_path / "installed"
    proc = subprocess.run(
        [sys.executable, "-m", "pip", "install", "--no-deps", "--no-index", "--quiet", "--target", str(target), str(wheel)],
        capture_output=True, text=True,
    )
    assert proc.returncode == 0, proc.stderr
    assert (target / "fakebot" / "__init__.py").read_text() == "VERSION = '1.2'\n"
    assert (target / "bin" / "fakebot").exists()  # the console script, made again by pip


def test_a_checkout_is_built_with_pip_wheel_and_an_installed_copy_is_not():
    import turtletui

    checkout = Path(__file__).resolve().parents[2]
    running_from_checkout = Path(turtletui.__file__).resolve().parent == checkout / "turtletui"
    root = source_tree()
    if running_from_checkout:
        assert root == checkout and (root / "pyproject.toml").is_file()
    else:  # a plain `pip install .` (as CI does): the bundle then ships the installed wheel
        assert root is None
