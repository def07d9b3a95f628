"""The app served to web browsers: textual-serve's server, started by
``turtletui serve``. Each browser tab starts its own app process with the
command given, under Textual's web driver."""

from __future__ import annotations

import sys

from aiohttp import web
from textual_serve.server import Server


class ServedApp(Server):
    """textual-serve's Server, announcing itself in one line instead of a banner."""

    async def on_startup(self, app: web.Application) -> None:
        sys.stderr.write(f"turtletui serve: open {self.public_url} in a web browser (Ctrl-C stops the server)\n")
        sys.stderr.flush()
