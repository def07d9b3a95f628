"""Turn what the user named (files, or controllers registered by plugins) into specs."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from turtletui.runtime.loader import ControllerError, ControllerSpec

if TYPE_CHECKING:
    from turtletui.plugins.manager import Plugins


def _looks_like_a_path(text: str) -> bool:
    return text.endswith(".py") or "/" in text or "\\" in text or Path(text).exists()


def resolve_controllers(names: Sequence[str | Path], *, plugins: Plugins = ()) -> list[ControllerSpec]:
    """A spec per controller: a file path (sandboxed), or the name of a
    controller a plugin registered (``turtletui plugins`` lists them);
    ``plugins`` is the plugin manager, or extra plugin paths.

    Registered files of the built-in plugin (the course's reference nodes) and
    node factories of installed plugins are trusted and run in-process; files
    named by the user are sandboxed. Unknown names raise ControllerError.
    """
    registered = None
    specs = []
    for item in names:
        text = str(item)
        if isinstance(item, Path) or _looks_like_a_path(text):
            path = Path(item)
            specs.append(ControllerSpec(name=path.stem, path=path))
            continue
        if registered is None:
            from turtletui.plugins.manager import collect_controllers, plugin_manager

            registered = collect_controllers(plugin_manager(plugins))
        entry = registered.get(text)
        if entry is None:
            known = ", ".join(sorted(registered)) or "none"
            raise ControllerError(
                f"{text}: no such file, and no plugin registers a controller of that name"
                f" (registered: {known})"
            )
        if entry.path is not None:
            specs.append(ControllerSpec(name=text, path=entry.path, trusted=entry.source == "builtin"))
        else:
            specs.append(ControllerSpec(name=text, factory=entry.object, trusted=True))
    return specs
