"""The plugin layer: hook specs, the manager, the built-in and example plugins."""

from __future__ import annotations

import importlib
import inspect
import json
import sys
import textwrap
from pathlib import Path

import pytest

from turtletui.plugins import PROJECT_NAME, hookimpl, hookspecs
from turtletui.plugins import builtin as builtin_plugin
from turtletui.plugins.bundled import reference_dir
from turtletui.plugins.manager import (
    BUILTIN_PLUGINS,
    DISABLE_AUTOLOAD_ENV,
    KINDS,
    collect_checks,
    collect_controllers,
    collect_lesson_entries,
    collect_lessons,
    collect_worlds,
    describe_plugins,
    get_plugin_manager,
    plugin_infos,
)

REPO = Path(__file__).resolve().parents[2]
EXAMPLE_PLUGIN = REPO / "plugins" / "example_plugin"
HOOK_NAMES = sorted(name for name in dir(hookspecs) if name.startswith(f"{PROJECT_NAME}_"))

REFERENCE_CONTROLLERS = {
    "part3_first_node": "my_first_node.py",
    "part4_draw_circle": "draw_circle.py",
    "part5_pose_subscriber": "pose_subscriber.py",
    "part6_wall_avoider": "turtle_controller.py",
    "part7_pen_color": "turtle_controller_pen.py",
    "go_to_goal": "go_to_goal.py",
    "rotate_action_client": "rotate_action_client.py",
    "parameters_wall_avoider": "parameters_wall_avoider.py",
    "turtle_chaser": "turtle_chaser.py",
    "lidar_obstacle_avoider": "lidar_obstacle_avoider.py",
    "tf2_buffer_server": "tf2_buffer_server.py",
}


@pytest.fixture(autouse=True)
def autoload_not_disabled(monkeypatch):
    """Each test decides about installed plugins itself."""
    monkeypatch.delenv(DISABLE_AUTOLOAD_ENV, raising=False)


@pytest.fixture
def pm():
    """A manager with only the built-in plugins (installed ones would make tests depend on the machine)."""
    return get_plugin_manager(load_entrypoints=False)


@pytest.fixture
def temporary_plugin(pm):
    """Register plugins on ``pm`` for one test; they are unregistered afterwards, whatever happens."""
    registered = []

    def register(plugin, name=None):
        pm.register(plugin, name=name)
        registered.append(plugin)
        return plugin

    try:
        yield register
    finally:
        for plugin in registered:
            if pm.is_registered(plugin):
                pm.unregister(plugin)


@pytest.fixture
def forget_modules():
    """Drop modules a test imported (fake plugins) from sys.modules afterwards."""
    before = set(sys.modules)
    try:
        yield
    finally:
        for name in set(sys.modules) - before:
            if (
                "turtletui_plugin" in name
                or "fake_turtletui" in name
                or "turtletui_example" in name
            ):
                del sys.modules[name]


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def fake_distribution(root: Path, dist: str, version: str, entry_points: dict[str, str]) -> None:
    """An installed distribution as importlib.metadata sees it: a .dist-info folder on sys.path."""
    info = root / f"{dist.replace('-', '_')}-{version}.dist-info"
    write(info / "METADATA", f"Metadata-Version: 2.1\nName: {dist}\nVersion: {version}\n")
    lines = "".join(f"{name} = {target}\n" for name, target in entry_points.items())
    write(info / "entry_points.txt", f"[{PROJECT_NAME}]\n{lines}")


PLUGIN_FILE = """
    from pathlib import Path

    from turtletui.plugins import hookimpl


    @hookimpl
    def turtletui_register_controllers(register):
        register("{name}", Path(__file__), "a controller from a file")
"""


# -- built-in plugin ------------------------------------------------------------


def test_builtin_plugins_registered(pm):
    assert "turtletui.plugins.builtin" in BUILTIN_PLUGINS
    for name in BUILTIN_PLUGINS:
        assert pm.source_of(name) == "builtin"
    assert pm.get_plugin("turtletui.plugins.builtin") is builtin_plugin
    assert pm.source_of("turtletui.plugins.builtin") == "builtin"


def test_builtin_reference_controllers(pm):
    controllers = collect_controllers(pm)
    assert set(controllers) >= set(REFERENCE_CONTROLLERS)
    for name, filename in REFERENCE_CONTROLLERS.items():
        entry = controllers[name]
        assert entry.object == reference_dir() / filename
        assert entry.path is not None and entry.path.is_file(), name
        assert entry.description
        assert (entry.plugin, entry.source) == ("turtletui.plugins.builtin", "builtin")


