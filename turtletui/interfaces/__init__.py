"""ROS 2 message, service and action types in pure Python.

Student rclpy code imports these through shim packages (``geometry_msgs.msg``
etc. re-export the per-package modules here) and must behave as with real
ROS 2: same field names, defaults, checks, ``repr``, equality.

Public helpers (the registry and the JSON bridge to the sandboxed process):

* :func:`get_interface` -- name ("geometry_msgs/msg/Twist", "geometry_msgs/Twist",
  "turtlesim/srv/SetPen", ...) -> class; :class:`InterfaceError` with close
  matches if unknown.
* :func:`interface_name` -- class or instance -> full ROS name.
* :func:`all_interfaces` -- every top-level msg/srv/action name, sorted.
* :func:`ros_module_members` -- the classes of one ROS python module
  (``turtlesim.srv``), for the shim packages; :func:`ros_submodules` -- the
  modules rosidl generates in it (``turtlesim.srv._spawn``).
* :func:`definition_text` -- what ``ros2 interface show`` prints.
* :func:`show_package_as` -- the package name a package's messages print with.
* :func:`to_dict` / :func:`from_dict` -- plain nested dicts for JSON; from_dict
  validates untrusted data completely.
* :func:`copier` -- the fast copy function of a message class (what a
  subscriber of a serialising middleware receives).

Every message class also has ``_trusted(*values)`` (no-check positional
constructor for the simulator) and ``_TYPE_NAME`` (its full ROS name).
Only the standard library is imported.
"""

from __future__ import annotations

from array import array as _array
from math import copysign as _copysign
from math import isinf as _isinf
from operator import attrgetter as _attrgetter
from struct import Struct as _Struct

from turtletui.interfaces import (  # noqa: F401  (registers every type)
    action_msgs,
    builtin_interfaces,
    example_interfaces,
    geometry_msgs,
    lifecycle_msgs,
    nav_msgs,
    rcl_interfaces,
    rosgraph_msgs,
    sensor_msgs,
    service_msgs,
    std_msgs,
    std_srvs,
    tf2_msgs,
    turtlesim,
    type_description_interfaces,
    unique_identifier_msgs,
    visualization_msgs,
)
from turtletui.interfaces._message import (
    _F32_BOUND,
    _FIXED,
    _PACKAGE_ALIASES,
    _REGISTRY,
    _SCALAR,
    _TOP_LEVEL,
    Action,
    FieldSpec,
    InterfaceError,
    Message,
    Service,
    _build,
    show_package_as,
)
from turtletui.interfaces._values import compile_values

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

__all__ = [
    'Action',
    'FieldSpec',
    'InterfaceError',
    'Message',
    'Service',
    'all_interfaces',
    'build_from_values',
    'copier',
    'definition_text',
    'fields_getter',
    'from_dict',
    'from_values',
    'get_interface',
    'interface_name',
    'ros_module_members',
    'ros_submodules',
    'show_package_as',
    'to_dict',
    'to_values',
    'trusted_from_values',
]

_KINDS = ('msg', 'srv', 'action')


def _describe(value: Any) -> str:
    from turtletui.interfaces._hints import describe

    return describe(value)


# --------------------------------------------------------------------------
# registry
# --------------------------------------------------------------------------

def _candidates(name: str) -> list[str]:
    text = name.strip()
    if '/' not in text and text.count('.') >= 1:
        text = text.replace('.', '/')  # 'geometry_msgs.msg.Twist' (the repr form)
    parts = text.split('/')
    if len(parts) not in (2, 3) or not all(parts):
        return []
    parts[0] = _PACKAGE_ALIASES.get(parts[0], parts[0])
    if len(parts) == 3:
        return ['/'.join(parts)]
    return [f'{parts[0]}/{kind}/{parts[1]}' for kind in _KINDS]


