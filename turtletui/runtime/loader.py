"""Find and load controller code: a file, a module, or a plugin's node factory."""

from __future__ import annotations

import ast
import importlib.abc
import importlib.util
import inspect
import io
import os
import sys
import tokenize
import types
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from turtletui.errors import TurtletuiError


class ControllerError(TurtletuiError):
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
    if not path.is_file():
        raise ControllerError(f"{path}: is not a regular file (a pipe or a device?); name a Python file")
    try:
        data = path.read_bytes()
    except OSError as err:
        raise ControllerError(f"{path}: cannot be read ({err.strerror or err}): check its permissions") from None
    if b"\0" in data[:8192]:
        raise ControllerError(f"{path}: is a binary file, not Python source")
    # as Python reads a file: a UTF-8 byte order mark, or a coding declaration in its first two lines
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
    except SyntaxError as err:
        if "unknown encoding" in str(err):
            raise ControllerError(f"{path}: {err}") from None
        encoding = "utf-8"  # no declaration and not UTF-8 text: said below, with where
    try:
        text = data.decode(encoding)
    except (UnicodeDecodeError, LookupError) as err:
        start = getattr(err, "start", 0)
        line = data.count(b"\n", 0, start) + 1
        raise ControllerError(f"{path}:{line}: is not {encoding} text (byte {start}); save it as UTF-8") from None
    try:
        ast.parse(text, filename=str(path))
    except SyntaxError as err:
        line = (err.text or "").strip()
        where = f"{path}:{err.lineno}" + (f":{err.offset}" if err.offset else "")
        raise ControllerError(f"{where}: SyntaxError: {err.msg}" + (f": {line}" if line else "")) from None
    return text


def run_controller(spec: ControllerSpec) -> None:
    """Run a controller file as ``python3 FILE`` would (as ``__main__``, so an
    ``if __name__ == "__main__":`` block runs, and so does code at its top
    level; a file inside a package runs as ``python3 -m package.module``
    would, relative imports included); then, if the file never calls its
    ``main()`` and running it started no node, do what ``ros2 run`` does:
    call ``main()``, or create and spin every Node subclass it defines. A
    console_scripts entry (``spec.function``) or an importable module is
    started as ``ros2 run`` starts one: imported, then its function called.

    Runs inside a bound compat host (turtletui.compat.context.bind_host)."""
    if spec.module or spec.function:
        entry_point(load_module(spec), spec.label, spec.function)()
        return
    assert spec.path is not None
    path = spec.path.resolve()
    source = check_source(path)
    code = compile(source, str(path), "exec", dont_inherit=True)  # see load_module
    module = types.ModuleType("__main__")
    module.__file__ = str(path)
    packages = _import_packages(path)
    if packages:
        module.__package__ = ".".join(packages)
        module.__spec__ = importlib.util.spec_from_file_location(".".join([*packages, path.stem]), path)
    from turtletui.compat import context

    graph = context.current_host().graph
    started = (graph.now_ns, context.Context.inits)
    previous = sys.modules.get("__main__")
    sys.modules["__main__"] = module
    try:
        exec(code, module.__dict__)
        if _calls_main(source) or graph.now_ns != started[0]:
            return  # it ran itself (``main()``, guarded or not, or a script)
        if context.Context.inits != started[1] and not callable(getattr(module, "main", None)):
            return  # a script that used rclpy and ended at once
        entry_point(module, spec.label)()
    finally:
        if previous is not None:
            sys.modules["__main__"] = previous


def _calls_main(source: str) -> bool:
    """Whether the file calls ``main`` in its top-level code (also inside
    ``if __name__ == "__main__":`` or ``sys.exit(main())``), not only in
    functions and classes."""
    tree = ast.parse(source)
    pending: list[ast.AST] = list(tree.body)
    while pending:
        node = pending.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            continue
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "main":
            return True
        pending.extend(ast.iter_child_nodes(node))
    return False


