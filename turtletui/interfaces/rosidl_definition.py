"""The field types of ``SLOT_TYPES``: rosidl_parser.definition's type classes.

A generated ROS message class lists its fields' types in ``SLOT_TYPES``, a
tuple of these objects (``NamespacedType(['geometry_msgs', 'msg'],
'Vector3')``, ``BasicType('double')``, ``UnboundedSequence(BasicType('float'))``
...). The classes here are the same, attribute for attribute, with the same
equality (and so unhashable); they say they are ``rosidl_parser.definition``'s,
so that a program printing ``Twist.SLOT_TYPES`` sees what it sees under ROS
(``<rosidl_parser.definition.NamespacedType object at 0x...>``). A controller
imports them as ``rosidl_parser.definition`` (turtletui/compat/ros). Only the
type classes are here, not the parser's IDL structures.
"""

from __future__ import annotations

from collections.abc import Iterable

__all__ = [
    'BASIC_TYPES', 'BOOLEAN_TYPE', 'CHARACTER_TYPES', 'EXPLICIT_INTEGER_TYPES', 'FLOATING_POINT_TYPES',
    'INTEGER_TYPES', 'NONEXPLICIT_INTEGER_TYPES', 'OCTET_TYPE', 'SIGNED_EXPLICIT_INTEGER_TYPES',
    'SIGNED_INTEGER_TYPES', 'SIGNED_NONEXPLICIT_INTEGER_TYPES', 'UNSIGNED_EXPLICIT_INTEGER_TYPES',
    'UNSIGNED_INTEGER_TYPES', 'UNSIGNED_NONEXPLICIT_INTEGER_TYPES',
    'AbstractType', 'AbstractNestableType', 'BasicType', 'NamedType', 'NamespacedType',
    'AbstractGenericString', 'AbstractString', 'BoundedString', 'UnboundedString',
    'AbstractWString', 'BoundedWString', 'UnboundedWString',
    'AbstractNestedType', 'Array', 'AbstractSequence', 'BoundedSequence', 'UnboundedSequence',
]

SIGNED_NONEXPLICIT_INTEGER_TYPES = ('short', 'long', 'long long')
UNSIGNED_NONEXPLICIT_INTEGER_TYPES = ('unsigned short', 'unsigned long', 'unsigned long long')
NONEXPLICIT_INTEGER_TYPES = (*SIGNED_NONEXPLICIT_INTEGER_TYPES, *UNSIGNED_NONEXPLICIT_INTEGER_TYPES)
FLOATING_POINT_TYPES = ('float', 'double', 'long double')
CHARACTER_TYPES = ('char', 'wchar')
BOOLEAN_TYPE = 'boolean'
OCTET_TYPE = 'octet'
SIGNED_EXPLICIT_INTEGER_TYPES = ('int8', 'int16', 'int32', 'int64')
UNSIGNED_EXPLICIT_INTEGER_TYPES = ('uint8', 'uint16', 'uint32', 'uint64')
EXPLICIT_INTEGER_TYPES = (*SIGNED_EXPLICIT_INTEGER_TYPES, *UNSIGNED_EXPLICIT_INTEGER_TYPES)
SIGNED_INTEGER_TYPES = (*SIGNED_NONEXPLICIT_INTEGER_TYPES, *SIGNED_EXPLICIT_INTEGER_TYPES)
UNSIGNED_INTEGER_TYPES = (*UNSIGNED_NONEXPLICIT_INTEGER_TYPES, *UNSIGNED_EXPLICIT_INTEGER_TYPES)
INTEGER_TYPES = (*SIGNED_INTEGER_TYPES, *UNSIGNED_INTEGER_TYPES)
BASIC_TYPES = (*INTEGER_TYPES, *FLOATING_POINT_TYPES, *CHARACTER_TYPES, BOOLEAN_TYPE, OCTET_TYPE)
"""All basic types as the IDL specification defines them."""


class AbstractType:
    """The abstract base class for all types."""

    __slots__ = ()

    def __eq__(self, other: object) -> bool:
        return type(self) is type(other)


class AbstractNestableType(AbstractType):
    """The abstract base class for types which can be used inside nested types
    (arrays and sequences): basic types, named and namespaced types, strings."""

    __slots__ = ()


class BasicType(AbstractNestableType):
    """A basic type according to the IDL specification; ``typename`` names it."""

    __slots__ = ('typename',)

    def __init__(self, typename: str) -> None:
        super().__init__()
        assert typename in BASIC_TYPES
        self.typename = typename

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, BasicType):
            return False
        return super().__eq__(other) and self.typename == other.typename