def get_interface(name: str | type) -> type:
    """Return the class for an interface name.

    Accepts ``"pkg/msg/Name"``, ``"pkg/srv/Name"``, ``"pkg/action/Name"``,
    the short ``"pkg/Name"`` form (msg, then srv, then action), the dotted
    repr form ``"pkg.msg.Name"``, sub-types such as ``"turtlesim/srv/SetPen_Request"``
    and the ``turtlesim_msgs`` package alias. A class is returned unchanged.
    Raises :class:`InterfaceError` (listing close matches) for unknown names.
    """
    if isinstance(name, type) and issubclass(name, (Message, Service, Action)):
        return name
    if not isinstance(name, str):
        raise InterfaceError(f'interface names are str, got {_describe(name)}')
    for candidate in _candidates(name):
        cls = _REGISTRY.get(candidate)
        if cls is not None:
            return cls
    raise InterfaceError(_unknown_message(name), type_name=name)


def _unknown_message(name: str) -> str:
    import difflib

    text = name.strip()
    message = f"unknown interface type '{name}'"
    known = list(_REGISTRY)
    if '/' not in text and '.' not in text:
        same = [n for n in _TOP_LEVEL if n.rsplit('/', 1)[1] == text]
        if same:
            return f"{message}; the full name is {' or '.join(same)}"
    short = {f'{n.split("/")[0]}/{n.split("/")[2]}': n for n in known}
    probe = text.replace('.', '/') if '/' not in text else text
    pool = known if probe.count('/') == 2 else list(short)
    lowered = {n.lower(): n for n in pool}
    close = difflib.get_close_matches(probe, pool, n=3, cutoff=0.6)
    if probe.lower() in lowered and lowered[probe.lower()] not in close:
        close.insert(0, lowered[probe.lower()])
    close = [short.get(n, n) if pool is not known else n for n in close]
    if close:
        return f"{message}; did you mean {', '.join(close)}?"
    return f'{message} (see all_interfaces() for the {len(_TOP_LEVEL)} known types)'


def interface_name(cls_or_instance: Any) -> str:
    """Full ROS name (``'geometry_msgs/msg/Twist'``) of an interface class or instance."""
    cls = cls_or_instance if isinstance(cls_or_instance, type) else type(cls_or_instance)
    if issubclass(cls, (Message, Service, Action)) and cls._TYPE_NAME:
        return cls._TYPE_NAME
    raise InterfaceError(f'{_describe(cls_or_instance)} is not a ROS interface type')


def all_interfaces() -> list[str]:
    """Every top-level interface name (msg, srv, action), sorted like ``ros2 interface list``."""
    return sorted(_TOP_LEVEL)


_EXPORTED_PARTS = {
    'srv': ('Event', 'Request', 'Response'),
    'action': tuple(f'{service}_{part}' for service in ('GetResult', 'SendGoal')
                    for part in ('Event', 'Request', 'Response')),
}
"""What rosidl_generator_py's ``__init__.py`` imports besides each interface
(Kilted's, measured): ``Spawn_Request`` from ``turtlesim_msgs.srv``."""


def ros_module_members(package: str, kind: str) -> dict[str, type]:
    """The classes a ROS python module exports, e.g. ``('turtlesim', 'srv')``:
    each interface and, as rosidl_generator_py writes them, a service's
    ``Spawn_Request``, ``Spawn_Response``, ``Spawn_Event`` and an action's
    ``RotateAbsolute_SendGoal_Request`` ... (its other parts only through it).

    For the shim packages: ``ros_module_members('turtlesim_msgs', 'msg')``
    gives ``Pose`` and ``Color`` (the same objects as for ``turtlesim``).
    Raises :class:`InterfaceError` if there are none.
    """
    package = _PACKAGE_ALIASES.get(package, package)
    prefix = f'{package}/{kind}/'
    members = {}
    for full_name in sorted(n for n in _TOP_LEVEL if n.startswith(prefix)):
        name = full_name[len(prefix):]
        members[name] = _REGISTRY[full_name]
        for part in _EXPORTED_PARTS.get(kind, ()):
            members[f'{name}_{part}'] = _REGISTRY[f'{full_name}_{part}']
    if not members:
        raise InterfaceError(f'no interfaces for {package}.{kind}')
    return members