def test_builtin_registers_bundled_lessons_folder(monkeypatch, tmp_path):
    monkeypatch.setattr(builtin_plugin, "lessons_dir", lambda: tmp_path)
    assert collect_lessons(get_plugin_manager(load_entrypoints=False)) == [tmp_path]
    monkeypatch.setattr(builtin_plugin, "lessons_dir", lambda: None)
    assert collect_lessons(get_plugin_manager(load_entrypoints=False)) == []


def test_lessons_dir_is_the_top_level_lessons_folder_when_present():
    folder = builtin_plugin.lessons_dir()
    if folder is None:
        assert not (REPO / "lessons").is_dir()
    else:
        assert folder.is_dir()


def test_builtin_registers_the_bundled_worlds_and_the_grading_checks(pm):
    from turtletui.grading.checks import BUILTIN_CHECKS

    assert "lidar-course" in collect_worlds(pm)
    checks = collect_checks(pm)
    assert list(checks) == list(BUILTIN_CHECKS)
    for name, entry in checks.items():
        assert entry.object is BUILTIN_CHECKS[name]
        assert (entry.plugin, entry.source) == ("turtletui.grading.builtin_checks", "builtin")


def test_manager_is_built_fresh_by_the_factory():
    first, second = (
        get_plugin_manager(load_entrypoints=False),
        get_plugin_manager(load_entrypoints=False),
    )
    assert first is not second
    builtins = {importlib.import_module(name) for name in BUILTIN_PLUGINS}
    assert first.get_plugins() == second.get_plugins() == builtins


def test_a_manager_calls_each_hook_once_through_pluggy_until_its_plugins_change(pm, temporary_plugin):
    calls: list[str] = []

    class Counting:
        @hookimpl
        def turtletui_register_worlds(self, register):
            calls.append("worlds")
            register("counted", lambda: {}, "")

    temporary_plugin(Counting(), name="counting")
    # pluggy's monitoring sees the calls: they go through pluggy, one plugin at a time
    undo = pm.add_hookcall_monitoring(
        lambda hook, impls, kwargs: calls.append(f"{hook}: {', '.join(i.plugin_name for i in impls)}"),
        lambda outcome, hook, impls, kwargs: None,
    )
    try:
        assert "counted" in collect_worlds(pm) and "counted" in collect_worlds(pm)
    finally:
        undo()
    assert calls.count("worlds") == 1
    assert "turtletui_register_worlds: counting" in calls
    temporary_plugin(type("Late", (), {})(), name="late")
    collect_worlds(pm)
    assert calls.count("worlds") == 2


def test_a_duplicate_name_is_reported_once_per_manager(pm, temporary_plugin, capsys):
    class Twice:
        @hookimpl
        def turtletui_register_worlds(self, register):
            register("lidar-course", lambda: {}, "again")

    temporary_plugin(Twice(), name="twice")
    for _ in range(3):
        collect_worlds(pm)
    plugin_infos(pm)
    assert capsys.readouterr().err.count("replaces") == 1


def test_a_registered_check_object_keeps_its_thresholds(pm, temporary_plugin):
    from turtletui.grading.checks import Check
    from turtletui.grading.engine import available_checks

    strict = Check("strict", lambda trace, thresholds: True, "takes one threshold", {"limit": "number"})

    class Checks:
        @hookimpl
        def turtletui_register_checks(self, register):
            register("strict", strict)

    temporary_plugin(Checks(), name="checks")
    check = available_checks(pm)["strict"]
    assert check.params == {"limit": "number"} and check.description == "takes one threshold"
    assert check.problem({"other": 1}) == "check 'strict' takes no threshold 'other' (it takes: limit)"


COUNTING_PLUGIN = """
    from pathlib import Path

    from turtletui.plugins import hookimpl

    with open({log!r}, "a") as log:
        log.write("imported\\n")


    @hookimpl
    def turtletui_register_worlds(register):
        register("counted", lambda: {{"name": "counted"}}, "a world from a plugin file")
"""


