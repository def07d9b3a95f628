"""tf2's BufferCore (tf2_py's ``BufferCore``): the tree of frames and the lookups on it.

Every frame named as a child has a cache of its transform to its parent over
time (static frames: one for all time). A lookup walks from the source frame
up to the root and from the target frame up to where the walks meet,
composing the transforms at the time asked (0: the latest time every link on
the way has data for), as buffer_core.cpp's walkToTopParent does; its errors
carry that file's texts."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from turtletui.compat.logging import get_logger
from turtletui.compat.tf2.cache import DEFAULT_CACHE_TIME_NS, StaticCache, TimeCache, show_time
from turtletui.compat.tf2.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
)
from turtletui.compat.tf2.transform import IDENTITY_QUAT, ZERO, Quat, Stored, Vec, compose, invert
from turtletui.interfaces.builtin_interfaces import Time as TimeMsg
from turtletui.interfaces.geometry_msgs import TransformStamped

MAX_GRAPH_DEPTH = 1000
QUATERNION_NORMALIZATION_TOLERANCE = 10e-3

_Result = tuple[Vec, Quat, int]
_Failure = tuple[type, str]


def time_ns(time: Any, what: str = "time") -> int:
    """A time or duration (rclpy's, builtin_interfaces', anything with
    ``nanoseconds``) in ns; tf2_py's TypeError for anything else."""
    if hasattr(time, "sec") and hasattr(time, "nanosec"):
        return int(time.sec) * 1_000_000_000 + int(time.nanosec)
    if hasattr(time, "nanoseconds"):
        return int(time.nanoseconds)
    raise TypeError(f"{what} must have sec and nanosec, or nanoseconds.")


