"""Read, validate and find lesson files.

A lesson file is Markdown with a TOML front matter block between two ``+++``
lines at its top (the format is documented in lessons/README.md).
:func:`load_lesson` reads one file; :func:`discover_lessons` loads every lesson
that plugins register (the bundled lessons/ folder comes from the built-in
plugin) plus extra folders; :func:`find_lesson` picks one by id or path.

Every problem raises :class:`LessonError` with a one-line message that starts
``FILE:LINE:`` and names the field, e.g.
``lessons/x.md:4: field 'part' must be an integer or omitted, got 'six'``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

from turtletui.compat.distro import check_distro
from turtletui.errors import TurtletuiError
from turtletui.lessons.model import DEFAULT_START, ArenaOverlay, CheckSpec, Lesson, Scenario
from turtletui.messages import did_you_mean, one_line

if TYPE_CHECKING:
    from turtletui.plugins.manager import Plugins

FENCE = "+++"
ID_PATTERN = re.compile(r"[a-z0-9][a-z0-9-]*")

LESSON_FIELDS = (
    "id",
    "title",
    "part",
    "objectives",
    "starter",
    "executable",
    "reference",
    "world",
    "time_limit",
    "distro",
    "scenarios",
    "checks",
    "overlays",
    "forbidden_services",
)
SCENARIO_FIELDS = (
    "name", "start", "duration", "seed", "seeds", "hidden", "world", "ros_args", "drive", "teleport",
)
START_FIELDS = ("x", "y", "theta")
DRIVE_FIELDS = ("linear", "angular")
TELEPORT_FIELDS = ("at", "x", "y", "theta")
CHECK_FIELDS = ("name", "label", "weight", "feedback", "thresholds", "scenarios", "requires")
OVERLAY_FIELDS = ("x0", "y0", "x1", "y1", "color")


class LessonError(TurtletuiError, ValueError):
    """A lesson file that cannot be used; the message is one line, ``FILE:LINE: ...``."""


# -- reading one file ---------------------------------------------------------------


def load_lesson(path: str | Path) -> Lesson:
    """Read and validate the lesson file at ``path``."""
    path = Path(path)
    shown = display_path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise LessonError(f"{shown}: no such lesson file") from None
    except (OSError, UnicodeDecodeError) as err:
        raise LessonError(f"{shown}: cannot read the lesson: {one_line(err)}") from None
    front, body = split_front_matter(text, shown)
    try:
        data = tomllib.loads(front)
    except tomllib.TOMLDecodeError as err:
        line, message = _toml_error(err, front)
        raise LessonError(f"{shown}:{line + 1}: invalid TOML: {message}") from None
    return _Validator(path, shown, front).lesson(data, body)


def split_front_matter(text: str, shown: str) -> tuple[str, str]:
    """(front matter TOML, Markdown body) of a lesson file's text."""
    lines = text.splitlines(keepends=True)
    if not lines or lines[0].strip() != FENCE:
        raise LessonError(f"{shown}:1: no {FENCE} front matter block")
    for index in range(1, len(lines)):
        if lines[index].strip() == FENCE:
            front = "".join(lines[1:index])
            body = "".join(lines[index + 1 :]).lstrip("\r\n")
            return front, body
    raise LessonError(
        f"{shown}:1: the {FENCE} front matter block is never closed by a {FENCE} line"
    )


def display_path(path: Path) -> str:
    """``path`` relative to the working directory when it is below it, else as given."""
    if path.is_absolute():
        try:
            return str(path.relative_to(Path.cwd()))
        except ValueError:
            pass
    return str(path)


def _toml_error(err: Exception, front: str) -> tuple[int, str]:
    """(line in the front matter, message without its position) of a TOML error."""
    message = str(err)
    found = re.search(r"\s*\(at line (\d+), column (\d+)\)\s*$", message)
    if found:
        return int(found.group(1)), f"{message[: found.start()]} (column {found.group(2)})"
    found = re.search(r"\s*\(at end of document\)\s*$", message)
    if found:
        return max(
            1, len(front.splitlines())
        ), f"{message[: found.start()]} (at the end of the block)"
    return 1, message


def _show(value: Any) -> str:
    return repr(value)


