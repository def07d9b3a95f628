"""Read the class list an LMS exports (Canvas's gradebook, Moodle's grades) and
match grading folders to its students."""

from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass, field
from pathlib import Path

from turtletui.errors import TurtletuiError
from turtletui.messages import one_line


class RosterError(TurtletuiError, ValueError):
    """A roster file that cannot be read; one line naming the file."""


@dataclass
class Roster:
    """A CSV class list: its header, its students' rows, and the rows that
    describe columns instead of students (Canvas's "Points Possible")."""

    path: Path
    header: list[str]
    students: list[list[str]] = field(default_factory=list)
    meta: list[list[str]] = field(default_factory=list)

    def column(self, name: str) -> int | None:
        """Index of the column called ``name`` (case and spaces ignored), or None."""
        wanted = _key(name)
        for i, title in enumerate(self.header):
            if _key(title) == wanted:
                return i
        return None

    def cell(self, row: list[str], name: str) -> str:
        index = self.column(name)
        return row[index].strip() if index is not None and index < len(row) else ""


def _key(text: str) -> str:
    return " ".join(text.replace("\ufeff", "").split()).casefold()


def _is_meta(row: list[str]) -> bool:
    """Canvas puts "Points Possible" (and, in newer exports, a row of "(read
    only)" and "Manual Posting" markers) between the header and the students."""
    first = row[0].strip() if row else ""
    if first.casefold() == "points possible":
        return True
    return not first and any(c.strip() in ("(read only)", "Manual Posting", "Muted") for c in row)


def read_roster(path: Path) -> Roster:
    """Parse a roster CSV (UTF-8, with or without a byte-order mark)."""
    try:
        text = path.read_bytes().decode("utf-8-sig")
    except OSError as err:
        raise RosterError(f"{path}: cannot read the roster ({err.strerror or err})") from None
    except UnicodeDecodeError as err:
        raise RosterError(f"{path}: the roster is not UTF-8 text (byte {err.start})") from None
    try:
        rows = [row for row in csv.reader(io.StringIO(text)) if any(cell.strip() for cell in row)]
    except csv.Error as err:
        raise RosterError(f"{path}: not a CSV file: {one_line(err)}") from None
    if not rows:
        raise RosterError(f"{path}: the roster is empty")
    roster = Roster(path, rows[0])
    for row in rows[1:]:
        (roster.meta if _is_meta(row) else roster.students).append(row)
    return roster


def _norm(text: str) -> str:
    return re.sub(r"[\s_.,\-]+", " ", text.casefold()).strip()


def identities(roster: Roster, row: list[str], columns: tuple[str, ...]) -> set[str]:
    """Every way a folder may name this student: the identifier columns, the
    e-mail's user part, and the name as "Last, First" and "First Last"."""
    found = set()
    for name in columns:
        value = roster.cell(row, name)
        if value:
            found.add(_norm(value))
            if "@" in value:
                found.add(_norm(value.split("@", 1)[0]))
    student = roster.cell(row, "Student")
    if "," in student:
        last, first = student.split(",", 1)
        found.add(_norm(f"{first} {last}"))
    first, last = roster.cell(row, "First name"), roster.cell(row, "Last name")
    if first or last:
        found.add(_norm(f"{first} {last}"))
        found.add(_norm(f"{last} {first}"))
    found.discard("")
    return found


def match_students(roster: Roster, students: list[str], columns: tuple[str, ...]) -> tuple[dict[int, str], list[str]]:
    """Roster row index -> the student (grading folder name) it matches, and
    the students no row matches (or more than one does)."""
    by_identity: dict[str, list[int]] = {}
    for index, row in enumerate(roster.students):
        for identity in identities(roster, row, columns):
            by_identity.setdefault(identity, []).append(index)
    matched: dict[int, str] = {}
    unmatched = []
    for student in students:
        rows = sorted(set(by_identity.get(_norm(student), [])))
        if len(rows) == 1 and rows[0] not in matched:
            matched[rows[0]] = student
        else:
            unmatched.append(student)
    return matched, unmatched
