"""turtletui's plugin layer, built on pluggy.

Controllers, lessons, worlds and checks all arrive through the hooks in
:mod:`turtletui.plugins.hookspecs`. A plugin is any module with functions
marked ``@hookimpl``::

    from turtletui.plugins import hookimpl

    @hookimpl
    def turtletui_register_controllers(register):
        register("square", my_node_classes, "Drives turtle1 in a square")

Plugins come from three places (see :mod:`turtletui.plugins.manager`): the
built-in plugins, installed packages exposing an entry point in the
``turtletui`` group, and files or folders named with ``--plugin``.
"""

from __future__ import annotations

import pluggy

PROJECT_NAME = "turtletui"
"""pluggy's project name, and the entry-point group plugins are found in."""

hookspec = pluggy.HookspecMarker(PROJECT_NAME)
"""Marks a hook specification (used only in :mod:`turtletui.plugins.hookspecs`)."""

hookimpl = pluggy.HookimplMarker(PROJECT_NAME)
"""Marks a plugin's implementation of a hook."""

__all__ = ["PROJECT_NAME", "hookimpl", "hookspec"]
