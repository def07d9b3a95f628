"""Message machinery: build fast rclpy-compatible classes from interface text.

Each type is made from the exact text of its .msg/.srv/.action file, so the
class and ``definition_text`` can never disagree. The classes behave like
those rosidl_generator_py writes: keyword-only constructor (unknown keyword
-> AssertionError), properties over ``__slots__`` named ``_x``, checked
assignment with ROS's own sentences (plus a hint, see _hints.py), ``==`` by
value, unhashable, ROS-style repr, ``get_fields_and_field_types()``.
ROS Iron+ only checks fields with ROS_PYTHON_CHECK_FIELDS=1 (Humble always
does); we always check, this being a teaching tool.

Speed: ``__init__``, ``_trusted``, ``_make_default``, ``_copy`` and the field
setters are generated source (like dataclasses), compiled the first time a
class is used, so importing the package stays cheap. Standard library only.
"""

from __future__ import annotations

import copyreg as _copyreg
import re as _re
from array import array as _array
from math import isinf as _isinf
from operator import attrgetter as _attrgetter

from turtletui.errors import TurtletuiError

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

_F32_BOUND = 3.402823466e+38
_F64_BOUND = 1.7976931348623157e+308
_new = object.__new__


class InterfaceError(TurtletuiError, ValueError):
    """Bad interface name or bad message data (e.g. in ``from_dict``).

    ``type_name`` is the full ROS name involved (or ``''``), ``path`` the field
    path such as ``'linear.x'`` or ``'ranges[3]'`` (or ``''``).
    """

    def __init__(self, message: str, type_name: str = '', path: str = '') -> None:
        super().__init__(message)
        self.type_name = type_name
        self.path = path


class _Missing:
    __slots__ = ()

    def __repr__(self) -> str:
        return '<default>'


_MISSING = _Missing()

# full name ('pkg/msg/Name', 'pkg/srv/Name_Request', ...) -> class
_REGISTRY: dict[str, type] = {}
# canonical names of the top-level interfaces (msg, srv, action)
_TOP_LEVEL: list[str] = []
# another package name for the same classes
_PACKAGE_ALIASES = {'turtlesim_msgs': 'turtlesim'}

# ROS type -> (get_fields_and_field_types name, python type, kind, lo, hi, typecode)
_PRIMITIVES: dict[str, tuple] = {
    'bool': ('boolean', bool, 'bool', None, None, None),
    'byte': ('octet', bytes, 'byte', None, None, None),
    'float32': ('float', float, 'float', -_F32_BOUND, _F32_BOUND, 'f'),
    'float64': ('double', float, 'float', -_F64_BOUND, _F64_BOUND, 'd'),
    'string': ('string', str, 'str', None, None, None),
    'wstring': ('wstring', str, 'str', None, None, None),
    # rosidl maps char to uint8: an int in [0, 255] in Python
    'char': ('uint8', int, 'int', 0, 255, 'B'),
}
for _bits, _code in ((8, 'b'), (16, 'h'), (32, 'i'), (64, 'q')):
    _PRIMITIVES[f'int{_bits}'] = (f'int{_bits}', int, 'int', -2 ** (_bits - 1),
                                  2 ** (_bits - 1) - 1, _code)
    _PRIMITIVES[f'uint{_bits}'] = (f'uint{_bits}', int, 'int', 0, 2 ** _bits - 1,
                                   _code.upper())

_ZERO = {'bool': False, 'byte': b'\x00', 'float': 0.0, 'int': 0, 'str': ''}

# FieldSpec.array values
_SCALAR, _SEQ, _BOUNDED, _FIXED = 0, 1, 2, 3


def is_primitive_type(base: str) -> bool:
    """True for ROS primitive type names, bounded ``string<=N`` / ``wstring<=N`` included."""
    return base in _PRIMITIVES or base.startswith(('string<=', 'wstring<='))


def _string_bound(base: str) -> tuple[str, int | None]:
    """('string' or 'wstring', N) for a bounded string type, (base, None) otherwise."""
    text, sep, bound = base.partition('<=')
    if sep and text in ('string', 'wstring'):
        return text, int(bound)
    return base, None


def _error(factory: str, *args: Any) -> Exception:
    """Build an exception with the (lazily imported) message helpers."""
    from turtletui.interfaces import _hints

    return getattr(_hints, factory)(*args)


