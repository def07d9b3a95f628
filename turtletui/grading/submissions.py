"""Find the students' submissions among the paths an instructor names.

A path is one of: a ``.py`` file (one student, named after the file), one
student's folder, or a folder of folders (a class: one student per subfolder).
A student's folder holds what students really hand in: loose Python files, a
ROS 2 Python package (``setup.py`` or ``setup.cfg`` with ``console_scripts``),
or a colcon workspace with packages under ``src/``, at any depth a zip or an
extra folder puts them.

The controller in a student's folder is picked as ``ros2 run PKG NAME`` would
pick it: a ``console_scripts`` executable of a package (``--executable NAME``,
or the lesson's default executable, chooses among several), else the one Python
file with a ``main()`` or a Node class (a file identical to the lesson's
starter is the lesson's, not the student's). Anything else is ambiguous: an
error listing the candidates. Files that are not Python (notes, READMEs,
``.DS_Store``) are never graded.
"""

from __future__ import annotations

import ast
import configparser
import hashlib
import os
import re
from dataclasses import dataclass, replace
from pathlib import Path

from turtletui.errors import TurtletuiError

MAX_SOURCE_BYTES = 1024 * 1024
"""A controller file larger than this is refused (it is not a student's node)."""

MAX_DEPTH = 6
"""How deep in a student's folder packages and controllers are looked for."""

_MAIN = re.compile(rb"^\s*def\s+main\s*\(|^class\s+\w+\s*\([^)]*Node\s*\)", re.MULTILINE)

_NOT_SOURCE_FOLDERS = frozenset(
    {"build", "install", "log", "node_modules", "venv", "site-packages", "dist", "__MACOSX"}
)
"""Folders that hold no student source: colcon's build, install and log
folders, virtual environments, the resource forks a Mac zip adds."""

_TEST_FOLDERS = frozenset({"test", "tests"})
_NOT_CONTROLLERS = frozenset({"setup.py", "conftest.py", "__init__.py", "__main__.py"})
_PACKAGE_FILES = ("setup.py", "setup.cfg", "pyproject.toml", "package.xml")
"""Files besides ``*.py`` that decide what is run: part of a submission's fingerprint."""


class SubmissionError(TurtletuiError, ValueError):
    """A path that names no submission at all; one line naming the path."""


@dataclass(frozen=True)
class Submission:
    """One student's work."""

    student: str
    path: Path
    """The file or folder as named (or found in a class folder)."""
    controller: Path | None
    """The file to run; None when ``error`` says why there is none."""
    error: str | None = None
    executable: str | None = None
    """What was chosen, as ``ros2 run`` names it: ``PKG NAME`` for a package's
    console_scripts executable, or the file's name for a plain file."""
    function: str | None = None
    """The function a console_scripts entry names; None: ``main()`` or Node classes."""

    @property
    def graded(self) -> str:
        """Which file (relative to the submission) and executable are graded."""
        if self.controller is None:
            return ""
        try:
            shown = self.controller.relative_to(self.path).as_posix() if self.path.is_dir() else self.controller.name
        except ValueError:
            shown = str(self.controller)
        if self.executable and self.function:
            return f"{shown} ({self.executable}: {self.function}())"
        return shown

    def fingerprint(self) -> str:
        """Hash of the student's Python and package files and of the executable
        chosen: a result is reused only for the same code run the same way."""
        digest = hashlib.sha256(f"{self.executable}\0{self.function}\0{self.graded}\0".encode())
        folder = self.path if self.path.is_dir() else None
        if folder is not None:
            files = sorted(
                p for p in folder.rglob("*") if (p.suffix == ".py" or p.name in _PACKAGE_FILES) and p.is_file()
            )
        else:
            files = [self.path]
        for file in files:
            try:
                data = file.read_bytes()
            except OSError:
                data = b"<unreadable>"
            digest.update(str(file.relative_to(folder) if folder else file.name).encode() + b"\0")
            digest.update(hashlib.sha256(data).digest())
        return digest.hexdigest()


@dataclass(frozen=True)
class Candidate:
    """Something in a student's folder that could be the controller."""

    path: Path
    name: str
    """The executable's name (console_scripts) or the file's stem."""
    package: str | None = None
    function: str | None = None
    shown: str = ""
    """The file's path within the student's folder."""

    @property
    def label(self) -> str:
        return f"{self.package} {self.name}" if self.package else (self.shown or self.path.name)

    def matches(self, wanted: str) -> bool:
        """``wanted`` names it: ``NAME``, ``PKG NAME``, ``PKG/NAME``, or a file name."""
        wanted = wanted.strip()
        names = {self.name, self.path.name, self.shown}
        if self.package:
            names |= {f"{self.package} {self.name}", f"{self.package}/{self.name}"}
        return wanted in names


