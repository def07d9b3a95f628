"""Error messages for the message classes (imported only when something fails).

Every assertion starts with the exact sentence rclpy's generated classes use
and goes on, in parentheses, with a plain-language hint for students, e.g.
``The 'x' field must be of type 'float' (got int 2; ROS 2 wants a float here:
write 2.0)``.
"""

from __future__ import annotations

import reprlib

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from turtletui.interfaces._message import FieldSpec

_SCALAR, _SEQ, _BOUNDED, _FIXED = 0, 1, 2, 3

_repr = reprlib.Repr()
_repr.maxstring = 40
_repr.maxother = 40
_repr.maxlist = _repr.maxtuple = _repr.maxdict = _repr.maxset = 6
_repr.maxlevel = 3


def short(value: Any) -> str:
    """A bounded-length repr (values may come from untrusted processes)."""
    return _repr.repr(value)


def describe(value: Any) -> str:
    """``"int 2"``, ``"str 'a'"``, ``"None"``: type name and short repr."""
    if value is None:
        return 'None'
    return f'{type(value).__name__} {short(value)}'


def _float_literal(value: int) -> str:
    return f'{value}.0'


def type_word(spec: FieldSpec) -> str:
    if spec.kind == 'msg':
        return spec.msg_cls.__name__
    return spec.pytype.__name__


# ---- ROS's own sentences ---------------------------------------------------

def type_sentence(spec: FieldSpec) -> str:
    name = spec.name
    if spec.kind == 'msg':
        return f"The '{name}' field must be a sub message of type '{spec.msg_cls.__name__}'"
    if spec.kind == 'byte':
        return f"The '{name}' field must be of type 'bytes' or 'ByteString' with length 1"
    if spec.strlen is not None:
        return f"The '{name}' field must be string value not longer than {spec.strlen}"
    return f"The '{name}' field must be of type '{spec.pytype.__name__}'"


def range_sentence(spec: FieldSpec) -> str:
    if spec.kind == 'float':
        word = 'float' if spec.f32 else 'double'
        return f"The '{spec.name}' field must be a {word} in [{spec.lo}, {spec.hi}]"
    if spec.lo == 0:
        return f"The '{spec.name}' field must be an unsigned integer in [0, {spec.hi}]"
    return f"The '{spec.name}' field must be an integer in [{spec.lo}, {spec.hi}]"


def sequence_sentence(spec: FieldSpec) -> str:
    parts = ['a set or sequence']
    if spec.array == _BOUNDED:
        parts.append(f'with length <= {spec.size}')
    elif spec.array == _FIXED:
        parts.append(f'with length {spec.size}')
    if spec.strlen is not None:
        parts.append(f'and each string value not longer than {spec.strlen}')
    parts.append(f"and each value of type '{type_word(spec)}'")
    if spec.kind == 'int':
        if spec.lo == 0:
            parts.append(f'and each unsigned integer in [0, {spec.hi}]')
        else:
            parts.append(f'and each integer in [{spec.lo}, {spec.hi}]')
    elif spec.kind == 'float':
        word = 'float' if spec.f32 else 'double'
        parts.append(f'and each {word} in [{spec.lo:f}, {spec.hi:f}]')
    return f"The '{spec.name}' field must be {' '.join(parts)}"


# ---- hints -------------------------------------------------------------------

def _message_hint(spec: FieldSpec, value: Any, got: str) -> str:
    cls = spec.msg_cls
    example = ', '.join(f'{s.name}=...' for s in cls._FIELDS)
    ros_name = cls._TYPE_NAME
    pkg, kind, name = ros_name.split('/')
    top, _, part = name.partition('_')
    if part and kind != 'msg':  # e.g. RotateAbsolute.Goal
        how = f'write {top}.{part}({example}) (from {pkg}.{kind} import {top})'
    else:
        how = f'write {name}({example}) after: from {pkg}.{kind} import {name}'
    if hasattr(type(value), '_FIELDS') and hasattr(value, '_TYPE_NAME'):
        return f'got a {value._TYPE_NAME} message; ROS 2 wants a {ros_name} here: {how}'
    if isinstance(value, dict):
        return f'{got}; ROS 2 wants a {ros_name} message object here, not a dict: {how}'
    return f'{got}; ROS 2 wants a {ros_name} message here: {how}'


