"""The app in a real browser: ``turtletui serve`` on a free port, Debian's
chromium driven by playwright, and the terminal's text read back by replaying
what the page's xterm.js receives into a terminal emulator (pyte).

Used by the browser tests and by bench/bench_serve.py. Playwright's own
browser download is not used: Debian's chromium at CHROMIUM is, installed
on first use where it can be (as root with apt-get: a fresh CI machine),
else named in the failure (``apt-get install -y chromium``).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import pyte

import turtletui

REPO = Path(turtletui.__file__).resolve().parents[1]
CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    # As root in a container there is no user namespace for chromium's sandbox.
    "--no-sandbox",
    "--disable-gpu",
    # This machine's network is closed: no update checks, sync or QUIC probes.
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-quic",
    "--no-first-run",
]
TURTLESIM_BLUE = (69, 86, 255)
"""turtlesim's background: the arena's colour on the page."""
PEN = (179, 184, 255)
"""turtlesim's default pen: the trail's colour."""


def require_chromium() -> Path:
    """The chromium to drive, installed first if missing and this is root with
    apt-get; a clear error otherwise (never a skip)."""
    if not CHROMIUM.exists() and os.geteuid() == 0 and shutil.which("apt-get"):
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        for command in (["apt-get", "update", "-q"], ["apt-get", "install", "-y", "-q", "chromium"]):
            subprocess.run(command, env=env, capture_output=True, timeout=1800)
    if not CHROMIUM.exists():
        raise RuntimeError(
            f"the browser tests need Debian's chromium at {CHROMIUM}: apt-get install -y chromium"
            " (playwright's own browser download is not used)"
        )
    return CHROMIUM


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


@contextmanager
def served(*args: str, cwd: Path, timeout: float = 30.0, port: int | None = None) -> Iterator[str]:
    """Run ``turtletui serve ARGS --port P`` in ``cwd``; yields the page's URL
    once the server accepts connections, and stops the server after."""
    port = port or free_port()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [str(REPO), os.environ.get("PYTHONPATH")])))
    proc = subprocess.Popen(
        [sys.executable, "-m", "turtletui", "serve", *args, "--port", str(port)],
        cwd=cwd,
        env=env,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        start_new_session=True,  # the server and every app process it starts end together
    )
    try:
        deadline = time.monotonic() + timeout
        while True:
            if proc.poll() is not None:
                raise RuntimeError(f"turtletui serve exited ({proc.returncode}): {proc.stdout.read().decode()}")
            try:
                socket.create_connection(("127.0.0.1", port), timeout=0.5).close()
                break
            except OSError:
                if time.monotonic() > deadline:
                    raise RuntimeError(f"turtletui serve did not listen on port {port} within {timeout:g} s") from None
                time.sleep(0.1)
        yield f"http://127.0.0.1:{port}/"
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGINT)  # as Ctrl-C: the server stops its apps
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
        proc.stdout.close()


@contextmanager
def chromium() -> Iterator[object]:
    """A headless chromium (playwright's Browser)."""
    from playwright.sync_api import sync_playwright

    executable = require_chromium()
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(executable), args=CHROMIUM_ARGS)
        try:
            yield browser
        finally:
            browser.close()


