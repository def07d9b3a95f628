"""Describe message classes as a program sees them: run under the real rclpy and under turtletui.

    python probe_messages.py PACKAGE...   (prints JSON on stdout)
    python probe_messages.py --identities PACKAGE...

For every message class of the packages (services' Request/Response and
actions' Goal/Result/Feedback included): its fields and their types, its
constants and field defaults, a default instance (as plain data, and its
repr), and what happens when each field is set to each of a list of values
(accepted and stored as what, or refused with which exception and sentence).
With the real rclpy it also gives the text of each interface file, read
where ament_index finds the package. With --identities it gives instead what
every class of the packages is called (``__module__``, ``__qualname__``,
``repr``, its metaclass, where ``import`` and pickle find it, a message
class's SLOT_TYPES) and what the package's modules hold.
tests/interfaces/test_real_definitions.py runs it both ways and compares.
"""

from __future__ import annotations

import array
import importlib
import json
import os
import pickle
import sys

os.environ["ROS_PYTHON_CHECK_FIELDS"] = "1"  # the real classes check only when asked (Iron on)

PROBES = [
    0, 1, -1, 255, 256, 2**31, 2**63, 2**64, 1.5, -0.5, 1e39, float("inf"), True, "a", "abc", b"a",
    None, [], [1], [1.5], [1.5, 2.5], [1, 2, 3], (1.5,), ["a"], [True], b"ab", "x" * 300,
    array.array("f", [1.0]), array.array("d", [1.0]), array.array("i", [1]), array.array("B", [1]),
]
SKIP = {"header", "stamp"}  # nested messages: probed in their own class


def plain(value):
    """A value as JSON-able data that does not depend on numpy or array reprs."""
    if hasattr(value, "get_fields_and_field_types"):
        return {name: plain(getattr(value, name)) for name in value.get_fields_and_field_types()}
    if isinstance(value, array.array):
        return ["array", value.typecode, value.tolist()]
    if type(value).__module__ == "numpy":
        return ["fixed", value.tolist()]
    if isinstance(value, bytes):
        return ["bytes", list(value)]
    if isinstance(value, list):
        return [plain(v) for v in value]
    if isinstance(value, float) and value != value:
        return "nan"
    if isinstance(value, float) and value in (float("inf"), -float("inf")):
        return str(value)
    return value


def sentence(exc: BaseException) -> str:
    """The exception's own sentence (turtletui adds a hint in parentheses after it)."""
    return f"{type(exc).__name__}: {str(exc).split(' (')[0]}"


def exported(package: str):
    """(kind, name, class) of every class the package's msg, srv and action modules export."""
    for kind in ("msg", "srv", "action"):
        try:
            module = importlib.import_module(f"{package}.{kind}")
        except ImportError:
            continue
        for name in sorted(n for n in dir(module) if n[0].isupper()):
            yield kind, name, getattr(module, name)


def message_classes(package: str):
    for kind, name, cls in exported(package):
        if "_" in name:
            continue  # a part (Spawn_Request): named below through its interface
        if kind == "msg":
            yield f"{package}/msg/{name}", cls
        elif kind == "srv":
            yield f"{package}/srv/{name}_Request", cls.Request
            yield f"{package}/srv/{name}_Response", cls.Response
        else:
            for part in ("Goal", "Result", "Feedback"):
                yield f"{package}/action/{name}_{part}", getattr(cls, part)


def constant_names(cls) -> list[str]:
    names = []
    for name in dir(cls):
        if name.startswith("_") or name == "SLOT_TYPES" or not name.isupper() and "__DEFAULT" not in name:
            continue
        if callable(getattr(cls, name)):
            continue
        names.append(name)
    return sorted(names)


def describe(cls) -> dict:
    default = cls()
    fields = cls.get_fields_and_field_types()
    has_fixed = any("[" in t for t in fields.values())
    sets = {}
    for field in fields:
        if field in SKIP:
            continue
        outcomes = []
        for value in PROBES:
            msg = cls()
            try:
                setattr(msg, field, value)
            except BaseException as exc:  # noqa: BLE001 - what is raised is the point
                outcomes.append(sentence(exc))
            else:
                outcomes.append(["ok", plain(getattr(msg, field))])
        sets[field] = outcomes
    try:
        cls(no_such_field=1)
        unknown = "accepted"
    except BaseException as exc:  # noqa: BLE001
        unknown = type(exc).__name__
    return {
        "fields": fields,
        "slots": list(cls.__slots__),
        "constants": {name: plain(getattr(cls, name)) for name in constant_names(cls)},
        "default": plain(default),
        "repr": None if has_fixed else repr(default),
        "sets": sets,
        "unknown_keyword": unknown,
        "equal_defaults": cls() == cls(),
    }


