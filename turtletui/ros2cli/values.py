"""Message arguments in, messages out, with PyYAML as ros2cli uses it.

``ros2 topic pub``, ``service call`` and ``action send_goal`` read their
values with ``yaml.safe_load`` (YAML 1.1: ``017`` is 15, ``0o17`` and ``1e3``
stay strings, ``off`` is false) and fill the message as
rosidl_runtime_py's ``set_message_fields`` does: a value of another type is
passed through the field's Python type (``float(1)``, ``str(42)``,
``int(2.9)``, ``bool('false')``). ``ros2 topic echo`` prints messages with
``yaml.dump`` (``message_to_yaml``). Using the same library makes turtletui
agree with the real tools by construction.
"""

from __future__ import annotations

import sys
from typing import Any

import yaml

from turtletui.interfaces import InterfaceError, Message, from_dict, to_dict
from turtletui.ros2cli.common import CommandError, PlainError, one_line

__all__ = ["YamlError", "message_values", "message_yaml", "parse_yaml", "populate", "yaml_lines"]


class YamlError(ValueError):
    """Text that PyYAML cannot read; the message says why in one line."""


def parse_yaml(text: str) -> Any:
    """``yaml.safe_load(text)``, with a one-line :class:`YamlError` for bad YAML."""
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise YamlError(_yaml_problem(text, exc)) from None


def _yaml_problem(text: str, exc: yaml.YAMLError) -> str:
    unbalanced = _balance_problem(text)
    if unbalanced:
        return unbalanced  # PyYAML would say "expected ',' or '}', but got '<stream end>'"
    problem = getattr(exc, "problem", None) or str(exc).split("\n")[0]
    mark = getattr(exc, "problem_mark", None)
    where = f" at column {mark.column + 1}" if mark is not None and "\n" not in text else ""
    return f"{one_line(problem)}{where}"


def _balance_problem(text: str) -> str | None:
    """'unbalanced braces' / 'unbalanced brackets' if the collections of flow
    YAML do not pair up (quoted scalars skipped), else None."""
    stack: list[str] = []
    i, n = 0, len(text)
    token_start = True
    while i < n:
        c = text[i]
        if c in ("'", '"') and token_start:
            end = i + 1
            while end < n and not (text[end] == c and (c == '"' or text[end + 1:end + 2] != "'")):
                end += 2 if (c == '"' and text[end] == "\\") or (c == "'" and text[end:end + 2] == "''") else 1
            if end >= n:
                return None  # an unclosed quote is PyYAML's to report
            i = end + 1
            token_start = False
            continue
        if c in "{[":
            stack.append(c)
        elif c in "}]":
            if not stack or stack[-1] != {"}": "{", "]": "["}[c]:
                return _unbalanced(stack[-1] if stack else c)
            stack.pop()
        token_start = c in " \t\n,{[:"
        i += 1
    return _unbalanced(stack[-1]) if stack else None


def _unbalanced(c: str) -> str:
    return "unbalanced braces" if c in "{}" else "unbalanced brackets"


# -- YAML out ------------------------------------------------------------------------

def yaml_lines(value: Any) -> list[str]:
    """``value`` (from ``to_dict``) in PyYAML's block style, as ``ros2 topic
    echo`` and ``ros2 param dump`` print it."""
    text = yaml.safe_dump(value, sort_keys=False, allow_unicode=True, width=sys.maxsize,
                          default_flow_style=False)
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if lines and lines[-1] == "...":  # a lone scalar's end-of-document marker
        lines.pop()
    return lines


def message_yaml(msg: Message) -> str:
    """rosidl_runtime_py's ``message_to_yaml`` (with its final newline)."""
    return "\n".join(yaml_lines(to_dict(msg))) + "\n"


# -- values in --------------------------------------------------------------------------

def message_values(text: str | None, cls: type, what: str) -> Message:
    """Parse a YAML argument and fill a ``cls`` message from it, as ``ros2 topic
    pub`` does; :class:`CommandError` with one line if that fails."""
    text = "{}" if text is None else text
    try:
        data = parse_yaml(text)
    except YamlError as exc:
        raise CommandError(f"could not parse {what} '{text}' as YAML ({exc})") from None
    if data is None:
        data = {}
    if not isinstance(data, dict):
        raise CommandError(f"the {what} must be a YAML dictionary such as '{{x: 1.0}}', got '{text}'")
    return populate(cls, data)


def populate(cls: type, data: dict) -> Message:
    """A ``cls`` message from YAML values, converted as ``set_message_fields``
    converts them; anything still wrong is one line naming the field."""
    try:
        return from_dict(cls, _convert(cls, data, ""))
    except InterfaceError as exc:
        raise PlainError(f"Failed to populate field: {one_line(str(exc))}") from None


def _convert(cls: type, data: Any, path: str) -> Any:
    if not isinstance(data, dict):
        return data  # from_dict says what the field needs
    specs = {spec.name: spec for spec in cls._FIELDS}
    out = {}
    for key, value in data.items():
        if isinstance(key, bool):
            raise PlainError(
                f"Failed to populate field: a field name {'in ' + path[:-1] + ' ' if path else ''}"
                f"was read as the boolean {str(key).lower()} (YAML reads on, off, yes and no as"
                " booleans): quote it, e.g. \"{'off': 1}\"")
        spec = specs.get(key)
        if spec is None:
            out[key] = value
        elif spec.array and isinstance(value, (list, tuple)):
            out[key] = [_convert_item(spec, item, f"{path}{key}.") for item in value]
        else:
            out[key] = _convert_one(spec, value, f"{path}{key}.")
    return out


def _convert_item(spec: Any, value: Any, path: str) -> Any:
    """An item of a sequence: set_message_fields builds the sequence as a whole
    (``array('d', [1, 2])``), so only ints become floats; messages recurse."""
    if spec.kind == "msg":
        return _convert(spec.msg_cls, value, path)
    if spec.kind == "float" and type(value) is int:
        return float(value)
    return value


_SCALAR_TYPES = {"float": float, "int": int, "bool": bool, "str": str}


def _convert_one(spec: Any, value: Any, path: str) -> Any:
    if spec.kind == "msg":
        return _convert(spec.msg_cls, value, path)
    field_type = _SCALAR_TYPES.get(spec.kind)
    if field_type is None or type(value) is field_type or isinstance(value, (dict, list)) or value is None:
        return value
    try:
        return field_type(value)  # what set_message_fields does: float('1e3'), str(42), int(2.9)
    except (TypeError, ValueError, OverflowError):
        return value  # from_dict names the field and what it needs