def test_one_command_imports_a_plugin_file_once(cli_app, tmp_path, forget_modules):
    from typer.testing import CliRunner

    log = tmp_path / "imports.log"
    plugin = write(tmp_path / "counting.py", COUNTING_PLUGIN.format(log=str(log)))
    args = ["lessons", "--plugin", str(plugin)]
    result = CliRunner().invoke(cli_app, args, env={DISABLE_AUTOLOAD_ENV: "1"})
    assert result.exit_code == 0, result.output
    assert result.stderr == ""
    assert log.read_text() == "imported\n"


# -- one test per hook (the meta-test below insists) ---------------------------------


def test_hook_turtletui_register_controllers(pm, temporary_plugin, tmp_path, capsys):
    def node_classes():
        return []

    node_file = write(tmp_path / "my_node.py", "def main():\n    pass\n")

    class Controllers:
        @hookimpl
        def turtletui_register_controllers(self, register):
            register("from_factory", node_classes, "a node factory")
            register("from_file", node_file)

    temporary_plugin(Controllers(), name="controllers")
    controllers = collect_controllers(pm)
    assert controllers["from_factory"].object is node_classes
    assert controllers["from_factory"].path is None
    assert controllers["from_factory"].description == "a node factory"
    assert controllers["from_file"].path == node_file
    assert controllers["from_file"].description == ""
    assert controllers["from_file"].plugin == "controllers"
    assert "part6_wall_avoider" in controllers
    assert capsys.readouterr().err == ""


def test_later_plugin_wins_a_duplicate_name_with_a_warning(pm, temporary_plugin, capsys):
    class Override:
        @hookimpl
        def turtletui_register_controllers(self, register):
            register("part6_wall_avoider", lambda: [], "my own wall avoider")

    temporary_plugin(Override(), name="override")
    entry = collect_controllers(pm)["part6_wall_avoider"]
    assert (entry.plugin, entry.description) == ("override", "my own wall avoider")
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert "part6_wall_avoider" in err[0]
    assert "override" in err[0] and "turtletui.plugins.builtin (builtin)" in err[0]


def test_bad_registration_is_reported_and_other_plugins_still_count(pm, temporary_plugin, capsys):
    class Sloppy:
        @hookimpl
        def turtletui_register_controllers(self, register):
            register("good_one", lambda: [])
            register("as_text", "plugins/reference/turtle_controller.py")  # a str, not a Path

    temporary_plugin(Sloppy(), name="sloppy")
    controllers = collect_controllers(pm)
    # The plugin's whole registration is dropped, not half of it.
    assert "good_one" not in controllers and "as_text" not in controllers
    assert set(REFERENCE_CONTROLLERS) <= set(controllers)
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert (
        "sloppy" in err[0] and "turtletui_register_controllers" in err[0] and "TypeError" in err[0]
    )


def test_hook_turtletui_register_lessons(pm, temporary_plugin, tmp_path):
    lesson = write(tmp_path / "part3.md", "---\ntitle: Part 3\n---\n")
    folder = tmp_path / "more"
    folder.mkdir()

    class Lessons:
        @hookimpl
        def turtletui_register_lessons(self, register):
            register(lesson)
            register(folder)
            register(tmp_path / "." / "part3.md")  # the same file again

    temporary_plugin(Lessons(), name="lessons")
    lessons = [path for path in collect_lessons(pm) if path.is_relative_to(tmp_path)]
    assert lessons == [lesson, folder]
    entries = [e for e in collect_lesson_entries(pm) if e.plugin == "lessons"]
    assert [e.object for e in entries] == [lesson, folder]


def test_hook_turtletui_register_worlds(pm, temporary_plugin, capsys):
    def empty_world():
        return {"obstacles": []}

    def maze():
        return {"obstacles": ["wall"]}

    class First:
        @hookimpl
        def turtletui_register_worlds(self, register):
            register("empty", empty_world)
            register("maze", empty_world, "a first maze")

    class Second:
        @hookimpl
        def turtletui_register_worlds(self, register):
            register("maze", maze, "a better maze")

    temporary_plugin(First(), name="first")
    temporary_plugin(Second(), name="second")
    worlds = collect_worlds(pm)
    assert worlds["empty"].object() == {"obstacles": []}
    assert worlds["maze"].object is maze
    assert (worlds["maze"].plugin, worlds["maze"].description) == ("second", "a better maze")
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "'maze'" in err[0] and "first" in err[0] and "second" in err[0]