class NamedType(AbstractNestableType):
    """A type identified by the name."""

    __slots__ = ('name',)

    def __init__(self, name: str) -> None:
        super().__init__()
        self.name = name

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, NamedType):
            return False
        return super().__eq__(other) and self.name == other.name


class NamespacedType(AbstractNestableType):
    """A type identified by a name in a namespaced scope (``['geometry_msgs', 'msg']``)."""

    __slots__ = ('namespaces', 'name')

    def __init__(self, namespaces: Iterable[str], name: str) -> None:
        super().__init__()
        self.namespaces = namespaces
        self.name = name

    def namespaced_name(self) -> tuple[str, ...]:
        return (*self.namespaces, self.name)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, NamespacedType):
            return False
        return super().__eq__(other) and self.namespaces == other.namespaces and self.name == other.name


class AbstractGenericString(AbstractNestableType):
    """The abstract base class of all string types."""

    __slots__ = ()

    def has_maximum_size(self) -> bool:
        raise NotImplementedError('Only implemented in subclasses')


class AbstractString(AbstractGenericString):
    """The abstract base class of 8-bit string types."""

    __slots__ = ()


class BoundedString(AbstractString):
    """A 8-bit string type with a limited number of characters."""

    __slots__ = ('maximum_size',)

    def __init__(self, maximum_size: int) -> None:
        super().__init__()
        assert maximum_size >= 0
        self.maximum_size = maximum_size

    def has_maximum_size(self) -> bool:
        return True

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, BoundedString):
            return False
        return super().__eq__(other) and self.maximum_size == other.maximum_size


class UnboundedString(AbstractString):
    """A 8-bit string type with an unlimited number of characters."""

    __slots__ = ()

    def has_maximum_size(self) -> bool:
        return False


class AbstractWString(AbstractGenericString):
    """The abstract base class of 16-bit string types."""

    __slots__ = ()


class BoundedWString(AbstractWString):
    """A 16-bit string type."""

    __slots__ = ('maximum_size',)

    def __init__(self, maximum_size: int | str) -> None:
        super().__init__()
        self.maximum_size = maximum_size

    def has_maximum_size(self) -> bool:
        return True

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, BoundedWString):
            return False
        return super().__eq__(other) and self.maximum_size == other.maximum_size


class UnboundedWString(AbstractWString):
    """A 16-bit string type."""

    __slots__ = ()

    def has_maximum_size(self) -> bool:
        return False


class AbstractNestedType(AbstractType):
    """The abstract base class of nested types: arrays and sequences of ``value_type``."""

    __slots__ = ('value_type',)

    def __init__(self, value_type: AbstractNestableType) -> None:
        super().__init__()
        assert isinstance(value_type, AbstractNestableType)
        self.value_type = value_type

    def has_maximum_size(self) -> bool:
        raise NotImplementedError('Only implemented in subclasses')

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, AbstractNestedType):
            return False
        return super().__eq__(other) and self.value_type == other.value_type


class Array(AbstractNestedType):
    """An array type with a static size."""

    __slots__ = ('size',)

    def __init__(self, value_type: AbstractNestableType, size: int) -> None:
        super().__init__(value_type)
        assert size > 0
        self.size = size

    def has_maximum_size(self) -> bool:
        return True

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Array):
            return False
        return super().__eq__(other) and self.size == other.size


class AbstractSequence(AbstractNestedType):
    """The abstract base class of sequence types."""

    __slots__ = ()


class BoundedSequence(AbstractSequence):
    """A sequence type with a maximum number of elements."""

    __slots__ = ('maximum_size',)

    def __init__(self, value_type: AbstractNestableType, maximum_size: int) -> None:
        super().__init__(value_type)
        assert maximum_size > 0
        self.maximum_size = maximum_size

    def has_maximum_size(self) -> bool:
        return True

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, BoundedSequence):
            return False
        return super().__eq__(other) and self.maximum_size == other.maximum_size


class UnboundedSequence(AbstractSequence):
    """A sequence type with an unlimited number of elements."""

    __slots__ = ()

    def has_maximum_size(self) -> bool:
        return False


for _name in __all__:
    if isinstance(globals()[_name], type):
        globals()[_name].__module__ = 'rosidl_parser.definition'
del _name