def ros_submodules(package: str, kind: str) -> dict[str, dict[str, type]]:
    """The modules rosidl generates inside a ROS python module, one per
    interface, with the classes each defines, e.g. for ``('turtlesim_msgs',
    'srv')``: ``{'_spawn': {'Spawn': ..., 'Spawn_Request': ...,
    'Metaclass_Spawn': ..., ...}, ...}`` (named after the classes'
    ``__module__``, which follows the distro for turtlesim's)."""
    modules = {cls.__module__ for cls in ros_module_members(package, kind).values()}
    found: dict[str, dict[str, type]] = {}
    for cls in _REGISTRY.values():
        if cls.__module__ in modules:
            members = found.setdefault(cls.__module__.rpartition('.')[2], {})
            members[cls.__qualname__] = cls
            members[type(cls).__qualname__] = type(cls)
    return found


# --------------------------------------------------------------------------
# definition_text: `ros2 interface show`
# --------------------------------------------------------------------------

def definition_text(name_or_cls: Any, *, all_comments: bool = False,
                    no_comments: bool = False) -> str:
    """The interface definition exactly as ``ros2 interface show`` prints it.

    Top-level comments are kept, nested types are expanded below their field
    with one tab per level and without their comments; ``all_comments`` /
    ``no_comments`` act like the CLI flags. Services and actions keep their
    ``---`` separators. The result has no trailing newline (``print`` it).
    Accepts a name, a class or an instance.
    """
    if isinstance(name_or_cls, (Message, Service, Action)):
        cls: type = type(name_or_cls)
    else:
        cls = get_interface(name_or_cls)
    from turtletui.interfaces import _show

    out: list[str] = []
    _show.show(cls, get_interface, all_comments or not no_comments, all_comments, 0, out)
    return '\n'.join(out)


# --------------------------------------------------------------------------
# to_dict
# --------------------------------------------------------------------------

def _byte_to_int(value: bytes) -> int:
    return value[0]


def _scalar_to_plain(spec: FieldSpec) -> Callable[[Any], Any]:
    kind = spec.kind
    if kind == 'msg':
        return _to_dict
    if kind == 'byte':
        return _byte_to_int
    return {'float': float, 'int': int, 'bool': bool, 'str': str}[kind]


def _to_plain(spec: FieldSpec) -> Callable[[Any], Any]:
    conv = _scalar_to_plain(spec)
    if spec.array == _SCALAR:
        return conv
    if spec.typecode is not None and spec.array != _FIXED:
        def seq(value: Any) -> list:
            if value.__class__ is _array:
                return value.tolist()
            return [conv(v) for v in value]
        return seq
    return lambda value: [conv(v) for v in value]


def _to_dict_plan(cls: type) -> tuple:
    plan = cls.__dict__.get('_TO_DICT_PLAN')
    if plan is None:
        plan = tuple((s.name, s.get, _to_plain(s)) for s in cls._FIELDS)
        cls._TO_DICT_PLAN = plan
    return plan


def _to_dict(msg: Message) -> dict[str, Any]:
    return {name: conv(get(msg)) for name, get, conv in _to_dict_plan(type(msg))}


def to_dict(msg: Message) -> dict[str, Any]:
    """Message -> nested plain dicts / lists / numbers / str, ready for JSON.

    ``Twist`` gives ``{'linear': {'x': 5.0, 'y': 0.0, 'z': 0.0}, 'angular': {...}}``.
    Numeric arrays become lists of float/int, ``byte`` values become ints
    (0-255) and float subclasses (numpy) plain floats.
    """
    if not isinstance(msg, Message):
        raise InterfaceError(f'to_dict() needs a message instance, got {_describe(msg)}')
    return _to_dict(msg)


# --------------------------------------------------------------------------
# from_dict
# --------------------------------------------------------------------------

class _Bad(Exception):
    """Internal: a bad value; ``path`` is filled in while unwinding."""

    def __init__(self, what: str, value: Any, unknown_in: type | None = None) -> None:
        super().__init__(what)
        self.what = what
        self.value = value
        self.unknown_in = unknown_in
        self.path: list[str] = []


