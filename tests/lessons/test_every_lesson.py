"""Every bundled lesson: it renders in the terminal and in the app's lesson
pane, it can be graded (its checks exist, its reference is registered), and
its starter file is there to copy."""

from __future__ import annotations

import pytest
from support.pilot import SIZE, pilot_test
from typer.testing import CliRunner

from turtletui.cli import app
from turtletui.grading.engine import prepare
from turtletui.lessons.loader import discover_lessons
from turtletui.plugins.manager import collect_controllers, get_plugin_manager
from turtletui.tui.app import TurtleApp

LESSONS = discover_lessons()
IDS = [lesson.id for lesson in LESSONS]


def test_the_series_and_the_lessons_beyond_it_are_all_there():
    assert {f"part{n}" for n in range(3, 8)} <= {i.split("-")[0] for i in IDS}
    assert {"go-to-goal", "actions-rotate", "parameters", "several-turtles", "lidar-obstacles"} <= set(IDS)
    assert [lesson.part for lesson in LESSONS if lesson.part is not None] == [3, 4, 5, 6, 7]


@pytest.mark.parametrize("lesson", LESSONS, ids=IDS)
def test_a_lesson_renders_in_the_terminal_and_can_be_graded(lesson):
    result = CliRunner().invoke(app, ["lesson", lesson.id])
    assert result.exit_code == 0, result.output
    assert lesson.title in result.stdout and "+++" not in result.stdout
    plan = prepare(lesson)
    assert plan.max_score == pytest.approx(10.0)
    assert lesson.reference in collect_controllers(get_plugin_manager())
    assert lesson.starter_path is not None and lesson.starter_path.is_file()
    assert "On a real ROS 2" in lesson.body


@pytest.mark.parametrize("lesson", LESSONS, ids=IDS)
@pilot_test
async def test_a_lesson_shows_in_the_apps_lesson_pane(lesson):
    app_ = TurtleApp(lesson=lesson.path)
    async with app_.run_test(size=SIZE) as pilot:
        await pilot.press("4")
        assert app_.query_one("#side").current == "lesson"
        assert app_.query_one("#lesson").source == lesson.body
