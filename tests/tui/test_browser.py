"""``turtletui serve`` in a real browser (Debian's chromium, driven by
playwright): the page starts the app, the arena is drawn, the editor saves
and the node reloads, keys drive, every tab has its own app, and small
windows and --ascii work. The screen's text is read from what the page's
terminal receives; colours from screenshots."""

from __future__ import annotations

import re
import textwrap
import time
from pathlib import Path

import pytest
from support.browser import (
    PEN,
    TURTLESIM_BLUE,
    BrowserTerminal,
    chromium,
    count_pixels,
    free_port,
    prefix_proxy,
    served,
    shows_the_arena,
)

# A node that drives at SPEED on every pose: 0.0 until the student edits line 1.
DRIVER = textwrap.dedent("""
    SPEED = 0.0
    import rclpy
    from geometry_msgs.msg import Twist
    from rclpy.node import Node
    from turtlesim.msg import Pose


    def main():
        rclpy.init()
        node = Node("driver")
        publisher = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)

        def on_pose(pose):
            cmd = Twist()
            cmd.linear.x = SPEED
            cmd.angular.z = SPEED / 2
            publisher.publish(cmd)

        node.create_subscription(Pose, "/turtle1/pose", on_pose, 10)
        rclpy.spin(node)
""").lstrip()

IDLE = textwrap.dedent("""
    import rclpy
    from rclpy.node import Node


    def main():
        rclpy.init()
        rclpy.spin(Node("idle"))
""").lstrip()


@pytest.fixture(scope="module")
def browser():
    with chromium() as launched:
        yield launched


def open_app(browser, url: str, width: int = 1280, height: int = 800):
    """A new page on the served app; (page, its terminal) once the arena is shown."""
    page = browser.new_page(viewport={"width": width, "height": height})
    terminal = BrowserTerminal(page)
    page.goto(url)
    terminal.wait_for(shows_the_arena, "the arena")
    # The page's terminal takes the keys (xterm.js reads them from this
    # textarea, as after a click): the app hears it has the focus again.
    page.evaluate("document.activeElement && document.activeElement.blur()")
    page.focus(".xterm-helper-textarea")
    # The editor opens with the app and takes the keys, as its first line says.
    terminal.wait_for(lambda text: "Esc: back to the arena" in text, "the editor taking the keys")
    return page, terminal


def leave_the_editor(page, terminal: BrowserTerminal) -> None:
    """Esc, and wait until it took effect: a terminal tells a lone Esc from the
    start of an escape sequence only by the pause after it."""
    page.keyboard.press("Escape")
    terminal.wait_for(lambda text: "E: edit here" in text, "the keys back with the arena")


def wait_for_pixels(page, colour, minimum: int, what: str, timeout: float = 20.0) -> int:
    deadline = time.monotonic() + timeout
    while True:
        count = count_pixels(page.screenshot(), colour)
        if count >= minimum:
            return count
        assert time.monotonic() < deadline, f"{what}: {count} pixels of {colour} after {timeout:g} s"
        page.wait_for_timeout(250)


def status_time(terminal: BrowserTerminal) -> float:
    status = terminal.lines[0]
    return float(status.split("t =")[1].split()[0])


def test_a_browser_user_edits_saves_and_sees_the_node_reload(browser, tmp_path: Path) -> None:
    (tmp_path / "driver.py").write_text(DRIVER, encoding="utf-8")
    with served("driver.py", "--lesson", "part6-closed-loop", cwd=tmp_path) as url:
        page, terminal = open_app(browser, url)
        # The editor is open beside the arena (a browser user has no other editor).
        terminal.wait_for(lambda text: "SPEED = 0.0" in text and "driver.py" in text, "the editor on driver.py")
        shot = page.screenshot()
        width, height = 1280, 800
        assert count_pixels(shot, TURTLESIM_BLUE) > 0.15 * width * height  # the arena, in turtlesim's blue
        assert count_pixels(shot, PEN) == 0  # SPEED 0.0: no trail yet
        # Type the change into the editor and save it with ctrl+s.
        page.keyboard.press("End")
        for _ in range(3):
            page.keyboard.press("Backspace")
        page.keyboard.type("1.5")
        terminal.wait_for(lambda text: "SPEED = 1.5" in text and "(modified)" in text, "the edit")
        page.keyboard.press("Control+s")
        # (The editor's first line wraps in a narrow pane: look for its first words.)
        terminal.wait_for(lambda text: re.search(r"saved \d\d:\d\d:\d\d: the", text), "the save")
        assert (tmp_path / "driver.py").read_text(encoding="utf-8") == DRIVER.replace("0.0", "1.5", 1)
        # The node reloaded with the new speed: the turtle draws its trail.
        wait_for_pixels(page, PEN, 30, "the trail of the reloaded node")
        # A syntax error is reported in the editor and the running node kept.
        page.keyboard.press("End")
        page.keyboard.type(" +")
        page.keyboard.press("Control+s")
        terminal.wait_for(lambda text: re.search(r"saved \d\d:\d\d:\d\d, but ", text) and "SyntaxError" in text,
                          "the syntax error")


