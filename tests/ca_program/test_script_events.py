"""The scripted-input parser: every command, every error path, arbitrary text."""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.program.script_events import MouseState, ScriptError, parse, play
from camlab88.protocols.rainbow.events import KeyEvent, MouseEvent


def test_commands():
    steps = parse("# a comment\nmove 3 4\npress left 3 4\nmove 5 6\nrelease left 5 6\n"
                  "click right 1 2\nkey return\ntype ab c\nframes 2\ndrag middle 0 0 4 0 2\n")
    assert steps[0] == MouseEvent(0, 3, 4, 0)
    assert steps[1] == MouseEvent(0, 3, 4, 1, 1, True)
    assert steps[2] == MouseEvent(0, 5, 6, 1)  # the left button is still held
    assert steps[3] == MouseEvent(0, 5, 6, 0, 1, False)
    assert steps[4:6] == [MouseEvent(0, 1, 2, 4, 3, True), MouseEvent(0, 1, 2, 0, 3, False)]
    assert steps[6] == KeyEvent(0, "return", "", True)
    typed = [s.char for s in steps[8:16] if isinstance(s, KeyEvent) and s.pressed]
    assert typed == ["a", "b", " ", "c"]
    assert steps[16] == 2
    assert steps[17:] == [MouseEvent(0, 0, 0, 2, 2, True), MouseEvent(0, 2, 0, 2),
                          MouseEvent(0, 4, 0, 2), MouseEvent(0, 4, 0, 0, 2, False), 1]


def test_mouse_state_carries_between_scripts():
    m = MouseState()
    parse("press left 1 1", mouse=m)
    assert parse("move 2 2", mouse=m) == [MouseEvent(0, 2, 2, 1), 1]


@pytest.mark.parametrize("text, message", [
    ("jump 1 2", "<events>:1:1: unknown command 'jump'"),
    ("\nmove 1", "<events>:2:6: move wants 2 numbers (X Y), found 1"),
    ("move a b", "<events>:1:6: expected a whole number, found 'a'"),
    ("press 1 2", "<events>:1:7: press needs a button"),
    ("click thumb 1 2", "<events>:1:7: click needs a button"),
    ("drag left 1 2 3", "drag wants 4 or 5 numbers"),
    ("drag left 1 2 3 4 0", "<events>:1:19: number of steps 0 is outside 1..10000"),
    ("key", "key wants one key name"),
    ("frames -1", "<events>:1:8: value -1 is outside 0..1000000"),
    ("drag left 0 0 9 9 20000", "number of steps 20000 is outside 1..10000"),
    ("move 0 -99999999999", "<events>:1:8: coordinate -99999999999 is outside"),
])
def test_errors_name_the_line(text, message):
    with pytest.raises(ScriptError, match=re.escape(message)):
        parse(text)


@settings(max_examples=150, deadline=None)
@given(st.text(max_size=80))
def test_arbitrary_text_parses_or_raises_script_error(text):
    try:
        steps = parse(text)
    except ScriptError:
        return
    assert all(isinstance(s, (int, MouseEvent, KeyEvent)) for s in steps)


def test_play_runs_frames_and_reads_leftover_events():
    got: list = []
    n = play(parse("move 1 1\nframes 2\nmove 2 2"), got.append, lambda: got.append("F"))
    assert n == 3 and got == [MouseEvent(0, 1, 1, 0), "F", "F", MouseEvent(0, 2, 2, 0), "F"]
