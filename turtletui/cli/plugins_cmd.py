"""``turtletui plugins``: what plugins were found and where from."""

from __future__ import annotations

from pathlib import Path

import typer

from turtletui.cli.plugin_manager import plugins_of


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
    pm = plugins_of(plugin)
    if as_json:
        import json

        from turtletui.plugins.manager import plugin_infos

        print(json.dumps([info.as_dict() for info in plugin_infos(pm)], indent=2))
        return
    from turtletui.plugins.manager import describe_plugins

    for line in describe_plugins(pm=pm):
        print(line)