# -- a student's folder ------------------------------------------------------------------


def ignored(path: Path) -> bool:
    """Whether a file or folder in a submission holds no source of the
    student's: hidden, a cache, build output, an environment."""
    name = path.name
    return name.startswith((".", "__")) or name in _NOT_SOURCE_FOLDERS or name.endswith(".egg-info")


def _walk(folder: Path, depth: int = 0):
    """Files under ``folder`` (sorted, folders after files), skipping folders that hold no source."""
    try:
        entries = sorted(folder.iterdir())
    except OSError:
        return
    for entry in entries:
        if entry.is_file() and not entry.is_symlink():
            yield entry
    if depth >= MAX_DEPTH:
        return
    for entry in entries:
        if entry.is_dir() and not entry.is_symlink() and not ignored(entry):
            yield from _walk(entry, depth + 1)


def _read_head(path: Path) -> bytes:
    if not path.is_file():
        return b""  # a pipe would block the read for ever
    try:
        with open(path, "rb") as file:
            return file.read(MAX_SOURCE_BYTES)
    except OSError:
        return b""


def _has_entry(path: Path) -> bool:
    return bool(_MAIN.search(_read_head(path)))


def _same_text(a: bytes, b: bytes) -> bool:
    def norm(data: bytes) -> bytes:
        return b"\n".join(line.rstrip() for line in data.replace(b"\r\n", b"\n").strip().splitlines())

    return norm(a) == norm(b)


# console_scripts: "name = package.module:function"
_SCRIPT = re.compile(r"^\s*([A-Za-z0-9_.\-]+)\s*=\s*([A-Za-z_][\w.]*)\s*(?::\s*([A-Za-z_][\w.]*))?\s*(\[.*\])?\s*$")


def _literal(node: ast.AST, names: dict[str, object]) -> object:
    """A literal from setup.py's syntax tree, with the simple string variables
    the ROS template uses (``package_name``) and f-strings of them."""
    if isinstance(node, ast.Name) and node.id in names:
        return names[node.id]
    if isinstance(node, ast.JoinedStr):
        parts = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                parts.append(str(_literal(value.value, names)))
            else:
                parts.append(str(_literal(value, names)))
        return "".join(parts)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        return _literal(node.left, names) + _literal(node.right, names)  # type: ignore[operator]
    if isinstance(node, ast.Dict):
        return {_literal(k, names): _literal(v, names) for k, v in zip(node.keys, node.values, strict=True) if k}
    if isinstance(node, (ast.List, ast.Tuple)):
        return [_literal(item, names) for item in node.elts]
    return ast.literal_eval(node)


def _setup_py(path: Path) -> tuple[str | None, list[str]]:
    """(name, console_scripts lines) that setup.py's ``setup()`` call declares."""
    try:
        tree = ast.parse(_read_head(path))
    except (SyntaxError, ValueError):
        return None, []
    names: dict[str, object] = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            try:
                names[node.targets[0].id] = _literal(node.value, names)
            except (ValueError, TypeError, KeyError):
                pass
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", "")) == "setup"):
            continue
        found: dict[str, object] = {}
        for keyword in node.keywords:
            if keyword.arg in ("name", "entry_points"):
                try:
                    found[keyword.arg] = _literal(keyword.value, names)
                except (ValueError, TypeError, KeyError):
                    pass
        entries = found.get("entry_points")
        scripts = entries.get("console_scripts", []) if isinstance(entries, dict) else []
        if isinstance(scripts, str):
            scripts = scripts.splitlines()
        name = found.get("name")
        return (name if isinstance(name, str) else None), [s for s in scripts if isinstance(s, str)]
    return None, []


def _setup_cfg(path: Path) -> tuple[str | None, list[str]]:
    parser = configparser.ConfigParser(interpolation=None)
    try:
        parser.read_string(_read_head(path).decode("utf-8", "replace"))
    except configparser.Error:
        return None, []
    name = parser.get("metadata", "name", fallback=None)
    scripts = parser.get("options.entry_points", "console_scripts", fallback="")
    return name, scripts.splitlines()


