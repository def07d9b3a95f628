"""Build the plugin manager and collect what plugins register.

Plugins are loaded in this order, and when two register the same name the
one loaded later wins (with a warning on stderr):

1. the built-in plugins, module names in :data:`BUILTIN_PLUGINS`;
2. installed packages with an entry point in the ``turtletui`` group, unless
   the environment variable ``TURTLETUI_DISABLE_PLUGIN_AUTOLOAD`` is set to a
   non-empty value (as pytest's ``PYTEST_DISABLE_PLUGIN_AUTOLOAD``);
3. files and folders named on the command line (``--plugin PATH``).

A plugin that fails to import or to register is reported on stderr in one
line naming it, and the others still load. Nothing happens at import time:
:func:`get_plugin_manager` builds a fresh manager on every call, so a command
builds one and passes it down (library functions take it as ``plugins``, or
extra plugin paths to build one from). A manager calls each registration hook
once, through pluggy, and keeps what it collected until a plugin is
registered or unregistered.
"""

from __future__ import annotations

import hashlib
import importlib
import importlib.metadata
import importlib.util
import os
import re
import sys
import types
from collections.abc import Callable, Iterator, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, TypeVar

import pluggy

from turtletui.plugins import PROJECT_NAME, hookspecs

BUILTIN_PLUGINS: tuple[str, ...] = ("turtletui.plugins.builtin", "turtletui.grading.builtin_checks")
"""Modules registered as plugins before anything else: the reference
controllers, bundled lessons and worlds, and the grading engine's own checks
(named, not imported, here: the grading layer sits above this one, as pytest
names its own features' plugins)."""

ENTRY_POINT_GROUP = PROJECT_NAME
"""The entry-point group installed plugins declare (``[project.entry-points.turtletui]``)."""

DISABLE_AUTOLOAD_ENV = "TURTLETUI_DISABLE_PLUGIN_AUTOLOAD"
"""Set to a non-empty value to skip installed plugins (entry points)."""

BUILTIN_SOURCE = "builtin"


class TurtletuiPluginManager(pluggy.PluginManager):
    """A pluggy PluginManager that remembers where each plugin came from and
    what the registration hooks gave."""

    def __init__(self) -> None:
        super().__init__(PROJECT_NAME)
        self.sources: dict[str, str] = {}
        """Plugin name -> ``"builtin"``, ``"entry point DIST VERSION"`` or ``"file PATH"``."""
        self.extra_paths: tuple[Path, ...] = ()
        """The plugin files and folders named on the command line (what a
        grading worker started afresh loads again)."""
        self.collected: dict[str, Any] = {}
        """What each registration hook gave, by hook name (see :func:`_collected`)."""

    def register(self, plugin: object, name: str | None = None) -> str | None:
        self.collected.clear()
        return super().register(plugin, name)

    def unregister(self, plugin: object | None = None, name: str | None = None) -> Any:
        self.collected.clear()
        return super().unregister(plugin, name)

    def source_of(self, name: str) -> str:
        """Where the plugin registered under ``name`` came from."""
        return self.sources.get(name, "registered directly")

    def label(self, name: str) -> str:
        """How messages name a plugin: ``name (source)``, or just the path of a file."""
        source = self.source_of(name)
        return name if source == f"file {name}" else f"{name} ({source})"


def get_plugin_manager(
    *, extra: Sequence[str | Path] = (), load_entrypoints: bool | None = None
) -> TurtletuiPluginManager:
    """A new plugin manager with the hook specs and every plugin that loads.

    ``extra`` names plugin files (``.py``) or folders (every ``.py`` in them).
    ``load_entrypoints``: True or False to force installed plugins on or off;
    None (the default) loads them unless ``TURTLETUI_DISABLE_PLUGIN_AUTOLOAD``
    is set.
    """
    pm = TurtletuiPluginManager()
    pm.add_hookspecs(hookspecs)
    for module_name in BUILTIN_PLUGINS:
        add_plugin(pm, module_name, BUILTIN_SOURCE, _importer(module_name))
    if load_entrypoints is None:
        load_entrypoints = not os.environ.get(DISABLE_AUTOLOAD_ENV)
    if load_entrypoints:
        load_entrypoint_plugins(pm)
    pm.extra_paths = tuple(Path(item) for item in extra)
    for path in pm.extra_paths:
        load_plugin_path(pm, path)
    return pm


Plugins = pluggy.PluginManager | Sequence[str | Path]
"""What library functions take as ``plugins``: the command's plugin manager,
or the extra plugin files and folders to build one with (a new one per call)."""


def plugin_manager(plugins: Plugins = ()) -> pluggy.PluginManager:
    """``plugins`` if it is a plugin manager already, else a new manager with
    the extra plugin files and folders ``plugins`` names."""
    if isinstance(plugins, pluggy.PluginManager):
        return plugins
    return get_plugin_manager(extra=plugins)