def load_module(spec: ControllerSpec) -> types.ModuleType:
    """Import the controller's module, as ``ros2 run`` imports the module of a
    console_scripts entry (its top level runs now, not as ``__main__``).

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
    # dont_inherit: the program gets its own __future__ imports, not this module's
    # (annotations stay objects, as under python itself).
    code = compile(check_source(path), str(path), "exec", dont_inherit=True)
    packages = _import_packages(path)
    if packages:
        name = ".".join([*packages, path.stem])
        module = importlib.util.module_from_spec(importlib.util.spec_from_file_location(name, path))
    else:
        name = f"__turtletui_controller_{abs(hash(str(path))):x}"
        module = types.ModuleType(name)
        module.__file__ = str(path)
    sys.modules[name] = module
    exec(code, module.__dict__)
    return module


def _import_packages(path: Path) -> list[str]:
    """Put the file's folder (and, for a file inside packages, the folder above
    them) on ``sys.path`` and import its packages; their names, outermost first."""
    packages, root = _enclosing_packages(path)
    for folder in (str(path.parent), str(root)):
        if folder not in sys.path:
            sys.path.insert(1, folder)
    if packages:
        try:
            importlib.import_module(".".join(packages))
        except Exception as err:  # the student's package __init__.py failed: report it as theirs
            raise ControllerError(f"{path}: importing its package {'.'.join(packages)} failed: {type(err).__name__}: {err}") from err
    return packages


def _enclosing_packages(path: Path) -> tuple[list[str], Path]:
    """The package names a file sits in (outermost first) and the folder above them."""
    packages: list[str] = []
    folder = path.parent
    while (folder / "__init__.py").is_file() and folder.name.isidentifier() and folder.parent != folder:
        packages.insert(0, folder.name)
        folder = folder.parent
    return packages, folder


def entry_point(module: types.ModuleType, label: str, function: str | None = None) -> Callable[[], Any]:
    """What ``ros2 run`` would call to start the controller: ``function`` when
    a console_scripts entry names one, else ``main()``, or a function that
    creates and spins every Node subclass the module defines."""
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
    import rclpy.executors

    if not rclpy.ok():
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
    """Seed numpy's global generator now if numpy is imported, else as soon
    as the controller imports it (before its code can draw a number)."""
    numpy = sys.modules.get("numpy")
    if numpy is not None:
        numpy.random.seed(seed % 2**32)
        return
    sys.meta_path.insert(0, _AfterImport("numpy", lambda module: module.random.seed(seed % 2**32)))


class _AfterImport(importlib.abc.MetaPathFinder):
    """Calls ``then(module)`` once the module ``name`` has been imported (once)."""

    def __init__(self, name: str, then: Callable[[types.ModuleType], None]) -> None:
        self.name = name
        self.then = then

    def find_spec(self, fullname: str, path: Any, target: Any = None) -> Any:
        if fullname != self.name:
            return None
        sys.meta_path.remove(self)
        spec = importlib.util.find_spec(fullname)
        if spec is None or spec.loader is None or not hasattr(spec.loader, "exec_module"):
            return spec
        exec_module = spec.loader.exec_module
        then = self.then

        def run(module: types.ModuleType) -> None:
            exec_module(module)
            then(module)

        spec.loader.exec_module = run  # type: ignore[method-assign]
        return spec


def user_frames(tb: Any, path: Path | None) -> list[str]:
    """Traceback lines from the student's own files (:func:`own_files`: the
    controller file and the modules of its folder or package, such as a
    helper it imports); for a controller that is not one file (a plugin's
    node factory), every frame outside turtletui."""
    import traceback

    frames = traceback.extract_tb(tb)
    if path is not None:
        mine = own_files(path)
        own = [f for f in frames if mine(f.filename)]
    else:
        package = str(Path(__file__).resolve().parents[1]) + "/"
        # "<turtletui pkg/msg/Name>": a message class's generated methods (turtletui.interfaces)
        own = [f for f in frames if not f.filename.startswith((package, "<turtletui "))]
    frames = own or frames[-1:]
    return [frame_text(f.filename, f.lineno, f.name, f.line or "") for f in frames]


def own_files(path: Path) -> Callable[[str], bool]:
    """Which source files are the student's, for the controller file ``path``:
    ``.py`` files under the folder it sits in (for a file inside packages,
    the folder above the outermost: the course's ``my_robot_controller/``
    package and its helpers), but none of an interpreter's or a virtual
    environment's (a venv in that folder, site-packages) and none of turtletui's."""
    import sysconfig

    target = str(path.resolve())
    root = str(_enclosing_packages(Path(target))[1]) + os.sep
    others = {str(Path(__file__).resolve().parents[1]) + os.sep}
    for prefix in (sys.prefix, sys.base_prefix, sys.exec_prefix, *sysconfig.get_paths().values()):
        others.add(os.path.join(prefix, ""))
    others_tuple = tuple(others)

    def mine(filename: str) -> bool:
        if filename == target:
            return True
        if not filename.endswith(".py") or not filename.startswith(root) or filename.startswith(others_tuple):
            return False
        parts = filename[len(root):].split(os.sep)
        return not any(part in _NOT_OWN_FOLDERS or part.startswith(".") for part in parts[:-1])

    return mine


_NOT_OWN_FOLDERS = frozenset({"site-packages", "dist-packages", "__pypackages__", "node_modules"})
"""Folders whose modules are installed ones, wherever they are (a venv in the student's folder)."""


def frame_text(filename: str, lineno: int | None, name: str, source: str) -> str:
    """One frame as a crash report carries it: a traceback's two lines
    (CrashReport.summary shows the first)."""
    return f'  File "{filename}", line {lineno}, in {name}\n    {source.strip()}'