def _int_words(spec: FieldSpec) -> str:
    return f'an int in [{spec.lo}, {spec.hi}] ({spec.base})'


def _scalar_from_plain(spec: FieldSpec) -> Callable[[Any], Any]:
    kind = spec.kind
    if kind == 'float':
        f32 = spec.f32

        def conv(value: Any) -> Any:
            cls = value.__class__
            if cls is not float:
                if cls is not int:
                    raise _Bad('a float', value)
                try:
                    value = float(value)
                except OverflowError:
                    raise _Bad('a float (this number is too large)', value) from None
            if f32 and (value < -_F32_BOUND or value > _F32_BOUND) and not _isinf(value):
                raise _Bad(f'a float32 in [{-_F32_BOUND}, {_F32_BOUND}]', value)
            return value
        return conv
    if kind == 'int':
        lo, hi = spec.lo, spec.hi

        def conv(value: Any) -> Any:
            if value.__class__ is not int or not lo <= value <= hi:
                raise _Bad(_int_words(spec), value)
            return value
        return conv
    if kind == 'bool':
        def conv(value: Any) -> Any:
            if value.__class__ is not bool:
                raise _Bad('a bool', value)
            return value
        return conv
    if kind == 'str':
        strlen = spec.strlen

        def conv(value: Any) -> Any:
            if value.__class__ is not str:
                raise _Bad('a str', value)
            if strlen is not None and len(value) > strlen:
                raise _Bad(f'a str of at most {strlen} characters', value)
            return value
        return conv
    if kind == 'byte':
        def conv(value: Any) -> Any:
            if value.__class__ is not int or not 0 <= value <= 255:
                raise _Bad('an int in [0, 255] (byte)', value)
            return bytes((value,))
        return conv
    msg_cls = spec.msg_cls

    def conv(value: Any) -> Any:
        if value.__class__ is not dict:
            raise _Bad(f'a dict (a {msg_cls._TYPE_NAME} message)', value)
        return _from_dict(msg_cls, value)
    return conv


def _from_plain(spec: FieldSpec) -> Callable[[Any], Any]:
    conv = _scalar_from_plain(spec)
    if spec.array == _SCALAR:
        return conv
    arr, size = spec.array, spec.size
    tc = spec.typecode if arr != _FIXED else None
    if arr == _FIXED:
        need = f'a list of exactly {size} items'
    elif size is not None:
        need = f'a list of at most {size} items'
    else:
        need = 'a list'

    def seq(value: Any) -> Any:
        if value.__class__ is not list and value.__class__ is not tuple:
            raise _Bad(need, value)
        n = len(value)
        if (arr == _FIXED and n != size) or (size is not None and n > size):
            raise _Bad(need, value)
        out = []
        append = out.append
        for i, item in enumerate(value):
            try:
                append(conv(item))
            except _Bad as bad:
                bad.path.insert(0, f'[{i}]')
                raise
        if tc is not None:
            return _array(tc, out)
        return out
    return seq


def _from_dict_plan(cls: type) -> dict[str, tuple]:
    plan = cls.__dict__.get('_FROM_DICT_PLAN')
    if plan is None:
        plan = {s.name: (s.set, _from_plain(s)) for s in cls._FIELDS}
        cls._FROM_DICT_PLAN = plan
    return plan


def _from_dict(cls: type, data: dict) -> Message:
    plan = _from_dict_plan(cls)
    msg = cls._make_default()
    for key, value in data.items():
        entry = plan.get(key) if key.__class__ is str else None
        if entry is None:
            bad = _Bad('', key, unknown_in=cls)
            bad.path.append(str(key))
            raise bad
        try:
            entry[0](msg, entry[1](value))
        except _Bad as bad:
            bad.path.insert(0, key)
            raise
    return msg


def _render_path(parts: list[str]) -> str:
    text = ''
    for part in parts:
        if part.startswith('['):
            text += part
        else:
            text += ('.' if text else '') + part
    return text


