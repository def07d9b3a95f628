"""``turtletui plugins``: what plugins were found and where from."""

from __future__ import annotations


def plugins() -> None:
    """List the plugins turtletui found (built-in, installed, named on the command line)."""
    from turtletui.plugins.manager import describe_plugins

    for line in describe_plugins():
        print(line)
