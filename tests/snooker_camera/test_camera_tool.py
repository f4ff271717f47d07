"""The interactive camera tool (thesis §6.5): edits re-interpreted at once, the file watched
on disk, errors at their lines without stopping the preview, scrubbing, the time line."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.snooker.camera import motion
from camlab88.apps.snooker.camera_tool import layout
from camlab88.apps.snooker.camera_tool.editor import TextBuffer
from camlab88.apps.snooker.camera_tool.tool import CameraTool
from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow.events import LEFT, KeyEvent, MouseEvent
from tests.support.golden import assert_matches_golden

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"


@pytest.fixture()
def tool(tmp_path: Path):
    script = tmp_path / "cam.ccl"
    shutil.copy(DATA / "thesis_example.ccl", script)
    rb = RainbowMachine()
    t = CameraTool(rb.client, motion.load(DATA / "pink_shot.checkpoint"), script)
    t.step()
    return rb, t


def keys(rb, text: str) -> None:
    for ch in text:
        name = {"\n": "return", " ": "space"}.get(ch, ch)
        rb.post(KeyEvent(0, name, "" if ch == "\n" else ch, True))


@pytest.mark.claim(
    "§6.5: better would be to combine the camera language interpreter and the perspective viewer,"
    " with immediate visual feedback for each command",
    measured="an edit to the script in the camera tool is interpreted at once and the preview "
             "shows the new view",
    verdict="agrees (built: the thesis only proposed it)")
def test_an_edit_is_interpreted_at_once_and_the_view_follows(tool) -> None:
    rb, t = tool
    rb.post(KeyEvent(0, "tab", "", True))  # pause on frame 2
    t.step()
    before = rb.executor.frame_copy()
    assert t.result.observer[1].tolist() == [-5.5, 0.0, 2.5]
    t.buf.place(2, 0)  # "observer at camera 1;" -> "observer at camera 5;"
    t.buf.end()
    for _ in range(2):
        rb.post(KeyEvent(0, "backspace", "", True))
    keys(rb, "5;")
    t.step()
    assert t.result.observer[1].tolist() == [5.5, 0.0, 2.5] and t.modified
    assert not np.array_equal(rb.executor.last_frame, before)


def test_errors_are_marked_and_the_preview_goes_on(tool) -> None:
    rb, t = tool
    t.buf.place(3, 0)
    keys(rb, "veiw")  # "veiwviewpoint at (0,0,0);" on line 4
    t.step()
    assert [(e.line, e.col) for e in t.result.errors] == [(4, 1)]
    assert "did you mean VIEWPOINT?" in t.result.errors[0].message
    # the rest of the script still runs: command 2 still moves the observer
    assert t.result.observer[43].tolist() == pytest.approx([-7.3, -4.5, 1.2])  # table frame
    pane = rb.client.get_pixels(t.script_pane.pad, 0, 30, layout.SCRIPT[2], 10)  # line 4
    assert (pane == 2).sum() > 200  # its row has the error background
    frame_before = t.frame
    t.step()
    assert t.frame == frame_before + 1  # still playing


def test_a_change_saved_from_another_editor_is_picked_up(tool) -> None:
    rb, t = tool
    path = t.path
    path.write_text(path.read_text().replace("focal length of 50", "focal length of 90"))
    st = path.stat()
    os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000))  # a new mtime, surely
    t.step()
    assert t.result.focal[0] == 90 and "reloaded" in t.status and not t.modified


def test_a_disk_change_does_not_overwrite_unsaved_edits(tool) -> None:
    rb, t = tool
    keys(rb, "x")
    t.step()
    t.path.write_text(":focal length of 200\n")
    os.utime(t.path, ns=(1, 2))
    t.step()
    assert t.buf.text.startswith("x:") and "ctrl-r reloads" in t.status
    rb.post(KeyEvent(0, "ctrl", "", True))
    rb.post(KeyEvent(0, "r", "", True))
    rb.post(KeyEvent(0, "ctrl", "", False))
    t.step()
    assert t.buf.text == ":focal length of 200\n" and t.result.focal[5] == 200


def test_ctrl_s_saves_atomically_and_is_not_seen_as_a_change(tool) -> None:
    rb, t = tool
    keys(rb, "A comment ")
    rb.post(KeyEvent(0, "ctrl", "", True))
    rb.post(KeyEvent(0, "s", "", True))
    t.step()
    assert t.path.read_text().startswith("A comment :") and not t.modified
    n = t.interpretations
    t.step()
    assert t.interpretations == n  # our own save does not trigger a reload


def test_scrub_on_the_time_line_and_step_keys(tool) -> None:
    rb, t = tool
    y = layout.TIMELINE[1] + 20
    x = layout.TIMELINE[0] + layout.timeline_x(44, 75)
    rb.post(MouseEvent(0, x, y, LEFT, 1, True))
    t.step()
    assert t.frame == 44 and not t.playing
    rb.post(MouseEvent(0, x + 100, y, LEFT))  # dragging
    t.step()
    assert t.frame == layout.timeline_frame(x + 100, 75)
    rb.post(MouseEvent(0, x + 100, y, 0, 1, False))
    rb.post(KeyEvent(0, "page_up", "", True))
    t.step()
    assert t.frame == layout.timeline_frame(x + 100, 75) - 1


def test_timeline_marks_the_strike_and_the_tool_screen(tool) -> None:
    rb, t = tool
    assert (44, "strike", 5) in t.events and (75, "stop", 5) in t.events
    tl = rb.client.get_pixels(t.timeline.pad, 0, 0, *layout.TIMELINE[2:])
    x = layout.timeline_x(44, 75)
    assert (tl[6:42, x] == 2).all()  # the strike's red tick
    rb.post(MouseEvent(0, layout.timeline_x(50, 75), layout.TIMELINE[1] + 5, LEFT, 1, True))
    t.step()
    assert_matches_golden(rb.executor.last_frame, DATA / "golden" / "camera_tool_050.png")


def test_text_buffer_edits() -> None:
    b = TextBuffer("ab\ncd")
    b.place(0, 2)
    b.delete()  # joins the lines
    assert b.text == "abcd" and (b.line, b.col) == (0, 2)
    b.newline()
    b.insert("x\ny")
    assert b.text == "ab\nx\nycd" and (b.line, b.col) == (2, 1)
    b.move(0, -2)
    assert (b.line, b.col) == (1, 1)
    b.home()
    b.backspace()
    assert b.text == "abx\nycd" and (b.line, b.col) == (0, 2)