ARENA_METRES = 11.09
"""The arena's width and height as a lesson gives them (turtletui.sim's ARENA_SIZE, 11.0889 m)."""


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _pose_numbers(value: dict[str, Any], fields: Sequence[str], field: str, bad: Any) -> dict[str, float]:
    """A table of ``fields`` (start's, teleport's), each a finite number;
    ``theta`` may be left out (0.0). ``bad(field, message)`` makes the error."""
    for key in value:
        if key not in fields:
            raise bad(field, f"has unknown field {key!r}{did_you_mean(key, fields)}")
    numbers: dict[str, float] = {}
    for key in fields:
        number = value.get(key, 0.0 if key == "theta" else None)
        if number is None:
            raise bad(field, f"is missing {key!r}")
        # inf or nan would reach turtlesim mid-run and stop the grading there
        if not _is_number(number) or not math.isfinite(number):
            raise bad(field, f"{key} must be a number, got {_show(number)}")
        numbers[key] = float(number)
    return numbers


def _in_arena(numbers: dict[str, float], field: str, bad: Any) -> dict[str, float]:
    """``numbers`` if its x and y lie in the arena (a pose outside it would
    grade every answer against the lesson's mistake)."""
    for key in ("x", "y"):
        if not 0.0 <= numbers[key] <= ARENA_METRES:
            raise bad(field, f"{key} must be a number of metres in the arena (0 to {ARENA_METRES}), got {numbers[key]:g}")
    return numbers


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


