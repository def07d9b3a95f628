"""Write turtletui/interfaces/<package>.py from a ROS 2 package's .msg/.srv/.action files.

turtletui's message classes are made from the exact text of ROS's interface
files (turtletui.interfaces._message), so that ``ros2 interface show``, MCAP
schemas and type hashes match ROS byte for byte. This script copies those
texts from a ROS installation into the modules, in an order where every
nested type is defined before it is used:

    python scripts/interfaces_from_ros.py --share /opt/ros/kilted/share geometry_msgs std_msgs

``--share`` is a folder holding ``<package>/msg/*.msg`` (and ``srv/``,
``action/``): a ROS installation's ``share/``, the ``share/`` of a venv with
the ros-* wheels (see scripts/real_ros_env.py), or a source checkout's
folder of packages. tests/interfaces/test_real_definitions.py checks the
result against the real files.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "turtletui" / "interfaces"

_PRIMITIVES = {
    "bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
    "int32", "uint32", "int64", "uint64", "string", "wstring",
}
_KINDS = ("msg", "srv", "action")
_WRAP = 90
"""Long definition lines are continued with a backslash near this column."""

DOCS = {
    "std_msgs": "std_msgs: Header, ColorRGBA, the wrapper messages and the MultiArrays.",
    "geometry_msgs": "geometry_msgs: points, vectors, poses, twists, wrenches and the rest.",
    "sensor_msgs": "sensor_msgs: LaserScan, Imu, Image, JointState, NavSatFix and the rest.",
    "nav_msgs": "nav_msgs: Odometry, Path, OccupancyGrid and the map and plan services.",
    "std_srvs": "std_srvs: Empty, Trigger and SetBool.",
    "example_interfaces": "example_interfaces: AddTwoInts, Fibonacci and the tutorials' simple types.",
    "tf2_msgs": "tf2_msgs: TFMessage (what /tf carries), TF2Error and tf2's service and action.",
    "rcl_interfaces": "rcl_interfaces: /rosout's Log, the parameter messages and the parameter services.",
    "lifecycle_msgs": "lifecycle_msgs: a managed (lifecycle) node's states, transitions and services.",
    "rosgraph_msgs": "rosgraph_msgs: Clock, what /clock carries when a node uses simulated time.",
    "service_msgs": "service_msgs: ServiceEventInfo, the header of a service's event messages.",
    "type_description_interfaces": (
        "type_description_interfaces: type descriptions and the GetTypeDescription service every node serves."
    ),
}


def _base_types(text: str, package: str) -> set[str]:
    """The ``pkg/Name`` of every non-primitive field type in a definition."""
    found = set()
    for line in text.splitlines():
        line = line.partition("#")[0].strip()
        if not line or line == "---":
            continue
        type_string = line.split()[0]
        base = re.sub(r"\[.*\]$", "", type_string)
        base = re.sub(r"<=\d+$", "", base)
        if base in _PRIMITIVES:
            continue
        found.add(base if "/" in base else f"{package}/{base}")
    return found


def _quote(text: str) -> str:
    """``text`` as a ``'''\\`` literal that evaluates to exactly ``text``."""
    out = []
    for line in text.split("\n"):
        line = line.replace("\\", "\\\\").replace("'''", "\\'\\'\\'").replace("\t", "\\t")
        if line.endswith(" "):
            line = line[:-1] + "\\x20"
        while len(line) > _WRAP + 10:
            cut = line.rfind(" ", 20, _WRAP)
            if cut < 0 or line[cut - 1 : cut] == "\\":
                break
            out.append(line[: cut + 1] + "\\")
            line = line[cut + 1 :]
        out.append(line)
    body = "\n".join(out)
    if body.endswith("'"):
        body = body[:-1] + "\\'"
    return "'''\\\n" + body + "'''"


def _read(share: list[Path], package: str) -> dict[str, tuple[str, str]]:
    """name -> (kind, text) of every interface of ``package``."""
    for folder in share:
        if (folder / package).is_dir():
            found = {}
            for kind in _KINDS:
                for path in sorted((folder / package / kind).glob(f"*.{kind}")):
                    found[path.stem] = (kind, path.read_bytes().decode("utf-8"))
            if found:
                return found
    sys.exit(f"{package}: no msg/, srv/ or action/ files under {', '.join(map(str, share))}")


def _order(package: str, items: dict[str, tuple[str, str]]) -> list[str]:
    """Names in an order where nested types come first (then by kind and name)."""
    done: list[str] = []
    visiting: set[str] = set()

    def visit(name: str) -> None:
        if name in done:
            return
        if name in visiting:
            sys.exit(f"{package}/{name}: recursive type")
        visiting.add(name)
        for dep in sorted(_base_types(items[name][1], package)):
            pkg, _, short = dep.partition("/")
            if pkg == package and short in items:
                visit(short)
        visiting.discard(name)
        done.append(name)

    for kind in _KINDS:
        for name in sorted(n for n, (k, _) in items.items() if k == kind):
            visit(name)
    return done


def module_source(package: str, items: dict[str, tuple[str, str]]) -> str:
    """The Python source of turtletui/interfaces/<package>.py."""
    deps = set()
    for _, text in items.values():
        deps |= {d.partition("/")[0] for d in _base_types(text, package)}
    kinds = {kind for kind, _ in items.values()}
    if "action" in kinds:
        deps |= {"action_msgs", "builtin_interfaces", "unique_identifier_msgs"}
    deps.discard(package)
    paths = ", ".join(f"{package}.{kind}" for kind in _KINDS if kind in kinds)
    lines = [
        f'"""{DOCS.get(package, package)}',
        "",
        f"Import path{'s' if len(kinds) > 1 else ''} in ROS 2: {paths}.",
        "Definitions copied from the ROS 2 interface packages (Apache-2.0) by",
        "scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.",
        '"""',
        "",
    ]
    for dep in sorted(deps):
        lines.append(f"from turtletui.interfaces import {dep} as _{dep}  # noqa: F401  (nested types)")
    factories = {"action": "define_action as _action", "msg": "define_message as _msg",
                 "srv": "define_service as _srv"}
    for kind in sorted(kinds):  # isort's order: by the name imported
        lines.append(f"from turtletui.interfaces._message import {factories[kind]}")
    lines += ["", "__all__ = ["]
    lines += [f"    '{name}'," for name in sorted(items)]
    lines += ["]", ""]
    short = {"msg": "_msg", "srv": "_srv", "action": "_action"}
    for name in _order(package, items):
        kind, text = items[name]
        lines.append(f"{name} = {short[kind]}('{package}/{kind}/{name}', {_quote(text)}, globals())")
        lines.append("")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--share", action="append", type=Path, required=True,
                        help="a folder of ROS packages (repeatable)")
    parser.add_argument("packages", nargs="+")
    args = parser.parse_args()
    for package in args.packages:
        items = _read(args.share, package)
        path = OUT / f"{package}.py"
        path.write_text(module_source(package, items))
        print(f"{path.relative_to(ROOT)}: {len(items)} interfaces")


if __name__ == "__main__":
    main()