class FieldSpec:
    """Everything known about one field of a message type.

    Read-only attributes: ``name``, ``slot`` (``'_' + name``), ``ros_type``
    (as written, package-qualified for messages: ``'geometry_msgs/Vector3'``,
    ``'float32[]'``), ``fields_type`` (the get_fields_and_field_types string),
    ``kind`` (``'float'``, ``'int'``, ``'bool'``, ``'str'``, ``'byte'`` or
    ``'msg'``), ``array`` (0 scalar, 1 sequence, 2 bounded sequence, 3 fixed
    array), ``size``, ``msg_cls``, ``typecode`` (array.array code of numeric
    sequences), ``lo``/``hi``, ``f32``, ``strlen``, ``default``, and the fast
    accessors ``get(msg)`` / ``set(msg, value)`` (the latter without checks).
    """

    __slots__ = (
        'name', 'slot', 'base', 'ros_type', 'fields_type', 'kind', 'pytype',
        'lo', 'hi', 'f32', 'typecode', 'msg_cls', 'array', 'size', 'strlen',
        'default', 'has_default', 'get', 'set', 'check', 'check_init',
    )

    def __repr__(self) -> str:
        return f'FieldSpec({self.name!r}, {self.ros_type!r})'

    def new_default(self) -> Any:
        """A fresh default value (new list / array / nested message)."""
        if self.array == _SCALAR:
            return self.msg_cls._make_default() if self.kind == 'msg' else self.default
        if self.has_default:
            value = list(self.default)
        elif self.array == _FIXED:
            if self.kind == 'msg':
                return [self.msg_cls._make_default() for _ in range(self.size)]
            value = [_ZERO[self.kind]] * self.size
        else:
            value = []
        if self.typecode is not None and self.array != _FIXED:
            return _array(self.typecode, value)
        return value

    def default_factory(self) -> Callable[[], Any]:
        """A zero-argument callable making fresh defaults, as fast as possible."""
        if self.array == _SCALAR and self.kind == 'msg':
            return self.msg_cls._make_default
        if self.array == _SEQ and not self.has_default:
            if self.typecode is not None:
                tc = self.typecode
                return lambda: _array(tc)
            return list
        return self.new_default


# --------------------------------------------------------------------------
# checkers: value -> value (maybe converted), or AssertionError
# --------------------------------------------------------------------------

def _element_test(spec: FieldSpec) -> Callable[[Any], bool]:
    kind, lo, hi = spec.kind, spec.lo, spec.hi
    if kind == 'float':
        return lambda v: isinstance(v, float) and (lo <= v <= hi or v != v or _isinf(v))
    if kind == 'int':
        return lambda v: isinstance(v, int) and lo <= v <= hi
    if kind == 'str' and spec.strlen is not None:
        strlen = spec.strlen
        return lambda v: isinstance(v, str) and len(v) <= strlen
    pytype = spec.msg_cls if kind == 'msg' else spec.pytype
    return lambda v: isinstance(v, pytype)


def _make_scalar_check(spec: FieldSpec) -> Callable[[Any], Any]:
    if spec.kind == 'byte':
        def test(v: Any) -> bool:
            return isinstance(v, (bytes, bytearray)) and len(v) == 1
    elif spec.kind == 'str' and spec.strlen is not None:
        strlen = spec.strlen

        def test(v: Any) -> bool:
            from collections import UserString

            return isinstance(v, (str, UserString)) and len(v) <= strlen
    else:
        test = _element_test(spec)

    def check(value: Any) -> Any:
        if test(value):
            return value
        raise _error('scalar_error', spec, value)
    return check


def _make_sequence_check(spec: FieldSpec) -> tuple[Callable, Callable]:
    """(setter check, constructor check) of a sequence / array field."""
    tc, kind, size = spec.typecode, spec.array, spec.size
    numeric_seq = tc is not None and kind != _FIXED
    test = _element_test(spec)

    def check(value: Any) -> Any:
        if numeric_seq and isinstance(value, _array):
            if value.typecode == tc and (kind != _BOUNDED or len(value) <= size):
                return value  # stored as is, like ROS
            raise _error('array_error', spec, value)
        if kind == _FIXED and tc is not None and hasattr(value, 'tolist') \
                and not isinstance(value, (list, tuple)):
            value = value.tolist()  # numpy array (ROS keeps these as numpy)
        from collections import UserList, UserString
        from collections.abc import Sequence, Set

        is_seq = isinstance(value, (Sequence, Set, UserList)) and \
            not isinstance(value, (str, UserString))
        if is_seq and (kind == _SEQ or (kind == _BOUNDED and len(value) <= size)
                       or (kind == _FIXED and len(value) == size)) \
                and all(test(v) for v in value):
            if numeric_seq:
                return _array(tc, value)
            return list(value) if tc is not None else value
        raise _error('sequence_error', spec, value, is_seq, test)

    if not numeric_seq:
        return check, check

    def check_init(value: Any) -> Any:
        # ROS converts with array.array() before the setter runs, so the
        # constructor takes e.g. ints for float32[] (the setter does not).
        return check(_array(tc, value))
    return check, check_init