class _Validator:
    """Turns the parsed front matter into a :class:`Lesson`, or a one-line error."""

    def __init__(self, path: Path, shown: str, front: str) -> None:
        self.path = path
        self.shown = shown
        self.lines = front.splitlines()

    # where things are in the file

    def _file_line(self, front_index: int) -> int:
        """File line number of the front matter's line at ``front_index`` (0-based)."""
        return front_index + 2  # line 1 is the opening +++

    def _section(self, table: str | None, index: int = 0) -> tuple[int, int]:
        """(first, end) front matter line indices of the top level (``table`` None)
        or of the ``index``-th ``[[table]]``."""
        headers = [
            i
            for i, line in enumerate(self.lines)
            if re.match(r"\s*\[", line) and "=" not in line.split("]")[0]
        ]
        if table is None:
            return 0, headers[0] if headers else len(self.lines)
        mine = [
            i for i in headers if re.match(rf"\s*\[\[\s*{re.escape(table)}\s*\]\]", self.lines[i])
        ]
        if index < len(mine):
            start = mine[index]
            later = [i for i in headers if i > start]
            return start, later[0] if later else len(self.lines)
        # an inline array (``scenarios = [{...}]``): point at its key
        return self._key_index(table, None), len(self.lines)

    def _key_index(self, key: str, section: tuple[int, int] | None) -> int:
        first, end = section if section is not None else self._section(None)
        pattern = re.compile(rf"""\s*["']?{re.escape(key)}["']?\s*=""")
        for i in range(first, end):
            if pattern.match(self.lines[i]):
                return i
        # a key inside an inline table, or anywhere in the section
        word = re.compile(rf"""(^|[\s{{,"']){re.escape(key)}["']?\s*=""")
        for i in range(first, end):
            if word.search(self.lines[i]):
                return i
        return max(first, 0) if section is not None else -1

    def _error(
        self, message: str, key: str | None = None, section: tuple[int, int] | None = None
    ) -> LessonError:
        index = -1
        if key is not None:
            index = self._key_index(key, section)
        elif section is not None:
            index = section[0]
        line = self._file_line(index) if index >= 0 else 1
        return LessonError(f"{self.shown}:{line}: {message}")

    # the lesson

    def lesson(self, data: dict[str, Any], body: str) -> Lesson:
        top = self._section(None)
        for key in data:
            if key not in LESSON_FIELDS:
                raise self._error(
                    f"unknown field {key!r}{did_you_mean(key, LESSON_FIELDS)}", key, top
                )
        lesson_id = self._required_text(data, "id", top)
        if not ID_PATTERN.fullmatch(lesson_id):
            raise self._error(
                f"field 'id' must be lower-case letters, digits and '-' (like 'part6-closed-loop'), got {lesson_id!r}",
                "id",
                top,
            )
        title = self._required_text(data, "title", top)
        part = data.get("part")
        if part is not None and not (_is_int(part) and part >= 0):
            raise self._error(
                f"field 'part' must be an integer or omitted, got {_show(part)}", "part", top
            )
        objectives = data.get("objectives", [])
        if not isinstance(objectives, list) or not all(isinstance(o, str) for o in objectives):
            raise self._error(
                f"field 'objectives' must be a list of strings, got {_show(objectives)}",
                "objectives",
                top,
            )
        starter = self._optional_text(data, "starter", top)
        if starter is not None and not (self.path.parent / starter).is_file():
            raise self._error(
                f"starter file {starter!r} not found next to the lesson ({display_path(self.path.parent / starter)})",
                "starter",
                top,
            )
        executable = self._optional_text(data, "executable", top)
        reference = self._optional_text(data, "reference", top)
        world = self._optional_text(data, "world", top) or "empty"
        time_limit = data.get("time_limit")
        if time_limit is not None and not (_is_number(time_limit) and time_limit > 0):
            raise self._error(
                f"field 'time_limit' must be a positive number of seconds, got {_show(time_limit)}",
                "time_limit",
                top,
            )
        distro = self._optional_text(data, "distro", top)
        if distro is not None:
            try:
                distro = check_distro(distro)
            except ValueError as err:
                raise self._error(f"field 'distro': {err}", "distro", top) from None
        scenarios = tuple(
            self._scenario(i, item) for i, item in enumerate(self._tables(data, "scenarios", top))
        )
        seen: dict[str, int] = {}
        for i, scenario in enumerate(scenarios):
            if scenario.name in seen:
                raise self._error(
                    f"scenarios[{i}].name {scenario.name!r} is already used by scenarios[{seen[scenario.name]}]",
                    "name",
                    self._section("scenarios", i),
                )
            seen[scenario.name] = i
        checks = tuple(
            self._check(i, item, seen) for i, item in enumerate(self._tables(data, "checks", top))
        )
        self._gates(checks, tuple(seen))
        forbidden = data.get("forbidden_services", [])
        if not isinstance(forbidden, list) or not all(
            isinstance(f, str) and f.startswith("/") for f in forbidden
        ):
            raise self._error(
                "field 'forbidden_services' must be a list of service names or patterns like"
                f' "/turtle1/teleport_absolute" or "/*/teleport_*", got {_show(forbidden)}',
                "forbidden_services",
                top,
            )
        # a check may repeat (other thresholds per scenario), but results name
        # each by its label and scenario: those pairs must be unique
        every = set(seen)
        judged: dict[tuple[str, str], int] = {}
        for i, check in enumerate(checks):
            for scenario in check.scenarios or every:
                other = judged.setdefault((check.title, scenario), i)
                if other != i:
                    raise self._error(
                        f"checks[{i}] judges scenario {scenario!r} under the name {check.title!r} like"
                        f" checks[{other}]: give one of them a label",
                        "name",
                        self._section("checks", i),
                    )
        overlays = tuple(
            self._overlay(i, item) for i, item in enumerate(self._tables(data, "overlays", top))
        )
        return Lesson(
            id=lesson_id,
            title=title,
            path=self.path,
            body=body,
            part=part,
            objectives=tuple(objectives),
            starter=starter,
            executable=executable,
            reference=reference,
            world=world,
            time_limit=None if time_limit is None else float(time_limit),
            distro=distro,
            scenarios=scenarios,
            checks=checks,
            overlays=overlays,
            forbidden_services=tuple(forbidden),
        )

    def _gates(self, checks: tuple[CheckSpec, ...], every: tuple[str, ...]) -> None:
        """Each name in a check's ``requires`` names checks judged in some of
        its scenarios, each of its scenarios is gated by one of them at least,
        and no chain of requirements comes back to where it started."""
        needs: dict[int, list[int]] = {}
        for i, check in enumerate(checks):
            needs[i] = []
            mine = check.scenarios or every
            for name in check.requires:
                matched = [j for j, other in enumerate(checks) if other.is_named(name)]
                if not matched:
                    known = sorted({c.title for c in checks} | {c.name for c in checks})
                    raise self._error(
                        f"checks[{i}].requires names no check {name!r}{did_you_mean(name, known)}",
                        "requires",
                        self._section("checks", i),
                    )
                if not any(set(mine) & set(checks[j].scenarios or every) for j in matched):
                    raise self._error(
                        f"checks[{i}].requires {name!r}, which judges none of its scenarios",
                        "requires",
                        self._section("checks", i),
                    )
                needs[i].extend(matched)
            if check.requires:
                for scenario in mine:
                    if not any(scenario in (checks[j].scenarios or every) for j in needs[i]):
                        raise self._error(
                            f"checks[{i}] judges scenario {scenario!r}, where none of the checks it"
                            f" requires ({', '.join(check.requires)}) is judged",
                            "requires",
                            self._section("checks", i),
                        )
        state: dict[int, str] = {}

        def visit(i: int, path: list[int]) -> None:
            state[i] = "open"
            for j in needs[i]:
                if state.get(j) == "open":  # on the path being walked: a loop
                    loop = [*path[path.index(j) :], j]
                    names = " -> ".join(checks[k].title for k in loop)
                    raise self._error(
                        f"checks[{i}].requires makes a loop ({names}): a check cannot require itself",
                        "requires",
                        self._section("checks", i),
                    )
                if j not in state:
                    visit(j, [*path, j])
            state[i] = "done"

        for i in needs:
            if i not in state:
                visit(i, [i])

    def _required_text(self, data: dict[str, Any], key: str, top: tuple[int, int]) -> str:
        if key not in data:
            raise self._error(f"missing field {key!r}")
        value = data[key]
        if not isinstance(value, str) or not value.strip():
            raise self._error(
                f"field {key!r} must be a non-empty string, got {_show(value)}", key, top
            )
        return value

    def _optional_text(self, data: dict[str, Any], key: str, top: tuple[int, int]) -> str | None:
        value = data.get(key)
        if value is not None and (not isinstance(value, str) or not value.strip()):
            raise self._error(
                f"field {key!r} must be a non-empty string or omitted, got {_show(value)}", key, top
            )
        return value

    def _tables(self, data: dict[str, Any], key: str, top: tuple[int, int]) -> list[dict[str, Any]]:
        value = data.get(key, [])
        if not isinstance(value, list) or not all(isinstance(item, dict) for item in value):
            raise self._error(
                f"field {key!r} must be a list of tables ([[{key}]] sections), got {_show(value)}",
                key,
                top,
            )
        return value

    # scenarios and checks

    def _named_table(
        self, kind: str, i: int, item: dict[str, Any], fields: Sequence[str]
    ) -> tuple[Any, str]:
        """Check one [[kind]] table's keys and its required name; returns an
        error maker for its fields (``bad(field, message)``) and the name."""
        where = f"{kind}[{i}]"
        section = self._section(kind, i)

        def bad(field: str, message: str) -> LessonError:
            return self._error(f"{where}.{field} {message}", field, section)

        for key in item:
            if key not in fields:
                raise self._error(
                    f"{where}: unknown field {key!r}{did_you_mean(key, fields)}", key, section
                )
        if "name" not in item:
            raise self._error(f"{where}: missing field 'name'", None, section)
        name = item["name"]
        if not isinstance(name, str) or not name.strip():
            raise bad("name", f"must be a non-empty string, got {_show(name)}")
        return bad, name

    def _scenario(self, i: int, item: dict[str, Any]) -> Scenario:
        bad, name = self._named_table("scenarios", i, item, SCENARIO_FIELDS)
        start = self._start(item.get("start", dict(DEFAULT_START)), bad)
        duration = item.get("duration", 60.0)
        if not _is_number(duration) or not duration > 0:
            raise bad("duration", f"must be a positive number, got {_show(duration)}")
        if "seed" in item and "seeds" in item:
            raise bad("seeds", "and seed cannot both be given: use one")
        seeds: tuple[int, ...]
        if "seeds" in item:
            value = item["seeds"]
            if not isinstance(value, list) or not value or not all(_is_int(s) for s in value):
                raise bad("seeds", f"must be a non-empty list of integers, got {_show(value)}")
            seeds = tuple(value)
        else:
            seed = item.get("seed", 0)
            if not _is_int(seed):
                raise bad("seed", f"must be an integer, got {_show(seed)}")
            seeds = (seed,)
        hidden = item.get("hidden", False)
        if not isinstance(hidden, bool):
            raise bad("hidden", f"must be true or false, got {_show(hidden)}")
        world = item.get("world")
        if world is not None and (not isinstance(world, str) or not world.strip()):
            raise bad("world", f"must be a non-empty string or omitted, got {_show(world)}")
        ros_args = item.get("ros_args", [])
        if not isinstance(ros_args, list) or not all(isinstance(a, str) for a in ros_args):
            raise bad("ros_args", f'must be a list of strings like ["-p", "speed:=2.0"], got {_show(ros_args)}')
        drive = item.get("drive")
        if drive is not None:
            if (
                not isinstance(drive, dict)
                or set(drive) - set(DRIVE_FIELDS)
                or not all(_is_number(v) for v in drive.values())
            ):
                raise bad("drive", f"must be a table {{linear = m/s, angular = rad/s}}, got {_show(drive)}")
            drive = (float(drive.get("linear", 0.0)), float(drive.get("angular", 0.0)))
        teleport = self._teleport(item.get("teleport"), float(duration), bad)
        return Scenario(
            name=name,
            start=start,
            duration=float(duration),
            seeds=seeds,
            hidden=hidden,
            world=world,
            ros_args=tuple(ros_args),
            drive=drive,
            teleport=teleport,
        )

    @staticmethod
    def _teleport(value: Any, duration: float, bad: Any) -> tuple[float, float, float, float] | None:
        if value is None:
            return None
        if not isinstance(value, dict):
            raise bad("teleport", f"must be a table {{at = s, x = m, y = m, theta = rad}}, got {_show(value)}")
        numbers = _pose_numbers(value, TELEPORT_FIELDS, "teleport", bad)
        at, x, y, theta = (numbers[key] for key in TELEPORT_FIELDS)
        if not 0.0 < at < duration:
            raise bad("teleport", f"at must lie within the run (after 0 and before {duration:g} s), got {at:g}")
        _in_arena(numbers, "teleport", bad)
        return at, x, y, theta

    def _overlay(self, i: int, item: dict[str, Any]) -> ArenaOverlay:
        where = f"overlays[{i}]"
        section = self._section("overlays", i)
        for key in item:
            if key not in OVERLAY_FIELDS:
                raise self._error(
                    f"{where}: unknown field {key!r}{did_you_mean(key, OVERLAY_FIELDS)}", key, section
                )
        corners = []
        for key in ("x0", "y0", "x1", "y1"):
            if key not in item:
                raise self._error(f"{where}: missing field {key!r}", None, section)
            value = item[key]
            if not _is_number(value) or not 0.0 <= value <= ARENA_METRES:
                raise self._error(
                    f"{where}.{key} must be a number of metres in the arena (0 to {ARENA_METRES}), got {_show(value)}",
                    key,
                    section,
                )
            corners.append(float(value))
        color = item.get("color")
        if color is not None:
            if not (
                isinstance(color, list)
                and len(color) == 3
                and all(_is_int(c) and 0 <= c <= 255 for c in color)
            ):
                raise self._error(
                    f"{where}.color must be [r, g, b] with integers 0..255, got {_show(color)}",
                    "color",
                    section,
                )
            color = tuple(color)
        return ArenaOverlay(*corners, color=color)

    def _start(self, value: Any, bad: Any) -> dict[str, float] | str:
        if value == "random":
            return "random"
        if not isinstance(value, dict):
            raise bad(
                "start",
                f'must be a table {{x = ..., y = ..., theta = ...}} or "random", got {_show(value)}',
            )
        return _in_arena(_pose_numbers(value, START_FIELDS, "start", bad), "start", bad)

    def _check(self, i: int, item: dict[str, Any], scenario_names: dict[str, int]) -> CheckSpec:
        bad, name = self._named_table("checks", i, item, CHECK_FIELDS)
        weight = item.get("weight", 1.0)
        if not _is_number(weight) or weight < 0:
            raise bad("weight", f"must be a number >= 0, got {_show(weight)}")
        feedback = item.get("feedback", "")
        if not isinstance(feedback, str):
            raise bad("feedback", f"must be a string, got {_show(feedback)}")
        thresholds = item.get("thresholds", {})
        if not isinstance(thresholds, dict):
            raise bad("thresholds", f"must be a table, got {_show(thresholds)}")
        scenarios = item.get("scenarios", [])
        if not isinstance(scenarios, list) or not all(isinstance(n, str) for n in scenarios):
            raise bad("scenarios", f"must be a list of scenario names, got {_show(scenarios)}")
        for scenario in scenarios:
            if scenario not in scenario_names:
                raise bad(
                    "scenarios",
                    f"names no scenario {scenario!r}{did_you_mean(scenario, list(scenario_names))}",
                )
        label = item.get("label", "")
        if not isinstance(label, str):
            raise bad("label", f"must be a string, got {_show(label)}")
        requires = item.get("requires", [])
        if not isinstance(requires, list) or not all(isinstance(n, str) and n.strip() for n in requires):
            raise bad("requires", f'must be a list of check names like ["distance"], got {_show(requires)}')
        return CheckSpec(
            name=name,
            label=label.strip(),
            weight=float(weight),
            feedback=feedback,
            thresholds=dict(thresholds),
            scenarios=tuple(scenarios),
            requires=tuple(requires),
            line=self._file_line(self._section("checks", i)[0]),
        )