def test_hook_turtletui_register_checks(pm, temporary_plugin):
    def reaches_goal(run):
        return 1.0

    class Checks:
        @hookimpl
        def turtletui_register_checks(self, register):
            register("reaches_goal", reaches_goal, "the turtle ends within 0.5 m of the goal")

    temporary_plugin(Checks(), name="checks")
    checks = collect_checks(pm)
    assert list(checks)[-1] == "reaches_goal"
    assert checks["reaches_goal"].object is reaches_goal
    assert checks["reaches_goal"].description == "the turtle ends within 0.5 m of the goal"
    assert checks["reaches_goal"].source == "registered directly"


# -- meta-tests (datasette's test_plugin_hooks_have_tests) ----------------------------


@pytest.mark.parametrize("hook_name", HOOK_NAMES)
def test_every_hook_has_a_test(hook_name):
    assert f"test_hook_{hook_name}" in globals(), f"add a test named test_hook_{hook_name}"


@pytest.mark.parametrize("hook_name", HOOK_NAMES)
def test_every_hook_is_documented_and_typed(hook_name):
    spec = getattr(hookspecs, hook_name)
    doc = inspect.getdoc(spec) or ""
    assert "Called when" in doc, f"{hook_name}: say when it is called"
    assert "register(" in doc, f"{hook_name}: say what register gets"
    assert "Returns" in doc, f"{hook_name}: say what it returns"
    signature = inspect.signature(spec)
    assert list(signature.parameters) == ["register"]
    assert all(p.annotation is not inspect.Parameter.empty for p in signature.parameters.values())
    assert signature.return_annotation is not inspect.Signature.empty


def test_every_hook_is_collected_by_the_manager():
    assert sorted(kind.hook for kind in KINDS.values()) == HOOK_NAMES
    assert len(HOOK_NAMES) == 4


# -- installed plugins (entry points) -----------------------------------------------


FAKE_PLUGIN = """
    from turtletui.plugins import hookimpl


    @hookimpl
    def turtletui_register_controllers(register):
        register("fake_square", lambda: [], "from an installed package")
"""


@pytest.fixture
def fake_installed_plugin(tmp_path, monkeypatch, forget_modules):
    """A distribution 'fakeplugin 1.0' with entry point ``fake = fake_turtletui_plugin``."""
    fake_distribution(tmp_path, "fakeplugin", "1.0", {"fake": "fake_turtletui_plugin"})
    write(tmp_path / "fake_turtletui_plugin.py", FAKE_PLUGIN)
    monkeypatch.syspath_prepend(str(tmp_path))
    return tmp_path


def test_entry_point_plugin_is_discovered(fake_installed_plugin):
    pm = get_plugin_manager()
    assert pm.has_plugin("fake")
    assert pm.source_of("fake") == "entry point fakeplugin 1.0"
    entry = collect_controllers(pm)["fake_square"]
    assert (entry.plugin, entry.source) == ("fake", "entry point fakeplugin 1.0")
    lines = describe_plugins(pm=pm)
    at = lines.index("fake (entry point fakeplugin 1.0)")
    assert lines[at + 1] == "  controllers (1): fake_square"


def test_entry_points_switched_off_by_environment(fake_installed_plugin, monkeypatch):
    monkeypatch.setenv(DISABLE_AUTOLOAD_ENV, "1")
    pm = get_plugin_manager()
    assert not pm.has_plugin("fake")
    assert "fake_square" not in collect_controllers(pm)
    assert set(REFERENCE_CONTROLLERS) <= set(collect_controllers(pm))
    # An explicit argument overrides the environment either way.
    assert get_plugin_manager(load_entrypoints=True).has_plugin("fake")
    monkeypatch.setenv(DISABLE_AUTOLOAD_ENV, "")
    assert get_plugin_manager().has_plugin("fake")
    assert not get_plugin_manager(load_entrypoints=False).has_plugin("fake")


