"""Find a world by name (registered by plugins) or by the path of its file.

``empty`` (turtlesim's arena) is built in; the built-in plugin registers the
world files bundled in lessons/worlds/; installed plugins and ``--plugin``
files add theirs through the ``turtletui_register_worlds`` hook (a plugin may
replace ``empty`` too). A world's factory
returns a :class:`WorldSpec`, the path of a TOML world file, or a dict in that
file's format.
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

from turtletui.messages import did_you_mean
from turtletui.plugins.manager import Plugins, WorldEntry, collect_worlds, plugin_manager
from turtletui.worlds.files import load_world_file, parse_world
from turtletui.worlds.spec import WorldError, WorldSpec

EMPTY = WorldSpec("empty", "turtlesim's arena: no obstacles, no LiDAR")
"""The world every lesson runs in unless it names another."""


def registered_worlds(plugins: Plugins = ()) -> dict[str, WorldEntry]:
    """Every world plugins register, by name (built-ins, installed, ``plugins``:
    the plugin manager, or extra plugin paths)."""
    return collect_worlds(plugin_manager(plugins))


def world_names(plugins: Plugins = ()) -> list[str]:
    """The names of the worlds there are (``empty`` and the registered ones), sorted."""
    return sorted({EMPTY.name, *registered_worlds(plugins)})


def is_world_path(name: str | Path) -> bool:
    """Whether ``name`` means a file rather than a registered world."""
    text = str(name)
    return isinstance(name, Path) or text.endswith(".toml") or "/" in text or os.sep in text


def resolve_world(name: str | Path, plugins: Plugins = ()) -> WorldSpec:
    """The world called ``name``, or the world file at path ``name`` (``.toml``).

    Raises WorldError with one line for an unknown name, a bad file or a
    factory that fails or returns something else.
    """
    if is_world_path(name):
        return load_world_file(name)
    worlds = registered_worlds(plugins)
    entry = worlds.get(name)
    if entry is None and name == EMPTY.name:
        return EMPTY
    if entry is None:
        known = sorted({EMPTY.name, *worlds})
        hint = did_you_mean(name, known, cutoff=0.5)
        raise WorldError(f"unknown world {name!r}{hint}; known: {', '.join(known) or 'none'}")
    return spec_of(entry)


def spec_of(entry: WorldEntry) -> WorldSpec:
    """Call a registered world's factory and make a WorldSpec of what it returns."""
    where = f"world {entry.name!r} (plugin {entry.plugin})"
    try:
        made = entry.object()
    except Exception as err:  # noqa: BLE001 - plugin code; becomes a one-line error
        raise WorldError(f"{where}: its factory failed: {type(err).__name__}: {err}") from None
    if isinstance(made, WorldSpec):
        spec = made
    elif isinstance(made, (str, os.PathLike)):
        spec = load_world_file(made)
    elif isinstance(made, dict):
        spec = parse_world(made, name=entry.name, where=where)
    else:
        raise WorldError(
            f"{where}: the factory returned {type(made).__name__}; expected a WorldSpec,"
            " the path of a .toml world file or a dict in that format"
        )
    return replace(spec, name=entry.name, description=spec.description or entry.description)