# -- finding lessons ------------------------------------------------------------------


def lesson_files(source: Path) -> list[Path]:
    """The lesson files of a registered file or folder: a folder gives every ``*.md``
    directly in it except README.md, in name order."""
    if source.is_dir():
        return sorted(
            p for p in source.glob("*.md") if p.is_file() and p.name.lower() != "readme.md"
        )
    if source.is_file():
        return [source]
    raise LessonError(f"{display_path(source)}: no such lesson file or folder")


def lesson_sources(plugins: Plugins = ()) -> list[Path]:
    """The lesson files and folders plugins register (the built-in plugin registers
    the bundled lessons/ folder); ``plugins`` is the plugin manager, or extra
    plugin files or folders."""
    from turtletui.plugins.manager import collect_lessons, plugin_manager

    return collect_lessons(plugin_manager(plugins))


def discover_lessons(extra_folders: Iterable[str | Path] = (), plugins: Plugins = ()) -> list[Lesson]:
    """Every lesson registered by plugins and in ``extra_folders`` (folders or files),
    sorted by part (lessons without one last), then id. Two lessons with the same
    id are an error naming both files."""
    sources = [*lesson_sources(plugins), *(Path(f) for f in extra_folders)]
    seen_files: set[Path] = set()
    by_id: dict[str, Lesson] = {}
    for source in sources:
        for file in lesson_files(source):
            key = file.resolve()
            if key in seen_files:
                continue
            seen_files.add(key)
            lesson = load_lesson(file)
            if lesson.id in by_id:
                other = by_id[lesson.id]
                raise LessonError(
                    f"{display_path(file)}:{_id_line(file)}: lesson id {lesson.id!r} is already used by "
                    f"{display_path(other.path)}:{_id_line(other.path)}"
                )
            by_id[lesson.id] = lesson
    return sorted(by_id.values(), key=lambda ls: (ls.part is None, ls.part or 0, ls.id))


def _id_line(path: Path) -> int:
    """Line of the ``id =`` key in a lesson file that already loaded."""
    lines = path.read_text(encoding="utf-8-sig").splitlines()
    for number, line in enumerate(lines, start=1):
        if re.match(r"""\s*["']?id["']?\s*=""", line):
            return number
        if number > 1 and line.strip() == FENCE:
            break
    return 1


def looks_like_path(text: str) -> bool:
    return text.endswith(".md") or "/" in text or "\\" in text


def find_lesson(
    id_or_path: str | Path,
    extra_folders: Iterable[str | Path] = (),
    plugins: Plugins = (),
) -> Lesson:
    """The lesson with this id among :func:`discover_lessons`, or the lesson file at
    this path; an unknown id is an error listing the known ones."""
    text = str(id_or_path)
    if isinstance(id_or_path, Path) or looks_like_path(text):
        return load_lesson(Path(id_or_path))
    lessons = discover_lessons(extra_folders, plugins)
    for lesson in lessons:
        if lesson.id == text:
            return lesson
    known = ", ".join(lesson.id for lesson in lessons) or "none"
    hint = did_you_mean(text, [lesson.id for lesson in lessons])
    raise LessonError(f"no lesson {text!r}{hint}; known lessons: {known}")