# --------------------------------------------------------------------------
# parsing the .msg language
# --------------------------------------------------------------------------

def _literal(kind: str, text: str) -> Any:
    text = text.strip()
    if kind == 'bool':
        if text.lower() not in ('true', '1', 'false', '0'):
            raise ValueError(f'bad bool {text!r}')
        return text.lower() in ('true', '1')
    if kind == 'int':
        return int(text)
    if kind == 'float':
        return float(text)
    if kind == 'byte':
        return bytes((int(text),))
    if len(text) >= 2 and text[0] == text[-1] and text[0] in '\'"':
        return text[1:-1]
    return text


def _resolve_nested(base: str, package: str) -> type:
    pkg, _, name = (base if '/' in base else f'{package}/{base}').partition('/')
    for sub in ('msg', 'srv', 'action'):
        cls = _REGISTRY.get(f'{pkg}/{sub}/{name}')
        if cls is not None and issubclass(cls, Message):
            return cls
    raise LookupError(f'nested type {pkg}/{name} is not defined (yet)')


def _make_field(package: str, type_string: str, name: str, default: str | None) -> FieldSpec:
    spec = FieldSpec()
    spec.name, spec.slot = name, '_' + name
    base, spec.array, spec.size, spec.strlen = type_string, _SCALAR, None, None
    if base.endswith(']'):
        base, _, bracket = base[:-1].partition('[')
        if bracket == '':
            spec.array = _SEQ
        elif bracket.startswith('<='):
            spec.array, spec.size = _BOUNDED, int(bracket[2:])
        else:
            spec.array, spec.size = _FIXED, int(bracket)
    string_type, spec.strlen = _string_bound(base)
    if is_primitive_type(base):
        ftype, pytype, kind, lo, hi, tc = _PRIMITIVES[string_type]
        if spec.strlen is not None:
            ftype = f'{string_type}<{spec.strlen}>'
        spec.msg_cls = None
        spec.ros_type = type_string
    else:
        spec.msg_cls = _resolve_nested(base, package)
        type_pkg, _, type_name = spec.msg_cls._TYPE_NAME.split('/')
        ftype = f'{type_pkg}/{type_name}'
        pytype, kind, lo, hi, tc = spec.msg_cls, 'msg', None, None, None
        spec.ros_type = ftype + type_string[len(base):]
    spec.base, spec.kind, spec.pytype, spec.lo, spec.hi = base, kind, pytype, lo, hi
    spec.f32 = base == 'float32'
    spec.typecode = tc
    spec.fields_type = (ftype, f'sequence<{ftype}>', f'sequence<{ftype}, {spec.size}>',
                        f'{ftype}[{spec.size}]')[spec.array]
    spec.get = _attrgetter(spec.slot)
    if spec.array == _SCALAR:
        spec.check = spec.check_init = _make_scalar_check(spec)
    else:
        spec.check, spec.check_init = _make_sequence_check(spec)
    spec.has_default = default is not None
    if default is None:
        spec.default = _ZERO[kind] if spec.array == _SCALAR and kind != 'msg' else None
    elif spec.array == _SCALAR:
        spec.default = spec.check(_literal(kind, default))
    else:
        inner = default.strip()[1:-1].strip()
        spec.default = tuple(_literal(kind, p) for p in inner.split(',')) if inner else ()
    return spec


def _parse_section(package: str, text: str) -> tuple[list[FieldSpec], dict[str, Any]]:
    """Fields and constants of one message body (no ``---`` inside)."""
    fields: list[FieldSpec] = []
    constants: dict[str, Any] = {}
    for line in text.splitlines():
        line = line.replace('\t', ' ').partition('#')[0].strip()
        if not line:
            continue
        type_string, _, rest = line.partition(' ')
        rest = rest.lstrip()
        if '=' in rest:
            cname, _, value = rest.partition('=')
            kind = _PRIMITIVES[_string_bound(type_string)[0]][2]
            constants[cname.strip()] = _literal(kind, value)
            continue
        name, _, default = rest.partition(' ')
        fields.append(_make_field(package, type_string, name, default.strip() or None))
    return fields, constants


def _split_sections(text: str) -> list[str]:
    sections: list[list[str]] = [[]]
    for line in text.splitlines():
        if line.rstrip() == '---':
            sections.append([])
        else:
            sections[-1].append(line)
    return ['\n'.join(lines) + '\n' if lines else '' for lines in sections]


# --------------------------------------------------------------------------
# base classes
# --------------------------------------------------------------------------

