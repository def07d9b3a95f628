"""Which ROS 2 distribution a run behaves as (``--distro``).

The distributions differ where a student's file can tell: up to Jazzy
turtlesim's own types are ``turtlesim/msg/Pose`` (``from turtlesim.msg
import Pose``); from Kilted on they live in ``turtlesim_msgs``. A run has
exactly one of the two, as a real installation has, and importing the other
fails as it would there, with one line saying why and what to do.
"""

from __future__ import annotations

import ast
import functools
import os
import re
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from importlib.abc import MetaPathFinder
from pathlib import Path
from typing import Any

from turtletui.interfaces import (
    InterfaceError,
    all_interfaces,
    get_interface,
    interface_name,
    show_package_as,
)
from turtletui.interfaces.type_descriptions import renamed_type_name


@dataclass(frozen=True)
class Distro:
    """A ROS 2 distribution: its name, release year, whether it is LTS, and
    the package turtlesim's interfaces are in."""

    name: str
    year: int
    lts: bool
    turtlesim_package: str

    @property
    def title(self) -> str:
        """``"Jazzy (LTS)"``."""
        return f"{self.name.capitalize()}{' (LTS)' if self.lts else ''}"


DISTROS = {
    d.name: d
    for d in (
        Distro("humble", 2022, True, "turtlesim"),
        Distro("jazzy", 2024, True, "turtlesim"),
        Distro("kilted", 2025, False, "turtlesim_msgs"),
        Distro("lyrical", 2026, True, "turtlesim_msgs"),
    )
}
NEWEST_LTS = max((d for d in DISTROS.values() if d.lts), key=lambda d: d.year).name
"""The default: what a student installing ROS 2 today gets (Lyrical Luth, May 2026)."""

ENV_VAR = "TURTLETUI_DISTRO"
"""Sets the default distro (a class whose course targets Jazzy sets it once)."""

_TURTLESIM_PACKAGES = ("turtlesim", "turtlesim_msgs")


def check_distro(name: str) -> str:
    """The distro's name in lower case; ValueError (one line) if unknown."""
    key = str(name).strip().lower()
    if key not in DISTROS:
        known = ", ".join(DISTROS)
        raise ValueError(f"unknown ROS 2 distro {name!r}: use one of {known}")
    return key


def resolve_distro(name: str | None = None, fallback: str | None = None) -> str:
    """The distro a run uses: ``name`` (the command line), else ``$TURTLETUI_DISTRO``,
    else ``fallback`` (a lesson's), else the newest LTS. ValueError (one line) if unknown."""
    if name is not None:
        return check_distro(name)
    value = os.environ.get(ENV_VAR, "").strip()
    if value:
        try:
            return check_distro(value)
        except ValueError as err:
            raise ValueError(f"${ENV_VAR}: {err}") from None
    return check_distro(fallback) if fallback is not None else NEWEST_LTS


def choose_distro(
    given: str | None, lesson: str | None = None, paths: Iterable[Path] = ()
) -> tuple[str | None, str | None]:
    """The distro of a run, and the line that says why when the files' imports
    chose it: ``given`` (``--distro``), else ``$TURTLETUI_DISTRO``, else the
    lesson's, else what the files import (:func:`distro_of_imports`); (None,
    None) when nothing chose one (the newest LTS then). ValueError (one line)
    for an unknown name."""
    if given is not None or lesson is not None or os.environ.get(ENV_VAR, "").strip():
        return resolve_distro(given, lesson), None
    return distro_of_imports(paths) or (None, None)


def distro_of_imports(paths: Iterable[Path]) -> tuple[str, str] | None:
    """The distro controller files need when nothing else chose one: files
    that import ``turtlesim`` (the course's ``from turtlesim.msg import Pose``)
    and none ``turtlesim_msgs`` run as Jazzy, the newest distro with that
    package; returns it with a line saying so, or None (the default holds).
    ``$TURTLETUI_DISTRO``, ``--distro`` and a lesson's distro come first."""
    if os.environ.get(ENV_VAR, "").strip():
        return None
    importers = {"turtlesim": [], "turtlesim_msgs": []}
    for path in paths:
        try:
            tree = ast.parse(Path(path).read_bytes())
        except (OSError, SyntaxError, ValueError):
            continue  # the run reports an unreadable file itself
        for package in _imported_packages(tree) & set(importers):
            importers[package].append(Path(path).name)
    if not importers["turtlesim"] or importers["turtlesim_msgs"]:
        return None
    newest = DISTROS[newest_with_package("turtlesim")]
    files = ", ".join(importers["turtlesim"])
    return newest.name, (
        f"{files} import{'s' if len(importers['turtlesim']) == 1 else ''} turtlesim's types from turtlesim: running as ROS 2"
        f" {newest.name.capitalize()}, the newest with that package (from Kilted on turtlesim's types are in"
        f" turtlesim_msgs); --distro chooses another"
    )


def newest_with_package(package: str) -> str:
    """The newest distro whose turtlesim interfaces are in ``package``."""
    return max((d for d in DISTROS.values() if d.turtlesim_package == package), key=lambda d: d.year).name