def test_keys_drive_the_turtle_and_every_tab_has_its_own_app(browser, tmp_path: Path) -> None:
    (tmp_path / "idle.py").write_text(IDLE, encoding="utf-8")
    with served("idle.py", cwd=tmp_path) as url:
        first, first_terminal = open_app(browser, url)
        leave_the_editor(first, first_terminal)  # from the editor back to the arena: keys drive
        for _ in range(4):
            first.keyboard.press("ArrowUp")  # turtle_teleop_key: linear.x 2.0
            first.wait_for_timeout(300)
        wait_for_pixels(first, PEN, 30, "the trail driven with the arrow keys")
        first_t = status_time(first_terminal)
        second, second_terminal = open_app(browser, url)
        # Its own app: started from zero, with nothing driven yet.
        assert status_time(second_terminal) < first_t
        assert count_pixels(second.screenshot(), PEN) == 0
        leave_the_editor(second, second_terminal)
        second.keyboard.press(" ")  # pausing this tab's app leaves the other running
        second_terminal.wait_for(lambda text: "paused" in text.splitlines()[0], "the pause")
        before = status_time(first_terminal)
        first.wait_for_timeout(500)
        assert status_time(first_terminal) > before


def test_small_windows_and_ascii_in_the_browser(browser, tmp_path: Path) -> None:
    (tmp_path / "idle.py").write_text(IDLE, encoding="utf-8")
    with served("idle.py", "--ascii", cwd=tmp_path) as url:
        # About 80x24 cells: everything still there, and no colour in the arena.
        page, terminal = open_app(browser, url, width=740, height=450)
        assert terminal.screen.columns <= 84 and terminal.screen.lines <= 25
        assert count_pixels(page.screenshot(), TURTLESIM_BLUE) == 0
        arena = [line[: terminal.screen.columns // 2] for line in terminal.lines[1:-1]]
        assert all(line.isascii() for line in arena), "\n".join(arena)
        # Smaller than the arena can be drawn, then back: the app follows the window.
        page.set_viewport_size({"width": 300, "height": 180})
        terminal.wait_for(lambda text: not shows_the_arena(text) and " t = " in text, "the small window")
        page.set_viewport_size({"width": 1280, "height": 800})
        terminal.wait_for(shows_the_arena, "the arena again")
        assert terminal.screen.columns > 120


def test_behind_a_proxy_that_serves_it_under_a_path(browser, tmp_path: Path) -> None:
    """The JupyterHub recipe: a proxy serves the app under /user/ann/turtletui/
    (jupyter-server-proxy's shape), and --public-url names that address."""
    (tmp_path / "idle.py").write_text(IDLE, encoding="utf-8")
    port = free_port()
    with prefix_proxy("/user/ann/turtletui/", port) as proxy_port:
        public = f"http://127.0.0.1:{proxy_port}/user/ann/turtletui"
        with served("idle.py", "--public-url", public, cwd=tmp_path, port=port):
            page, terminal = open_app(browser, public + "/")
            assert "idle.py" in terminal.text


def braille(text: str) -> bool:
    return any("\u2801" <= ch <= "\u28ff" for ch in text)


def test_pixels_in_the_browser_half_blocks_unless_braille_is_asked(browser, tmp_path: Path, monkeypatch) -> None:
    """Served from kitty (whose TERM would mean braille in a terminal), the page
    gets half blocks, which xterm.js draws itself; --pixels braille is passed on."""
    monkeypatch.setenv("TERM", "xterm-kitty")
    monkeypatch.setenv("KITTY_WINDOW_ID", "1")
    (tmp_path / "idle.py").write_text(IDLE, encoding="utf-8")
    for option, finer in (((), False), (("--pixels", "braille"), True)):
        with served("idle.py", *option, cwd=tmp_path) as url:
            page, terminal = open_app(browser, url)
            leave_the_editor(page, terminal)
            for _ in range(3):
                page.keyboard.press("ArrowUp")  # a trail to draw
                page.wait_for_timeout(300)
            if finer:
                terminal.wait_for(braille, "braille dots")
            else:
                wait_for_pixels(page, PEN, 30, "the trail")
                assert not braille(terminal.text)
