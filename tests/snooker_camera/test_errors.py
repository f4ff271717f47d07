"""Errors for a non-expert (thesis §6.3.1): line and column, what was expected, the nearest
keyword, events that never happen, focal lengths out of range; all at once."""

from __future__ import annotations

import pytest

from camlab88.apps.snooker.camera import ccl
from camlab88.apps.snooker.camera.errors import CclErrors
from tests.snooker_camera.helpers import pink_rolls


def errors(text: str) -> list[str]:
    with pytest.raises(CclErrors) as err:
        ccl.compile_script(text, pink_rolls(), "cam.ccl")
    return str(err.value).splitlines()


@pytest.mark.parametrize(("text", "want"), [
    (":\nveiwpoint at (0,0,0)", "cam.ccl:2:1: expected a sub-command (FROM, UNTIL, OBSERVER, "
     "VIEWPOINT, FOCAL LENGTH, CAMERA or COORDS) but found VEIWPOINT (did you mean VIEWPOINT?)"),
    (": observer folowing pink ball", "cam.ccl:1:12: expected AT, MOVING or FOLLOWING but found "
     "FOLOWING (did you mean FOLLOWING?)"),
    (": until pnik ball stops", "(did you mean PINK?)"),
    (": focal length of 5", "cam.ccl:1:19: a focal length of 5 mm is out of range: it must be "
     "8 to 2000 mm"),
    (": focal length from 30 to 2500", "cam.ccl:1:27: a focal length of 2500 mm is out of range"),
    (": from 13 until pink ball stops", "cam.ccl:1:17: the pink ball never stops at or after "
     "frame 13"),
    (": from 6 until pink ball starts", "the pink ball never starts at or after frame 6"),
    (": until 3 : from 8 until cueball strikes", "the cue ball never strikes another ball at or "
     "after frame 8"),
    (": from 10 until 4", "cam.ccl:1:17: the period runs backwards: from frame 10 until frame 4"),
    (": until 25", "cam.ccl:1:9: this command would run until frame 25, after the last frame "
     "(20)"),
    (": until pink ball stops + 10", "after the last frame (20)"),
    (": from pink ball starts - 9 until 8", "would start at frame -4, before frame 1"),
    (": camera 12 at (0,0,0)", "cam.ccl:1:10: a camera number must be 0 to 9, not 12"),
    (": until 2.5", "a frame number must be a whole number, not 2.5"),
    (": observer at red 16", "there are only 15 reds on the table at frame 1, so there is no "
     "red 16"),
    (": observer at pink", "expected BALL after PINK (or SPOT, where a position is meant) but "
     "found the end of the script"),
    (": observer at (1, 2 3)", "cam.ccl:1:21: expected ',' between y and z but found the "
     "number 3"),
    (": observer at (1,2,3) viewpoint at (0,0,0)", "cam.ccl:1:23: unexpected VIEWPOINT after a "
     "complete sub-command (is a ';' missing before it?)"),
    (": until 3; until 4", "cam.ccl:1:12: a second time period (FROM/UNTIL) in one command"),
    (": coords (#1,2,3) 1 1 1", "cannot use '#'"),
    (": coords (0,0,0) 1 0 1", "user units per metre in y cannot be 0"),
    (": observer at (0,0,1); viewpoint at (0,0,1)", "cam.ccl:1:3: the observer and the "
     "viewpoint are the same point at frame 1 (and 19 more frames)"),
    (": observer at (1,2,3) @", "cam.ccl:1:23: unexpected character '@'"),
    ("no colon at all", "cam.ccl:1:1: no commands: everything before the first colon is a "
     "comment"),
    (": from frame until 3", "expected a frame number but found UNTIL"),
])
def test_one_error(text: str, want: str) -> None:
    got = errors(text)
    assert len(got) == 1, got
    assert got[0].startswith(want) if want.startswith("cam.ccl") else want in got[0], got


def test_all_errors_of_a_script_at_once_in_order() -> None:
    got = errors("comment:\n"
                 "until 5; veiwpoint at (0,0,0); focal length of 3\n"
                 ":\n"
                 "from 13 until pink ball stops; observer at camera 11\n"
                 ":\n"
                 "until 19; observer folowing cueball\n")
    assert [g.split(": ", 1)[0] for g in got] == [
        "cam.ccl:2:10", "cam.ccl:2:48", "cam.ccl:4:15", "cam.ccl:4:51", "cam.ccl:6:20"]
    assert "did you mean VIEWPOINT?" in got[0] and "the pink ball never stops" in got[2]


def test_errors_do_not_stop_the_rest_being_interpreted() -> None:
    r = ccl.run(": until 5; veiwpoint at (0,0,0); observer at (1,1,1) : focal length of 70 :",
                pink_rolls())
    assert len(r.errors) == 1 and r.observer[0].tolist() == [-1, 1, 1] and r.focal[6] == 70
