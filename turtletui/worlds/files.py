"""World files: a world described in TOML.

Every field is optional; lengths in metres, angles in radians::

    name = "lidar-course"          # default: the file name without .toml
    description = "one line"
    background = [69, 86, 255]     # r, g, b (0..255); default turtlesim's

    [[circles]]                    # any number of round obstacles
    x = 3.0                        # centre
    y = 8.0
    r = 0.6                        # radius

    [[boxes]]                      # any number of axis-aligned rectangles
    x0 = 1.0                       # one corner ...
    y0 = 1.0
    x1 = 2.5                       # ... and the opposite one (x0 < x1, y0 < y1)
    y1 = 1.8

    [lidar]                        # omit for no LiDAR
    samples = 72                   # beams per scan
    angle_min = 0.0                # first beam, relative to the heading (default 0: ahead)
    angle_max = 6.196              # last beam; default: a full turn, 2 pi / samples apart
    range_min = 0.12               # default 0.0
    range_max = 3.5                # default 3.5
    noise_std = 0.01               # Gaussian noise, standard deviation (default 0)
    dropout = 0.02                 # share of readings that come back nan (default 0)
    rate = 10.0                    # scans per second; default: every 16 ms tick

The arena is 0 .. 11.0889 m on both axes; turtle1 starts at its centre
(5.544445, 5.544445). A plugin's world factory may return the same fields as
a dict (:func:`parse_world`). Errors are :class:`WorldError` with one line
``FILE:LINE: ...`` naming the field.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from turtletui.messages import did_you_mean, one_line
from turtletui.sim import Box, Circle, Lidar
from turtletui.worlds.spec import WorldError, WorldSpec

WORLD_FIELDS = ("name", "description", "background", "circles", "boxes", "lidar")
CIRCLE_FIELDS = ("x", "y", "r")
BOX_FIELDS = ("x0", "y0", "x1", "y1")
LIDAR_FIELDS = ("samples", "angle_min", "angle_max", "range_min", "range_max", "noise_std", "dropout", "rate")


def load_world_file(path: str | Path) -> WorldSpec:
    """Read and validate the TOML world file at ``path``."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise WorldError(f"{path}: no such world file") from None
    except (OSError, UnicodeDecodeError) as err:
        raise WorldError(f"{path}: cannot read the world file: {one_line(err)}") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise WorldError(f"{path}:{_toml_error(err)}") from None
    return _Parser(str(path), text.splitlines()).world(data, default_name=path.stem)


def parse_world(data: Mapping[str, Any], *, name: str, where: str | None = None) -> WorldSpec:
    """A WorldSpec from a dict in the world file's format; ``name`` is used when
    the dict has none; errors start with ``where`` (default ``world 'NAME'``)."""
    if not isinstance(data, Mapping):
        raise WorldError(f"{where or f'world {name!r}'}: expected a table of fields, got {type(data).__name__}")
    return _Parser(where or f"world {name!r}", None).world(dict(data), default_name=name)


def _toml_error(err: Exception) -> str:
    message = str(err)
    found = re.search(r"\s*\(at line (\d+), column (\d+)\)\s*$", message)
    if found:
        return f"{found.group(1)}: invalid TOML: {message[: found.start()]} (column {found.group(2)})"
    return f"1: invalid TOML: {message}"






def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