def scalar_hint(spec: FieldSpec, value: Any) -> str:
    """Explain a refused scalar value in plain language."""
    kind = spec.kind
    got = 'got ' + describe(value)
    if kind == 'float':
        want = 'ROS 2 wants a float here'
        if type(value) is bool:
            return f'{got}; {want}: write {float(value)!r}'
        if isinstance(value, int):
            return f'{got}; {want}: write {_float_literal(value)}'
        if isinstance(value, float):  # right type, out of range
            return f'{got}; a float32 field can only hold numbers up to about 3.4e38'
        if isinstance(value, str):
            return f'{got}; {want}: convert text with float(...)'
        if value is None:
            return f'{got}; {want}, e.g. 0.0'
        return f'{got}; {want}: convert it with float(...)'
    if kind == 'int':
        want = f'ROS 2 wants a whole number (int) for this {spec.base} field'
        if isinstance(value, float):
            if value.is_integer():
                return f'{got}; {want}: write {int(value)}'
            return f'{got}; {want}: use round(...) or int(...)'
        if isinstance(value, int):  # right type, out of range
            return f'{got}; {spec.base} holds whole numbers from {spec.lo} to {spec.hi}'
        if isinstance(value, str):
            return f'{got}; {want}: convert text with int(...)'
        return f'{got}; {want}'
    if kind == 'str':
        if isinstance(value, str):  # bounded string too long
            return f'got a str of length {len(value)}; at most {spec.strlen} characters fit'
        return f'{got}; ROS 2 wants a str here: convert it with str(...)'
    if kind == 'bool':
        return f'{got}; ROS 2 wants True or False here'
    if kind == 'byte':
        return f"{got}; ROS 2 wants a single byte here, e.g. b'\\x00' or bytes([65])"
    return _message_hint(spec, value, got)


def element_problem(spec: FieldSpec, index: int, v: Any) -> str:
    kind = spec.kind
    item = f'item [{index}] is {describe(v)}'
    if kind == 'float':
        if isinstance(v, int) and not isinstance(v, bool):
            return f'{item}: write {_float_literal(v)} (every item must be a float)'
        if isinstance(v, float):
            return f'{item}: too large for a float32'
        return f'{item}, but every item must be a float'
    if kind == 'int':
        if isinstance(v, float) and v.is_integer():
            return f'{item}: write {int(v)} (every item must be an int)'
        if isinstance(v, int):
            return f'{item}, outside [{spec.lo}, {spec.hi}]'
        return f'{item}, but every item must be an int'
    if kind == 'msg':
        return f'{item}, but every item must be a {spec.msg_cls._TYPE_NAME} message'
    return f"{item}, but every item must be of type '{type_word(spec)}'"


# ---- exceptions ------------------------------------------------------------

def _fail(sentence: str, hint: str) -> AssertionError:
    return AssertionError(f'{sentence} ({hint})')


def scalar_error(spec: FieldSpec, value: Any) -> AssertionError:
    """The AssertionError for a refused value of a scalar field."""
    in_type = (spec.kind == 'float' and isinstance(value, float)) or \
        (spec.kind == 'int' and isinstance(value, int))
    sentence = range_sentence(spec) if in_type else type_sentence(spec)
    return _fail(sentence, scalar_hint(spec, value))


def array_error(spec: FieldSpec, value: Any) -> AssertionError:
    """The AssertionError for an ``array.array`` of the wrong kind / size."""
    tc = spec.typecode
    if value.typecode != tc:
        return _fail(f"The '{spec.name}' array.array() must have the type code of '{tc}'",
                     f"got array.array with type code '{value.typecode}'; "
                     f'convert it with array.array({tc!r}, value) or pass a list')
    return _fail(f"The '{spec.name}' array.array() must have a size <= {spec.size}",
                 f'got {len(value)} items')


def sequence_error(spec: FieldSpec, value: Any, is_sequence: bool,
                   element_ok: Any) -> AssertionError:
    """The AssertionError for a refused value of a sequence / array field."""
    size = spec.size
    if not is_sequence:
        problem = f'ROS 2 wants a list of {type_word(spec)} here'
    elif spec.array == _BOUNDED and len(value) > size:
        problem = f'it has {len(value)} items but at most {size} fit'
    elif spec.array == _FIXED and len(value) != size:
        problem = f'it has {len(value)} items but exactly {size} are needed'
    else:
        problem = 'some item is wrong'
        for i, v in enumerate(value):
            if not element_ok(v):
                problem = element_problem(spec, i, v)
                break
    return _fail(sequence_sentence(spec), f'got {describe(value)}; {problem}')


def bad_kwargs_error(cls: type, kwargs: dict) -> AssertionError:
    """ROS's 'Invalid arguments passed to constructor' plus a did-you-mean hint."""
    import difflib

    unknown = sorted(kwargs)
    names = [s.name for s in cls._FIELDS]
    sentence = f"Invalid arguments passed to constructor: {', '.join(unknown)}"
    if names:
        plural = 's' if len(unknown) > 1 else ''
        hint = f"{cls._TYPE_NAME} has no field{plural} {', '.join(repr(u) for u in unknown)}"
        for wrong in unknown:
            close = difflib.get_close_matches(wrong, names, n=1)
            if close:
                hint += f"; did you mean '{close[0]}' instead of '{wrong}'?"
                break
        hint += f"{' ' if hint.endswith('?') else '. '}Its fields are: {', '.join(names)}"
    else:
        hint = f'{cls._TYPE_NAME} has no fields at all'
    return AssertionError(f'{sentence} ({hint})')
