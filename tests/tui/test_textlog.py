"""TextLog: lines wrap at the pane's real width, at every size and after a
resize; a bounded window of entries with "N older lines" above it."""

from __future__ import annotations

from support.pilot import pilot_test
from textual.app import App, ComposeResult

from turtletui.tui.widgets.textlog import TextLog

LONG = "[first_node] Hello " + " ".join(f"word{i}" for i in range(30)) + " THE-END 42"


class LogApp(App):
    CSS = "TextLog { width: 30; height: 10; }"

    def __init__(self, max_entries: int = 5000) -> None:
        super().__init__()
        self.max_entries = max_entries

    def compose(self) -> ComposeResult:
        yield TextLog(self.max_entries)


def shown(log: TextLog) -> str:
    return " ".join(log.visible_lines)


@pilot_test
async def test_a_long_line_wraps_at_the_real_width_and_nothing_is_cut() -> None:
    app = LogApp()
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        log.write(LONG)
        await pilot.pause()
        width = log.scrollable_content_region.width
        assert width < 30
        lines = [line.rstrip() for line in log.visible_lines if line.strip()]
        assert all(len(line) <= width for line in lines)
        assert " ".join(lines).split() == LONG.split()  # every word, in order, none cut
        assert "THE-END 42" in shown(log)


@pilot_test
async def test_lines_wrap_again_after_a_resize() -> None:
    app = LogApp()
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        log.write(LONG)
        await pilot.pause()
        narrow = len([line for line in log.visible_lines if line.strip()])
        log.styles.width = 60
        await pilot.pause()
        wide = [line.rstrip() for line in log.visible_lines if line.strip()]
        assert len(wide) < narrow
        assert max(map(len, wide)) > 30  # the new width is used, not the old one
        assert " ".join(wide).split() == LONG.split()


@pilot_test
async def test_the_window_keeps_the_latest_entries_and_counts_the_older() -> None:
    app = LogApp(max_entries=100)
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        log.write_all(f"line {i}" for i in range(250))
        await pilot.pause()
        assert log.entries == [f"line {i}" for i in range(150, 250)]
        assert log.older == 150
        assert log.visible_lines[-1].strip() == "line 249"  # it follows the end
        log.scroll_home(animate=False)
        await pilot.pause()
        assert log.visible_lines[0].strip() == "... 150 older lines"
        assert log.visible_lines[1].strip() == "line 150"


@pilot_test
async def test_reading_back_is_not_disturbed_by_new_lines() -> None:
    app = LogApp(max_entries=100)
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        log.write_all(f"line {i}" for i in range(100))
        await pilot.pause()
        log.scroll_to(y=40, animate=False)
        await pilot.pause()
        top = log.visible_lines[0]
        log.write_all(f"line {i}" for i in range(100, 110))  # ten old ones go
        await pilot.pause()
        assert log.visible_lines[0] == top


@pilot_test
async def test_entries_written_while_hidden_appear_wrapped_once_shown() -> None:
    app = LogApp()
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        log.display = False
        await pilot.pause()
        log.write(LONG)
        log.display = True
        await pilot.pause()
        assert "THE-END 42" in shown(log)


@pilot_test
async def test_any_line_of_a_long_log_can_be_scrolled_to_and_read() -> None:
    app = LogApp(max_entries=3000)
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        log.write_all(f"entry {i} " + "x" * (i % 40) for i in range(4000))
        await pilot.pause()
        assert "entry 3999" in shown(log)
        log.scroll_home(animate=False, immediate=True)
        await pilot.pause()
        assert log.visible_lines[0].startswith("... 1,000 older lines")
        assert log.visible_lines[1].startswith("entry 1000 ")
        log.scroll_to(y=log.max_scroll_y // 2, animate=False, immediate=True)
        await pilot.pause()
        numbers = [int(line.split()[1]) for line in log.visible_lines if line.startswith("entry ")]
        assert numbers == sorted(numbers) and 1000 < numbers[0] < 3999
        assert numbers == list(range(numbers[0], numbers[0] + len(numbers)))


@pilot_test
async def test_a_full_window_holds_few_objects_for_the_garbage_collector() -> None:
    """The app's full collections scan every tracked object: 5,000 wrapped
    entries kept as Textual strips (each with its own caches) made them pause
    the 16 ms loop for a quarter second."""
    import gc

    app = LogApp()
    async with app.run_test(size=(80, 24)) as pilot:
        log = app.query_one(TextLog)
        await pilot.pause()
        gc.collect()
        before = len(gc.get_objects())
        log.write_all(f"[INFO] [1700000000.{i:03d}] [turtle_controller]: x={i % 11}.5 y=5.5 " + LONG
                      for i in range(5000))
        await pilot.pause()
        gc.collect()
        per_entry = (len(gc.get_objects()) - before) / 5000
        assert per_entry < 20, per_entry  # 120 when every wrapped line was kept as a strip