class _SlotTypes:
    """A message class's ``SLOT_TYPES``: its fields' types as
    rosidl_parser.definition objects, in field order (see rosidl_definition.py),
    made the first time a program asks."""

    def __get__(self, obj: object, cls: type) -> tuple:
        types = cls.__dict__.get('_slot_types')
        if types is None:
            types = tuple(_slot_type(spec) for spec in cls._FIELDS)
            cls._slot_types = types
        return types


def _slot_type(spec: FieldSpec) -> Any:
    """The rosidl_parser.definition type of a field, as rosidl_generator_py writes it."""
    from turtletui.interfaces import rosidl_definition as d

    if spec.kind == 'msg':
        package, kind, name = spec.msg_cls._TYPE_NAME.split('/')
        shown = _SHOWN.get(package)
        value: Any = d.NamespacedType([shown[1] if shown else package, kind], name)
    elif spec.kind == 'str':
        wide = spec.base.startswith('wstring')
        if spec.strlen is None:
            value = d.UnboundedWString() if wide else d.UnboundedString()
        else:
            value = d.BoundedWString(spec.strlen) if wide else d.BoundedString(spec.strlen)
    else:
        value = d.BasicType(_PRIMITIVES[spec.base][0])
    if spec.array == _SEQ:
        return d.UnboundedSequence(value)
    if spec.array == _BOUNDED:
        return d.BoundedSequence(value, spec.size)
    if spec.array == _FIXED:
        return d.Array(value, spec.size)
    return value


class Message:
    """Base class of every message class (not part of ROS)."""

    __slots__ = ()
    SLOT_TYPES = _SlotTypes()

    _TYPE_NAME = ''          # full ROS name, e.g. 'geometry_msgs/msg/Twist'
    _REPR_PREFIX = ''        # e.g. 'geometry_msgs.msg.Twist'
    _DEFINITION = ''         # the .msg text
    _FIELDS: tuple[FieldSpec, ...] = ()
    _fields_and_field_types: dict[str, str] = {}

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, self.__class__):
            return False
        for spec in self._FIELDS:
            if spec.get(self) != spec.get(other):
                return False
        return True

    def __repr__(self) -> str:
        args = []
        for spec in self._FIELDS:
            value = spec.get(self)
            text = repr(value)
            if spec.typecode is not None and spec.array != _FIXED and \
                    value.__class__ is _array:
                text = text[len("array('X', "):-1] if value else '[]'
            args.append(f'{spec.name}={text}')
        return f"{self._REPR_PREFIX}({', '.join(args)})"

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]:
        """Field name -> ROS type string, exactly as rclpy messages return it."""
        return dict(cls._fields_and_field_types)


class Service:
    """Base class of service classes (``Request`` / ``Response`` inside)."""

    _TYPE_NAME = ''
    _DEFINITION = ''

    def __init__(self) -> None:
        raise NotImplementedError('Service classes can not be instantiated')


class Action:
    """Base class of action classes (``Goal`` / ``Result`` / ``Feedback``, ``Impl``)."""

    _TYPE_NAME = ''
    _DEFINITION = ''

    def __init__(self) -> None:
        raise NotImplementedError('Action classes can not be instantiated')


# --------------------------------------------------------------------------
# lazy code generation
# --------------------------------------------------------------------------

def _bad_kwargs(self: Message, kwargs: dict) -> None:
    raise _error('bad_kwargs_error', type(self), kwargs)


def _init_expr(spec: FieldSpec, i: int) -> str:
    n = spec.name
    if spec.array != _SCALAR:
        return f'_d{i}() if {n} is _M else _c{i}({n})'
    if spec.kind == 'msg':
        return f'_d{i}() if {n} is _M else ({n} if {n}.__class__ is _T{i} else _c{i}({n}))'
    if spec.kind in ('int', 'float') and (spec.kind == 'int' or spec.f32):
        return f'{n} if ({n}.__class__ is _T{i} and _lo{i} <= {n} <= _hi{i}) else _c{i}({n})'
    if spec.kind in ('float', 'bool') or (spec.kind == 'str' and spec.strlen is None):
        # every Python float is a valid float64 (inf and nan included)
        return f'{n} if {n}.__class__ is _T{i} else _c{i}({n})'
    return f'_c{i}({n})'


def _plain_copy(spec: FieldSpec, value: str, pytype: str) -> str:
    """The copy of a scalar field's ``value`` as the middleware carries it: a
    value of a subclass (numpy's float64, an IntEnum, a str subclass) arrives
    as the plain int, float, bool or str."""
    if spec.kind not in ('int', 'float', 'bool', 'str'):
        return value
    return f'_a if (_a := {value}).__class__ is {pytype} else {pytype}(_a)'