def _pyproject(path: Path) -> tuple[str | None, list[str]]:
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib
    try:
        data = tomllib.loads(_read_head(path).decode("utf-8", "replace"))
    except (tomllib.TOMLDecodeError, ValueError):
        return None, []
    project = data.get("project", {}) if isinstance(data.get("project"), dict) else {}
    scripts = project.get("scripts", {}) if isinstance(project.get("scripts"), dict) else {}
    name = project.get("name")
    return (name if isinstance(name, str) else None), [f"{k} = {v}" for k, v in scripts.items()]


def _package_xml_name(folder: Path) -> str | None:
    match = re.search(rb"<name>\s*([^<\s]+)\s*</name>", _read_head(folder / "package.xml"))
    return match.group(1).decode("utf-8", "replace") if match else None


def _module_file(root: Path, module: str) -> Path | None:
    relative = Path(*module.split("."))
    for base in (root, root / "src"):
        for path in (base / relative.with_suffix(".py"), base / relative / "__init__.py"):
            if path.is_file():
                return path
    return None


def _package_candidates(root: Path) -> tuple[list[Candidate], list[str]]:
    """The console_scripts executables of the package at ``root`` (a folder with
    setup.py, setup.cfg or pyproject.toml), and problems with entries that name
    a module the package does not have."""
    name, scripts = None, []
    for file, reader in (("setup.py", _setup_py), ("setup.cfg", _setup_cfg), ("pyproject.toml", _pyproject)):
        if (root / file).is_file():
            found_name, found_scripts = reader(root / file)
            name = name or found_name
            scripts = scripts or found_scripts
    package = _package_xml_name(root) or name or root.name
    candidates, problems = [], []
    for line in scripts:
        match = _SCRIPT.match(line)
        if not match:
            continue
        executable, module, function = match.group(1), match.group(2), match.group(3)
        path = _module_file(root, module)
        if path is None:
            problems.append(f"{package} {executable} names {module}, which the package does not have")
            continue
        candidates.append(Candidate(path, executable, package, function))
    return candidates, problems


def _package_roots(folder: Path) -> list[Path]:
    """Folders under ``folder`` that are Python packages of the pip or ROS kind."""
    roots = []
    for file in _walk(folder):
        if file.name in ("setup.py", "setup.cfg", "pyproject.toml") and file.parent not in roots:
            roots.append(file.parent)
    return roots


def _file_candidates(folder: Path, skip: list[Path]) -> list[Candidate]:
    files = []
    for file in _walk(folder):
        if file.suffix != ".py" or file.name in _NOT_CONTROLLERS or file.name.startswith("test_"):
            continue
        if file.stem.endswith("_test") or any(part in _TEST_FOLDERS for part in file.relative_to(folder).parts[:-1]):
            continue
        if any(root in file.parents for root in skip):
            continue
        files.append(Candidate(file, file.stem, shown=file.relative_to(folder).as_posix()))
    return files


def controller_candidates(folder: Path, starter: Path | None = None) -> tuple[list[Candidate], list[str]]:
    """What could be the controller in a student's folder, and problems found on
    the way: the package executables when there are any, else the Python files
    with a ``main()`` or a Node class (all Python files when none has one)."""
    candidates: list[Candidate] = []
    problems: list[str] = []
    roots = _package_roots(folder)
    for root in roots:
        found, wrong = _package_candidates(root)
        candidates += found
        problems += wrong
    if candidates:
        return candidates, problems
    files = _file_candidates(folder, skip=[])
    with_entry = [c for c in files if _has_entry(c.path)]
    files = with_entry or files
    if starter is not None and len(files) > 1:
        starter_text = _read_head(starter)
        own = [c for c in files if not _same_text(_read_head(c.path), starter_text)]
        files = own or files
    return files, problems


_NOT_PYTHON = {
    ".ipynb": "a Jupyter notebook: export it as a .py file (jupyter nbconvert --to script)",
    ".zip": "an archive: unpack it into the folder",
    ".tar": "an archive: unpack it into the folder",
    ".gz": "an archive: unpack it into the folder",
    ".pyc": "compiled Python: hand in the .py source",
}
"""What a student sometimes hands in instead of a .py file, and what to do about it."""


