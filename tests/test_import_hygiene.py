"""The core never imports the front ends (STYLE.md, "Layout that shows the
architecture"): each check runs in a fresh interpreter and inspects sys.modules."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import turtletui

PACKAGE_ROOT = Path(turtletui.__file__).resolve().parents[1]
PART6 = Path(__file__).resolve().parents[1] / "plugins" / "reference" / "turtle_controller.py"

CORE = [
    "turtletui.sim", "turtletui.graph", "turtletui.runtime", "turtletui.interfaces", "turtletui.compat",
    "turtletui.ros2cli", "turtletui.testing",
]
FRONT_ENDS = ["textual", "typer"]


def imported_after(code: str, watch: list[str]) -> list[str]:
    """Run ``code`` in a new interpreter; which of ``watch`` are in sys.modules then."""
    script = textwrap.dedent(code) + textwrap.dedent(f"""
        import json, sys
        print(json.dumps(sorted(m for m in {watch!r} if m in sys.modules)))
    """)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(PACKAGE_ROOT), env.get("PYTHONPATH")) if p)
    proc = subprocess.run(
        [sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=60,
        stdin=subprocess.DEVNULL,
    )
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout.splitlines()[-1])


def test_the_checker_sees_an_import():
    """The subprocess check can fail: importing textual is seen."""
    assert imported_after("import textual", ["textual"]) == ["textual"]


def test_cli_help_and_headless_runs_never_import_textual():
    code = f"""
        import contextlib, io, sys
        from pathlib import Path

        import turtletui.cli
        from turtletui.api import run

        sys.argv = ["turtletui", "--help"]
        with contextlib.redirect_stdout(io.StringIO()) as out:
            try:
                turtletui.cli.main()
            except SystemExit as exc:
                assert exc.code in (None, 0), exc.code
        assert "run" in out.getvalue()

        part6 = Path({str(PART6)!r})
        for sandbox in (None, False):
            result = run([part6], duration=2.0, sandbox=sandbox)
            assert result.ok and result.sim_time == 2.0, result.crashes
    """
    assert imported_after(code, ["textual"]) == []


def test_grading_a_class_never_imports_textual(tmp_path):
    student = tmp_path / "class" / "ann"
    student.mkdir(parents=True)
    (student / "controller.py").write_text(PART6.read_text())
    lesson = tmp_path / "one.md"
    lesson.write_text(
        '+++\nid = "one"\ntitle = "One"\n[[scenarios]]\nname = "s"\nduration = 1.0\n'
        '[[checks]]\nname = "no_crash"\n+++\n# One\n'
    )
    code = f"""
        import contextlib, io, sys
        import turtletui.cli

        sys.argv = ["turtletui", "grade", {str(student.parent)!r}, "--lesson", {str(lesson)!r},
                    "--results", {str(tmp_path / "results")!r}, "--same-user", "--quiet"]
        with contextlib.redirect_stdout(io.StringIO()) as out:
            try:
                turtletui.cli.main()
            except SystemExit as exc:
                assert exc.code in (None, 0), exc.code
        assert "1/1" in out.getvalue(), out.getvalue()
    """
    assert imported_after(code, ["textual"]) == []


def test_headless_sim_never_imports_textual():
    code = """
        import contextlib, io, sys
        import turtletui.cli

        sys.argv = ["turtletui", "sim", "--headless", "--duration", "0.1", "--ros-args", "-p", "holonomic:=true"]
        with contextlib.redirect_stderr(io.StringIO()) as out:
            try:
                turtletui.cli.main()
            except SystemExit as exc:
                assert exc.code in (None, 0), exc.code
        assert "Starting turtlesim" in out.getvalue(), out.getvalue()
    """
    assert imported_after(code, ["textual"]) == []


@pytest.mark.parametrize("module", CORE)
def test_core_imports_no_front_end(module):
    assert imported_after(f"import {module}", FRONT_ENDS) == []


def test_check_controller_needs_no_pytest():
    """turtletui.testing is a library API; only its pytest_plugin module imports pytest."""
    assert imported_after("import turtletui.testing", ["pytest", "_pytest"]) == []


@pytest.mark.parametrize("module", ["turtletui.interfaces", "turtletui.runtime.child"])
def test_child_side_imports_no_numpy(module):
    """A sandboxed controller's process starts without numpy (start-up time)."""
    assert imported_after(f"import {module}", ["numpy"]) == []


def test_sandboxed_controller_process_has_no_numpy_or_front_ends(tmp_path):
    """What the child actually loaded, as the controller itself sees it."""
    node = tmp_path / "modules.py"
    node.write_text(textwrap.dedent("""
        import sys

        import rclpy
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("modules")
            heavy = sorted(m for m in ("numpy", "textual", "typer") if m in sys.modules)
            node.get_logger().info(f"heavy={heavy}")
            rclpy.spin_once(node, timeout_sec=0.1)
            rclpy.shutdown()
    """), encoding="utf-8")
    from turtletui.api import run
    from turtletui.runtime.sandbox import Limits

    result = run([node], duration=0.5, limits=Limits(lockstep=True))
    assert [r.msg for r in result.logs if r.node == "modules"] == ["heavy=[]"]
    # the fast path's child holds a copy of the simulator, which draws with numpy
    fast = run([node], duration=0.5, limits=Limits(lockstep=False))
    assert [r.msg for r in fast.logs if r.node == "modules"] == ["heavy=['numpy']"]
