"""tf2's exceptions as tf2_py raises them: TransformException and its five kinds.

The messages are buffer_core.cpp's and cache.cpp's, word for word, so a
student's ``except TransformException as ex: log(f"... {ex}")`` prints what
it would print on a real system."""

from __future__ import annotations


class TransformException(Exception):
    """Any tf2 error (tf2_py's ``tf2.TransformException``)."""


class ConnectivityException(TransformException):
    """The two frames are in trees that do not meet."""


class LookupException(TransformException):
    """A frame the lookup names does not exist (yet)."""


class ExtrapolationException(TransformException):
    """The time asked for is outside the data a cache holds."""


class InvalidArgumentException(TransformException):
    """A frame id that tf2 refuses (empty, or starting with '/')."""


class TimeoutException(TransformException):
    """A wait for a transform ran out of time."""


for _cls in (
    TransformException, ConnectivityException, LookupException,
    ExtrapolationException, InvalidArgumentException, TimeoutException,
):
    _cls.__module__ = "tf2"  # tracebacks name them as tf2_py's do: tf2.LookupException
del _cls
