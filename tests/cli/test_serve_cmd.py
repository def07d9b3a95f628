"""``turtletui serve`` without a browser: what it serves, the file it edits,
one-line errors; and the app starting under textual-serve's web driver (pipes,
no terminal), which is what every browser tab runs."""

from __future__ import annotations

import os
import re
import socket
import subprocess
import sys
import urllib.request
from pathlib import Path

import pytest
from support.browser import served
from support.web_driver import run_app_and_quit

import turtletui
from turtletui.cli.serve_cmd import _is_loopback
from turtletui.plugins.bundled import lessons_dir

REPO = Path(turtletui.__file__).resolve().parents[1]


def serve_cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "turtletui", "serve", *args],
        cwd=cwd,
        env=dict(os.environ, PYTHONPATH=str(REPO)),
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=60,
    )


def one_line_error(proc: subprocess.CompletedProcess[str]) -> str:
    assert proc.returncode == 2, (proc.returncode, proc.stdout, proc.stderr)
    assert "Traceback" not in proc.stderr + proc.stdout
    [line] = proc.stderr.splitlines()
    assert line.startswith("turtletui: error: ")
    return line


def page(url: str) -> str:
    with urllib.request.urlopen(url, timeout=10) as response:
        return response.read().decode()


def test_a_missing_file_is_written_from_the_lessons_starter_and_served(tmp_path: Path) -> None:
    with served("mine.py", "--lesson", "part7-pen-service", cwd=tmp_path) as url:
        html = page(url)
    written = (tmp_path / "mine.py").read_text()
    assert written == (lessons_dir() / "part7_starter.py").read_text().replace(
        "turtletui run part7_starter.py", "turtletui run mine.py --lesson part7-pen-service"
    ).replace("part7_starter.py", "mine.py")
    assert 'data-session-websocket-url="ws://127.0.0.1:' in html and "turtletui: mine.py" in html


def test_without_a_file_the_part6_lesson_file_is_served_and_kept(tmp_path: Path) -> None:
    work = tmp_path / "part6_closed_loop.py"
    with served(cwd=tmp_path) as url:
        page(url)
    assert "Run it with:  turtletui run part6_closed_loop.py --lesson part6-closed-loop\n" in work.read_text()
    work.write_text("# my work\n")
    with served(cwd=tmp_path) as url:
        page(url)
    assert work.read_text() == "# my work\n"  # an existing file is never overwritten


def test_behind_a_proxy_the_page_connects_to_the_public_url(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_text("")
    with served("a.py", "--public-url", "https://hub.example.edu/user/ann/proxy/8000", cwd=tmp_path) as url:
        html = page(url)
    assert 'data-session-websocket-url="wss://hub.example.edu/user/ann/proxy/8000/ws"' in html


def test_the_page_asks_no_other_site_for_anything(tmp_path: Path) -> None:
    # textual-serve's own page fetched its font from Google's font service:
    # every student's browser told Google each time it opened the app
    (tmp_path / "a.py").write_text("")
    with served("a.py", cwd=tmp_path) as url:
        html = page(url)
        fetched = re.findall(r'(?:href|src)=["\']([^"\']+)', html) + re.findall(r'url\(["\']?([^"\')]+)', html)
        font = next(link for link in fetched if link.endswith("RobotoMono-VariableFont_wght.ttf"))
        with urllib.request.urlopen(font, timeout=10) as response:
            assert response.status == 200 and len(response.read()) > 10_000
    assert "googleapis" not in html
    assert fetched and all(link.startswith(url) for link in fetched), fetched


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["a.py", "--port", "0"], "--port must be in 1..65535, got 0"),
        (["a.py", "--port", "70000"], "--port must be in 1..65535"),
        (["--lesson", "no-such-lesson"], "--lesson: no lesson 'no-such-lesson'"),
        (["missing.py"], "missing.py: no such file; start from a lesson's starter"),
        (["folder"], "folder is a folder"),
        (["a.py", "--host", "no.such.host.invalid"], "cannot serve on no.such.host.invalid:"),
        (["a.py", "--pixels", "graphics"], "--pixels: expected one of auto, half, braille, got 'graphics'"
         " (a browser page has no terminal graphics)"),
        (["a.py", "--pixels", "octant"], "--pixels: expected one of auto, half, braille, got 'octant'"),
    ],
)
def test_bad_input_is_a_one_line_error(tmp_path: Path, args: list[str], expected: str) -> None:
    (tmp_path / "a.py").write_text("")
    (tmp_path / "folder").mkdir()
    line = one_line_error(serve_cli(*args, cwd=tmp_path))
    assert expected in line
    assert not (tmp_path / "missing.py").exists()


def test_a_port_in_use_is_a_one_line_error(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_text("")
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        line = one_line_error(serve_cli("a.py", "--port", str(port), cwd=tmp_path))
    assert line == f"turtletui: error: cannot serve on 127.0.0.1:{port}: Address already in use"


def test_only_loopback_addresses_count_as_this_machine_only() -> None:
    assert _is_loopback("127.0.0.1") and _is_loopback("localhost") and _is_loopback("::1")
    assert not _is_loopback("0.0.0.0") and not _is_loopback("192.0.2.7") and not _is_loopback("example.org")


@pytest.mark.parametrize("command", [["run", "node.py"], ["sim"]], ids=["run", "sim"])
def test_the_app_starts_under_the_web_driver_without_a_terminal(tmp_path: Path, command: list[str]) -> None:
    """What textual-serve does for each tab: pipes, TEXTUAL_DRIVER, a quit packet at the end."""
    (tmp_path / "node.py").write_text("import rclpy\n\n\ndef main():\n    rclpy.init()\n")
    run_app_and_quit(command, tmp_path)
