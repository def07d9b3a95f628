"""Find and load controller code: a file, a module, or a plugin's node factory."""

from __future__ import annotations

import ast
import importlib.util
import inspect
import sys
import types
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any


class ControllerError(Exception):
    """A controller that cannot be loaded; the message is one line naming the file."""


@dataclass
class ControllerSpec:
    """What to run: a file path, an importable module name, or a node factory."""

    name: str
    path: Path | None = None
    module: str | None = None
    factory: Callable[[], Any] | None = None
    trusted: bool = False
    function: str | None = None
    """The function to call, as a console_scripts entry names it (``module:function``);
    None: ``main()``, or the file's Node subclasses."""

    @property
    def label(self) -> str:
        return str(self.path) if self.path else (self.module or self.name)


def check_source(path: Path) -> str:
    """Read a controller file, refusing what is not Python source, with one-line errors."""
    if not path.exists():
        raise ControllerError(f"{path}: no such file")
    if path.is_dir():
        raise ControllerError(f"{path}: is a folder; name a Python file (e.g. {path}/my_node.py)")
    data = path.read_bytes()
    if b"\0" in data[:8192]:
        raise ControllerError(f"{path}: is a binary file, not Python source")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as err:
        raise ControllerError(f"{path}: is not UTF-8 text (byte {err.start})") from None
    try:
        ast.parse(text, filename=str(path))
    except SyntaxError as err:
        line = (err.text or "").strip()
        where = f"{path}:{err.lineno}" + (f":{err.offset}" if err.offset else "")
        raise ControllerError(f"{where}: SyntaxError: {err.msg}" + (f": {line}" if line else "")) from None
    return text


def load_module(spec: ControllerSpec) -> types.ModuleType:
    """Import the controller's module (its top level runs now).

    A file inside a Python package (folders with ``__init__.py``, as in a ROS 2
    ament_python package) is imported as ``package.module`` with the package's
    parent folder on ``sys.path``, as ``ros2 run`` would import it: relative
    imports and ``from my_package.utils import x`` both work."""
    if spec.module:
        return importlib.import_module(spec.module)
    assert spec.path is not None
    path = spec.path.resolve()
    # Compiled from the text just checked, never from a cached .pyc: a file
    # edited twice within a second at the same size would look unchanged to
    # the bytecode cache, and a hot reload would run the old code.
    code = compile(check_source(path), str(path), "exec")
    packages, root = _enclosing_packages(path)
    for folder in (str(path.parent), str(root)):
        if folder not in sys.path:
            sys.path.insert(1, folder)
    if packages:
        name = ".".join([*packages, path.stem])
        try:
            importlib.import_module(".".join(packages))
        except Exception as err:  # the student's package __init__.py failed: report it as theirs
            raise ControllerError(f"{path}: importing its package {'.'.join(packages)} failed: {type(err).__name__}: {err}") from err
        module = importlib.util.module_from_spec(importlib.util.spec_from_file_location(name, path))
    else:
        name = f"__turtletui_controller_{abs(hash(str(path))):x}"
        module = types.ModuleType(name)
        module.__file__ = str(path)
    sys.modules[name] = module
    exec(code, module.__dict__)
    return module


def _enclosing_packages(path: Path) -> tuple[list[str], Path]:
    """The package names a file sits in (outermost first) and the folder above them."""
    packages: list[str] = []
    folder = path.parent
    while (folder / "__init__.py").is_file() and folder.name.isidentifier() and folder.parent != folder:
        packages.insert(0, folder.name)
        folder = folder.parent
    return packages, folder


def entry_point(module: types.ModuleType, label: str, function: str | None = None) -> Callable[[], Any]:
    """What to call to start the controller: ``function`` when a console_scripts
    entry names one, else ``main()``, or a function that creates every Node
    subclass the module defines."""
    if function is not None:
        named = getattr(module, function, None)
        if not callable(named):
            raise ControllerError(f"{label}: has no function {function}() (its console_scripts entry names it)")
        return named
    main = getattr(module, "main", None)
    if callable(main):
        return main
    from turtletui.compat.node import Node

    classes = [
        obj
        for obj in vars(module).values()
        if inspect.isclass(obj) and issubclass(obj, Node) and obj is not Node and obj.__module__ == module.__name__
    ]
    if not classes:
        raise ControllerError(
            f"{label}: found no main() function and no rclpy Node subclass to run"
        )
    return lambda: spin_nodes(classes)


def spin_nodes(classes: list[type]) -> None:
    """Run Node classes the way a ROS main() would: init, create, spin, shut down."""
    import rclpy

    rclpy.init()
    nodes = [cls() for cls in classes]
    executor = rclpy.executors.SingleThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    try:
        executor.spin()
    finally:
        for node in nodes:
            node.destroy_node()
        rclpy.try_shutdown()


def factory_reference(factory: Callable[[], Any]) -> str:
    """``module:qualified.name`` of a node factory, to find it in another process."""
    module = getattr(factory, "__module__", None)
    qualname = getattr(factory, "__qualname__", "")
    if not module or "<" in qualname:
        raise ControllerError(f"{factory!r}: a node factory must be a module-level function to run sandboxed")
    return f"{module}:{qualname}"


def import_root(factory: Callable[[], Any]) -> str | None:
    """The sys.path entry the factory's top-level package was imported from."""
    top = sys.modules.get(factory.__module__.partition(".")[0])
    origin = getattr(top, "__file__", None)
    if origin is None:
        return None
    path = Path(origin).resolve()
    return str(path.parents[1] if path.name == "__init__.py" else path.parent)


def resolve_factory(reference: str) -> Callable[[], Any]:
    """The node factory named by factory_reference()."""
    module_name, _, qualname = reference.partition(":")
    obj: Any = importlib.import_module(module_name)
    for part in qualname.split("."):
        obj = getattr(obj, part)
    return obj


def seed_numpy(seed: int) -> None:
    """Seed numpy's global generator if the controller imported numpy."""
    numpy = sys.modules.get("numpy")
    if numpy is not None:
        numpy.random.seed(seed % 2**32)


def user_frames(tb: Any, path: Path | None) -> list[str]:
    """Traceback lines from the controller's own file; for a controller that is
    not one file (a plugin's node factory), every frame outside turtletui."""
    import traceback

    frames = traceback.extract_tb(tb)
    if path is not None:
        target = str(path.resolve())
        own = [f for f in frames if f.filename == target]
    else:
        package = str(Path(__file__).resolve().parents[1]) + "/"
        own = [f for f in frames if not f.filename.startswith(package)]
    frames = own or frames[-1:]
    return [f"  File \"{f.filename}\", line {f.lineno}, in {f.name}\n    {(f.line or '').strip()}" for f in frames]
