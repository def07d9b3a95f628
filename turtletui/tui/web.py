"""The app served to web browsers: textual-serve's server, started by
``turtletui serve``. Each browser tab starts its own app process with the
command given, under Textual's web driver."""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

import aiohttp_jinja2
import jinja2
from aiohttp import web
from textual_serve.server import Server

_GOOGLE_FONT = re.compile(r'<link\s+rel="stylesheet"\s+href="https://fonts\.googleapis\.com/[^"]*"\s*/>')
_BUNDLED_FONT = """<style>
      @font-face {
        font-family: "Roboto Mono";
        font-style: normal;
        font-weight: 100 700;
        src: url("{{ config.static.url }}fonts/RobotoMono-VariableFont_wght.ttf") format("truetype");
      }
      @font-face {
        font-family: "Roboto Mono";
        font-style: italic;
        font-weight: 100 700;
        src: url("{{ config.static.url }}fonts/RobotoMono-Italic-VariableFont_wght.ttf") format("truetype");
      }
    </style>"""
"""textual-serve ships Roboto Mono in its static files, yet its page asks
Google's font service for it: every student's browser would tell Google
each time it opened the app (a school's network may also block it)."""


class _BundledFonts(jinja2.BaseLoader):
    """textual-serve's templates, with its fonts served from its own static files."""

    def __init__(self, folder: Path) -> None:
        self._files = jinja2.FileSystemLoader(folder)

    def get_source(self, environment: jinja2.Environment, template: str) -> tuple[str, str | None, Any]:
        source, filename, uptodate = self._files.get_source(environment, template)
        return _GOOGLE_FONT.sub(lambda _: _BUNDLED_FONT, source), filename, uptodate


class ServedApp(Server):
    """textual-serve's Server, announcing itself in one line instead of a banner,
    its page asking no other site for anything."""

    async def _make_app(self) -> web.Application:
        app = await super()._make_app()
        aiohttp_jinja2.setup(app, loader=_BundledFonts(self.templates_path))
        return app

    async def on_startup(self, app: web.Application) -> None:
        sys.stderr.write(f"turtletui serve: open {self.public_url} in a web browser (Ctrl-C stops the server)\n")
        sys.stderr.flush()