def distro_of_ros(ros_distro: str, turtlesim_package: str) -> str:
    """The distro to run as on a real ROS 2 graph (its ``$ROS_DISTRO`` and the
    package its turtlesim types are in), so both name types alike: that distro
    when turtletui knows it, else the newest with that package."""
    name = ros_distro.strip().lower()
    if name in DISTROS and DISTROS[name].turtlesim_package == turtlesim_package:
        return name
    return newest_with_package(turtlesim_package if turtlesim_package in _TURTLESIM_PACKAGES else "turtlesim_msgs")


def _imported_packages(tree: ast.AST) -> set[str]:
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name.partition(".")[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module.partition(".")[0])
    return found


def missing_package_message(package: str, distro: str) -> str:
    """What importing ``package`` (turtlesim or turtlesim_msgs) says where it is missing."""
    return f"No module named '{package}' ({missing_package_reason(distro)})"


def missing_package_reason(distro: str) -> str:
    """Why ``distro`` has the other turtlesim interface package only, and what to do."""
    if DISTROS[distro].turtlesim_package == "turtlesim":
        where, other, missing = "'turtlesim' up to Jazzy", "kilted or newer", "turtlesim_msgs"
    else:
        where, other, missing = "'turtlesim_msgs' from Kilted on", "jazzy or older", "turtlesim"
    return f"turtlesim's types are in {where}; this run is --distro {distro}, use --distro {other} for '{missing}'"


class MissingPackageFinder(MetaPathFinder):
    """Makes the turtlesim interface package the distro lacks fail to import."""

    def __init__(self, distro: str) -> None:
        self.distro = check_distro(distro)
        present = DISTROS[self.distro].turtlesim_package
        self.missing = next(p for p in _TURTLESIM_PACKAGES if p != present)

    def find_spec(self, fullname: str, path: object = None, target: object = None) -> None:
        if fullname.partition(".")[0] == self.missing:
            raise ModuleNotFoundError(missing_package_message(self.missing, self.distro), name=fullname)
        return None


def install_finder(distro: str) -> None:
    """Put the finder for ``distro`` first on sys.meta_path (replacing an
    earlier one) and forget modules of the package it hides."""
    finder = MissingPackageFinder(distro)
    sys.meta_path[:] = [f for f in sys.meta_path if not isinstance(f, MissingPackageFinder)]
    sys.meta_path.insert(0, finder)
    for name in list(sys.modules):
        if name.partition(".")[0] == finder.missing:
            del sys.modules[name]


def current_distro() -> str:
    """The distro this process's ROS packages are installed as (see install_finder)."""
    for finder in sys.meta_path:
        if isinstance(finder, MissingPackageFinder):
            return finder.distro
    return NEWEST_LTS


def package_renames(distro: str) -> dict[str, str]:
    """How ``distro`` renames turtletui's interface packages (old -> new): the
    one source of the names a run shows. turtletui defines turtlesim's types
    as ``turtlesim/...``; from Kilted on they are ``turtlesim_msgs/...``."""
    package = DISTROS[check_distro(distro)].turtlesim_package
    return {"turtlesim": package} if package != "turtlesim" else {}


def ros_type_name(type_name: str, distro: str) -> str:
    """A type's full name as ``distro`` has it (``turtlesim/msg/Pose`` is
    ``turtlesim_msgs/msg/Pose`` from Kilted on); other names as they are."""
    return renamed_type_name(type_name, package_renames(distro))


def type_namer(distro: str) -> Callable[[Any], str]:
    """``interface_name`` as ``distro`` names types, for a graph's endpoints."""
    renames = package_renames(distro)

    @functools.cache
    def name(cls: type) -> str:
        return renamed_type_name(interface_name(cls), renames)

    return name


def lacks_package_of(type_name: str, distro: str) -> bool:
    """Whether ``type_name`` (``turtlesim/srv/Spawn``, dotted or short) is in
    the turtlesim interface package ``distro`` does not have."""
    package = re.split(r"[/.]", str(type_name).strip(), maxsplit=1)[0]
    return package == MissingPackageFinder(distro).missing


def distro_interface(type_name: str, distro: str) -> type:
    """``get_interface`` as ``distro``'s ROS knows types: a name in the
    turtlesim package it lacks is unknown there (InterfaceError saying why)."""
    if lacks_package_of(type_name, distro):
        raise InterfaceError(f"unknown interface type '{type_name}' ({missing_package_reason(distro)})",
                             type_name=str(type_name))
    return get_interface(type_name)


def distro_interfaces(distro: str) -> list[str]:
    """Every interface ``distro`` has, by full name, sorted (``ros2 interface list``)."""
    return sorted(ros_type_name(name, distro) for name in all_interfaces())


def show_types_as(distro: str) -> None:
    """Make messages print (repr) with the package names ``distro`` has."""
    show_package_as("turtlesim", package_renames(distro).get("turtlesim", "turtlesim"))


def type_description_names(distro: str) -> tuple[tuple[str, str], ...] | None:
    """How ``distro`` names turtlesim's types in type descriptions and hashes
    (turtletui.interfaces.type_descriptions.Names: turtlesim_msgs from Kilted
    on); None where nodes serve no ~/get_type_description (Humble: Iron on)."""
    if check_distro(distro) == "humble":
        return None
    return tuple(package_renames(distro).items())
