"""Generated ``to_values`` / ``from_values`` for messages of plain fields.

The sandbox sends every message across as its values (turtletui.interfaces
.to_values): a Twist is ``[[5.0, 0.0, 0.0], [0.0, 0.0, 1.5]]``. For a class
whose fields are all scalars or nested messages of scalars (Twist, Pose,
Color, Vector3 ...) the conversions are compiled once per class, like the
class's own ``__init__`` (turtletui.interfaces._message): straight-line code
instead of a loop over a plan with a call per field.

The checked builder accepts exactly what the generic one does without
converting anything (a float where a float is due, an int in range ...);
anything else, right or wrong, goes to the generic path, which converts it or
names what is wrong. Classes with sequences or bytes get no generated code.
"""

from __future__ import annotations

from turtletui.interfaces._message import _F32_BOUND, _SCALAR, FieldSpec, _build

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

_PLAIN_TYPES = {'float': '_F', 'int': '_I', 'bool': '_B', 'str': '_S'}
"""What to_values makes of a scalar of each kind (float(v) for a numpy float)."""


def _plain(spec: FieldSpec) -> bool:
    if spec.array != _SCALAR or spec.kind == 'byte':
        return False
    return spec.kind != 'msg' or all(_plain(f) for f in spec.msg_cls._FIELDS)


def plain_fields(cls: type) -> bool:
    """Whether ``cls``'s fields are scalars or messages of scalars, all the way down."""
    return all(_plain(f) for f in cls._FIELDS)


class _Source:
    """Generated code, with the names it needs."""

    def __init__(self) -> None:
        self.ns: dict[str, Any] = {
            '_new': object.__new__, '_L': list, '_F': float, '_I': int, '_B': bool, '_S': str,
            '_F32': _F32_BOUND,
        }
        self.lines: list[str] = []
        self.count = 0

    def name(self, prefix: str) -> str:
        self.count += 1
        return f'{prefix}{self.count}'

    def constant(self, value: Any) -> str:
        name = self.name('_k')
        self.ns[name] = value
        return name


def _to_expr(src: _Source, cls: type, obj: str) -> str:
    items = []
    for spec in cls._FIELDS:
        value = f'{obj}.{spec.slot}'
        if spec.kind == 'msg':
            items.append(_to_expr(src, spec.msg_cls, value))
        else:
            kind = _PLAIN_TYPES[spec.kind]
            items.append(f'(_t if (_t := {value}).__class__ is {kind} else {kind}(_t))')
    return '[' + ', '.join(items) + ']'


def _bad_test(src: _Source, spec: FieldSpec, v: str) -> str:
    """A test true when ``v`` is not a value the field takes as it is."""
    kind = spec.kind
    if kind == 'float':
        if spec.f32:  # inf and nan are fine too, but left to the generic path
            return f'{v}.__class__ is not _F or not -_F32 <= {v} <= _F32'
        return f'{v}.__class__ is not _F'
    if kind == 'int':
        return f'{v}.__class__ is not _I or not {src.constant(spec.lo)} <= {v} <= {src.constant(spec.hi)}'
    if kind == 'bool':
        return f'{v}.__class__ is not _B'
    if spec.strlen is not None:
        return f'{v}.__class__ is not _S or len({v}) > {spec.strlen}'
    return f'{v}.__class__ is not _S'


def _checks(src: _Source, cls: type, values: str, checked: bool) -> list[tuple[FieldSpec, Any]]:
    """Lines that take ``values`` apart into names (checking them when
    ``checked``); returns each field's spec with its name, or its parts."""
    pad = '    '
    names = [src.name('_v') for _ in cls._FIELDS]
    if checked:
        src.lines.append(f'{pad}if {values}.__class__ is not _L or len({values}) != {len(names)}:')
        src.lines.append(f'{pad}    return _slow(_values)')
    if names:
        src.lines.append(f'{pad}{", ".join(names)}{"," if len(names) == 1 else ""} = {values}')
    parts = []
    for spec, name in zip(cls._FIELDS, names, strict=True):
        if spec.kind == 'msg':
            parts.append((spec, _checks(src, spec.msg_cls, name, checked)))
            continue
        if checked:
            src.lines.append(f'{pad}if {_bad_test(src, spec, name)}:')
            src.lines.append(f'{pad}    return _slow(_values)')
        parts.append((spec, name))
    return parts


def _builds(src: _Source, cls: type, parts: list[tuple[FieldSpec, Any]]) -> str:
    """Lines that make the message from its parts; returns its name."""
    fields = [(spec, _builds(src, spec.msg_cls, part) if spec.kind == 'msg' else part) for spec, part in parts]
    name = src.name('_m')
    src.lines.append(f'    {name} = _new({src.constant(cls)})')
    src.lines.extend(f'    {name}.{spec.slot} = {value}' for spec, value in fields)
    return name


def compile_values(cls: type, slow: Callable[[list], Any]) -> tuple[Callable, Callable, Callable] | None:
    """``(to_values, from_values, trusted_from_values)`` compiled for ``cls``;
    ``slow(values)`` is the generic checked builder the compiled one falls back
    on. None when ``cls`` has fields that are not plain (see plain_fields)."""
    if not plain_fields(cls):
        return None
    _build(cls)
    src = _Source()
    src.ns['_slow'] = slow
    src.lines.append('def to_values(_s):')
    src.lines.append(f'    return {_to_expr(src, cls, "_s")}')
    src.lines.append('def from_values(_values):')
    parts = _checks(src, cls, '_values', checked=True)
    src.lines.append(f'    return {_builds(src, cls, parts)}')
    src.lines.append('def trusted_from_values(_values):')
    parts = _checks(src, cls, '_values', checked=False)
    src.lines.append(f'    return {_builds(src, cls, parts)}')
    exec(compile('\n'.join(src.lines) + '\n', f'<turtletui {cls._TYPE_NAME} values>', 'exec'), src.ns)
    return src.ns['to_values'], src.ns['from_values'], src.ns['trusted_from_values']