def from_dict(cls: type | str, data: Any) -> Message:
    """Build a message of type *cls* (class or name) from plain dicts / lists.

    Meant for data from an untrusted process: every field is validated and
    anything wrong raises :class:`InterfaceError` naming the type and the
    field path, e.g. ``"geometry_msgs/msg/Twist: field 'linear.x' must be a
    float, got str 'a'"``. Unknown fields are errors; missing fields keep
    their defaults. Ints are accepted for float fields (never bools); byte
    fields take ints 0-255. NaN / infinity pass through unchanged (the
    caller decides about non-finite values).
    """
    target = _message_class(cls)
    root = target._TYPE_NAME
    if data.__class__ is not dict:
        raise InterfaceError(f'{root}: message data must be a dict, got {_describe(data)}',
                             type_name=root)
    try:
        return _from_dict(target, data)
    except _Bad as bad:
        raise _interface_error(root, bad) from None


def _message_class(cls: type | str) -> type:
    """The message class named by ``cls``; a service or action is an error."""
    target = get_interface(cls)
    if not issubclass(target, Message):
        raise InterfaceError(f'{target._TYPE_NAME} is not a message type; use its '
                             f'Request/Response (or Goal/Result/Feedback) class',
                             type_name=target._TYPE_NAME)
    return target


def _interface_error(root: str, bad: _Bad) -> InterfaceError:
    path = _render_path(bad.path)
    if bad.unknown_in is not None:
        fields = [s.name for s in bad.unknown_in._FIELDS]
        has = f"has fields: {', '.join(fields)}" if fields else 'has no fields'
        text = (f"{root}: unknown field '{path}' "
                f'({bad.unknown_in._TYPE_NAME} {has})')
    elif path:
        text = f"{root}: field '{path}' must be {bad.what}, got {_describe(bad.value)}"
    else:
        text = f"{root}: the message must be {bad.what}, got {_describe(bad.value)}"
    return InterfaceError(text, type_name=root, path=path)


# --------------------------------------------------------------------------
# to_values / from_values: the same, positionally (the sandbox's wire format)
# --------------------------------------------------------------------------

def _values_of(spec: FieldSpec) -> Callable[[Any], Any]:
    if spec.kind != 'msg':
        return _to_plain(spec)
    if spec.array == _SCALAR:
        return _to_values
    return lambda value: [_to_values(item) for item in value]


def _to_values_plan(cls: type) -> tuple:
    plan = cls.__dict__.get('_TO_VALUES_PLAN')
    if plan is None:
        plan = tuple((s.get, _values_of(s)) for s in cls._FIELDS)
        cls._TO_VALUES_PLAN = plan
    return plan


def _to_values_generic(msg: Message) -> list[Any]:
    return [conv(get(msg)) for get, conv in _to_values_plan(type(msg))]


def _to_values(msg: Message) -> list[Any]:
    return _values_functions(type(msg))[0](msg)


def to_values(msg: Message) -> list[Any]:
    """Message -> its field values in field order, nested messages as lists:
    ``Twist`` gives ``[[5.0, 0.0, 0.0], [0.0, 0.0, 1.5]]``. Compact for a wire."""
    functions = msg.__class__.__dict__.get('_VALUES_FUNCTIONS')  # only message classes have them
    if functions is not None:
        return functions[0](msg)  # the hot path: a sandbox's every message
    if not isinstance(msg, Message):
        raise InterfaceError(f'to_values() needs a message instance, got {_describe(msg)}')
    return _to_values(msg)


def _values_functions(cls: type) -> tuple[Callable, Callable, Callable]:
    """``(to_values, from_values, trusted_from_values)`` of ``cls`` (its from_values
    raises _Bad): compiled for a class of plain fields (turtletui.interfaces
    ._values), else the generic ones. Made once per class."""
    functions = cls.__dict__.get('_VALUES_FUNCTIONS')
    if functions is None:
        def checked(values: list) -> Message:
            return _from_values(cls, values)

        def trusted(values: list) -> Message:
            return from_values(cls, values)

        functions = compile_values(cls, checked) or (_to_values_generic, checked, trusted)
        cls._VALUES_FUNCTIONS = functions
    return functions