def definition_files(package: str) -> dict[str, str]:
    try:
        from ament_index_python.packages import get_package_share_directory

        share = get_package_share_directory(package)
    except (ImportError, OSError, LookupError):  # the ros-* wheels: no AMENT_PREFIX_PATH needed
        share = os.path.join(sys.prefix, "share", package)
    texts = {}
    for kind in ("msg", "srv", "action"):
        folder = os.path.join(share, kind)
        if not os.path.isdir(folder):
            continue
        for file in sorted(os.listdir(folder)):
            if file.endswith(f".{kind}"):
                with open(os.path.join(folder, file), "rb") as f:
                    texts[f"{package}/{kind}/{file.rsplit('.', 1)[0]}"] = f.read().decode("utf-8")
    return texts


def interface_classes(package: str):
    """(label, class) of every interface class of a package, its parts included."""
    for kind, name, cls in exported(package):
        label = f"{package}.{kind}.{name}"
        yield label, cls
        if "_" in name:
            continue  # a part the module exports too (Spawn_Request): its identity only
        parts = {"srv": ("Request", "Response", "Event"), "action": ("Goal", "Result", "Feedback", "Impl")}
        for part in parts.get(kind, ()):
            yield f"{label}.{part}", getattr(cls, part)
        if kind == "action":
            for part in ("SendGoalService", "GetResultService", "FeedbackMessage", "CancelGoalService",
                         "GoalStatusMessage"):
                inner = getattr(cls.Impl, part)
                yield f"{label}.Impl.{part}", inner
                for service_part in ("Request", "Response", "Event") if part.endswith("Service") else ():
                    yield f"{label}.Impl.{part}.{service_part}", getattr(inner, service_part)


def type_description(slot_type) -> dict:
    """One of SLOT_TYPES as plain data: its class (and the classes it is an
    instance of), its repr without the address, its attributes."""
    kind = type(slot_type)
    attributes = {}
    for klass in kind.__mro__:
        names = vars(klass).get("__slots__", ())
        for name in (names,) if isinstance(names, str) else names:  # rosidl's Array: __slots__ = ('size')
            value = getattr(slot_type, name)
            attributes[name] = type_description(value) if name == "value_type" else value
    text = repr(slot_type)
    return {
        "class": [f"{k.__module__}.{k.__qualname__}" for k in kind.__mro__],
        "repr": text[: text.find(" at 0x")] if " at 0x" in text else text,
        "attributes": attributes,
        "bounded": slot_type.has_maximum_size() if hasattr(slot_type, "has_maximum_size") else None,
    }


def slot_types(cls) -> list | None:
    """What a program sees of a message class's SLOT_TYPES (None for a service or action)."""
    if not hasattr(cls, "get_fields_and_field_types"):
        return None
    types = cls.SLOT_TYPES
    assert type(types) is tuple and types is cls.SLOT_TYPES and types == cls().SLOT_TYPES
    return [type_description(t) for t in types]


def identity(cls) -> dict:
    """What a program printing or pickling the class sees."""
    try:
        found = importlib.import_module(cls.__module__)
        for name in cls.__qualname__.split("."):
            found = getattr(found, name)
        importable = found is cls
    except (ImportError, AttributeError) as err:
        importable = f"{type(err).__name__}: {err}"
    module = sys.modules.get(cls.__module__)
    return {
        "module": cls.__module__,
        "qualname": cls.__qualname__,
        "name": cls.__name__,
        "repr": repr(cls),
        "str": str(cls),
        "doc": cls.__doc__,
        "metaclass": repr(type(cls)),
        "metaclass_doc": type(cls).__doc__,
        "importable": importable,
        "module_classes": sorted(n for n in vars(module) if n[0].isupper()) if module else None,
        "pickles": pickle.loads(pickle.dumps(cls)) is cls,
        "slot_types": slot_types(cls),
    }


def package_modules(package: str) -> dict:
    """The public names and the per-interface modules of the package's modules."""
    out = {}
    for kind in ("msg", "srv", "action"):
        try:
            module = importlib.import_module(f"{package}.{kind}")
        except ImportError:
            continue
        out[kind] = sorted(n for n in vars(module) if not n.startswith("__"))
    return out


def main() -> None:
    packages = [a for a in sys.argv[1:] if not a.startswith("--")]
    if "--identities" in sys.argv:
        out = {"classes": {}, "modules": {}}
        for package in packages:
            out["modules"][package] = package_modules(package)
            for label, cls in interface_classes(package):
                out["classes"][label] = identity(cls)
        json.dump(out, sys.stdout, sort_keys=True)
        return
    out = {"classes": {}, "files": {}}
    for package in packages:
        for name, cls in message_classes(package):
            out["classes"][name] = describe(cls)
        if "--files" in sys.argv:
            out["files"].update(definition_files(package))
    json.dump(out, sys.stdout, sort_keys=True)


if __name__ == "__main__":
    main()