def _not_python(folder: Path) -> str:
    """", but NAME, what it is" for the first thing in ``folder`` that explains
    why no Python file was found: a folder turtletui may not read, a .py that
    is a link (never followed: it could point at anything on the grader's
    machine), a usual wrong hand-in (a notebook, an archive); else ""."""
    if not os.access(folder, os.R_OK | os.X_OK):
        return ", or turtletui may not read it (check its permissions)"
    unreadable = _unreadable_folder(folder)
    if unreadable is not None:
        return f", or none turtletui may read: it may not read {unreadable.relative_to(folder)} (check its permissions)"
    try:
        odd = sorted(p for p in folder.rglob("*.py") if (p.is_symlink() or not p.is_file()) and not ignored(p))
    except OSError:
        odd = []
    if odd:
        shown = odd[0].relative_to(folder)
        if odd[0].is_symlink():
            return f", but {shown} is a link (to {os.readlink(odd[0])}), which is not graded: hand in the file itself"
        if not odd[0].is_dir():
            return f", but {shown} is not a regular file (a pipe or a device?)"
    try:
        files = sorted(p for p in folder.rglob("*") if p.is_file() and not ignored(p))
    except OSError:
        return ""
    for path in files:
        what = _NOT_PYTHON.get(path.suffix.lower())
        if what is None and path.suffix.lower() == ".txt" and _looks_like_python(path):
            what = f"Python saved as text: name it {path.stem}.py"
        if what is not None:
            return f", but {path.relative_to(folder)}, {what}"
    return ""


def _unreadable_folder(folder: Path) -> Path | None:
    """The first folder under ``folder`` (within MAX_DEPTH) that cannot be listed, if any."""
    pending = [(folder, 0)]
    while pending:
        current, depth = pending.pop(0)
        try:
            entries = sorted(current.iterdir())
        except OSError:
            return current
        if depth < MAX_DEPTH:
            pending += [(e, depth + 1) for e in entries if e.is_dir() and not e.is_symlink() and not ignored(e)]
    return None


def _looks_like_python(path: Path) -> bool:
    """A text file that holds a node's code (not a note to the instructor)."""
    head = _read_head(path)
    return b"import rclpy" in head or b"from rclpy" in head


def choose_controller(
    folder: Path,
    *,
    executable: str | None = None,
    default_executable: str | None = None,
    starter: Path | None = None,
) -> Candidate:
    """The controller to grade in a student's folder; SubmissionError (one line,
    listing the candidates) when there is none or the choice is ambiguous."""
    candidates, problems = controller_candidates(folder, starter)
    listed = ", ".join(c.label for c in candidates)
    if executable is not None:
        chosen = [c for c in candidates if c.matches(executable)]
        if len(chosen) == 1:
            return chosen[0]
        if not chosen and len(candidates) == 1 and candidates[0].package is None:
            return candidates[0]  # a plain file upload: the executable named a package's node
        if not chosen:
            found = f"found: {listed}" if candidates else "found no Python controller"
            raise SubmissionError(f"{folder}: no executable {executable!r} ({found})")
        raise SubmissionError(
            f"{folder}: {len(chosen)} executables named {executable!r} "
            f"({', '.join(c.label for c in chosen)}): name one as PKG/NAME"
        )
    if default_executable is not None:
        chosen = [c for c in candidates if c.matches(default_executable)]
        if len(chosen) == 1:
            return chosen[0]
    if len(candidates) == 1:
        return candidates[0]
    if not candidates:
        why = f"; {problems[0]}" if problems else f": the folder has no Python (.py) file{_not_python(folder)}"
        raise SubmissionError(f"{folder}: no controller{why}")
    raise SubmissionError(
        f"{folder}: several possible controllers ({listed}): choose one with --executable NAME"
    )


# -- paths on the command line -----------------------------------------------------------


def _file_problem(path: Path) -> str | None:
    if path.suffix != ".py":
        return f"{path}: not a Python file (a controller is a .py file)"
    try:
        size = path.stat().st_size
    except OSError as err:
        return f"{path}: cannot read it ({err.strerror})"
    if size > MAX_SOURCE_BYTES:
        return f"{path}: {size} bytes is too large for a controller (at most {MAX_SOURCE_BYTES})"
    return None


@dataclass(frozen=True)
class _Choice:
    executable: str | None
    default_executable: str | None
    starter: Path | None


def _student(path: Path, choice: _Choice, name: str | None = None) -> Submission:
    student = name or (path.name if path.is_dir() else path.stem)
    if not path.is_dir():
        error = _file_problem(path)
        return Submission(student, path, None if error else path, error, path.name if not error else None)
    try:
        chosen = choose_controller(
            path,
            executable=choice.executable,
            default_executable=choice.default_executable,
            starter=choice.starter,
        )
    except SubmissionError as err:
        return Submission(student, path, None, str(err))
    error = _file_problem(chosen.path)
    if error:
        return Submission(student, path, None, error)
    return Submission(student, path, chosen.path, None, chosen.label, chosen.function)