def _build(cls: type) -> None:
    """Compile ``__init__``, ``_trusted`` and ``_make_default`` for *cls*."""
    if '_BUILT' in cls.__dict__:
        return
    specs = cls._FIELDS
    ns: dict[str, Any] = {'_M': _MISSING, '_new': _new, '_cls': cls, '_bad': _bad_kwargs}
    params, body, default_body = [], [], []
    for i, spec in enumerate(specs):
        ns.update({f'_T{i}': spec.pytype, f'_c{i}': spec.check_init,
                   f'_lo{i}': spec.lo, f'_hi{i}': spec.hi})
        if spec.array == _SCALAR and spec.kind == 'msg':
            _build(spec.msg_cls)  # capture the real factory, not the lazy stub
        if spec.array == _SCALAR and spec.kind != 'msg':
            ns[f'_k{i}'] = spec.default
            params.append(f'{spec.name}=_k{i}, ')
            default_body.append(f'    _o.{spec.slot} = _k{i}')
        else:
            ns[f'_d{i}'] = spec.default_factory()
            params.append(f'{spec.name}=_M, ')
            default_body.append(f'    _o.{spec.slot} = _d{i}()')
        inner = spec.msg_cls._FIELDS if spec.array == _SCALAR and spec.kind == 'msg' else None
        if inner is not None and all(f.array == _SCALAR and f.kind != 'msg' for f in inner):
            # A flat nested message (Vector3 in Twist) defaults inline: no call.
            n = spec.name
            body.append(f'    if {n} is _M:')
            body.append(f'        _v = _new(_T{i})')
            for j, field in enumerate(inner):
                ns[f'_k{i}_{j}'] = field.default
                body.append(f'        _v.{field.slot} = _k{i}_{j}')
            body.append(f'        self.{spec.slot} = _v')
            body.append('    else:')
            body.append(f'        self.{spec.slot} = {n} if {n}.__class__ is _T{i} else _c{i}({n})')
        else:
            body.append(f'    self.{spec.slot} = {_init_expr(spec, i)}')
    copy_lines = []
    for i, spec in enumerate(specs):
        value = f'_s.{spec.slot}'
        inner = spec.msg_cls._FIELDS if spec.array == _SCALAR and spec.kind == 'msg' else None
        if inner is not None and all(f.array == _SCALAR and f.kind != 'msg' for f in inner):
            # A flat nested message (Vector3 in Twist) is copied inline: no call.
            copy_lines.append(f'    _n = {value}')
            copy_lines.append(f'    _v = _new(_T{i})')
            for j, f in enumerate(inner):
                ns[f'_T{i}_{j}'] = f.pytype
                copy_lines.append(f'    _v.{f.slot} = {_plain_copy(f, f"_n.{f.slot}", f"_T{i}_{j}")}')
            copy_lines.append(f'    _o.{spec.slot} = _v')
            continue
        if spec.kind == 'msg':
            _build(spec.msg_cls)
            ns[f'_y{i}'] = spec.msg_cls._copy
            if spec.array == _SCALAR:
                value = f'_y{i}({value})'
            else:
                value = f'[_y{i}(_m) for _m in {value}]'
        elif spec.array != _SCALAR:
            # a numeric sequence is an array.array (sliced: a new array of the
            # same type), anything else a list or another sequence (a new list)
            value = f'{value}[:]' if spec.typecode is not None and spec.array != _FIXED \
                else f'list({value})'
        else:
            value = _plain_copy(spec, value, f'_T{i}')
        copy_lines.append(f'    _o.{spec.slot} = {value}')
    setter_lines = []
    for i, spec in enumerate(specs):
        ns[f'_s{i}'] = spec.check
        setter_lines.extend(_setter_source(spec, i))
    src = [
        'def _copy(_s):',
        '    _o = _new(_cls)',
        *copy_lines,
        '    return _o',
        f"def __init__(self, *, {''.join(params)}check_fields=None, **_kw):",
        '    if _kw:',
        '        _bad(self, _kw)',
        *body,
        f"def _trusted({', '.join(s.name for s in specs)}):",
        '    _o = _new(_cls)',
        *(f'    _o.{s.slot} = {s.name}' for s in specs),
        '    return _o',
        'def _make_default():',
        '    _o = _new(_cls)',
        *default_body,
        '    return _o',
        *setter_lines,
    ]
    exec(compile('\n'.join(src) + '\n', f'<turtletui {cls._TYPE_NAME}>', 'exec'), ns)
    for func in (ns['__init__'], ns['_trusted'], ns['_make_default'], ns['_copy']):
        func.__qualname__ = f'{cls.__name__}.{func.__name__}'
        func.__module__ = cls.__module__
    ns['__init__'].__doc__ = f'Create a {cls._TYPE_NAME} message (keyword-only fields).'
    ns['_trusted'].__doc__ = _TRUSTED_DOC
    ns['_copy'].__doc__ = _COPY_DOC
    cls.__init__ = ns['__init__']
    cls._trusted = staticmethod(ns['_trusted'])
    cls._make_default = staticmethod(ns['_make_default'])
    cls._copy = staticmethod(ns['_copy'])
    for i, spec in enumerate(specs):
        setter = ns[f'_set{i}']
        qualname = f'{cls.__name__}.{spec.name}'
        setter.__code__ = setter.__code__.replace(co_name=spec.name, co_qualname=qualname)
        setter.__name__, setter.__qualname__ = spec.name, qualname
        setter.__module__ = cls.__module__
        setattr(cls, spec.name, property(spec.get, setter, None, cls.__dict__[spec.name].__doc__))
    cls._BUILT = True


