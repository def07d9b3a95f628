"""Where the bundled reference nodes (top-level plugins/reference) are."""

from __future__ import annotations

from pathlib import Path


def reference_dir() -> Path:
    """The folder of reference nodes, installed or in a source checkout."""
    try:
        import turtletui.reference as package

        return Path(package.__file__).parent
    except ImportError:
        return Path(__file__).resolve().parents[2] / "plugins" / "reference"


def reference_path(filename: str) -> Path:
    return reference_dir() / filename