def _is_one_student(folder: Path) -> bool:
    """A folder is one student's work (not a class) when it holds Python files
    or a package of its own at its top level, or a workspace's ``src/``."""
    for entry in folder.iterdir():
        if ignored(entry):
            continue
        if entry.is_file() and (entry.suffix == ".py" or entry.name in _PACKAGE_FILES):
            return True
    return (folder / "src").is_dir() and bool(_package_roots(folder / "src"))


def _is_class_of_files(folder: Path, choice: _Choice) -> bool:
    """A folder whose top level holds several complete nodes (``.py`` files
    with a ``main()`` or a Node class), no package and no workspace, and where
    no executable was named, is a class of one-file submissions: each file is
    a student (the lesson's starter, copied in unchanged, is nobody's)."""
    if choice.executable is not None or any((folder / name).exists() for name in _PACKAGE_FILES):
        return False
    if (folder / "src").is_dir() and _package_roots(folder / "src"):
        return False
    nodes = [p for p in folder.iterdir() if p.is_file() and p.suffix == ".py" and not ignored(p) and _has_entry(p)]
    if choice.default_executable is not None and any(p.stem == choice.default_executable for p in nodes):
        return False  # one student's folder with the lesson's node (turtle_controller.py) among others
    return len(nodes) >= 2


def find_submissions(
    paths: list[Path],
    *,
    starter: Path | None = None,
    executable: str | None = None,
    default_executable: str | None = None,
    single: bool = False,
) -> list[Submission]:
    """Every student's submission under ``paths``, in a stable order, with
    unique student names (a clash gets ``-2``, ``-3``...).

    ``single``: each path is one student's work whatever its layout (a platform
    that grades one upload per container): an empty or unusable upload is that
    student's error, not a SubmissionError. Otherwise SubmissionError for a
    path that does not exist or a folder with nothing to grade."""
    choice = _Choice(executable, default_executable, starter)
    found: list[Submission] = []
    for path in paths:
        if not path.exists():
            raise SubmissionError(f"{path}: no such file or folder")
        if path.is_file() or single or (_is_one_student(path) and not _is_class_of_files(path, choice)):
            found.append(_single(path, choice) if single else _student(path, choice))
            continue
        students = sorted(p for p in path.iterdir() if p.is_dir() and not ignored(p))
        loose = sorted(p for p in path.iterdir() if p.is_file() and p.suffix == ".py" and not ignored(p))
        if not students and not loose:
            anything = any(not ignored(p) for p in path.iterdir())
            what = (
                f"no Python (.py) file and no student's folder in it{_not_python(path)}" if anything else "empty folder"
            )
            raise SubmissionError(f"{path}: {what}: no submissions to grade")
        # Files that are not Python next to the students' folders (notes.txt, a
        # README, .DS_Store) are not submissions: nobody is graded 0 for them.
        found.extend(_student(p, choice) for p in [*students, *loose])
    return _unique(found)


def _single(path: Path, choice: _Choice) -> Submission:
    """One upload, as a platform hands it over (a zip comes unpacked)."""
    name = path.stem if path.is_file() else path.name
    if path.is_dir() and not any(not ignored(p) for p in path.iterdir()):
        return Submission(name, path, None, f"{path}: the upload is empty: submit your controller (.py file or ROS package)")
    upload = _student(path, choice, name)
    if upload.controller is None and path.is_dir() and not _is_one_student(path):
        # an instructor's class folder given to a one-upload format, most likely
        students = [p for p in sorted(path.iterdir()) if p.is_dir() and not ignored(p)]
        if sum(_student(p, choice).controller is not None for p in students) > 1:
            upload = replace(upload, error=(
                f"{upload.error} (a class folder, one student per subfolder? this format grades one upload:"
                " grade the class with --format table, json or csv)"
            ))
    return upload


def _unique(submissions: list[Submission]) -> list[Submission]:
    seen: dict[str, int] = {}
    unique = []
    for sub in submissions:
        name = sub.student
        if name in seen:
            seen[name] += 1
            name = f"{name}-{seen[sub.student]}"
        else:
            seen[name] = 1
        unique.append(sub if name == sub.student else replace(sub, student=name))
    return unique
