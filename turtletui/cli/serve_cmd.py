"""``turtletui serve``: the app in a web browser, through textual-serve.

Each browser tab that opens the page starts its own app process
(``turtletui run FILE`` under Textual's web driver), with the editor pane
open on FILE: a student with only a browser edits, saves, and watches the
node reload.
"""

from __future__ import annotations

import sys
from pathlib import Path

import typer

from turtletui.cli.errors import fail

DEFAULT_LESSON = "part6-closed-loop"

SERVED_PIXELS = ("auto", "half", "braille")
"""``--pixels`` in a browser: xterm.js draws half blocks itself and shows no
Kitty or Sixel pictures; braille is drawn from the browser's fonts."""


def serve(
    file: Path = typer.Argument(
        None,
        metavar="FILE",
        help="The controller file to edit and run; written from the lesson's starter if it does not exist."
        " Default: LESSON.py in this folder (part6_closed_loop.py for the default lesson).",
    ),
    lesson: str = typer.Option(
        None, "--lesson", help="Lesson to open beside it: an id (see turtletui lessons) or a file."
        " Default without FILE: part6-closed-loop.",
    ),
    host: str = typer.Option("127.0.0.1", "--host", help="Address to listen on (127.0.0.1: this machine only)."),
    port: int = typer.Option(8000, "--port", help="Port to listen on."),
    public_url: str = typer.Option(
        None,
        "--public-url",
        help="The address browsers reach this server at, when it is not http://HOST:PORT"
        " (behind a proxy, e.g. https://hub.example.edu/user/ann/proxy/8000).",
    ),
    ascii_only: bool = typer.Option(False, "--ascii", help="Draw with plain ASCII and no colour."),
    pixels: str = typer.Option(
        "auto",
        "--pixels",
        help="How the arena is drawn in the browser: half (half blocks, drawn by the page itself), braille"
        " (finer trails where the browser's fonts have braille) or auto (half).",
    ),
    plugin: list[Path] = typer.Option(None, "--plugin", help="Load a plugin file or folder (repeatable)."),
    distro: str = typer.Option(
        None,
        "--distro",
        metavar="NAME",
        help="The ROS 2 the served nodes run as: humble, jazzy, kilted or lyrical (see turtletui run --help).",
    ),
) -> None:
    """Serve the app to a web browser: one app per tab, with an editor on FILE.

    The served app runs FILE, and whatever code is saved into it, as you:
    keep the default --host 127.0.0.1 unless a proxy in front checks who connects.
    """
    import shlex  # here, not at the top: turtletui --help stays quick

    if not 0 < port < 65536:
        fail(f"--port must be in 1..65535, got {port}")
    if distro is not None:
        from turtletui.compat.distro import check_distro

        try:
            distro = check_distro(distro)
        except ValueError as err:
            fail(f"--distro: {err}")
    if pixels not in SERVED_PIXELS:
        extra = " (a browser page has no terminal graphics)" if pixels == "graphics" else ""
        fail(f"--pixels: expected one of {', '.join(SERVED_PIXELS)}, got {pixels!r}{extra}")
    lesson_path, file = _lesson_and_file(lesson, file, plugin)
    command = [sys.executable, "-m", "turtletui", "run", str(file.resolve())]
    if lesson_path is not None:
        command += ["--lesson", str(lesson_path.resolve())]
    if ascii_only:
        command.append("--ascii")
    if distro is not None:
        command += ["--distro", distro]
    command += ["--pixels", pixels]
    for path in plugin or ():
        command += ["--plugin", str(path.resolve())]
    problem = _cannot_listen(host, port)
    if problem is not None:
        fail(f"cannot serve on {host}:{port}: {problem}")
    from turtletui.tui.web import ServedApp

    server = ServedApp(
        shlex.join(command), host=host, port=port, title=f"turtletui: {file.name}", public_url=public_url
    )
    if not _is_loopback(host):
        sys.stderr.write(
            f"turtletui serve: warning: listening on {host}: anyone who can reach it runs code on this"
            " machine as you; put an authenticating proxy in front (see README, 'In a browser')\n"
        )
    try:
        server.serve()
    except OSError as err:
        fail(f"cannot serve on {host}:{port}: {err.strerror or err}")


def _lesson_and_file(lesson: str | None, file: Path | None, plugins: list[Path] | None) -> tuple[Path | None, Path]:
    """The lesson file to open and the controller file to edit, written from
    the lesson's starter when it does not exist yet."""
    from turtletui.lessons.loader import LessonError, find_lesson

    if lesson is None and file is None:
        lesson = DEFAULT_LESSON
    found = None
    if lesson is not None:
        try:
            found = find_lesson(lesson, plugins=plugins or ())
        except LessonError as err:
            fail(f"--lesson: {err}")
    if file is None:
        file = Path(f"{found.id.replace('-', '_')}.py")
    if file.is_dir():
        fail(f"{file} is a folder; name the controller file to edit")
    if not file.exists():
        if found is None:
            fail(f"{file}: no such file; start from a lesson's starter: turtletui serve {file} --lesson ID")
        if found.starter_path is None:
            fail(f"{file}: no such file, and lesson {found.id!r} has no starter file to begin it with")
        from turtletui.lessons.starter import starter_for

        try:
            file.write_bytes(starter_for(found, file, found.id))
        except OSError as err:
            fail(f"cannot write {file}: {err.strerror or err}")
        sys.stderr.write(f"turtletui serve: wrote {file} (starter of lesson {found.id})\n")
    return (None if found is None else found.path), file


def _cannot_listen(host: str, port: int) -> str | None:
    """Why the server could not listen on host:port (unknown host, port in use), or None.

    Tried before the server starts, so that the error is one line and comes
    before the server announces its address.
    """
    import socket

    try:
        addresses = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    except socket.gaierror as err:
        return err.strerror or str(err)
    for family, kind, proto, _, address in addresses:
        with socket.socket(family, kind, proto) as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as aiohttp does
            try:
                probe.bind(address)
            except OSError as err:
                return err.strerror or str(err)
    return None


def _is_loopback(host: str) -> bool:
    import ipaddress

    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False
