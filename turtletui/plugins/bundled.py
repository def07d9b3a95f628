"""Where the content shipped with turtletui is: the reference nodes (top-level
plugins/reference) and the lesson files (top-level lessons/). Installed, they
are the packages turtletui.reference and turtletui.lessons_data."""

from __future__ import annotations

import importlib
from pathlib import Path


def bundled_dir(package: str, source_folder: str) -> Path:
    """The folder of ``package`` when installed, else ``source_folder`` at the
    top of the source checkout turtletui runs from."""
    try:
        module = importlib.import_module(package)
    except ModuleNotFoundError as err:
        if err.name != package:
            raise
        import turtletui

        return Path(turtletui.__file__).resolve().parents[1] / source_folder
    return Path(next(iter(module.__path__)))


def reference_dir() -> Path:
    """The folder of the course's reference nodes."""
    return bundled_dir("turtletui.reference", "plugins/reference")


def reference_path(filename: str) -> Path:
    return reference_dir() / filename


def lessons_dir() -> Path | None:
    """The bundled lessons folder; None if absent."""
    folder = bundled_dir("turtletui.lessons_data", "lessons")
    return folder if folder.is_dir() else None