_TRUSTED_DOC = (
    'Fast constructor for trusted code: sets every field positionally, in field '
    'order (see get_fields_and_field_types), with NO checks and no copies. '
    'Only for values known to be right, e.g. the simulator\'s own Pose/Color.'
)


_COPY_DOC = (
    'A copy of a message of this class that shares nothing mutable with it (what '
    'a subscriber gets from a middleware that serialises): fields copied as they '
    'are, without checks, nested messages and sequences copied too.'
)


def _lazy_methods(cls: type) -> None:
    """Stubs that compile the real methods on first use, then delegate."""
    def __init__(self: Message, *args: Any, **kwargs: Any) -> None:
        _build(cls)
        cls.__init__(self, *args, **kwargs)

    def _copy(msg: Message) -> Message:
        _build(cls)
        return cls._copy(msg)

    def _trusted(*values: Any) -> Message:
        _build(cls)
        return cls._trusted(*values)

    def _make_default() -> Message:
        _build(cls)
        return cls._make_default()

    _trusted.__doc__ = _TRUSTED_DOC
    _copy.__doc__ = _COPY_DOC
    cls.__init__ = __init__
    cls._trusted = staticmethod(_trusted)
    cls._make_default = staticmethod(_make_default)
    cls._copy = staticmethod(_copy)


def _setter_source(spec: FieldSpec, i: int) -> list[str]:
    """The checked setter of field ``i`` (``_s{i}`` is its check): a value of
    the field's own type (and range) is stored as it is, anything else is
    checked first. It stores the slot by name, a specialised store."""
    lines = [f'def _set{i}(self, value):']
    if spec.array != _SCALAR or spec.kind == 'byte' or spec.strlen is not None:
        return [*lines, f'    self.{spec.slot} = _s{i}(value)']
    test = f'value.__class__ is not _T{i}'
    if spec.kind == 'int' or spec.f32:
        test += f' or not _lo{i} <= value <= _hi{i}'
    return [*lines, f'    if {test}:', f'        value = _s{i}(value)', f'    self.{spec.slot} = value']


def _lazy_property(cls: type, spec: FieldSpec) -> property:
    """The field's property until the class is built (_build compiles its
    setter): reads the slot, and a first assignment builds the class."""
    name = spec.name

    def setter(self: Message, value: Any) -> None:
        _build(cls)
        setattr(self, name, value)

    return property(spec.get, setter, None, f"Message field '{name}'.")


# --------------------------------------------------------------------------
# factories
# --------------------------------------------------------------------------

_RESERVED = frozenset(dir(Message)) | {'_BUILT', '_trusted', '_make_default', '_copy', 'self',
                                       'check_fields'}


def _split_name(full_name: str, kind: str) -> tuple[str, str]:
    parts = full_name.split('/')
    if len(parts) != 3 or parts[1] != kind:
        raise ValueError(f'{full_name!r} is not a {kind} name')
    return parts[0], parts[2]


def ros_module_name(full_name: str) -> str:
    """The module rosidl_generator_py writes an interface's classes in:
    ``'geometry_msgs/msg/Twist'`` -> ``'geometry_msgs.msg._twist'`` (its
    camel-case name in lower case with underscores, as rosidl_pycommon's
    convert_camel_case_to_lower_case_underscore makes it)."""
    package, kind, name = full_name.split('/')
    snake = _re.sub('([a-z0-9])([A-Z])', r'\1_\2', _re.sub('(.)([A-Z][a-z]+)', r'\1_\2', name)).lower()
    return f'{package}.{kind}._{snake}'


def _metaclass(name: str, module: str, role: str) -> type:
    """The class of an interface class, named as rosidl's (``Metaclass_Twist``):
    ``type(Twist)`` prints as in ROS. Pickle reaches a class (and so a message)
    through it by its full name (``_by_name``), so that no process needs a
    module named ``geometry_msgs.msg._twist`` to unpickle one."""
    meta = type(f'Metaclass_{name}', (type,), {
        '__module__': module,
        '__qualname__': f'Metaclass_{name}',
        '__doc__': f"Metaclass of {role} '{name}'.",
    })
    _copyreg.pickle(meta, _reduce_class)
    return meta


