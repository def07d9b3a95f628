"""Lesson files: the format's loader, its one-line errors, and discovery."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from turtletui.lessons.loader import LessonError, discover_lessons, find_lesson, load_lesson
from turtletui.plugins.bundled import lessons_dir

ROOT = Path(__file__).resolve().parents[2]
PART6 = ROOT / "lessons" / "part6_closed_loop.md"

GOOD_FRONT = """\
id = "demo-lesson"
title = "A demo"
part = 2
"""


def write(folder: Path, name: str, front: str, body: str = "# Body\n\nText.\n") -> Path:
    path = folder / name
    path.write_text(f"+++\n{textwrap.dedent(front)}+++\n{body}", encoding="utf-8")
    return path


def error_of(path: Path) -> str:
    with pytest.raises(LessonError) as info:
        load_lesson(path)
    message = str(info.value)
    assert "\n" not in message
    return message


# -- the Part 6 lesson ----------------------------------------------------------------


def test_the_part6_lesson_loads():
    lesson = load_lesson(PART6)
    assert lesson.id == "part6-closed-loop"
    assert lesson.part == 6
    assert lesson.title == "Closed-loop control: never hit the wall"
    assert lesson.reference == "part6_wall_avoider"
    assert lesson.world == "empty"
    assert lesson.path == PART6
    assert lesson.body.startswith("# Part 6 - Closed-loop control")
    assert "+++" not in lesson.body
    assert lesson.starter_path == PART6.parent / "part6_starter.py"
    assert lesson.starter_path.is_file()
    assert [c.name for c in lesson.checks] == ["wall_hits", "no_crash", "closed_loop", "distance", "coverage"]
    assert lesson.checks[0].thresholds == {"max": 0} and lesson.checks[0].weight == 5.0
    assert lesson.checks[0].requires == ("distance", "coverage", "closed_loop")
    assert "/*/teleport_absolute" in lesson.forbidden_services
    assert lesson.checks[0].line > 1
    by_name = {s.name: s for s in lesson.scenarios}
    centre, random_starts = by_name["centre"], by_name["random starts"]
    assert (centre.name, centre.duration, centre.hidden, centre.seeds) == (
        "centre",
        60.0,
        False,
        (0,),
    )
    assert centre.start == pytest.approx({"x": 5.544445, "y": 5.544445, "theta": 0.0})
    assert random_starts.start == "random"
    assert len(random_starts.seeds) > 1
    assert any(s.hidden for s in lesson.scenarios)


def test_the_run_command_default_lesson_file_is_still_there():
    assert lessons_dir() is not None
    assert (lessons_dir() / "part6_closed_loop.md").is_file()


def test_the_part6_starter_compiles_and_publishes_a_zero_twist():
    source = (ROOT / "lessons" / "part6_starter.py").read_text(encoding="utf-8")
    compile(source, "part6_starter.py", "exec")
    assert "def pose_callback" in source
    assert "TODO" in source
    assert "self.cmd_vel_publisher_.publish(cmd)" in source


def test_a_full_lesson_loads_with_defaults_and_checks(tmp_path):
    (tmp_path / "start.py").write_text("print('hi')\n")
    path = write(
        tmp_path,
        "full.md",
        """\
        id = "full"
        title = "Full"
        objectives = ["one", "two"]
        starter = "start.py"

        [[scenarios]]
        name = "a"

        [[checks]]
        name = "no_wall_hits"
        weight = 2
        feedback = "Hit a wall"
        thresholds = {max = 0}
        """,
    )
    lesson = load_lesson(path)
    assert lesson.part is None
    assert lesson.objectives == ("one", "two")
    assert lesson.world == "empty"
    assert lesson.reference is None
    assert lesson.starter_path == tmp_path / "start.py"
    (scenario,) = lesson.scenarios
    assert (scenario.duration, scenario.seed, scenario.hidden) == (60.0, 0, False)
    assert scenario.start == {"x": 5.544445, "y": 5.544445, "theta": 0.0}
    (check,) = lesson.checks
    assert (check.name, check.weight, check.feedback, check.thresholds) == (
        "no_wall_hits",
        2.0,
        "Hit a wall",
        {"max": 0},
    )


# -- one-line errors naming file, line and field -----------------------------------------


def test_no_front_matter(tmp_path):
    path = tmp_path / "x.md"
    path.write_text("# Just Markdown\n")
    assert error_of(path) == f"{path}:1: no +++ front matter block"


def test_unclosed_front_matter(tmp_path):
    path = tmp_path / "x.md"
    path.write_text('+++\nid = "x"\n# no closing line\n')
    assert error_of(path).startswith(f"{path}:1: the +++ front matter block is never closed")


def test_invalid_toml_gives_the_file_line(tmp_path):
    path = write(tmp_path, "x.md", 'id = "x"\ntitle = "T"\npart = \n')
    message = error_of(path)
    assert message.startswith(f"{path}:4: invalid TOML: ")  # front matter line 3 is file line 4
    assert "column" in message


def test_unknown_field_suggests_the_right_one(tmp_path):
    path = write(tmp_path, "x.md", 'id = "x"\n\ntittle = "T"\n')
    assert error_of(path) == f"{path}:4: unknown field 'tittle' (did you mean 'title'?)"


def test_unknown_field_without_a_close_match(tmp_path):
    path = write(tmp_path, "x.md", GOOD_FRONT + "colour = 3\n")
    assert error_of(path) == f"{path}:5: unknown field 'colour'"


def test_wrong_type_for_part(tmp_path):
    path = write(tmp_path, "x.md", 'id = "x"\ntitle = "T"\npart = "six"\n')
    assert error_of(path) == f"{path}:4: field 'part' must be an integer or omitted, got 'six'"


def test_a_boolean_is_not_a_part_number(tmp_path):
    path = write(tmp_path, "x.md", 'id = "x"\ntitle = "T"\npart = true\n')
    assert error_of(path) == f"{path}:4: field 'part' must be an integer or omitted, got True"


def test_objectives_must_be_strings(tmp_path):
    path = write(tmp_path, "x.md", GOOD_FRONT + "objectives = [1, 2]\n")
    assert error_of(path).startswith(f"{path}:5: field 'objectives' must be a list of strings")


def test_missing_title(tmp_path):
    path = write(tmp_path, "x.md", 'id = "x"\n')
    assert error_of(path) == f"{path}:1: missing field 'title'"


@pytest.mark.parametrize("bad_id", ["Part6", "part 6", "-x", "part_6", ""])
def test_bad_id_format(tmp_path, bad_id):
    path = write(tmp_path, "x.md", f'title = "T"\nid = "{bad_id}"\n')
    message = error_of(path)
    assert message.startswith(f"{path}:3: field 'id' must ")


def test_scenario_field_errors_name_their_index_and_line(tmp_path):
    path = write(
        tmp_path,
        "x.md",
        GOOD_FRONT
        + """
