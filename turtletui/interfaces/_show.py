"""``ros2 interface show`` for our types (imported on first use).

Mirrors ros2cli's ``ros2interface/verb/show.py``: every line of the
definition is printed as written (top level keeps its comments), each field
of a message type is followed by that type's definition indented one tab
further, without comments or blank lines. Each line is parsed on its own the
way rosidl_adapter does, quirks included, so the output matches byte for byte.
"""

from __future__ import annotations

import re
import textwrap

from turtletui.interfaces._message import is_primitive_type

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable

_PRIMITIVES = frozenset((
    'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16', 'uint16',
    'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring', 'duration', 'time',
))
_UNIT = re.compile(r'(\s*\[([^,\]]+)\])')


def _process_comment(comment: str) -> list[str]:
    """rosidl_adapter's clean-up of a one-line comment (units in [] removed)."""
    matches = _UNIT.findall(comment)
    if len(matches) == 1:
        comment = comment.replace(matches[0][0], '')
    if comment == '':
        return []
    return textwrap.dedent(comment).split('\n')


def line_info(line: str, package: str) -> tuple[bool, str | None, str | None]:
    """(is a comment, trailing comment, nested type 'pkg/Name') of one line."""
    if line == '---':
        return False, None, None
    text = line.replace('\t', ' ')
    if text.startswith('#'):
        return bool(_process_comment(text.lstrip('#'))), None, None
    if not text.strip():
        return False, None, None
    comment = None
    at = text.find('#')
    if at >= 0:
        comment = text[at:].lstrip('#')
        if not text[:at].strip():
            return False, None, None  # indented comment line
        text = text[:at].rstrip()
    type_string, _, rest = text.partition(' ')
    rest = rest.lstrip()
    if not rest or '=' in rest:
        return False, None, None  # a constant
    processed = _process_comment(comment) if comment is not None else []
    base = type_string.split('[', 1)[0]
    nested = None
    if base not in _PRIMITIVES and not is_primitive_type(base) \
            and not base.startswith('wstring<='):
        nested = base if '/' in base else f'{package}/{base}'
    return False, processed[0] if processed else None, nested


def show(cls: type, lookup: Callable[[str], type], comments: bool,
         nested_comments: bool, indent: int, out: list[str]) -> None:
    """Append the lines ``ros2 interface show`` prints for *cls* to *out*."""
    package = cls._TYPE_NAME.split('/', 1)[0]
    for raw in cls._DEFINITION.splitlines():
        line = raw.rstrip()
        is_comment, trailing, nested = line_info(line, package)
        text: str | None = line
        if not comments:
            if not line or is_comment:
                text = None
            elif trailing is not None:
                text = line[:line.find(trailing) - 1].strip()
        if text is not None:
            out.append('\t' * indent + text if text else '')
        if nested is not None:
            show(lookup(nested), lookup, nested_comments, nested_comments, indent + 1, out)
