"""--distro: a run has turtlesim's types where its ROS 2 has them, and only there."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.compat.distro import DISTROS, NEWEST_LTS, distro_of_imports, resolve_distro
from turtletui.lessons.loader import LessonError, load_lesson

HOSTS = [True, False]  # sandboxed, in-process


def controller(tmp_path: Path, package: str) -> Path:
    path = tmp_path / f"uses_{package}.py"
    path.write_text(textwrap.dedent(f"""\
        import rclpy
        from rclpy.node import Node
        from {package}.msg import Pose
        from {package}.srv import Spawn


        def main():
            rclpy.init()
            node = Node("reader")
            node.get_logger().info(f"{{Pose.__name__}} and {{Spawn.__name__}} from {package}")
            rclpy.shutdown()
    """))
    return path


def test_the_newest_lts_is_the_default(monkeypatch):
    monkeypatch.delenv("TURTLETUI_DISTRO", raising=False)
    assert NEWEST_LTS == "lyrical" and DISTROS["lyrical"].lts and DISTROS["lyrical"].year == 2026
    assert resolve_distro() == "lyrical"
    assert resolve_distro(None, "jazzy") == "jazzy"  # a lesson's


def test_the_command_line_then_the_environment_then_the_lesson(monkeypatch):
    monkeypatch.setenv("TURTLETUI_DISTRO", "Kilted")
    assert resolve_distro(None, "jazzy") == "kilted"
    assert resolve_distro("humble", "jazzy") == "humble"
    with pytest.raises(ValueError, match=r"unknown ROS 2 distro 'rolling': use one of humble, jazzy, kilted, lyrical"):
        resolve_distro("rolling")
    monkeypatch.setenv("TURTLETUI_DISTRO", "iron")
    with pytest.raises(ValueError, match=r"^\$TURTLETUI_DISTRO: unknown ROS 2 distro 'iron'"):
        resolve_distro()


@pytest.mark.parametrize("sandbox", HOSTS, ids=["sandboxed", "in-process"])
@pytest.mark.parametrize(
    ("distro", "present", "missing", "hint"),
    [
        ("humble", "turtlesim", "turtlesim_msgs", "in 'turtlesim' up to Jazzy; this run is --distro humble"),
        ("jazzy", "turtlesim", "turtlesim_msgs", "in 'turtlesim' up to Jazzy; this run is --distro jazzy"),
        ("kilted", "turtlesim_msgs", "turtlesim", "in 'turtlesim_msgs' from Kilted on; this run is --distro kilted"),
        ("lyrical", "turtlesim_msgs", "turtlesim", "in 'turtlesim_msgs' from Kilted on; this run is --distro lyrical"),
    ],
)
def test_one_package_imports_and_the_other_says_why_not(tmp_path, sandbox, distro, present, missing, hint):
    good = run([controller(tmp_path, present)], duration=0.5, sandbox=sandbox, distro=distro)
    assert good.ok, good.crashes
    assert f"Pose and Spawn from {present}" in [r.msg for r in good.logs]
    bad = run([controller(tmp_path, missing)], duration=0.5, sandbox=sandbox, distro=distro)
    (crash,) = bad.crashes
    assert crash.message.startswith(f"ModuleNotFoundError: No module named '{missing}' (turtlesim's types are {hint}")
    assert "\n" not in crash.message
    # the line of the student's file that imported it
    assert any(f"from {missing}.msg import Pose" in str(frame) for frame in crash.frames)


def test_a_lesson_names_its_distro_and_a_wrong_one_is_refused(tmp_path):
    from turtletui.lessons.loader import discover_lessons

    course = {lesson.id: lesson.distro for lesson in discover_lessons()}
    assert course["part6-closed-loop"] == "jazzy"
    lesson = tmp_path / "l.md"
    lesson.write_text('+++\nid = "x"\ntitle = "X"\ndistro = "foxy"\n+++\nbody\n')
    with pytest.raises(LessonError, match=r"l\.md.*field 'distro': unknown ROS 2 distro 'foxy'"):
        load_lesson(lesson)


def test_the_command_line_option(tmp_path):
    path = controller(tmp_path, "turtlesim_msgs")

    def cli(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "turtletui", "run", *args], cwd=tmp_path,
                              capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)

    ok = cli(str(path), "--headless", "--duration", "0.5", "--distro", "kilted")
    assert ok.returncode == 0, ok.stderr
    assert "[reader]: Pose and Spawn from turtlesim_msgs" in ok.stderr
    wrong = cli(str(path), "--headless", "--duration", "0.5", "--distro", "jazzy")
    assert wrong.returncode == 1
    assert "No module named 'turtlesim_msgs'" in wrong.stderr
    bad = cli(str(path), "--headless", "--distro", "dashing")
    assert bad.returncode == 2
    assert bad.stderr.strip() == (
        "turtletui: error: --distro: unknown ROS 2 distro 'dashing': use one of humble, jazzy, kilted, lyrical")


def test_without_a_choice_files_that_import_turtlesim_run_as_jazzy_and_are_told_why(tmp_path, monkeypatch):
    monkeypatch.delenv("TURTLETUI_DISTRO", raising=False)
    course = controller(tmp_path, "turtlesim")
    newer = controller(tmp_path, "turtlesim_msgs")
    distro, note = distro_of_imports([course])
    assert distro == "jazzy"
    assert note.startswith("uses_turtlesim.py imports turtlesim's types from turtlesim: running as ROS 2 Jazzy")
    assert distro_of_imports([newer]) is None and distro_of_imports([course, newer]) is None
    for sandbox in HOSTS:
        result = run([course], duration=0.5, sandbox=sandbox)
        assert result.ok, result.crashes
        assert ("turtletui", note) in [(r.node, r.msg) for r in result.logs]
    # an explicit choice (or the environment) is never second-guessed
    assert not run([course], duration=0.5, distro="kilted").ok
    monkeypatch.setenv("TURTLETUI_DISTRO", "lyrical")
    assert distro_of_imports([course]) is None and not run([course], duration=0.5).ok


def test_headless_runs_take_the_lessons_distro_and_refuse_a_bad_lesson_or_pixels(tmp_path, monkeypatch):
    monkeypatch.delenv("TURTLETUI_DISTRO", raising=False)
    path = controller(tmp_path, "turtlesim")

    def cli(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "turtletui", "run", str(path), "--headless", "-d", "0.5", *args],
                              cwd=tmp_path, capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)

    lesson = cli("--lesson", "part6-closed-loop")
    assert lesson.returncode == 0, lesson.stderr
    assert "Pose and Spawn from turtlesim" in lesson.stderr and "running as ROS 2 Jazzy" not in lesson.stderr
    for args, message in [
        (["--lesson", "nosuch"], "turtletui: error: --lesson: no lesson 'nosuch'"),
        (["--pixels", "nonsense"], "turtletui: error: --pixels: expected one of auto, half, braille, graphics"),
    ]:
        bad = cli(*args)
        assert bad.returncode == 2 and bad.stderr.startswith(message), bad.stderr
        assert len(bad.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("sandbox", HOSTS, ids=["sandboxed", "in-process"])
@pytest.mark.parametrize(
    ("line", "says"),
    [
        ("from turtlesim.msg import Pos", "ImportError: cannot import name 'Pos' from 'turtlesim.msg'. Did you mean: 'Pose'?"),
        ("from geometry_msgs.msg import twist", "from 'geometry_msgs.msg'. Did you mean: 'Twist'?"),
        ("from turtlesim.msgs import Pose", "ModuleNotFoundError: No module named 'turtlesim.msgs'. Did you mean: 'turtlesim.msg'?"),
    ],
)
def test_a_misspelt_import_says_which_was_meant_and_not_where_turtletui_keeps_ros(tmp_path, sandbox, line, says):
    # as Python 3.12 says it (ROS 2 Jazzy's Ubuntu), whatever Python runs turtletui
    path = tmp_path / "typo.py"
    path.write_text(f"import rclpy\n{line}\n")
    (crash,) = run([path], duration=0.5, sandbox=sandbox, distro="jazzy").crashes
    assert says in crash.message
    assert "turtletui" not in crash.message and "\n" not in crash.message
