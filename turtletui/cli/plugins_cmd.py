"""``turtletui plugins``: what plugins were found and where from."""

from __future__ import annotations

from pathlib import Path

import typer


def plugins(
    plugin: list[Path] = typer.Option(  # noqa: B008 - Typer's way of declaring options
        None,
        "--plugin",
        metavar="PATH",
        help="Also load this plugin file, or every .py in this folder (repeatable).",
    ),
    as_json: bool = typer.Option(
        False, "--json", help="Print a JSON list of objects, one per plugin."
    ),
) -> None:
    """List the plugins turtletui found (built-in, installed, named on the command line)."""
    extra = list(plugin or [])
    if as_json:
        import json

        from turtletui.plugins.manager import get_plugin_manager, plugin_infos

        infos = plugin_infos(get_plugin_manager(extra=extra))
        print(json.dumps([info.as_dict() for info in infos], indent=2))
        return
    from turtletui.plugins.manager import describe_plugins

    for line in describe_plugins(extra):
        print(line)
