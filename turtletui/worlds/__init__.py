"""Worlds: arenas with obstacles and a LiDAR, from files or plugins.

A :class:`WorldSpec` describes a world and builds a fresh
:class:`turtletui.sim.World` for each run (``spec.build(seed)``).
:func:`load_world_file` reads a TOML world file (the format is in
:mod:`turtletui.worlds.files` and lessons/README.md), and
:func:`resolve_world` finds a world by registered name or file path.
"""

from turtletui.worlds.files import load_world_file, parse_world
from turtletui.worlds.registry import resolve_world, world_names
from turtletui.worlds.spec import WorldError, WorldSpec

__all__ = ["WorldError", "WorldSpec", "load_world_file", "parse_world", "resolve_world", "world_names"]