def extra_paths(plugins: Plugins) -> list[str]:
    """The plugin files and folders named on the command line, as text (what a
    fresh process needs to build the same manager)."""
    if isinstance(plugins, TurtletuiPluginManager):
        return [str(p) for p in plugins.extra_paths]
    if isinstance(plugins, pluggy.PluginManager):
        return []
    return [str(p) for p in plugins]


def _importer(module_name: str) -> Callable[[], types.ModuleType]:
    return lambda: importlib.import_module(module_name)


def add_plugin(
    pm: TurtletuiPluginManager, name: str, source: str, load: Callable[[], object]
) -> object | None:
    """Load a plugin with ``load()`` and register it as ``name``.

    Returns the plugin, or None when it is already registered or fails to
    load; a failure is reported on stderr in one line and nothing of the
    plugin stays registered.
    """
    if pm.has_plugin(name) or pm.is_blocked(name):
        return None
    pm.sources[name] = source
    try:
        plugin = load()
        pm.register(plugin, name=name)
    except Exception as err:  # noqa: BLE001 - a plugin's import can raise anything; we report it
        _report(f"plugin {pm.label(name)} failed to load: {_one_line(err)}")
        del pm.sources[name]
        return None
    try:
        _check_hook_names(pm, plugin)
    except pluggy.PluginValidationError as err:
        _report(f"plugin {pm.label(name)} failed to load: {_one_line(err)}")
        pm.unregister(plugin)
        del pm.sources[name]
        return None
    return plugin


def _check_hook_names(pm: pluggy.PluginManager, plugin: object) -> None:
    """Refuse marked hooks turtletui does not define (a typo would do nothing
    silently); warn about hook functions that lack ``@hookimpl``."""
    known = {name for name in dir(hookspecs) if name.startswith(f"{PROJECT_NAME}_")}
    name = pm.get_name(plugin)
    for attr in dir(plugin):
        opts = pm.parse_hookimpl_opts(plugin, attr)
        if opts is None:
            if attr in known and callable(getattr(plugin, attr, None)):
                _report(f"plugin {_label(pm, name)}: {attr} is not marked @hookimpl; it is ignored")
            continue
        hook_name = opts.get("specname") or attr
        if hook_name not in known and not opts.get("optionalhook"):
            raise pluggy.PluginValidationError(
                plugin,
                f"unknown hook {hook_name!r} (turtletui's hooks: {', '.join(sorted(known))})",
            )


def load_entrypoint_plugins(pm: TurtletuiPluginManager) -> None:
    """Register every installed plugin (entry points in the ``turtletui`` group)."""
    for ep in importlib.metadata.entry_points(group=ENTRY_POINT_GROUP):
        dist = getattr(ep, "dist", None)
        if dist is not None:
            dist_name = dist.metadata["Name"] or "?"
            source = f"entry point {dist_name} {dist.version}"
        else:
            dist_name = ep.value
            source = f"entry point {ep.value}"
        name = ep.name
        if pm.has_plugin(name) and pm.source_of(name) != source:
            name = f"{ep.name} ({dist_name})"  # two distributions chose the same name
        add_plugin(pm, name, source, ep.load)


def load_plugin_path(pm: TurtletuiPluginManager, path: Path) -> None:
    """Register a plugin file, or every ``.py`` file in a folder (sorted)."""
    if path.is_dir():
        files = sorted(p for p in path.glob("*.py") if p.is_file())
        if not files:
            _report(f"plugin folder {path} has no .py files")
    elif not path.exists():
        _report(f"plugin file {path} does not exist")
        files = []
    elif path.suffix != ".py":
        _report(f"plugin file {path} is not a .py file")
        files = []
    else:
        files = [path]
    for file in files:
        resolved = file.resolve()
        add_plugin(pm, str(resolved), f"file {resolved}", lambda f=resolved: import_plugin_file(f))


