"""tf2_ros's BufferInterface: the lookups every tf2 buffer offers, and
``transform()``, which moves a stamped message into another frame with the
conversions that packages such as tf2_geometry_msgs register on import."""

from __future__ import annotations

from collections.abc import Callable
from copy import deepcopy
from typing import Any

from turtletui.compat.time import Duration
from turtletui.interfaces.std_msgs import Header


class TypeException(Exception):
    """A type no transform or conversion is registered for."""

    def __init__(self, errstr: str) -> None:
        super().__init__(errstr)
        self.errstr = errstr


class NotImplementedException(Exception):
    """A BufferInterface method its subclass does not provide."""

    def __init__(self) -> None:
        self.errstr = "CanTransform or LookupTransform not implemented"
        super().__init__(self.errstr)


def _get(table: dict, key: Any) -> Callable:
    if key not in table:
        raise TypeException(f"Type {key} is not loaded or supported")
    return table[key]


class TransformRegistration:
    """How to transform each stamped type (shared by every instance, as tf2_ros's)."""

    _type_map: dict = {}

    def add(self, key: type, callback: Callable[[Any, Any], Any]) -> None:
        TransformRegistration._type_map[key] = callback

    def get(self, key: type) -> Callable[[Any, Any], Any]:
        return _get(TransformRegistration._type_map, key)


class ConvertRegistration:
    """How to convert between stamped types (shared by every instance)."""

    _to_msg_map: dict = {}
    _from_msg_map: dict = {}
    _convert_map: dict = {}

    def add_from_msg(self, key: type, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._from_msg_map[key] = callback

    def add_to_msg(self, key: type, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._to_msg_map[key] = callback

    def add_convert(self, key: tuple[type, type], callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._convert_map[key] = callback

    def get_from_msg(self, key: type) -> Callable[[Any], Any]:
        return _get(ConvertRegistration._from_msg_map, key)

    def get_to_msg(self, key: type) -> Callable[[Any], Any]:
        return _get(ConvertRegistration._to_msg_map, key)

    def get_convert(self, key: tuple[type, type]) -> Callable[[Any], Any]:
        return _get(ConvertRegistration._convert_map, key)


def convert(a: Any, b_type: type) -> Any:
    """``a`` as a ``b_type``, by a registered conversion (or a copy if it is one)."""
    registry = ConvertRegistration()
    try:
        return registry.get_convert((type(a), b_type))(a)
    except TypeException:
        if type(a) is b_type:
            return deepcopy(a)
        return registry.get_from_msg(b_type)(registry.get_to_msg(type(a))(a))


def Stamped(obj: Any, stamp: Any, frame_id: str) -> Any:  # noqa: N802 - tf2_ros's name
    """``obj`` with a header of ``stamp`` and ``frame_id``."""
    obj.header = Header(frame_id=frame_id, stamp=stamp)
    return obj


class BufferInterface:
    """What a buffer of transforms answers; Buffer implements the lookups."""

    def __init__(self) -> None:
        self.registration = TransformRegistration()

    def transform(self, object_stamped: Any, target_frame: str, timeout: Duration = Duration(), new_type: Any = None) -> Any:
        """``object_stamped`` (a PointStamped, PoseStamped, ...: see tf2_geometry_msgs)
        in ``target_frame``, at its own stamp."""
        do_transform = self.registration.get(type(object_stamped))
        header = object_stamped.header
        result = do_transform(object_stamped, self.lookup_transform(target_frame, header.frame_id, header.stamp, timeout))
        return result if new_type is None else convert(result, new_type)

    def transform_full(
        self, object_stamped: Any, target_frame: str, target_time: Any, fixed_frame: str,
        timeout: Duration = Duration(), new_type: Any = None,
    ) -> Any:
        """transform() through ``fixed_frame``, into ``target_frame`` at ``target_time``."""
        do_transform = self.registration.get(type(object_stamped))
        header = object_stamped.header
        transform = self.lookup_transform_full(
            target_frame, target_time, header.frame_id, header.stamp, fixed_frame, timeout
        )
        result = do_transform(object_stamped, transform)
        return result if new_type is None else convert(result, new_type)

    def lookup_transform(self, target_frame: str, source_frame: str, time: Any, timeout: Duration = Duration()) -> Any:
        raise NotImplementedException()

    def lookup_transform_full(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any,
        fixed_frame: str, timeout: Duration = Duration(),
    ) -> Any:
        raise NotImplementedException()

    def can_transform(self, target_frame: str, source_frame: str, time: Any, timeout: Duration = Duration()) -> bool:
        raise NotImplementedException()

    def can_transform_full(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any,
        fixed_frame: str, timeout: Duration = Duration(),
    ) -> bool:
        raise NotImplementedException()
