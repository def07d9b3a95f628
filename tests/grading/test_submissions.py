"""What a student hands in (turtletui.grading.submissions): files, folders, ROS 2
packages and workspaces; --executable and the lesson's default; ambiguity."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from support.grading import HONEST, WALL_HITTER, grade_cli
from support.ros_package import EXECUTABLE, PACKAGE, write_package, write_workspace

from turtletui.grading.submissions import choose_controller, find_submissions


def test_a_ros_package_is_graded_by_its_console_scripts_executable(tmp_path: Path, lesson: Path):
    package = write_package(tmp_path / "alice")
    with pytest.raises(ValueError, match=f"several possible controllers \\({PACKAGE} test_node, {PACKAGE} {EXECUTABLE}\\)"):
        choose_controller(package)
    chosen = choose_controller(package, executable=EXECUTABLE)
    assert chosen.path == package / PACKAGE / f"{EXECUTABLE}.py" and chosen.function == "main"
    assert choose_controller(package, default_executable=EXECUTABLE).path == chosen.path
    assert choose_controller(package, executable=f"{PACKAGE}/{EXECUTABLE}").path == chosen.path
    with pytest.raises(ValueError, match="no executable 'nope' \\(found: "):
        choose_controller(package, executable="nope")
    # graded sandboxed, its package-relative imports working, the report naming what ran
    result = grade_cli(package, "--lesson", lesson, "--executable", EXECUTABLE, "--format", "json",
                       "--results", tmp_path / "res", "--same-user")
    assert result.exit_code == 0, result.stderr
    sub = json.loads(result.stdout)["submissions"][0]
    assert sub["error"] is None and sub["score"] == 3.0, sub
    assert sub["graded"] == f"{PACKAGE}/{EXECUTABLE}.py ({PACKAGE} {EXECUTABLE}: main())"


def test_a_submission_is_graded_in_its_own_folder(tmp_path: Path, lesson: Path, monkeypatch):
    # a file read by a relative path, beside the controller: graded as the student ran it
    folder = tmp_path / "ann"
    folder.mkdir()
    (folder / "speed.txt").write_text("5.0\n")
    (folder / "my_controller.py").write_text(
        HONEST.replace("cmd.linear.x = 5.0", "cmd.linear.x = float(open('speed.txt').read())")
    )
    monkeypatch.chdir(tmp_path)
    result = grade_cli(folder, "--lesson", lesson, "--format", "json", "--results", tmp_path / "res", "--same-user")
    assert result.exit_code == 0, result.stderr
    sub = json.loads(result.stdout)["submissions"][0]
    assert sub["error"] is None and sub["score"] == 3.0, sub


def test_a_workspace_and_nested_uploads_are_found(tmp_path: Path):
    workspace = write_workspace(tmp_path)
    chosen = choose_controller(workspace, executable=EXECUTABLE)  # build/ and install/ are skipped
    assert chosen.path == workspace / "src" / PACKAGE / PACKAGE / f"{EXECUTABLE}.py"
    (found,) = find_submissions([workspace], executable=EXECUTABLE)
    assert found.student == "ros2_ws" and found.controller == chosen.path
    # a setup.cfg package (console_scripts in [options.entry_points]) with a src/ layout
    cfg = tmp_path / "cfgpkg"
    (cfg / "src" / "bot").mkdir(parents=True)
    (cfg / "src" / "bot" / "__init__.py").write_text("")
    (cfg / "src" / "bot" / "drive.py").write_text(HONEST.replace("def main():", "def run():"))
    (cfg / "setup.cfg").write_text("[metadata]\nname = bot\n[options.entry_points]\nconsole_scripts =\n    driver = bot.drive:run\n")
    chosen = choose_controller(cfg)
    assert (chosen.label, chosen.function) == ("bot driver", "run")


def test_a_folder_of_files_stray_files_and_the_untouched_starter(tmp_path: Path):
    klass = tmp_path / "class"
    (klass / "ann").mkdir(parents=True)
    (klass / "ann" / "my_controller.py").write_text(HONEST)
    starter = tmp_path / "part6_starter.py"
    starter.write_text(WALL_HITTER)
    (klass / "ann" / "part6_starter.py").write_text(WALL_HITTER.replace("\n", "\r\n") + "\n\n")
    (klass / "ann" / "helpers.py").write_text("SPEED = 1.0\n")
    (klass / "notes.txt").write_text("grading notes\n")
    (klass / ".DS_Store").write_bytes(b"\0")
    (klass / "__pycache__").mkdir()
    (klass / "ben").mkdir()
    (klass / "ben" / "a.py").write_text(HONEST)
    (klass / "ben" / "b.py").write_text(HONEST)
    found = find_submissions([klass], starter=starter)
    assert [s.student for s in found] == ["ann", "ben"]  # notes.txt is nobody's row
    ann, ben = found
    assert ann.controller == klass / "ann" / "my_controller.py"  # not the untouched starter
    assert ben.controller is None and ben.error.endswith(
        "several possible controllers (a.py, b.py): choose one with --executable NAME"
    )
    assert find_submissions([klass / "ben"], executable="b")[0].controller == klass / "ben" / "b.py"


def test_one_upload_as_a_platform_hands_it_over(tmp_path: Path):
    empty = tmp_path / "empty"
    empty.mkdir()
    (empty / ".DS_Store").write_bytes(b"\0")
    (sub,) = find_submissions([empty], single=True)
    assert sub.controller is None and "the upload is empty" in sub.error
    upload = tmp_path / "upload"
    write_package(upload / "__MACOSX")  # a Mac zip's resource forks are not code
    write_package(upload)
    (sub,) = find_submissions([upload], single=True, executable=EXECUTABLE)
    assert sub.controller == upload / PACKAGE / PACKAGE / f"{EXECUTABLE}.py"
    plain = tmp_path / "plain"
    plain.mkdir()
    (plain / "node.py").write_text(HONEST)
    (sub,) = find_submissions([plain], single=True, executable=EXECUTABLE)  # a package's name; a file upload
    assert sub.controller == plain / "node.py"


def test_a_folder_of_several_complete_nodes_is_a_class_of_one_file_submissions(tmp_path: Path):
    klass = tmp_path / "class"
    klass.mkdir()
    for name in ("ann", "ben", "cat"):
        (klass / f"{name}.py").write_text(HONEST)
    (klass / "notes.txt").write_text("marks due friday\n")
    found = find_submissions([klass])
    assert [(s.student, s.controller) for s in found] == [(n, klass / f"{n}.py") for n in ("ann", "ben", "cat")]
    # one student's folder: one node and its helper module, or a node named by --executable
    one = tmp_path / "dan"
    one.mkdir()
    (one / "turtle_controller.py").write_text(HONEST)
    (one / "helpers.py").write_text("SPEED = 1.0\n")
    assert [s.controller for s in find_submissions([one])] == [one / "turtle_controller.py"]
    assert [s.student for s in find_submissions([klass], executable="ben")] == ["class"]
    assert [s.student for s in find_submissions([klass], default_executable="ann")] == ["class"]


def test_a_notebook_or_an_archive_handed_in_instead_of_a_py_file_is_named_with_what_to_do(tmp_path: Path):
    klass = tmp_path / "class"
    for student, name in (("ann", "controller.ipynb"), ("ben", "node.ZIP"), ("cat", "readme.md")):
        (klass / student).mkdir(parents=True)
        (klass / student / name).write_text("{}")
    errors = {s.student: s.error for s in find_submissions([klass])}
    assert errors["ann"].endswith(
        "ann: no controller: the folder has no Python (.py) file, but controller.ipynb, a Jupyter notebook:"
        " export it as a .py file (jupyter nbconvert --to script)"
    )
    assert errors["ben"].endswith("no Python (.py) file, but node.ZIP, an archive: unpack it into the folder")
    assert errors["cat"].endswith("cat: no controller: the folder has no Python (.py) file")


def test_a_text_file_is_named_only_when_it_holds_the_code(tmp_path: Path):
    # a note to the instructor is no misnamed controller ("but notes.txt, text:
    # name a Python file .py" read as if the note should have been code)
    klass = tmp_path / "class"
    (klass / "dan").mkdir(parents=True)
    (klass / "dan" / "notes.txt").write_text("I could not get it to work, sorry\n")
    (klass / "eve").mkdir()
    (klass / "eve" / "node.txt").write_text(HONEST)
    errors = {s.student: s.error for s in find_submissions([klass])}
    assert errors["dan"].endswith("dan: no controller: the folder has no Python (.py) file")
    assert errors["eve"].endswith("no Python (.py) file, but node.txt, Python saved as text: name it node.py")


COURSE_NODES = {  # the course's my_robot_controller: executable, module, reference file
    "test_node": ("my_first_node", "my_first_node.py"),
    "draw_circle": ("draw_circle", "draw_circle.py"),
    "pose_subscriber": ("pose_subscriber", "pose_subscriber.py"),
    "turtle_controller": ("turtle_controller", "turtle_controller_pen.py"),
}


@pytest.mark.parametrize(("lesson_id", "executable"), [
    ("part3-first-node", "test_node"),
    ("part4-open-loop-circle", "draw_circle"),
    ("part5-pose-subscriber", "pose_subscriber"),
    ("part7-pen-service", "turtle_controller"),
])
def test_the_course_package_is_graded_by_each_parts_node_without_naming_it(tmp_path: Path, lesson_id, executable):
    # by Part 7 the package has all four nodes; only Part 6 named its own, so
    # every other part's package hand-in was "several possible controllers"
    reference = Path(__file__).parents[2] / "plugins" / "reference"
    root = tmp_path / "alice" / PACKAGE
    (root / PACKAGE).mkdir(parents=True)
    scripts = ", ".join(f"'{name} = {PACKAGE}.{module}:main'" for name, (module, _) in COURSE_NODES.items())
    (root / "setup.py").write_text(
        f"from setuptools import setup\nsetup(name='{PACKAGE}', packages=['{PACKAGE}'],\n"
        f"      entry_points={{'console_scripts': [{scripts}]}})\n"
    )
    (root / PACKAGE / "__init__.py").write_text("")
    for module, source in COURSE_NODES.values():
        (root / PACKAGE / f"{module}.py").write_text((reference / source).read_text())
    result = grade_cli(root, "--lesson", lesson_id, "--format", "json", "--results", tmp_path / "res", "--same-user")
    assert result.exit_code == 0, result.stderr
    (sub,) = json.loads(result.stdout)["submissions"]
    assert sub["error"] is None, sub["error"]
    module = COURSE_NODES[executable][0]
    assert sub["graded"] == f"{PACKAGE}/{module}.py ({PACKAGE} {executable}: main())"
    assert sub["score"] == sub["max_score"], sub["tests"]
