"""turtletui's rclpy shim has the real rclpy's API surface (names and signatures).

rclpy_surface.json is recorded from the real rclpy by make_rclpy_surface.py (see its
docstring). For every function and method recorded there, turtletui's must take the same
parameters, in the same order, of the same kinds, with a default wherever rclpy has one (the
same default where rclpy's is a simple literal), and nothing more. The only exceptions are
listed in ALLOWED with the reason; an entry that no longer matches a difference fails too.
"""

from __future__ import annotations

import inspect
import json
from pathlib import Path

import pytest

# The same description of a signature as the one the JSON was made with, so
# the two sides of every comparison cannot drift apart.
from make_rclpy_surface import enum_members, params_of, resolve  # noqa: E402

from turtletui import compat

SURFACE = json.loads(Path(__file__).with_name("rclpy_surface.json").read_text(encoding="utf-8"))

# difference (as produced by differences() below) -> why it is acceptable.
# Entries read "<dotted name>: <what>" or "<dotted name>(<parameter>): <what>", exactly as the
# failure message prints them. Empty: every difference found so far was fixed in turtletui
# (parameters that turtletui accepts but ignores are not differences: they are there).
ALLOWED: dict[str, str] = {}


@pytest.fixture(scope="module", autouse=True)
def shim() -> None:
    compat.install()
    import rclpy

    assert rclpy.__file__.startswith(compat.SHIM_PATH), rclpy.__file__


def ours(path: str, kind: str) -> dict | None:
    """Our counterpart of a recorded callable, described like the JSON does."""
    owner_path, _, name = path.rpartition(".")
    try:
        owner = resolve(owner_path)
    except (ImportError, AttributeError):
        return None
    if kind == "function":
        func = getattr(owner, name, None)
        if func is None:
            return None
        return {"kind": "function", "params": params_of(inspect.signature(func), False)}
    if name == "__init__":
        return {"kind": "constructor", "params": params_of(inspect.signature(owner), False)}
    for klass in owner.__mro__:
        if name in vars(klass):
            raw = vars(klass)[name]
            break
    else:
        return None
    if raw is None:
        return {"kind": "disabled"}
    if isinstance(raw, property):
        return {"kind": "property"}
    if isinstance(raw, classmethod):
        return {"kind": "classmethod", "params": params_of(inspect.signature(getattr(owner, name)), False)}
    if isinstance(raw, staticmethod):
        return {"kind": "staticmethod", "params": params_of(inspect.signature(raw.__func__), False)}
    if inspect.isfunction(raw):
        return {"kind": "method", "params": params_of(inspect.signature(raw), True)}
    return {"kind": type(raw).__name__}


def differences(path: str, real: dict) -> list[str]:
    mine = ours(path, real["kind"])
    if mine is None:
        return [f"{path}: missing"]
    if mine["kind"] != real["kind"]:
        return [f"{path}: is a {mine['kind']}, rclpy's is a {real['kind']}"]
    if "params" not in real:
        return []
    found = []
    theirs = {p["name"]: p for p in real["params"]}
    ours_by_name = {p["name"]: p for p in mine["params"]}
    for p in real["params"]:
        q = ours_by_name.get(p["name"])
        where = f"{path}({p['name']})"
        if q is None:
            found.append(f"{where}: missing")
            continue
        if q["kind"] != p["kind"]:
            found.append(f"{where}: {q['kind']}, rclpy's is {p['kind']}")
        if p["has_default"] and not q["has_default"]:
            found.append(f"{where}: no default")
        elif not p["has_default"] and q["has_default"]:
            found.append(f"{where}: has a default, rclpy's has none")
        elif p["has_default"] and p["default"] is not None and q["default"] != p["default"]:
            found.append(f"{where}: default {q['default']}, rclpy's is {p['default']}")
    for q in mine["params"]:
        if q["name"] not in theirs:
            found.append(f"{path}({q['name']}): not in rclpy")
    common_real = [p["name"] for p in real["params"] if p["name"] in ours_by_name]
    common_ours = [q["name"] for q in mine["params"] if q["name"] in theirs]
    if common_real != common_ours:
        found.append(f"{path}: order {common_ours}, rclpy's is {common_real}")
    return found


@pytest.mark.parametrize("path", sorted(SURFACE["callables"]))
def test_signature_matches_rclpy(path):
    unexpected = [d for d in differences(path, SURFACE["callables"][path]) if d not in ALLOWED]
    assert unexpected == []


def test_every_allowed_difference_is_still_a_difference():
    found = {d for path, real in SURFACE["callables"].items() for d in differences(path, real)}
    assert sorted(set(ALLOWED) - found) == []


@pytest.mark.parametrize("path", sorted(SURFACE["names"]))
def test_name_exists(path):
    obj = resolve(path)
    assert isinstance(obj, type)
    if SURFACE["names"][path] == "exception":
        assert issubclass(obj, Exception)


@pytest.mark.parametrize("alias", sorted(SURFACE["aliases"]))
def test_alias_is_the_same_object(alias):
    assert resolve(alias) is resolve(SURFACE["aliases"][alias])


@pytest.mark.parametrize("path", sorted(SURFACE["enums"]))
def test_enum_members_match(path):
    cls = resolve(path)
    assert enum_members(cls) == SURFACE["enums"][path]
    # rclpy's action responses and lifecycle results are plain Enums (an int
    # compares unequal), the rest IntEnums
    plain = path in ("rclpy.action.GoalResponse", "rclpy.action.CancelResponse", "rclpy.lifecycle.TransitionCallbackReturn")
    assert all(isinstance(value, int) is not plain for value in cls.__members__.values())


@pytest.mark.parametrize("path", sorted(SURFACE["qos_profiles"]))
def test_qos_preset_fields_match(path):
    profile = resolve(path)
    assert {
        "history": profile.history.name,
        "depth": profile.depth,
        "reliability": profile.reliability.name,
        "durability": profile.durability.name,
        "lifespan_ns": profile.lifespan.nanoseconds,
        "deadline_ns": profile.deadline.nanoseconds,
        "liveliness": profile.liveliness.name,
        "liveliness_lease_duration_ns": profile.liveliness_lease_duration.nanoseconds,
        "avoid_ros_namespace_conventions": profile.avoid_ros_namespace_conventions,
    } == SURFACE["qos_profiles"][path]


def test_logging_keywords_are_the_ones_turtletui_knows():
    from turtletui.compat import logging as compat_logging

    recorded = SURFACE["logging_keywords"]
    filters = {
        name: {param: {"required": required} for param, required in params.items()}
        for name, params in compat_logging.FILTERS.items()
    }
    assert filters == recorded["filters"]
    assert sorted(compat_logging.SEVERITY_METHOD_KEYWORDS) == recorded["severity_methods"]
    assert sorted(compat_logging.LOG_KEYWORDS) == recorded["log"]
