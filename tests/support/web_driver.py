"""The app as textual-serve starts it for each browser tab: pipes instead of a
terminal, ``TEXTUAL_DRIVER`` set to Textual's web driver, a quit packet at the
end. Lets tests run ``turtletui run`` and ``turtletui sim`` (the app, not
headless) end to end without a terminal or a browser."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import turtletui

REPO = Path(turtletui.__file__).resolve().parents[1]
WEB_DRIVER = "textual.drivers.web_driver:WebDriver"


def packet(kind: bytes, payload: bytes) -> bytes:
    """A packet of textual-serve's protocol on the app's stdin."""
    return kind + len(payload).to_bytes(4, "big") + payload


def run_app_and_quit(args: list[str], cwd: Path, deadline: float = 30.0) -> None:
    """``python -m turtletui ARGS`` under the web driver: wait until the app
    draws its status line, then quit it; it must end cleanly (exit 0)."""
    env = dict(os.environ, PYTHONPATH=str(REPO), TEXTUAL_DRIVER=WEB_DRIVER, COLUMNS="100", ROWS="30")
    proc = subprocess.Popen(
        [sys.executable, "-m", "turtletui", *args],
        cwd=cwd, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )
    try:
        assert proc.stdout.readline() == b"__GANGLION__\n", proc.stderr.read().decode()
        screen = b""
        give_up = time.monotonic() + deadline
        while b" t = " not in screen:  # the status line: the app draws
            assert time.monotonic() < give_up, screen[-500:]
            kind, size = proc.stdout.read(1), int.from_bytes(proc.stdout.read(4), "big")
            payload = proc.stdout.read(size)
            if kind == b"D":
                screen += payload
        proc.stdin.write(packet(b"M", json.dumps({"type": "quit"}).encode()))
        proc.stdin.flush()
        assert proc.wait(timeout=20) == 0
        assert b"Traceback" not in proc.stderr.read()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