def _reduce_class(cls: type) -> tuple:
    return _by_name, (cls._TYPE_NAME,)


def _by_name(full_name: str) -> type:
    """The interface class registered as ``full_name`` (what pickles name)."""
    return _REGISTRY[full_name]


def _message_doc(name: str, constants: dict[str, Any]) -> str:
    """A message class's docstring, as rosidl_generator_py writes it."""
    if not constants:
        return f"Message class '{name}'."
    listed = ''.join(f'      {constant}\n' for constant in constants)
    return f"\n    Message class '{name}'.\n\n    Constants:\n{listed}    "


def _create_message(full_name: str, text: str, module: str) -> type:
    package, _, name = full_name.split('/')
    if full_name in _REGISTRY:
        raise ValueError(f'{full_name} is defined twice')
    fields, constants = _parse_section(package, text)
    for spec in fields:
        if {spec.slot, spec.name} & _RESERVED or spec.name in constants:
            raise ValueError(f'{full_name}: field name {spec.name!r} is reserved')
    ns: dict[str, Any] = {
        '__slots__': tuple(s.slot for s in fields),
        '__module__': module,
        '__qualname__': name,
        '__doc__': _message_doc(name, constants),
        '_TYPE_NAME': full_name,
        '_REPR_PREFIX': full_name.replace('/', '.'),
        '_DEFINITION': text,
        '_FIELDS': tuple(fields),
        '_fields_and_field_types': {s.name: s.fields_type for s in fields},
        **constants,
    }
    for spec in fields:
        if spec.has_default:
            ns[f'{spec.name.upper()}__DEFAULT'] = spec.default
    cls = _metaclass(name, module, 'message')(name, (Message,), ns)
    for spec in fields:
        spec.set = cls.__dict__[spec.slot].__set__
        setattr(cls, spec.name, _lazy_property(cls, spec))
    _lazy_methods(cls)
    _REGISTRY[full_name] = cls
    return cls


def _create_wrapper(base: type, full_name: str, text: str, module: str,
                    members: dict[str, Any]) -> type:
    name = full_name.rsplit('/', 1)[1]
    role = 'service' if base is Service else 'action'
    cls = _metaclass(name, module, role)(name, (base,), {
        '__module__': module,
        '__qualname__': name,
        '__doc__': None,
        '_TYPE_NAME': full_name,
        '_DEFINITION': text,
        **members,
    })
    _REGISTRY[full_name] = cls
    return cls


def _create_service(full_name: str, text: str, module: str) -> type:
    """A service class, its ``Request``, ``Response`` and (service introspection's,
    Iron on) ``Event`` message; ``full_name`` may be an action's part (``..._SendGoal``)."""
    sections = _split_sections(text)
    if len(sections) != 2:
        raise ValueError(f'{full_name}: a service needs exactly one ---')
    _service_event_info()
    name = full_name.rsplit('/', 1)[1]
    request = _create_message(f'{full_name}_Request', sections[0], module)
    response = _create_message(f'{full_name}_Response', sections[1], module)
    event = _create_message(f'{full_name}_Event', (
        f'service_msgs/ServiceEventInfo info\n{name}_Request[<=1] request\n{name}_Response[<=1] response\n'),
        module)
    return _create_wrapper(Service, full_name, text, module,
                           {'Request': request, 'Response': response, 'Event': event})


def _service_event_info() -> None:
    """Define service_msgs (a service's Event message nests its ServiceEventInfo) first."""
    if 'service_msgs/msg/ServiceEventInfo' not in _REGISTRY:
        import turtletui.interfaces.service_msgs  # noqa: F401


def define_message(full_name: str, text: str, namespace: dict | None = None) -> type:
    """Create and register the message class *full_name* from its .msg *text*.

    Its ``__module__`` is rosidl's (``geometry_msgs.msg._twist``, see
    ros_module_name); *namespace*, the defining module's ``globals()``, is
    where services and actions put their parts.
    """
    _split_name(full_name, 'msg')
    cls = _create_message(full_name, text, ros_module_name(full_name))
    _TOP_LEVEL.append(full_name)
    return cls


def define_service(full_name: str, text: str, namespace: dict | None = None) -> type:
    """Create and register a service class with nested ``Request``, ``Response``
    and ``Event``.

    ``Name_Request``, ``Name_Response`` and ``Name_Event`` also go into
    *namespace* (the module's ``globals()``), as in ROS's ``_name.py``.
    """
    _, name = _split_name(full_name, 'srv')
    cls = _create_service(full_name, text, ros_module_name(full_name))
    if namespace is not None:
        for part in ('Request', 'Response', 'Event'):
            namespace[f'{name}_{part}'] = getattr(cls, part)
    _TOP_LEVEL.append(full_name)
    return cls