def import_plugin_file(path: Path) -> types.ModuleType:
    """Import a ``.py`` file as a module under a name unique to its path."""
    digest = hashlib.sha1(str(path).encode()).hexdigest()[:10]
    stem = re.sub(r"\W", "_", path.stem)
    module_name = f"turtletui_plugin_{stem}_{digest}"
    spec = importlib.util.spec_from_file_location(module_name, path)
    if spec is None or spec.loader is None:
        raise ImportError(f"cannot import {path}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[module_name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        sys.modules.pop(module_name, None)
        raise
    return module


def _source(pm: pluggy.PluginManager, name: str) -> str:
    return pm.source_of(name) if isinstance(pm, TurtletuiPluginManager) else "registered directly"


def _label(pm: pluggy.PluginManager, name: str) -> str:
    return pm.label(name) if isinstance(pm, TurtletuiPluginManager) else name


def _one_line(err: BaseException) -> str:
    return " ".join(f"{type(err).__name__}: {err}".split())


def _report(message: str) -> None:
    sys.stderr.write(f"turtletui: {message}\n")


# -- what plugins register ----------------------------------------------------


@dataclass(frozen=True)
class Entry:
    """Something a plugin registered."""

    name: str
    object: Any
    description: str
    plugin: str
    """The name of the plugin that registered it."""
    source: str
    """Where that plugin came from: ``builtin``, ``entry point DIST VERSION``, ``file PATH``."""


@dataclass(frozen=True)
class ControllerEntry(Entry):
    """A controller: ``object`` is a node factory or the Path of an rclpy file."""

    @property
    def path(self) -> Path | None:
        """The controller file, or None for a node factory."""
        return self.object if isinstance(self.object, Path) else None


@dataclass(frozen=True)
class LessonEntry(Entry):
    """A lesson file or folder: ``object`` is its Path, ``name`` the path as text."""


@dataclass(frozen=True)
class WorldEntry(Entry):
    """A world: ``object`` is the factory returning its description."""


@dataclass(frozen=True)
class CheckEntry(Entry):
    """A grading check: ``object`` is the check function."""


E = TypeVar("E", bound=Entry)


def _text(value: object, what: str) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{what} must be a str, got {type(value).__name__}")
    return value


def _name(value: object, kind: str) -> str:
    name = _text(value, f"{kind} name")
    if not name.strip():
        raise ValueError(f"{kind} name must not be empty")
    return name


def _controller_args(name: str, controller: Any, description: str = "") -> tuple[str, Any, str]:
    name = _name(name, "controller")
    if isinstance(controller, os.PathLike):
        controller = Path(controller)
    elif isinstance(controller, str) or not callable(controller):
        raise TypeError(
            f"controller {name!r}: expected a pathlib.Path to an rclpy file or a zero-argument "
            f"callable returning Node classes, got {type(controller).__name__}"
        )
    return name, controller, _text(description, "description")


def _lesson_args(path: Any) -> tuple[str, Any, str]:
    if not isinstance(path, os.PathLike):
        raise TypeError(f"lesson: expected a pathlib.Path, got {type(path).__name__}")
    path = Path(path)
    return str(path), path, ""


def _world_args(name: str, factory: Any, description: str = "") -> tuple[str, Any, str]:
    name = _name(name, "world")
    if not callable(factory):
        raise TypeError(f"world {name!r}: factory must be callable, got {type(factory).__name__}")
    return name, factory, _text(description, "description")


def _check_args(name: str, function: Any, description: str = "") -> tuple[str, Any, str]:
    name = _name(name, "check")
    if not callable(function):
        raise TypeError(f"check {name!r}: function must be callable, got {type(function).__name__}")
    return name, function, _text(description, "description")


@dataclass(frozen=True)
class _Kind:
    hook: str
    noun: str
    entry: type[Entry]
    parse: Callable[..., tuple[str, Any, str]]


CONTROLLERS = _Kind(
    "turtletui_register_controllers", "controller", ControllerEntry, _controller_args
)
LESSONS = _Kind("turtletui_register_lessons", "lesson", LessonEntry, _lesson_args)
WORLDS = _Kind("turtletui_register_worlds", "world", WorldEntry, _world_args)
CHECKS = _Kind("turtletui_register_checks", "check", CheckEntry, _check_args)
KINDS = {"controllers": CONTROLLERS, "lessons": LESSONS, "worlds": WORLDS, "checks": CHECKS}


def _gather(pm: pluggy.PluginManager, kind: _Kind) -> list[Entry]:
    """Call the hook through pluggy, for one plugin at a time in load order
    (so each registration is credited to its plugin), with a ``register`` that
    records the plugin; a plugin whose hook raises is reported and skipped."""
    entries: list[Entry] = []
    hook = getattr(pm.hook, kind.hook)
    plugins = pm.get_plugins()
    for impl in hook.get_hookimpls():
        if impl.hookwrapper or impl.wrapper:
            continue
        found: list[Entry] = []

        def register(
            *args: Any, _found: list[Entry] = found, _plugin: str = impl.plugin_name, **kwargs: Any
        ) -> None:
            name, obj, description = kind.parse(*args, **kwargs)
            _found.append(kind.entry(name, obj, description, _plugin, _source(pm, _plugin)))

        only_this = pm.subset_hook_caller(kind.hook, [p for p in plugins if p is not impl.plugin])
        try:
            only_this(register=register)
        except Exception as err:  # noqa: BLE001 - plugin code; reported, the rest go on
            _report(
                f"plugin {_label(pm, impl.plugin_name)} failed in {kind.hook}: {_one_line(err)}"
            )
            continue
        entries.extend(found)
    return entries


def _collected(pm: pluggy.PluginManager, key: str, collect: Callable[[], Any]) -> Any:
    """``collect()``, kept by a TurtletuiPluginManager until its plugins change:
    hooks are called, and duplicate names reported, once per manager."""
    if not isinstance(pm, TurtletuiPluginManager):
        return collect()
    if key not in pm.collected:
        pm.collected[key] = collect()
    return pm.collected[key]


def _entries(pm: pluggy.PluginManager, kind: _Kind) -> list[Entry]:
    return _collected(pm, kind.hook, lambda: _gather(pm, kind))


def _by_name(pm: pluggy.PluginManager, entries: list[E], noun: str) -> dict[str, E]:
    result: dict[str, E] = {}
    for entry in entries:
        previous = result.pop(entry.name, None)  # pop: the winner moves to the end
        if previous is not None:
            _report(
                f"warning: {noun} {entry.name!r} from plugin {_label(pm, entry.plugin)} "
                f"replaces the one from plugin {_label(pm, previous.plugin)}"
            )
        result[entry.name] = entry
    return result


def _named(pm: pluggy.PluginManager, kind: _Kind) -> dict[str, Entry]:
    return _collected(pm, f"{kind.hook} by name", lambda: _by_name(pm, _entries(pm, kind), kind.noun))


def collect_controllers(pm: pluggy.PluginManager) -> dict[str, ControllerEntry]:
    """Every registered controller by name (a later plugin's wins)."""
    return dict(_named(pm, CONTROLLERS))  # type: ignore[arg-type]


def collect_lesson_entries(pm: pluggy.PluginManager) -> list[LessonEntry]:
    """Every registered lesson file or folder, with the plugin that registered it."""
    unique: dict[Path, LessonEntry] = {}
    for entry in _entries(pm, LESSONS):
        unique.setdefault(entry.object.resolve(), entry)  # type: ignore[arg-type]
    return list(unique.values())


def collect_lessons(pm: pluggy.PluginManager) -> list[Path]:
    """Every registered lesson file or folder (each once, in load order)."""
    return [entry.object for entry in collect_lesson_entries(pm)]


def collect_worlds(pm: pluggy.PluginManager) -> dict[str, WorldEntry]:
    """Every registered world by name (a later plugin's wins)."""
    return dict(_named(pm, WORLDS))  # type: ignore[arg-type]


def collect_checks(pm: pluggy.PluginManager) -> dict[str, CheckEntry]:
    """Every registered check by name (a later plugin's wins)."""
    return dict(_named(pm, CHECKS))  # type: ignore[arg-type]


# -- turtletui plugins ---------------------------------------------------------


@dataclass
class PluginInfo:
    """One plugin, where it came from, and the names of what it registered."""

    name: str
    source: str
    controllers: list[str] = field(default_factory=list)
    lessons: list[str] = field(default_factory=list)
    worlds: list[str] = field(default_factory=list)
    checks: list[str] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def plugin_infos(pm: pluggy.PluginManager) -> list[PluginInfo]:
    """A PluginInfo per loaded plugin, in load order; warns about duplicate names."""
    infos = {
        name: PluginInfo(name, _source(pm, name))
        for name, plugin in pm.list_name_plugin()
        if plugin is not None
    }
    for attr, kind in KINDS.items():
        entries = _entries(pm, kind)
        if kind is not LESSONS:
            _named(pm, kind)  # only for its warnings
        for entry in entries:
            if entry.plugin in infos:
                getattr(infos[entry.plugin], attr).append(entry.name)
    return list(infos.values())


def _iter_lines(infos: list[PluginInfo]) -> Iterator[str]:
    for info in infos:
        yield (
            f"{info.name} ({info.source})"
            if info.source != f"file {info.name}"
            else f"{info.name} (file)"
        )
        empty = True
        for attr in KINDS:
            names: list[str] = getattr(info, attr)
            if names:
                empty = False
                yield f"  {attr} ({len(names)}): {', '.join(names)}"
        if empty:
            yield "  registers nothing"


def describe_plugins(
    extra: Sequence[str | Path] = (),
    *,
    load_entrypoints: bool | None = None,
    pm: pluggy.PluginManager | None = None,
) -> list[str]:
    """The lines ``turtletui plugins`` prints: each plugin, its source, and the
    counts and names of the controllers, lessons, worlds and checks it registered."""
    if pm is None:
        pm = get_plugin_manager(extra=extra, load_entrypoints=load_entrypoints)
    return list(_iter_lines(plugin_infos(pm)))
