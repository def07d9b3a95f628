"""`turtletui lessons`, `turtletui lesson ID` and `turtletui new --lesson ID FILE`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from support.grading import one_line_error
from typer.testing import CliRunner

from turtletui.cli import app

ROOT = Path(__file__).resolve().parents[2]
STARTER = ROOT / "lessons" / "part6_starter.py"


@pytest.fixture(autouse=True)
def _no_installed_plugins(monkeypatch):
    monkeypatch.setenv("TURTLETUI_DISABLE_PLUGIN_AUTOLOAD", "1")


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


def write_lesson(folder: Path, name: str, front: str) -> Path:
    path = folder / name
    path.write_text(f"+++\n{front}+++\n# Body\n", encoding="utf-8")
    return path


def test_lessons_table_lists_the_part6_lesson():
    result = invoke("lessons")
    assert result.exit_code == 0, result.output
    header, *rows = result.stdout.splitlines()
    assert header.split() == ["ID", "PART", "TITLE"]
    assert any(
        row.split(None, 2) == ["part6-closed-loop", "6", "Closed-loop control: never hit the wall"]
        for row in rows
    )


def test_lessons_json_has_the_fields():
    result = invoke("lessons", "--json")
    assert result.exit_code == 0, result.output
    rows = json.loads(result.stdout)
    (part6,) = [row for row in rows if row["id"] == "part6-closed-loop"]
    assert part6["title"] == "Closed-loop control: never hit the wall"
    assert part6["part"] == 6
    # The bundled copy: the repository's lessons/ in a checkout, the package's when installed.
    from turtletui.plugins.bundled import lessons_dir

    assert Path(part6["path"]).resolve() == (lessons_dir() / "part6_closed_loop.md").resolve()


def test_lessons_folder_adds_lessons_and_part_is_null_when_absent(tmp_path):
    write_lesson(tmp_path, "extra.md", 'id = "extra-one"\ntitle = "Extra"\n')
    rows = json.loads(invoke("lessons", "--json", "--folder", str(tmp_path)).stdout)
    (extra,) = [row for row in rows if row["id"] == "extra-one"]
    assert extra["part"] is None
    assert extra["path"] == str(tmp_path / "extra.md")
    table = invoke("lessons", "--folder", str(tmp_path)).stdout
    assert any(line.split(None, 2) == ["extra-one", "-", "Extra"] for line in table.splitlines())


def test_lessons_reports_a_bad_lesson_in_one_line(tmp_path):
    bad = write_lesson(tmp_path, "bad.md", 'id = "bad"\ntitle = "B"\npart = "six"\n')
    stderr = one_line_error(invoke("lessons", "--folder", str(tmp_path)))
    assert f"{bad}:4: field 'part' must be an integer or omitted, got 'six'" in stderr


def test_lessons_reports_duplicate_ids_naming_both_files(tmp_path):
    a = write_lesson(tmp_path, "a.md", 'id = "twin"\ntitle = "A"\n')
    b = write_lesson(tmp_path, "b.md", 'id = "twin"\ntitle = "B"\n')
    stderr = one_line_error(invoke("lessons", "--folder", str(tmp_path)))
    assert str(a) in stderr and str(b) in stderr


def test_lesson_prints_the_title_and_body():
    result = invoke("lesson", "part6-closed-loop")
    assert result.exit_code == 0, result.output
    assert "Closed-loop control: never hit the wall" in result.stdout
    assert "The controller" in result.stdout  # a heading of the body
    assert "+++" not in result.stdout
    assert 'id = "part6-closed-loop"' not in result.stdout


def test_lesson_accepts_a_file(tmp_path):
    path = write_lesson(tmp_path, "mine.md", 'id = "mine"\ntitle = "My own lesson"\n')
    result = invoke("lesson", str(path))
    assert result.exit_code == 0, result.output
    assert "My own lesson" in result.stdout


def test_an_unknown_id_lists_the_known_ids():
    stderr = one_line_error(invoke("lesson", "part9"))
    assert "no lesson 'part9'" in stderr
    assert "known lessons: " in stderr and "part6-closed-loop" in stderr.split("known lessons: ")[1]


def test_new_writes_the_starter(tmp_path):
    out = tmp_path / "out.py"
    result = invoke("new", "--lesson", "part6-closed-loop", str(out))
    assert result.exit_code == 0, result.output
    compile(out.read_text(), str(out), "exec")
    # the command it prints opens the lesson too, so that `k` has something to check
    assert f"Run it: turtletui run {out} --lesson part6-closed-loop" in result.stdout
    # and so does the file itself, which names itself rather than the lesson's starter
    assert out.read_text() == STARTER.read_text().replace(
        "turtletui run part6_starter.py", "turtletui run out.py --lesson part6-closed-loop"
    ).replace("part6_starter.py", "out.py")
    assert "Run it with:  turtletui run out.py --lesson part6-closed-loop\n" in out.read_text()


def test_new_from_a_lesson_folder_names_the_lesson_file(tmp_path):
    starter = tmp_path / "plain_starter.py"
    starter.write_text("def main():\n    pass\n")
    lesson = write_lesson(tmp_path, "plain.md", 'id = "plain"\ntitle = "Plain"\nstarter = "plain_starter.py"\n')
    out = tmp_path / "my node.py"
    result = invoke("new", "--lesson", "plain", "--folder", str(tmp_path), str(out))
    assert result.exit_code == 0, result.output
    assert f"Run it: turtletui run '{out}' --lesson {lesson}" in result.stdout
    assert out.read_text() == starter.read_text()  # it names no file: copied as it is


def test_new_refuses_to_overwrite_without_force(tmp_path):
    out = tmp_path / "out.py"
    out.write_text("my work\n")
    stderr = one_line_error(invoke("new", "--lesson", "part6-closed-loop", str(out)))
    assert "already exists" in stderr and "--force" in stderr
    assert out.read_text() == "my work\n"
    result = invoke("new", "--lesson", "part6-closed-loop", str(out), "--force")
    assert result.exit_code == 0, result.output
    assert out.read_text().startswith(STARTER.read_text()[:40])


def test_new_with_an_unknown_lesson(tmp_path):
    out = tmp_path / "out.py"
    stderr = one_line_error(invoke("new", "--lesson", "nope", str(out)))
    assert "no lesson 'nope'" in stderr and "part6-closed-loop" in stderr
    assert not out.exists()


def test_new_with_a_lesson_without_starter(tmp_path):
    write_lesson(tmp_path, "plain.md", 'id = "plain"\ntitle = "Plain"\n')
    out = tmp_path / "out.py"
    stderr = one_line_error(invoke("new", "--lesson", "plain", "--folder", str(tmp_path), str(out)))
    assert "lesson 'plain' has no starter file" in stderr
    assert not out.exists()


def test_lessons_reports_an_unknown_check_or_world_before_any_grading(tmp_path):
    check = write_lesson(tmp_path, "c.md", 'id = "c"\ntitle = "C"\n[[checks]]\nname = "wal_hits"\n')
    stderr = one_line_error(invoke("lessons", "--folder", str(tmp_path)))
    assert f"{check}:4: check 'wal_hits' is not a registered check (did you mean 'wall_hits'?)" in stderr
    check.unlink()
    write_lesson(tmp_path, "w.md", 'id = "w"\ntitle = "W"\nworld = "moon"\n')
    stderr = one_line_error(invoke("lessons", "--folder", str(tmp_path)))
    assert "unknown world 'moon'" in stderr