def define_action(full_name: str, text: str, namespace: dict | None = None) -> type:
    """Create and register an action class with ``Goal``, ``Result``, ``Feedback``.

    Like rclpy's it has ``Impl`` with the protocol's wrapper types
    (``SendGoalService``, ``GetResultService``, ``FeedbackMessage``,
    ``CancelGoalService``, ``GoalStatusMessage``), so ``action_msgs`` and
    ``unique_identifier_msgs`` must be defined first.
    """
    _, name = _split_name(full_name, 'action')
    module = ros_module_name(full_name)
    sections = _split_sections(text)
    if len(sections) != 3:
        raise ValueError(f'{full_name}: an action needs exactly two ---')
    made = {suffix: _create_message(f'{full_name}_{suffix}', body, module)
            for suffix, body in zip(('Goal', 'Result', 'Feedback'), sections, strict=True)}
    for service, request, response in (
        ('SendGoal', f'unique_identifier_msgs/UUID goal_id\n{name}_Goal goal\n',
         'bool accepted\nbuiltin_interfaces/Time stamp\n'),
        ('GetResult', 'unique_identifier_msgs/UUID goal_id\n', f'int8 status\n{name}_Result result\n'),
    ):
        made[service] = _create_service(f'{full_name}_{service}', f'{request}---\n{response}', module)
        for part in ('Request', 'Response', 'Event'):
            made[f'{service}_{part}'] = getattr(made[service], part)
    made['FeedbackMessage'] = _create_message(
        f'{full_name}_FeedbackMessage', f'unique_identifier_msgs/UUID goal_id\n{name}_Feedback feedback\n', module)
    impl = type('Impl', (), {
        '__module__': module,
        '__qualname__': f'{name}.Impl',
        '__doc__': None,
        'SendGoalService': made['SendGoal'],
        'GetResultService': made['GetResult'],
        'FeedbackMessage': made['FeedbackMessage'],
        'CancelGoalService': _REGISTRY['action_msgs/srv/CancelGoal'],
        'GoalStatusMessage': _REGISTRY['action_msgs/msg/GoalStatusArray'],
    })
    cls = _create_wrapper(Action, full_name, text, module, {
        'Goal': made['Goal'], 'Result': made['Result'], 'Feedback': made['Feedback'],
        'Impl': impl,
    })
    if namespace is not None:
        for suffix, part in made.items():
            namespace[f'{name}_{suffix}'] = part
    _TOP_LEVEL.append(full_name)
    return cls


_SHOWN: dict[str, tuple[str, str, int]] = {}
"""What show_package_as last did for a package, and the registry's size then."""


def show_package_as(package: str, shown: str) -> None:
    """Make the interfaces of ``package`` look as ``shown``'s do: the distro of
    a run decides (from Kilted on turtlesim's ``Pose`` prints as
    ``turtlesim_msgs.msg.Pose(...)``, its class is
    ``turtlesim_msgs.msg._pose.Pose``, and nested turtlesim types are
    ``turtlesim_msgs/...`` in ``get_fields_and_field_types()``). Their full
    names (the registry's) stay as defined."""
    done = (package, shown, len(_REGISTRY))
    if _SHOWN.get(package) == done:
        return  # every process that runs a controller asks again: nothing changed since
    _SHOWN[package] = done
    prefix = f'{package}/'
    for name, cls in _REGISTRY.items():
        if name.startswith(prefix):
            module = shown + cls.__module__[cls.__module__.index('.'):]
            cls.__module__ = type(cls).__module__ = module
            impl = cls.__dict__.get('Impl')
            if impl is not None:
                impl.__module__ = module
        if issubclass(cls, Message):
            if name.startswith(prefix):
                cls._REPR_PREFIX = f'{shown}/{name[len(prefix):]}'.replace('/', '.')
            cls._fields_and_field_types = {
                spec.name: _shown_type(spec, package, shown) for spec in cls._FIELDS}
            cls._slot_types = None  # made again, with the package's new name


def _shown_type(spec: FieldSpec, package: str, shown: str) -> str:
    """``spec.fields_type`` with a nested type of ``package`` named as ``shown``'s."""
    if spec.kind == 'msg' and spec.msg_cls._TYPE_NAME.startswith(f'{package}/'):
        return f'{shown}/{spec.fields_type.partition("/")[2]}' if spec.array in (_SCALAR, _FIXED) \
            else spec.fields_type.replace(f'<{package}/', f'<{shown}/', 1)
    return spec.fields_type