def _values_converter(spec: FieldSpec) -> Callable[[Any], Any]:
    if spec.kind != 'msg':
        return _from_plain(spec)
    msg_cls = spec.msg_cls

    def one(value: Any) -> Message:
        if value.__class__ is not list:
            raise _Bad(f'a list of the {msg_cls._TYPE_NAME} field values', value)
        return _from_values(msg_cls, value)

    if spec.array == _SCALAR:
        return one
    arr, size = spec.array, spec.size

    def seq(value: Any) -> list:
        if value.__class__ is not list or (arr == _FIXED and len(value) != size) or (
            size is not None and len(value) > size
        ):
            raise _Bad('a list of messages' + (f' ({size} at most)' if size else ''), value)
        out = []
        for i, item in enumerate(value):
            try:
                out.append(one(item))
            except _Bad as bad:
                bad.path.insert(0, f'[{i}]')
                raise
        return out
    return seq


def _from_values_plan(cls: type) -> tuple:
    plan = cls.__dict__.get('_FROM_VALUES_PLAN')
    if plan is None:
        plan = tuple((s.name, _values_converter(s)) for s in cls._FIELDS)
        cls._FROM_VALUES_PLAN = plan
    return plan


def _from_values(cls: type, values: list) -> Message:
    plan = _from_values_plan(cls)
    if len(values) != len(plan):
        raise _Bad(f'a list of {len(plan)} field values', values)
    # every value converted (checked) first, then set without a default built first
    args = []
    for (name, conv), value in zip(plan, values, strict=True):
        try:
            args.append(conv(value))
        except _Bad as bad:
            bad.path.insert(0, name)
            raise
    return cls._trusted(*args)


def from_values(cls: type | str, values: Any) -> Message:
    """Build a message from its field values in field order (see to_values),
    validating everything exactly as from_dict does."""
    target = _message_class(cls)
    root = target._TYPE_NAME
    if values.__class__ is not list:
        raise InterfaceError(f'{root}: message values must be a list, got {_describe(values)}',
                             type_name=root)
    try:
        return _values_functions(target)[1](values)
    except _Bad as bad:
        raise _interface_error(root, bad) from None


def build_from_values(cls: type, values: Any) -> Message:
    """``from_values(cls, values)`` for a message class (not a name): the same
    checks and errors, without looking the class up (a sandbox's every message)."""
    functions = cls.__dict__.get('_VALUES_FUNCTIONS')
    if functions is None or values.__class__ is not list:
        return from_values(cls, values)
    try:
        return functions[1](values)
    except _Bad as bad:
        raise _interface_error(cls._TYPE_NAME, bad) from None


def trusted_from_values(cls: type) -> Callable[[list], Message]:
    """A fast builder of ``cls`` messages from to_values output that the caller
    trusts (no checks for plain fields), e.g. what the simulator sends its own
    sandbox child. Falls back to the checked path for sequences and bytes."""
    functions = cls.__dict__.get('_VALUES_FUNCTIONS')
    return (functions or _values_functions(cls))[2]


def copier(cls: type) -> Callable[[Message], Message]:
    """The copy function of ``cls`` messages: ``copier(Twist)(msg)`` is a new
    Twist equal to ``msg`` that shares no nested message or sequence with it,
    made without checks (``msg`` was checked when its fields were set)."""
    if not (isinstance(cls, type) and issubclass(cls, Message)):
        raise InterfaceError(f'copier() needs a message class, got {_describe(cls)}')
    _build(cls)
    return cls._copy


_F32_STRUCT = _Struct('<f')


def _as_float32(value: float) -> float:
    """``value`` as a float32 field carries it over the middleware: rounded to
    the nearest float32 (an overflow becomes an infinity, as C's cast makes it)."""
    try:
        return _F32_STRUCT.unpack(_F32_STRUCT.pack(value))[0]
    except OverflowError:
        return _copysign(float('inf'), value)