def test_broken_entry_point_is_reported_and_others_load(
    tmp_path, monkeypatch, forget_modules, capsys
):
    fake_distribution(tmp_path, "brokenplugin", "2.0", {"broken": "fake_turtletui_broken"})
    write(tmp_path / "fake_turtletui_broken.py", "import fake_turtletui_missing_dependency\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    pm = get_plugin_manager()
    assert not pm.has_plugin("broken")
    assert set(REFERENCE_CONTROLLERS) <= set(collect_controllers(pm))
    err = [line for line in capsys.readouterr().err.splitlines() if "broken" in line]
    assert err == [
        "turtletui: plugin broken (entry point brokenplugin 2.0) failed to load: "
        "ModuleNotFoundError: No module named 'fake_turtletui_missing_dependency'"
    ]


def test_example_plugin_package_declares_a_working_entry_point(
    tmp_path, monkeypatch, forget_modules
):
    tomllib = pytest.importorskip("tomllib")
    project = tomllib.loads((EXAMPLE_PLUGIN / "pyproject.toml").read_text(encoding="utf-8"))[
        "project"
    ]
    entry_points = project["entry-points"][PROJECT_NAME]
    fake_distribution(tmp_path, project["name"], project["version"], entry_points)
    monkeypatch.syspath_prepend(str(EXAMPLE_PLUGIN))
    monkeypatch.syspath_prepend(str(tmp_path))
    rclpy_before = "rclpy" in sys.modules

    pm = get_plugin_manager()
    entry = collect_controllers(pm)["example_square"]
    assert entry.source == "entry point turtletui-example-plugin 0.1.0"
    assert entry.path is None and callable(entry.object)
    assert entry.description
    # Loading the plugin must not import the node module (it needs rclpy).
    assert "turtletui_example_plugin.square" not in sys.modules
    assert ("rclpy" in sys.modules) == rclpy_before


def test_example_plugin_node_drives_a_square():
    from turtletui.api import run
    from turtletui.runtime.loader import ControllerSpec

    square = EXAMPLE_PLUGIN / "turtletui_example_plugin" / "square.py"
    spec = ControllerSpec(name="example_square", path=square, trusted=True)
    result = run([spec], duration=11.5, keep_poses=True, keep_calls=False)
    assert result.ok and result.wall_hits == 0
    poses = result.poses["turtle1"]
    xs, ys = [p[1] for p in poses], [p[2] for p in poses]
    start_x, start_y = xs[0], ys[0]
    assert max(xs) - min(xs) == pytest.approx(2.0, abs=0.1)
    assert max(ys) - min(ys) == pytest.approx(2.0, abs=0.1)
    assert (xs[-1], ys[-1]) == (pytest.approx(start_x, abs=0.1), pytest.approx(start_y, abs=0.1))
    assert [r.msg for r in result.logs if "Side" in r.msg][-1] == "Side 4 done, turning left"


# -- plugin files and folders named on the command line -------------------------------


def test_extra_plugin_file(tmp_path, forget_modules):
    plugin = write(tmp_path / "my_plugin.py", PLUGIN_FILE.format(name="mine"))
    pm = get_plugin_manager(extra=[plugin], load_entrypoints=False)
    entry = collect_controllers(pm)["mine"]
    assert entry.path == plugin
    assert entry.plugin == str(plugin.resolve())
    assert entry.source == f"file {plugin.resolve()}"
    assert f"{plugin.resolve()} (file)" in describe_plugins(pm=pm)


def test_extra_plugin_folder_loads_every_py_file_in_order(tmp_path, forget_modules, capsys):
    write(tmp_path / "b_second.py", PLUGIN_FILE.format(name="shared"))
    write(tmp_path / "a_first.py", PLUGIN_FILE.format(name="shared"))
    write(tmp_path / "notes.txt", "not a plugin")
    pm = get_plugin_manager(extra=[str(tmp_path)], load_entrypoints=False)
    names = [name for name, _ in pm.list_name_plugin()]
    first, second = (tmp_path / "a_first.py").resolve(), (tmp_path / "b_second.py").resolve()
    assert names[len(BUILTIN_PLUGINS) :] == [str(first), str(second)]
    assert collect_controllers(pm)["shared"].path == second
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "a_first.py" in err[0] and "b_second.py" in err[0]


def test_broken_plugin_files_are_reported_one_line_each(tmp_path, forget_modules, capsys):
    folder = tmp_path / "plugins"
    write(folder / "a_import_error.py", "raise ImportError('needs numpy 3')\n")
    write(folder / "b_syntax_error.py", "def oops(:\n    pass\n")
    write(
        folder / "c_unknown_hook.py",
        """
        from turtletui.plugins import hookimpl

        @hookimpl
        def turtletui_register_controler(register):
            pass
        """,
    )
    write(
        folder / "d_wrong_argument.py",
        """
        from turtletui.plugins import hookimpl

        @hookimpl
        def turtletui_register_worlds(register, extra):
            pass
        """,
    )
    write(
        folder / "e_raises_in_hook.py",
        """
        from turtletui.plugins import hookimpl

        @hookimpl
        def turtletui_register_checks(register):
            raise RuntimeError("boom")
        """,
    )
    write(folder / "f_good.py", PLUGIN_FILE.format(name="still_here"))
    missing = tmp_path / "missing.py"

    pm = get_plugin_manager(extra=[folder, missing], load_entrypoints=False)
    assert set(collect_controllers(pm)) == {*REFERENCE_CONTROLLERS, "still_here"}
    assert "wall_hits" in collect_checks(pm)  # the built-in checks still count

    err = capsys.readouterr().err.splitlines()
    expected = {
        "a_import_error.py": "ImportError: needs numpy 3",
        "b_syntax_error.py": "SyntaxError",
        "c_unknown_hook.py": "unknown hook 'turtletui_register_controler'",
        "d_wrong_argument.py": "PluginValidationError",
        "e_raises_in_hook.py": "RuntimeError: boom",
        "missing.py": "does not exist",
    }
    assert len(err) == len(expected), err
    by_file = sorted(err, key=lambda line: line.split("/")[-1])
    for line, (filename, message) in zip(by_file, sorted(expected.items()), strict=True):
        assert line.startswith("turtletui: ")
        assert filename in line and message in line, line
    assert not any(pm.has_plugin(str((folder / name).resolve())) for name in list(expected)[:4])


def test_unmarked_hook_function_gets_a_warning(tmp_path, forget_modules, capsys):
    plugin = write(tmp_path / "forgot.py", "def turtletui_register_checks(register):\n    pass\n")
    pm = get_plugin_manager(extra=[plugin], load_entrypoints=False)
    assert pm.has_plugin(str(plugin.resolve()))
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "forgot.py" in err[0] and "@hookimpl" in err[0]


# -- describe_plugins and ``turtletui plugins`` ----------------------------------------


def test_describe_plugins_lists_sources_counts_and_names(pm, temporary_plugin):
    class Nothing:
        pass

    temporary_plugin(Nothing(), name="nothing")
    lines = describe_plugins(pm=pm)
    at = lines.index("turtletui.plugins.builtin (builtin)")
    assert lines[at : at + 2] == [
        "turtletui.plugins.builtin (builtin)",
        f"  controllers ({len(REFERENCE_CONTROLLERS)}): " + ", ".join(REFERENCE_CONTROLLERS),
    ]
    assert lines[-2:] == ["nothing (registered directly)", "  registers nothing"]
    infos = plugin_infos(pm)
    assert [info.name for info in infos] == [*BUILTIN_PLUGINS, "nothing"]
    by_name = {info.name: info for info in infos}
    assert by_name["turtletui.plugins.builtin"].as_dict()["controllers"] == list(
        REFERENCE_CONTROLLERS
    )


@pytest.fixture
def cli_app():
    try:
        from turtletui.cli import app
    except ImportError as err:  # the CLI is assembled from other modules still being written
        pytest.fail(f"turtletui.cli does not import: {err}")
    return app


def test_cli_plugins_lists_builtins(cli_app, monkeypatch):
    from typer.testing import CliRunner

    result = CliRunner().invoke(cli_app, ["plugins"], env={DISABLE_AUTOLOAD_ENV: "1"})
    assert result.exit_code == 0, result.output
    assert "turtletui.plugins.builtin (builtin)" in result.stdout
    for name in REFERENCE_CONTROLLERS:
        assert name in result.stdout


def test_cli_plugins_json(cli_app, tmp_path, forget_modules):
    from typer.testing import CliRunner

    plugin = write(tmp_path / "extra_plugin.py", PLUGIN_FILE.format(name="extra"))
    broken = write(tmp_path / "broken.py", "raise ImportError('nope')\n")
    args = ["plugins", "--json", "--plugin", str(plugin), "--plugin", str(broken)]
    result = CliRunner().invoke(cli_app, args, env={DISABLE_AUTOLOAD_ENV: "1"})
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert [item["source"] for item in data] == ["builtin"] * len(BUILTIN_PLUGINS) + [
        f"file {plugin.resolve()}"
    ]
    by_name = {item["name"]: item for item in data}
    assert by_name["turtletui.plugins.builtin"]["controllers"] == list(REFERENCE_CONTROLLERS)
    assert data[-1] == {
        "name": str(plugin.resolve()),
        "source": f"file {plugin.resolve()}",
        "controllers": ["extra"],
        "lessons": [],
        "worlds": [],
        "checks": [],
    }
    assert result.stderr.count("\n") == 1 and "broken.py" in result.stderr
