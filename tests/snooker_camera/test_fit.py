"""The camera tool's panes lose no text at their edges: long script lines scroll sideways
with markers, a long status is elided in the middle, long info rows wrap, extra rows are
counted."""

from __future__ import annotations

import shutil
from pathlib import Path

from camlab88.apps.snooker.camera import motion
from camlab88.apps.snooker.camera_tool import fit, layout
from camlab88.apps.snooker.camera_tool.tool import CameraTool
from camlab88.emulator.machine import RainbowMachine

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"


def test_a_line_wider_than_the_pane_is_marked_where_text_is_hidden() -> None:
    text = "".join(chr(97 + i % 26) for i in range(30))
    assert fit.window(text, 0, 40) == text
    assert fit.window(text, 0, 10) == text[:9] + ">"
    assert fit.window(text, 5, 10) == "<" + text[6:14] + ">"
    assert fit.window(text, 20, 10) == "<" + text[21:30]
    assert fit.window("     indented", 3, 10) == "  indented"  # only blanks hidden: no marker


def test_the_view_scrolls_to_keep_the_cursor_column_in_sight() -> None:
    assert fit.scroll_left(0, 5, 10) == 0
    left = fit.scroll_left(0, 25, 10)
    assert left < 25 < left + 10 - 1
    assert fit.scroll_left(left, 0, 10) == 0


def test_a_long_status_keeps_both_ends_and_info_rows_wrap_and_are_counted() -> None:
    status = "a" * 30 + " changed on disk: ctrl-r reloads it"
    short = fit.elide(status, 40)
    assert len(short) == 40 and "..." in short and short.endswith("ctrl-r reloads it")
    rows = fit.wrap_rows([("x " * 30, 2), ("ok", 1)], 20, 10)
    assert [v for _, v in rows] == [2] * (len(rows) - 1) + [1] and len(rows) > 2
    assert " ".join(t for t, _ in rows[:-1]).split() == ["x"] * 30
    assert all(len(t) <= 20 for t, _ in rows)
    cut = fit.wrap_rows([(str(i), 1) for i in range(12)], 20, 5)
    assert [t for t, _ in cut] == ["0", "1", "2", "3", "... 8 more rows"]


def test_the_script_pane_scrolls_sideways_to_a_long_lines_end_and_clicks_follow(
        tmp_path: Path) -> None:
    script = tmp_path / "cam.ccl"
    shutil.copy(DATA / "thesis_example.ccl", script)
    long = "{ " + "a long comment " * 8 + "}"
    script.write_text(long + "\n" + script.read_text())
    t = CameraTool(RainbowMachine().client, motion.load(DATA / "pink_shot.checkpoint"), script)
    t.step()
    t.buf.place(0, len(long))
    t.reinterpret()
    pane = t.script_pane
    assert pane.left > 0 and pane.left + layout.SCRIPT_COLS > len(long)
    x = layout.SCRIPT[0] + 3 + 2 * layout.CHAR_W
    assert pane.cell_at(x, layout.SCRIPT[1]) == (0, pane.left + 2)