class BrowserTerminal:
    """What the page's terminal shows, as text: every byte the app sends over
    the page's WebSocket is replayed into a pyte screen of the size the page
    asked the app for."""

    def __init__(self, page) -> None:
        self.page = page
        self.screen: pyte.Screen | None = None
        self._stream: pyte.ByteStream | None = None
        self._pending: list[bytes] = []
        self.first_data: float | None = None
        """time.monotonic() when the app's first bytes arrived."""
        page.on("websocket", self._attach)

    def _attach(self, websocket) -> None:
        websocket.on("framesent", self._sent)
        websocket.on("framereceived", self._received)

    def _sent(self, payload: str | bytes) -> None:
        if isinstance(payload, str) and payload.startswith('["resize"'):
            size = json.loads(payload)[1]
            if self.screen is None:
                self.screen = pyte.Screen(size["width"], size["height"])
                self._stream = pyte.ByteStream(self.screen)
                for data in self._pending:
                    self._stream.feed(data)
                self._pending.clear()
            else:
                self.screen.resize(size["height"], size["width"])

    def _received(self, payload: str | bytes) -> None:
        if not isinstance(payload, bytes):
            return  # JSON meta messages (pong, ...), not terminal output
        if self.first_data is None:
            self.first_data = time.monotonic()
        if self._stream is None:
            self._pending.append(payload)
        else:
            self._stream.feed(payload)

    @property
    def lines(self) -> list[str]:
        return [] if self.screen is None else list(self.screen.display)

    @property
    def text(self) -> str:
        return "\n".join(self.lines)

    def wait_for(self, condition: Callable[[str], bool], what: str, timeout: float = 30.0) -> float:
        """Wait (pumping the browser's events) until ``condition(text)`` holds;
        returns time.monotonic() then. AssertionError with the screen if it never does."""
        deadline = time.monotonic() + timeout
        while True:
            if condition(self.text):
                return time.monotonic()
            if time.monotonic() > deadline:
                raise AssertionError(f"the page never showed {what} within {timeout:g} s; it shows:\n{self.text}")
            self.page.wait_for_timeout(50)


_SCALE = re.compile(r"(?m)^ *0 +1 +2 +3 +4 +5 +6 +7 +8 +9 +10 +11\b")


def shows_the_arena(text: str) -> bool:
    """The status line and the arena's metre scale (0 to 11 under the arena) are on the screen."""
    return " t = " in text and _SCALE.search(text) is not None


def count_pixels(png: bytes, colour: tuple[int, int, int], tolerance: int = 8) -> int:
    """Pixels of about ``colour`` in a PNG screenshot."""
    import io

    import numpy as np
    from PIL import Image

    pixels = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)
    close = np.abs(pixels - np.array(colour, dtype=np.int16)).max(axis=2) <= tolerance
    return int(close.sum())


@contextmanager
def prefix_proxy(prefix: str, target_port: int) -> Iterator[int]:
    """A reverse proxy on a free port that serves ``http://127.0.0.1:TARGET``
    under ``prefix`` (stripped before forwarding), WebSockets included: what
    JupyterHub's jupyter-server-proxy does for a student's server. Yields its port."""
    import asyncio
    import threading

    import aiohttp
    from aiohttp import web

    async def forward(request: web.Request) -> web.StreamResponse:
        path = request.path_qs[len(prefix.rstrip("/")):] or "/"
        url = f"http://127.0.0.1:{target_port}{path}"
        async with aiohttp.ClientSession() as session:
            if request.headers.get("Upgrade", "").lower() == "websocket":
                browser_side = web.WebSocketResponse()
                await browser_side.prepare(request)
                async with session.ws_connect(url) as server_side:

                    async def pipe(source, sink) -> None:
                        async for message in source:
                            if message.type == aiohttp.WSMsgType.TEXT:
                                await sink.send_str(message.data)
                            elif message.type == aiohttp.WSMsgType.BINARY:
                                await sink.send_bytes(message.data)
                            else:
                                break
                        await sink.close()

                    await asyncio.gather(pipe(browser_side, server_side), pipe(server_side, browser_side))
                return browser_side
            async with session.get(url) as upstream:
                return web.Response(body=await upstream.read(), status=upstream.status,
                                    content_type=upstream.content_type)

    port = free_port()
    loop = asyncio.new_event_loop()
    runner_ready = threading.Event()
    app = web.Application()
    app.router.add_route("GET", prefix.rstrip("/") + "/{tail:.*}", forward)
    runner = web.AppRunner(app)

    def serve() -> None:
        asyncio.set_event_loop(loop)
        loop.run_until_complete(runner.setup())
        loop.run_until_complete(web.TCPSite(runner, "127.0.0.1", port).start())
        runner_ready.set()
        loop.run_forever()

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    runner_ready.wait(10)
    try:
        yield port
    finally:
        asyncio.run_coroutine_threadsafe(runner.cleanup(), loop).result(10)
        loop.call_soon_threadsafe(loop.stop)
        thread.join(10)