def float32_rounder(cls: type) -> Callable[[Message], None] | None:
    """What the middleware does to a ``cls`` message's float32 fields: rounds
    them, in place, to float32 (rclpy keeps the Python float a field is set
    to; the subscriber gets what CDR carried: ``Pose(x=0.1)`` arrives as
    0.10000000149011612). Nested messages included; float32 sequences are
    ``array('f')`` and rounded already. None when ``cls`` has no such field."""
    if not (isinstance(cls, type) and issubclass(cls, Message)):
        raise InterfaceError(f'float32_rounder() needs a message class, got {_describe(cls)}')
    cached = cls.__dict__.get('_F32_ROUNDER', _MISSING_ROUNDER)
    if cached is not _MISSING_ROUNDER:
        return cached
    steps: list[Callable[[Message], None]] = []
    scalars = [spec.slot for spec in cls._FIELDS if spec.kind == 'float' and spec.f32 and spec.array == _SCALAR]
    if scalars:
        steps.append(_scalars_rounder(scalars))
    for spec in cls._FIELDS:
        slot = spec.slot
        if spec.kind == 'float' and spec.f32 and spec.array == _FIXED and spec.typecode is None:
            steps.append(lambda msg, slot=slot: setattr(msg, slot, [_as_float32(v) for v in getattr(msg, slot)]))
        elif spec.kind == 'msg':
            inner = float32_rounder(spec.msg_cls)
            if inner is None:
                continue
            if spec.array == _SCALAR:
                steps.append(lambda msg, slot=slot, inner=inner: inner(getattr(msg, slot)))
            else:
                steps.append(lambda msg, slot=slot, inner=inner: [inner(m) for m in getattr(msg, slot)])
    rounder = None
    if len(steps) == 1:
        rounder = steps[0]
    elif steps:

        def rounder(msg: Message) -> None:
            for step in steps:
                step(msg)

    type.__setattr__(cls, '_F32_ROUNDER', rounder)
    return rounder


def _scalars_rounder(slots: list[str]) -> Callable[[Message], None]:
    """Rounds the float32 scalars in ``slots`` (a message's own slot names) in
    one pack and unpack: a pose's five fields for the price of one (a
    subscription rounds every message it takes)."""
    floats = _Struct('<' + 'f' * len(slots))
    fields = ', '.join(f'_m.{slot}' for slot in slots)
    source = (
        'def round_scalars(_m):\n'
        '    try:\n'
        f'        {fields}, = _unpack(_pack({fields}))\n'
        '    except OverflowError:\n'
        f'        {fields}, = [_as_float32(_v) for _v in ({fields},)]\n'
    )
    namespace = {'_pack': floats.pack, '_unpack': floats.unpack, '_as_float32': _as_float32}
    exec(compile(source, '<turtletui float32 rounder>', 'exec'), namespace)
    return namespace['round_scalars']


_MISSING_ROUNDER = object()


def fields_getter(cls: type, *paths: str) -> Callable[[Message], tuple]:
    """A function reading the fields at ``paths`` (``"linear.x"``, scalars
    or nested messages) of a ``cls`` message as a tuple, in one C call
    straight from the slots, without the properties: what a reader of a few
    values takes of each message (turtlesim of a Twist)."""
    if not (isinstance(cls, type) and issubclass(cls, Message)):
        raise InterfaceError(f'fields_getter() needs a message class, got {_describe(cls)}')
    slots = []
    for path in paths:
        owner, names = cls, []
        for name in path.split('.'):
            spec = None if owner is None else next((f for f in owner._FIELDS if f.name == name), None)
            if spec is None or spec.array != _SCALAR:
                raise InterfaceError(f'{cls._TYPE_NAME} has no scalar field {path!r}', type_name=cls._TYPE_NAME)
            names.append(spec.slot)
            owner = spec.msg_cls
        slots.append('.'.join(names))
    getter = _attrgetter(*slots)
    return getter if len(slots) != 1 else lambda msg: (getter(msg),)
