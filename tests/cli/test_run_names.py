"""`turtletui run NAME` runs a controller a plugin registered, by name."""

import os
import subprocess
import sys
from pathlib import Path

import turtletui

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "plugins" / "example_plugin"


def turtletui_cli(*args: str, pythonpath: tuple[Path, ...] = ()) -> subprocess.CompletedProcess:
    paths = [str(Path(turtletui.__file__).resolve().parents[1]), *map(str, pythonpath)]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(paths))
    return subprocess.run(
        [sys.executable, "-m", "turtletui", *args],
        capture_output=True,
        text=True,
        env=env,
        stdin=subprocess.DEVNULL,
        timeout=60,
    )


def test_a_reference_node_runs_by_its_registered_name():
    done = turtletui_cli("run", "part4_draw_circle", "--headless", "--duration", "2")
    assert done.returncode == 0, done.stderr
    assert "[draw_circle]: Draw circle node has been started" in done.stderr
    assert done.stdout.splitlines()[-1].startswith("sim time 2.000 s")


def test_an_unknown_name_lists_the_registered_controllers():
    done = turtletui_cli("run", "part9_teleport", "--headless")
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1
    assert "part9_teleport: no such file" in done.stderr
    assert "part6_wall_avoider" in done.stderr


def test_a_plugin_node_factory_runs_by_name():
    # As if the example package were installed: importable, registered by --plugin.
    done = turtletui_cli(
        "run",
        "example_square",
        "--plugin",
        str(EXAMPLE / "turtletui_example_plugin" / "__init__.py"),
        "--headless",
        "--duration",
        "8",
        pythonpath=(EXAMPLE,),
    )
    assert done.returncode == 0, done.stderr
    assert "[square_driver]: Side 1 done, turning left" in done.stderr