class _Parser:
    """Turns parsed TOML (or a plugin's dict) into a WorldSpec, or a one-line error."""

    def __init__(self, where: str, lines: list[str] | None) -> None:
        self.where = where
        self.lines = lines
        """The file's lines, to say where a field is; None for a dict."""

    # where things are in the file

    def _line(self, table: str | None, index: int, key: str | None) -> int | None:
        """1-based line of ``key`` in the top level (``table`` None), in ``[table]``
        or in the ``index``-th ``[[table]]``; of the table itself without a key."""
        lines = self.lines
        if lines is None:
            return None
        headers = [i for i, line in enumerate(lines) if re.match(r"\s*\[", line)]
        first, end = 0, headers[0] if headers else len(lines)
        if table is not None:
            mine = [i for i in headers if re.match(rf"\s*\[\[?\s*{re.escape(table)}\s*\]", lines[i])]
            if index < len(mine):
                first = mine[index]
                later = [i for i in headers if i > first]
                end = later[0] if later else len(lines)
            else:
                key, table = table, None  # an inline array or table: point at its key
        if key is None:
            return first + 1
        pattern = re.compile(rf"""(^|[\s{{,])["']?{re.escape(key)}["']?\s*=""")
        for i in range(first, end):
            if pattern.search(lines[i]):
                return i + 1
        return first + 1

    def _error(self, message: str, table: str | None = None, index: int = 0, key: str | None = None) -> WorldError:
        line = self._line(table, index, key)
        where = self.where if line is None else f"{self.where}:{line}"
        if table is not None and table != "lidar":
            message = f"[[{table}]] #{index + 1}: {message}"
        elif table == "lidar":
            message = f"[lidar]: {message}"
        return WorldError(f"{where}: {message}")

    # the world

    def world(self, data: dict[str, Any], default_name: str) -> WorldSpec:
        self._known(data, WORLD_FIELDS, None, 0)
        name = self._text(data, "name", default_name)
        description = self._text(data, "description", "")
        background = self._background(data)
        obstacles: list[Any] = []
        for index, item in enumerate(self._tables(data, "circles")):
            self._known(item, CIRCLE_FIELDS, "circles", index)
            x, y, r = (self._number(item, key, "circles", index) for key in CIRCLE_FIELDS)
            if not r > 0.0:
                raise self._error(f"field 'r' must be a positive number, got {r!r}", "circles", index, "r")
            obstacles.append(Circle(x, y, r))
        for index, item in enumerate(self._tables(data, "boxes")):
            self._known(item, BOX_FIELDS, "boxes", index)
            x0, y0, x1, y1 = (self._number(item, key, "boxes", index) for key in BOX_FIELDS)
            if not x0 < x1:
                raise self._error(f"field 'x1' must be greater than x0 ({x0}), got {x1!r}", "boxes", index, "x1")
            if not y0 < y1:
                raise self._error(f"field 'y1' must be greater than y0 ({y0}), got {y1!r}", "boxes", index, "y1")
            obstacles.append(Box(x0, y0, x1, y1))
        return WorldSpec(name, description, tuple(obstacles), self._lidar(data), background)

    def _known(self, data: dict[str, Any], fields: tuple[str, ...], table: str | None, index: int) -> None:
        for key in data:
            if key not in fields:
                raise self._error(f"unknown field {key!r}{did_you_mean(key, fields)}", table, index, key)

    def _text(self, data: dict[str, Any], key: str, default: str) -> str:
        value = data.get(key, default)
        if not isinstance(value, str):
            raise self._error(f"field {key!r} must be a string, got {value!r}", key=key)
        if key == "name" and not value.strip():
            raise self._error("field 'name' must not be empty", key=key)
        return value

    def _background(self, data: dict[str, Any]) -> tuple[int, int, int] | None:
        value = data.get("background")
        if value is None:
            return None
        if (
            not isinstance(value, (list, tuple))
            or len(value) != 3
            or not all(isinstance(c, int) and not isinstance(c, bool) and 0 <= c <= 255 for c in value)
        ):
            raise self._error(
                f"field 'background' must be [r, g, b] with integers 0..255, got {value!r}", key="background"
            )
        return (value[0], value[1], value[2])

    def _tables(self, data: dict[str, Any], key: str) -> list[dict[str, Any]]:
        value = data.get(key, [])
        if not isinstance(value, list) or not all(isinstance(item, dict) for item in value):
            raise self._error(f"field {key!r} must be an array of tables ([[{key}]]), got {value!r}", key=key)
        return value

    def _number(
        self, data: dict[str, Any], key: str, table: str, index: int, default: float | None = None
    ) -> float:
        if key not in data:
            if default is not None:
                return default
            raise self._error(f"field {key!r} is required", table, index)
        value = data[key]
        if not _is_number(value) or not math.isfinite(value):
            raise self._error(f"field {key!r} must be a finite number, got {value!r}", table, index, key)
        return float(value)

    def _lidar(self, data: dict[str, Any]) -> Lidar | None:
        table = data.get("lidar")
        if table is None:
            return None
        if not isinstance(table, dict):
            raise self._error(f"field 'lidar' must be a table ([lidar]), got {table!r}", key="lidar")
        self._known(table, LIDAR_FIELDS, "lidar", 0)
        samples = table.get("samples", 360)
        if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
            raise self._error(f"field 'samples' must be a positive integer, got {samples!r}", "lidar", 0, "samples")
        values = {
            key: self._number(table, key, "lidar", 0, default)
            for key, default in (
                ("angle_min", 0.0),
                ("range_min", 0.0),
                ("range_max", 3.5),
                ("noise_std", 0.0),
                ("dropout", 0.0),
            )
        }
        for key in ("angle_max", "rate"):
            if key in table:
                values[key] = self._number(table, key, "lidar", 0)
        try:
            return Lidar(samples=samples, **values)
        except ValueError as err:
            message = str(err)
            key = next((k for k in LIDAR_FIELDS if k in message and k in table), None)
            raise self._error(message, "lidar", 0, key) from None