[[scenarios]]
name = "one"

[[scenarios]]
name = "two"
duration = -5
""",
    )
    assert error_of(path) == f"{path}:11: scenarios[1].duration must be a positive number, got -5"


@pytest.mark.parametrize(
    ("lines", "expected"),
    [
        ('name = "s"\nseed = 1.5', "scenarios[0].seed must be an integer, got 1.5"),
        ('name = "s"\nhidden = "yes"', "scenarios[0].hidden must be true or false, got 'yes'"),
        ('name = "s"\nstart = {x = 1, y = "a"}', "scenarios[0].start y must be a number, got 'a'"),
        ('name = "s"\nstart = {x = 1}', "scenarios[0].start is missing 'y'"),
        ('name = "s"\nstart = {x = 1, y = 2, z = 3}', "scenarios[0].start has unknown field 'z'"),
        ('name = "s"\nstart = {x = 1, y = 2, theta = nan}', "scenarios[0].start theta must be a number, got nan"),
        # a start outside the arena would grade every answer against the lesson's mistake
        ('name = "s"\nstart = {x = 88, y = 2}', "scenarios[0].start x must be a number of metres in the arena (0 to 11.09), got 88"),
        ('name = "s"\nstart = {x = 1, y = -0.5}', "scenarios[0].start y must be a number of metres in the arena (0 to 11.09), got -0.5"),
        (
            'name = "s"\ndurration = 3',
            "scenarios[0]: unknown field 'durration' (did you mean 'duration'?)",
        ),
        (
            'name = "s"\nseeds = []',
            "scenarios[0].seeds must be a non-empty list of integers, got []",
        ),
        ("seed = 1\nduration = 2", "scenarios[0]: missing field 'name'"),
    ],
)
def test_scenario_errors(tmp_path, lines, expected):
    path = write(tmp_path, "x.md", GOOD_FRONT + "\n[[scenarios]]\n" + lines + "\n")
    line = 6 if "missing field" in expected else 8
    assert error_of(path) == f"{path}:{line}: {expected}"


def test_duplicate_scenario_names(tmp_path):
    path = write(
        tmp_path, "x.md", GOOD_FRONT + '[[scenarios]]\nname = "a"\n[[scenarios]]\nname = "a"\n'
    )
    assert error_of(path) == f"{path}:8: scenarios[1].name 'a' is already used by scenarios[0]"


def test_check_field_errors(tmp_path):
    path = write(
        tmp_path,
        "x.md",
        GOOD_FRONT + '[[checks]]\nname = "c"\nweight = -1\n[[checks]]\nname = "d"\n',
    )
    assert error_of(path) == f"{path}:7: checks[0].weight must be a number >= 0, got -1"
    path = write(tmp_path, "y.md", GOOD_FRONT + '[[checks]]\nname = "c"\nthresholds = 3\n')
    assert error_of(path) == f"{path}:7: checks[0].thresholds must be a table, got 3"


def test_overlays_are_read_with_their_colour(tmp_path):
    path = write(
        tmp_path,
        "x.md",
        GOOD_FRONT + "[[overlays]]\nx0 = 2\ny0 = 2.0\nx1 = 9.0\ny1 = 9\n"
        "[[overlays]]\nx0 = 1.0\ny0 = 1.0\nx1 = 3.0\ny1 = 3.0\ncolor = [0, 200, 0]\n",
    )
    overlays = load_lesson(path).overlays
    assert [(o.x0, o.y0, o.x1, o.y1, o.color) for o in overlays] == [
        (2.0, 2.0, 9.0, 9.0, None),
        (1.0, 1.0, 3.0, 3.0, (0, 200, 0)),
    ]
    assert [(o.x0, o.x1) for o in load_lesson(PART6).overlays] == [(2.0, 9.0)]


def test_overlay_field_errors(tmp_path):
    def error(lines: str) -> str:
        return error_of(write(tmp_path, "x.md", GOOD_FRONT + "[[overlays]]\n" + lines))

    assert error("x0 = 1.0\ny0 = 1.0\nx1 = 2.0\n").endswith("overlays[0]: missing field 'y1'")
    assert error("x0 = 1.0\ny0 = 1.0\nx1 = 2.0\ny1 = 20\n").endswith(
        "overlays[0].y1 must be a number of metres in the arena (0 to 11.09), got 20"
    )
    assert error('x0 = 1.0\ny0 = 1.0\nx1 = 2.0\ny1 = 2.0\ncolor = "red"\n').endswith(
        "overlays[0].color must be [r, g, b] with integers 0..255, got 'red'"
    )
    assert "overlays[0]: unknown field 'colour' (did you mean 'color'?)" in error(
        "x0 = 1.0\ny0 = 1.0\nx1 = 2.0\ny1 = 2.0\ncolour = [1, 2, 3]\n"
    )


TWO_SCENARIOS = '[[scenarios]]\nname = "a"\n[[scenarios]]\nname = "b"\n'


def test_requires_names_the_checks_a_check_is_gated_on(tmp_path):
    path = write(
        tmp_path,
        "x.md",
        GOOD_FRONT
        + TWO_SCENARIOS
        + '[[checks]]\nname = "distance"\nlabel = "far"\n'
        + '[[checks]]\nname = "wall_hits"\nrequires = ["far", "distance"]\n',
    )
    lesson = load_lesson(path)
    assert lesson.checks[1].requires == ("far", "distance")
    assert lesson.checks[0].is_named("far") and lesson.checks[0].is_named("distance")


@pytest.mark.parametrize(
    ("checks", "line", "expected"),
    [
        (
            '[[checks]]\nname = "distance"\n[[checks]]\nname = "wall_hits"\nrequires = ["distanse"]\n',
            13,
            "checks[1].requires names no check 'distanse' (did you mean 'distance'?)",
        ),
        (
            '[[checks]]\nname = "wall_hits"\nrequires = "distance"\n',
            11,
            "checks[0].requires must be a list of check names like [\"distance\"], got 'distance'",
        ),
        (
            '[[checks]]\nname = "distance"\nscenarios = ["a"]\n[[checks]]\nname = "wall_hits"\n'
            'scenarios = ["b"]\nrequires = ["distance"]\n',
            15,
            "checks[1].requires 'distance', which judges none of its scenarios",
        ),
        (
            '[[checks]]\nname = "distance"\nscenarios = ["a"]\n[[checks]]\nname = "wall_hits"\n'
            'requires = ["distance"]\n',
            14,
            "checks[1] judges scenario 'b', where none of the checks it requires (distance) is judged",
        ),
        (
            '[[checks]]\nname = "distance"\nrequires = ["wall_hits"]\n'
            '[[checks]]\nname = "wall_hits"\nrequires = ["distance"]\n',
            14,
            "checks[1].requires makes a loop (distance -> wall_hits -> distance): a check cannot require itself",
        ),
        (
            '[[checks]]\nname = "distance"\nrequires = ["distance"]\n',
            11,
            "checks[0].requires makes a loop (distance -> distance): a check cannot require itself",
        ),
    ],
)
def test_requires_errors(tmp_path, checks, line, expected):
    path = write(tmp_path, "x.md", GOOD_FRONT + TWO_SCENARIOS + checks)
    assert error_of(path) == f"{path}:{line}: {expected}"


def test_forbidden_services_and_a_scenarios_drive(tmp_path):
    front = GOOD_FRONT + 'forbidden_services = ["/*/teleport_absolute", "/reset"]\n'
    path = write(tmp_path, "x.md", front + '[[scenarios]]\nname = "a"\ndrive = {linear = 1.0, angular = -0.5}\n')
    lesson = load_lesson(path)
    assert lesson.forbidden_services == ("/*/teleport_absolute", "/reset")
    assert lesson.scenarios[0].drive == (1.0, -0.5)
    path = write(tmp_path, "y.md", GOOD_FRONT + 'forbidden_services = "teleport"\n')
    assert error_of(path).startswith(f"{path}:5: field 'forbidden_services' must be a list of service names")
    path = write(tmp_path, "z.md", GOOD_FRONT + '[[scenarios]]\nname = "a"\ndrive = {speed = 1.0}\n')
    assert error_of(path) == (
        f"{path}:7: scenarios[0].drive must be a table {{linear = m/s, angular = rad/s}}, got {{'speed': 1.0}}"
    )


@pytest.mark.parametrize(
    ("teleport", "expected"),
    [
        ("{at = 2.0, x = 3.0, y = 4.0}", (2.0, 3.0, 4.0, 0.0)),
        ("{at = 2.0, x = 3.0, y = 4.0, theta = 1.5}", (2.0, 3.0, 4.0, 1.5)),
        ("[2.0, 3.0, 4.0]", "teleport must be a table {at = s, x = m, y = m, theta = rad}, got [2.0, 3.0, 4.0]"),
        ("{x = 3.0, y = 4.0}", "teleport is missing 'at'"),
        ("{at = 2.0, x = 3.0, y = 4.0, z = 1.0}", "teleport has unknown field 'z'"),
        ("{at = 2.0, x = 3.0, y = 4.0, thetta = 1.0}", "teleport has unknown field 'thetta' (did you mean 'theta'?)"),
        ('{at = "soon", x = 3.0, y = 4.0}', "teleport at must be a number, got 'soon'"),
        ("{at = 2.0, x = true, y = 4.0}", "teleport x must be a number, got True"),
        ("{at = 2.0, x = 3.0, y = 4.0, theta = inf}", "teleport theta must be a number, got inf"),
        ("{at = nan, x = 3.0, y = 4.0}", "teleport at must be a number, got nan"),
        ("{at = 60.0, x = 3.0, y = 4.0}", "teleport at must lie within the run (after 0 and before 10 s), got 60"),
        ("{at = 10.0, x = 3.0, y = 4.0}", "teleport at must lie within the run (after 0 and before 10 s), got 10"),
        ("{at = 2.0, x = 12.0, y = 4.0}", "teleport x must be a number of metres in the arena (0 to 11.09), got 12"),
    ],
)
def test_a_scenarios_teleport(tmp_path, teleport, expected):
    path = write(tmp_path, "x.md", GOOD_FRONT + f'[[scenarios]]\nname = "a"\nduration = 10.0\nteleport = {teleport}\n')
    if isinstance(expected, tuple):
        assert load_lesson(path).scenarios[0].teleport == expected
    else:
        assert error_of(path).startswith(f"{path}:8: scenarios[0].{expected}")


def test_a_missing_starter_file(tmp_path):
    path = write(tmp_path, "x.md", GOOD_FRONT + 'starter = "nope.py"\n')
    assert error_of(path).startswith(
        f"{path}:5: starter file 'nope.py' not found next to the lesson"
    )


def test_a_missing_lesson_file(tmp_path):
    assert error_of(tmp_path / "gone.md") == f"{tmp_path / 'gone.md'}: no such lesson file"


def test_paths_below_the_working_directory_are_shown_relative(tmp_path, monkeypatch):
    (tmp_path / "lessons").mkdir()
    path = write(tmp_path / "lessons", "x.md", 'id = "x"\ntitle = "T"\npart = "six"\n')
    monkeypatch.chdir(tmp_path)
    assert error_of(path).startswith("lessons/x.md:4: field 'part'")


# -- discovery --------------------------------------------------------------------------


def test_discovery_finds_the_bundled_lesson():
    assert "part6-closed-loop" in [lesson.id for lesson in discover_lessons()]


def test_discovery_from_an_extra_folder(tmp_path):
    write(tmp_path, "b.md", 'id = "zeta"\ntitle = "Z"\n')
    write(tmp_path, "a.md", 'id = "alpha"\ntitle = "A"\npart = 1\n')
    (tmp_path / "README.md").write_text("# Not a lesson\n")
    (tmp_path / "notes.txt").write_text("not markdown")
    bundled = [lesson.id for lesson in discover_lessons()]
    ids = [lesson.id for lesson in discover_lessons([tmp_path])]
    assert ids.index("alpha") < ids.index("part6-closed-loop") < ids.index("zeta")
    assert sorted(ids) == sorted([*bundled, "alpha", "zeta"])


def test_discovery_through_a_plugin(tmp_path):
    folder = tmp_path / "more"
    folder.mkdir()
    write(folder, "p.md", 'id = "from-plugin"\ntitle = "P"\n')
    plugin = tmp_path / "my_plugin.py"
    plugin.write_text(
        "from pathlib import Path\n"
        "from turtletui.plugins import hookimpl\n\n"
        "@hookimpl\n"
        "def turtletui_register_lessons(register):\n"
        "    register(Path(__file__).parent / 'more')\n"
    )
    ids = [lesson.id for lesson in discover_lessons(plugins=[plugin])]
    assert "from-plugin" in ids
    assert "from-plugin" not in [lesson.id for lesson in discover_lessons()]


def test_duplicate_ids_name_both_files(tmp_path):
    first = write(tmp_path, "a.md", 'title = "A"\nid = "same"\n')
    second = write(tmp_path, "b.md", 'id = "same"\ntitle = "B"\n')
    with pytest.raises(LessonError) as info:
        discover_lessons([tmp_path])
    assert str(info.value) == f"{second}:2: lesson id 'same' is already used by {first}:3"


def test_a_bundled_id_cannot_be_reused(tmp_path):
    write(tmp_path, "copy.md", 'id = "part6-closed-loop"\ntitle = "Copy"\n')
    with pytest.raises(LessonError, match="lesson id 'part6-closed-loop' is already used by"):
        discover_lessons([tmp_path])


def test_a_missing_extra_folder(tmp_path):
    with pytest.raises(LessonError, match="no such lesson file or folder"):
        discover_lessons([tmp_path / "nope"])


def test_find_by_id_and_by_path(tmp_path):
    bundled = lessons_dir() / "part6_closed_loop.md"  # the package's copy when installed
    assert find_lesson("part6-closed-loop").path.resolve() == bundled.resolve()
    path = write(tmp_path, "mine.md", 'id = "mine"\ntitle = "M"\n')
    assert find_lesson(str(path)).id == "mine"
    assert find_lesson("mine", [tmp_path]).id == "mine"


def test_an_unknown_id_lists_the_known_ones(monkeypatch):
    monkeypatch.setenv("TURTLETUI_DISABLE_PLUGIN_AUTOLOAD", "1")
    with pytest.raises(LessonError) as info:
        find_lesson("part6-closed-lop")
    message = str(info.value)
    assert message.startswith("no lesson 'part6-closed-lop' (did you mean 'part6-closed-loop'?); known lessons: ")
    known = message.split("known lessons: ")[1].split(", ")
    assert "part6-closed-loop" in known and known == [lesson.id for lesson in discover_lessons()]
