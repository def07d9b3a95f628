"""The plugin manager of a command: built once, from its ``--plugin`` options,
and passed to every library function that looks plugins up."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from turtletui.plugins.manager import TurtletuiPluginManager


def plugins_of(paths: list[Path] | None) -> TurtletuiPluginManager:
    """The command's one plugin manager, with the ``--plugin`` files and folders."""
    from turtletui.plugins.manager import get_plugin_manager

    return get_plugin_manager(extra=paths or ())
