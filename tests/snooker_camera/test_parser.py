"""Every construct of CCL's grammar (thesis §6.3.1), case and layout freedom."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.snooker.camera import ccl
from camlab88.apps.snooker.camera.names import DEFAULT_CAMERAS
from camlab88.apps.snooker.camera.parser import parse
from camlab88.apps.snooker.camera.space import ccl_to_table
from tests.snooker_camera.helpers import R, T, make, pink_rolls, still

HX, HY = T.length_m / 2, T.width_m / 2
CAMERA_1 = ccl_to_table(DEFAULT_CAMERAS[1]).tolist()  # CCL's +x is the table frame's -x


def run(text: str, motion=None):
    return ccl.compile_script(text, motion or pink_rolls())


def test_comment_before_the_first_colon_and_empty_commands() -> None:
    r = run("Observer at (1,2,3) is only a comment here: : ; ; viewpoint at (0,0,1) ::")
    assert r.viewpoint[0].tolist() == [0, 0, 1]
    assert r.observer[0].tolist() == CAMERA_1  # the comment set nothing


def test_case_and_layout_are_free() -> None:
    a = run(":from FRAME 2 until frame 4; OBSERVER at (1, 2, 3); focal length of 35:")
    b = run(":\n   fRoM\tframe\n2 UNTIL\n\n fRaMe 4 ;\n focal  LENGTH  of\n35;oBsErVeR AT(1,2,3):")
    assert a.views() == b.views()
    assert a.observer[1].tolist() == [-1, 2, 3] and a.focal[3] == 35 and a.focal[4] == 35


def test_sub_commands_in_any_order() -> None:
    a = run(": until 5; viewpoint at (1,0,0); observer at (0,1,2); focal length of 90 :")
    b = run(": focal length of 90; observer at (0,1,2); viewpoint at (1,0,0); until 5 :")
    assert a.views() == b.views()


@pytest.mark.parametrize(("event", "frame"), [
    ("7", 7), ("frame 7", 7), ("cueball strikes", 5), ("any ball starts", 5),
    ("all balls stop", 12), ("pink ball starts", 5), ("pink ball stops", 12), ("end", 20),
    ("pink ball stops - 3", 9), ("pink ball stops + 2", 14), ("frame 3 + 1", 4),
    ("hitball stops", 12), ("cueball stops", None), ("Cue Ball Strike", 5),
])
def test_events(event: str, frame: int | None) -> None:
    text = f": until {event}; observer at (0,1,2) :"
    text += " observer at (5,5,5) :" if frame != 20 else ""
    if frame is None:
        with pytest.raises(ccl.CclErrors, match="the cue ball never stops at or after frame 1"):
            run(text)
        return
    r = run(text)
    assert r.periods[0] == (1, 1, frame)
    assert r.observer[frame - 1].tolist() == [0, 1, 2]
    if frame < 20:
        assert r.observer[frame].tolist() == [-5, 5, 5]


def test_from_until_and_default_start() -> None:
    r = run(": from 3 until 6; focal length of 40 : until 8; focal length of 60 :")
    assert r.periods == [(1, 3, 6), (1, 7, 8)]
    assert r.focal.tolist()[:10] == [50, 50, 40, 40, 40, 40, 60, 60, 60, 60]


@pytest.mark.claim(
    "§6.3.1: MOVING moves the observer smoothly between two points, FOCAL LENGTH FROM .. TO "
    "zooms, over the command's frames",
    measured="the parameter at each frame of a moving / zoom command: linear in frame number, "
             "from the first value at the period's first frame to the second at its last",
    verdict="agrees (linear is ours: the thesis gives no law; docs/fidelity/snooker.md)")
def test_moving_and_zoom_are_linear_in_frame_number() -> None:
    r = run(": from 2 until 6; observer moving from (0,0,1) to (4,8,1); "
            "focal length from 20 to 100 :")
    np.testing.assert_allclose(r.observer[1:6, 1], [0, 2, 4, 6, 8])
    np.testing.assert_allclose(r.focal[1:6], [20, 40, 60, 80, 100])
    assert r.observer[0].tolist() == CAMERA_1 and r.observer[10, 1] == 8


def test_following_and_at_a_ball() -> None:
    m = pink_rolls()
    r = run(": from 4 until 14; viewpoint following pink ball - (#0, 0, 2); "
            "observer at pink ball + (1, 0, 0) :", m)
    pink = m.centres[:, 5]
    np.testing.assert_allclose(r.viewpoint[3:14], pink[3:14] - [0, 0, 2])
    np.testing.assert_allclose(r.observer[3:14], np.broadcast_to(pink[3] + [-1, 0, 0], (11, 3)))


@pytest.mark.parametrize(("name", "where"), [
    ("cueball", (-1.0, 0.0, R)), ("cue ball", (-1.0, 0.0, R)), ("black ball", (-0.4, 0.12, R)),
    ("yellow spot", (-HX + 29 * 0.0254, -11.5 * 0.0254, 0)), ("pink spot", (0.9144, 0, 0)),
    ("bottom left pocket", (-HX, HY, 0)), ("bottom right pocket", (-HX, -HY, 0)),
    ("left centre pocket", (0, HY, 0)), ("right center pocket", (0, -HY, 0)),
    ("top left pocket", (HX, HY, 0)), ("top right pocket", (HX, -HY, 0)),
    ("camera 0", DEFAULT_CAMERAS[0]), ("camera 7", DEFAULT_CAMERAS[7]),  # both on x = 0
    ("red 1", (1.1, 0.42, R)), ("red 15", (-0.3, 0.14, R)), ("hitball", (-0.5, 0.1, R)),
    ("(1.5, -2, .25)", (-1.5, -2, 0.25)), ("(+1e-1, -2.5E0, 3)", (-0.1, -2.5, 3)),
])
def test_names_and_coordinates(name: str, where: tuple[float, float, float]) -> None:
    r = run(f": viewpoint at {name}; observer at (9, 9, 9) :")
    np.testing.assert_allclose(r.viewpoint[0], where, atol=1e-12)


def test_reds_at_equal_distance_count_left_to_right() -> None:
    c = still()
    c[:, 7:22] = (-1.5, -0.5, R)  # all reds in a heap...
    c[:, 8] = (1.0, -0.3, R)  # ...but two level nearest the top, red at +y is "left"
    c[:, 9] = (1.0, 0.3, R)
    r = run(": viewpoint at red 1; observer at red 2 + (0,0,1) :", make(c))
    assert r.viewpoint[0].tolist() == [1.0, 0.3, R] and r.observer[0].tolist() == [1, -0.3, R + 1]


def test_cameras_and_user_coordinates() -> None:
    r = run(": camera 4 at (1, 2, 3); coords top left pocket 100 100 -100; "
            "until 3; observer at camera 4 + (#100, 0, 0); viewpoint at (#-50, 0, 10) :")
    np.testing.assert_allclose(r.observer[0], (-2, 2, 3))  # CCL's +x is the table's -x
    np.testing.assert_allclose(r.viewpoint[0], (HX + 0.5, HY, -0.1))


def test_definitions_only_take_no_time() -> None:
    r = run(": camera 2 at (1,1,1) : coords (0,0,0) 2 2 2 : until 4; observer at camera 2 :")
    assert r.periods == [(1, 1, 4)] and r.observer[0].tolist() == [-1, 1, 1]


def test_a_command_without_until_runs_to_the_end() -> None:
    r = run(": until 3; focal length of 30 : focal length of 70 :")
    assert r.periods == [(1, 1, 3), (1, 4, 20)] and r.focal[19] == 70


def test_the_ast_keeps_positions() -> None:
    cmds, errors = parse("x:\n  until 5;\n  observer at (1,2,3)\n:")
    assert not errors and cmds[0].observer is not None
    assert (cmds[0].observer.tok.line, cmds[0].observer.tok.col) == (3, 3)