class BufferCore:
    """Frames and their transforms over the last ``cache_time`` (a Duration; 10 s by default)."""

    def __init__(self, cache_time: Any = None) -> None:
        self._cache_time_ns = DEFAULT_CACHE_TIME_NS if cache_time is None else time_ns(cache_time, "duration")
        self._frames: dict[str, TimeCache | StaticCache | None] = {}
        """Every frame named so far (parents too, which may have no cache), in order of naming."""
        self._authority: dict[str, str] = {}

    # -- storing ------------------------------------------------------------

    def set_transform(self, transform: TransformStamped, authority: str) -> bool:
        """Store a transform of ``transform.child_frame_id`` in ``header.frame_id``."""
        return self._store(transform, authority, static=False)

    def set_transform_static(self, transform: TransformStamped, authority: str) -> bool:
        """Store a transform that holds at every time."""
        return self._store(transform, authority, static=True)

    def _store(self, msg: TransformStamped, authority: str, static: bool) -> bool:
        parent = _strip_slash(msg.header.frame_id)
        child = _strip_slash(msg.child_frame_id)
        t = msg.transform.translation
        q = msg.transform.rotation
        translation = (float(t.x), float(t.y), float(t.z))
        rotation = (float(q.x), float(q.y), float(q.z), float(q.w))
        errors = []
        if child == parent:
            errors.append(
                f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" with frame_id and  '
                f'child_frame_id "{child}" because they are the same'
            )
        if not child:
            errors.append(f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "{authority}" because child_frame_id not set ')
        if not parent:
            errors.append(
                f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}"  from authority "{authority}" '
                "because frame_id not set"
            )
        if any(math.isnan(v) for v in translation + rotation):
            errors.append(
                f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority "{authority}" because'
                f" of a nan value in the transform ({_six(translation)}) ({_six(rotation)})"
            )
        if not abs(sum(v * v for v in rotation) - 1.0) < QUATERNION_NORMALIZATION_TOLERANCE:
            errors.append(
                f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" from authority'
                f' "{authority}" because of an invalid quaternion in the transform ({_six(rotation)})'
            )
        if errors:
            for error in errors:
                _logger().error(error)
            return False
        cache = self._frames.get(child)
        if cache is None or cache.static != static:
            cache = StaticCache() if static else TimeCache(self._cache_time_ns)
            self._frames[child] = cache
        self._frames.setdefault(parent, None)
        stamp = time_ns(msg.header.stamp)
        if not cache.insert(Stored(stamp, parent, translation, rotation)):
            _logger().warning(
                f"TF_OLD_DATA ignoring data from the past for frame {child} at time {show_time(stamp)} according to"
                f" authority {authority}\nPossible reasons are listed at http://wiki.ros.org/tf/Errors%20explained"
            )
            return False
        self._authority[child] = authority
        return True

    def clear(self) -> None:
        """Forget every transform (the frames stay known, as tf2's clear)."""
        for name, cache in self._frames.items():
            if cache is not None and not cache.static:
                self._frames[name] = TimeCache(self._cache_time_ns)

    # -- looking up ---------------------------------------------------------

    def lookup_transform_core(self, target_frame: str, source_frame: str, time: Any) -> TransformStamped:
        """The transform that takes ``source_frame`` coordinates into ``target_frame``'s at ``time``
        (a Time; zero: the latest available); raises tf2's exceptions."""
        translation, rotation, stamp = self._lookup(target_frame, source_frame, time_ns(time))
        return _stamped(target_frame, source_frame, translation, rotation, stamp)

    def lookup_transform_full_core(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> TransformStamped:
        """``source_frame`` at ``source_time`` into ``target_frame`` at ``target_time``,
        through ``fixed_frame``, the frame taken not to move between the two times."""
        for arg, frame in (("target_frame", target_frame), ("source_frame", source_frame), ("fixed_frame", fixed_frame)):
            self._validate(f"lookupTransform argument {arg}", frame)
        t1, q1, _ = self._lookup(fixed_frame, source_frame, time_ns(source_time))
        t2, q2, stamp = self._lookup(target_frame, fixed_frame, time_ns(target_time))
        translation, rotation = compose(t2, q2, t1, q1)
        return _stamped(target_frame, source_frame, translation, rotation, stamp)

    def can_transform_core(self, target_frame: str, source_frame: str, time: Any) -> tuple[bool, str]:
        """(whether the lookup would succeed, why not)."""
        if target_frame == source_frame:
            return True, ""
        t_ns = time_ns(time)
        for arg, frame in (("target_frame", target_frame), ("source_frame", source_frame)):
            error = self._invalid(f"canTransform argument {arg}", frame)
            if error:
                return False, error
        outcome = self._walk(t_ns, target_frame, source_frame)
        return (True, "") if len(outcome) == 3 else (False, outcome[1])

    def can_transform_full_core(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> tuple[bool, str]:
        """(whether lookup_transform_full_core would succeed, why not)."""
        for arg, frame in (("target_frame", target_frame), ("source_frame", source_frame), ("fixed_frame", fixed_frame)):
            error = self._invalid(f"canTransform argument {arg}", frame)
            if error:
                return False, error
        for target, source, time in ((target_frame, fixed_frame, target_time), (fixed_frame, source_frame, source_time)):
            if target != source:
                outcome = self._walk(time_ns(time), target, source)
                if len(outcome) != 3:
                    return False, outcome[1]
        return True, ""

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Any:
        """The latest time both frames' chains have data for (an rclpy Time)."""
        from turtletui.compat.time import Time

        for arg, frame in (("target_frame", target_frame), ("source_frame", source_frame)):
            self._validate(f"getLatestCommonTime argument {arg}", frame)
        outcome = self._latest_common_time(target_frame, source_frame)
        if isinstance(outcome, tuple):
            raise outcome[0](outcome[1])
        return Time(nanoseconds=outcome)

    def _lookup(self, target: str, source: str, t_ns: int) -> _Result:
        if target == source:
            cache = self._frames.get(target)
            stamp = cache.latest()[0] if t_ns == 0 and cache is not None else t_ns
            return ZERO, IDENTITY_QUAT, stamp
        self._validate("lookupTransform argument target_frame", target)
        self._validate("lookupTransform argument source_frame", source)
        outcome = self._walk(t_ns, target, source)
        if len(outcome) == 2:
            raise outcome[0](outcome[1])
        return outcome  # type: ignore[return-value]

    def _invalid(self, where: str, frame: str) -> str:
        """Why ``frame`` cannot be looked up (tf2's warning text), or ''."""
        if not frame:
            return f'Invalid frame ID "{frame}" passed to {where} - in tf2 frame_ids cannot be empty'
        if frame.startswith("/"):
            return f"Invalid frame ID \"{frame}\" passed to {where} - in tf2 frame_ids cannot start with a '/'"
        if frame not in self._frames:
            return f'Invalid frame ID "{frame}" passed to {where} - frame does not exist'
        return ""

    def _validate(self, where: str, frame: str) -> None:
        if not frame:
            raise InvalidArgumentException(f'Invalid argument "{frame}" passed to {where} - in tf2 frame_ids cannot be empty')
        if frame.startswith("/"):
            raise InvalidArgumentException(
                f"Invalid argument \"{frame}\" passed to {where} - in tf2 frame_ids cannot start with a '/'"
            )
        if frame not in self._frames:
            raise LookupException(f'"{frame}" passed to {where} does not exist. ')

    def _walk(self, t_ns: int, target: str, source: str) -> _Result | _Failure:
        """Compose the transforms from ``source`` up to where its chain meets
        ``target``'s; the result, or (exception class, message)."""
        if t_ns == 0:
            common = self._latest_common_time(target, source)
            if isinstance(common, tuple):
                return common
            t_ns = common
        src_t, src_q = ZERO, IDENTITY_QUAT
        frame, top, extrapolation = source, source, ""
        for _ in range(MAX_GRAPH_DEPTH + 1):
            cache = self._frames.get(frame)
            if cache is None:
                top = frame
                break
            got = cache.get(t_ns)
            if isinstance(got, str):  # there may still be a way from the target to here
                top, extrapolation = frame, got
                break
            if frame == target:
                return src_t, src_q, t_ns
            src_t, src_q = compose(got.translation, got.rotation, src_t, src_q)
            top, frame = frame, got.parent
        else:
            return self._loop_error()
        tgt_t, tgt_q = ZERO, IDENTITY_QUAT
        frame = target
        for _ in range(MAX_GRAPH_DEPTH + 1):
            if frame == top:
                break
            cache = self._frames.get(frame)
            if cache is None:
                break
            got = cache.get(t_ns)
            if isinstance(got, str):
                return ExtrapolationException, f"{got}, when looking up transform from frame [{source}] to frame [{target}]"
            if frame == source:
                return (*invert(tgt_t, tgt_q), t_ns)
            tgt_t, tgt_q = compose(got.translation, got.rotation, tgt_t, tgt_q)
            frame = got.parent
        else:
            return self._loop_error()
        if frame != top:
            if extrapolation:
                return (
                    ExtrapolationException,
                    f"{extrapolation}, when looking up transform from frame [{source}] to frame [{target}]",
                )
            return ConnectivityException, _not_connected(target, source)
        inv_t, inv_q = invert(tgt_t, tgt_q)
        return (*compose(inv_t, inv_q, src_t, src_q), t_ns)

    def _latest_common_time(self, target: str, source: str) -> int | _Failure:
        """The newest time every link between the frames has data for; 0 when all are static."""
        if source == target:
            cache = self._frames.get(source)
            return cache.latest()[0] if cache is not None else 0
        up = self._chain(source, lambda parent: parent == target)
        if up is None:
            return self._loop_error()
        if up and up[-1][1] == target:
            return _oldest_latest(up)
        parents = {parent for _, parent in up}
        down = self._chain(target, lambda parent: parent in parents or parent == source)
        if down is None:
            return self._loop_error()
        meeting = down[-1][1] if down else None
        if meeting in parents:
            to_meeting = next(i for i, (_, parent) in enumerate(up) if parent == meeting)
            return _oldest_latest(down + up[: to_meeting + 1])
        if meeting == source:
            return _oldest_latest(down)
        return ConnectivityException, _not_connected(target, source)

    def _chain(self, frame: str, last: Callable[[str], bool]) -> list[tuple[int, str]] | None:
        """(latest stamp, parent) of each link from ``frame`` towards the root, up
        to the first whose parent is ``last``; None when the links loop."""
        links = []
        for _ in range(MAX_GRAPH_DEPTH + 1):
            cache = self._frames.get(frame)
            stamp, parent = cache.latest() if cache is not None else (0, None)
            if parent is None:
                return links
            links.append((stamp, parent))
            if last(parent):
                return links
            frame = parent
        return None

    def _loop_error(self) -> _Failure:
        return LookupException, f"The tf tree is invalid because it contains a loop.\n{self.all_frames_as_string()}\n"

    # -- describing ---------------------------------------------------------

    def all_frames_as_string(self) -> str:
        """One line per frame with a transform: ``Frame turtle1 exists with parent world.``"""
        lines = []
        for name, cache in self._frames.items():
            if cache is not None:
                lines.append(f"Frame {name} exists with parent {cache.latest()[1] or 'NO_PARENT'}.\n")
        return "".join(lines)

    def all_frames_as_yaml(self, current_time: Any = None) -> str:
        """The frames as tf2's YAML (what ``ros2 run tf2_ros tf2_echo``'s tools read)."""
        now_ns = 0 if current_time is None else time_ns(current_time)
        parts = []
        for name, cache in self._frames.items():
            if cache is None:
                continue
            latest, parent = cache.latest()
            oldest = cache.oldest_ns()
            rate = len(cache) * 1e9 / max(latest - oldest, 100_000)
            parts.append(
                f"{name}: \n  parent: '{parent}'\n  broadcaster: '{self._authority.get(name, 'no recorded authority')}'\n"
                f"  rate: {rate:.3f}\n  most_recent_transform: {show_time(latest)}\n"
                f"  oldest_transform: {show_time(oldest)}\n"
                + (f"  transform_delay: {(now_ns - latest) / 1e9:.3f}\n" if now_ns else "")
                + f"  buffer_length: {(latest - oldest) / 1e9:.3f}\n"
            )
        return "".join(parts) or "[]"

    def _get_frame_strings(self) -> list[str]:
        return [name for name, cache in self._frames.items() if cache is not None]


def _oldest_latest(links: list[tuple[int, str]]) -> int:
    """The oldest of the links' latest stamps (static links, stamp 0, have none); 0 if none has one."""
    return min((stamp for stamp, _ in links if stamp), default=0)


def _strip_slash(frame: str) -> str:
    return frame[1:] if frame.startswith("/") else frame


def _six(values: tuple[float, ...]) -> str:
    return " ".join(f"{v:f}" for v in values)


def _not_connected(target: str, source: str) -> str:
    return (
        f"Could not find a connection between '{target}' and '{source}' because they are not part of the same tree."
        "Tf has two or more unconnected trees."
    )


def _stamped(target: str, source: str, translation: Vec, rotation: Quat, stamp_ns: int) -> TransformStamped:
    msg = TransformStamped()
    msg.header.stamp = TimeMsg(sec=stamp_ns // 1_000_000_000, nanosec=stamp_ns % 1_000_000_000)
    msg.header.frame_id = target
    msg.child_frame_id = source
    t, q = msg.transform.translation, msg.transform.rotation
    t.x, t.y, t.z = translation
    q.x, q.y, q.z, q.w = rotation
    return msg


def _logger() -> Any:
    return get_logger("tf2")
