"""§6.2.1 and §6.2.2's screen on the emulated Rainbow: the overhead table with its cushions,
pockets, baulk line and D; the frame number bottom right, the help area top left, the
selected ball top right; velocity arrows on every moving ball while not simulating."""

from __future__ import annotations

from camlab88.apps.snooker.program import layout, pads
from camlab88.apps.snooker.table import BLUE, BROWN, CUE
from tests.snooker_program.helpers import feed, hex_rgb, screen_colour


def test_overhead_table_with_cushions_pockets_baulk_line_and_d(rainbow, prog):
    v, t = prog.view, prog.session.table
    colour = {name: hex_rgb(pads.TABLE_COLOURS[k]) for name, k in
              (("cloth", pads.CLOTH), ("cushion", pads.CUSHION), ("pocket", pads.POCKET),
               ("marking", pads.MARKING))}
    # the baulk line, away from the D and the spots
    assert screen_colour(rainbow, *v.to_pixel(t.baulk_line_m, 0.15)) == colour["marking"]
    # the D: its far point behind the brown, on the semicircle
    bx, by = t.spots[BROWN]
    assert screen_colour(rainbow, *v.to_pixel(bx - t.d_radius_m, by)) == colour["marking"]
    assert screen_colour(rainbow, *v.to_pixel(bx - t.d_radius_m / 2, by + 0.1)) \
        == colour["cloth"]
    for p in t.pockets:  # every pocket's mouth is drawn as a pocket
        assert screen_colour(rainbow, *v.to_pixel(*p.centre)) == colour["pocket"]
    x, y, w, h = v.play_rect
    assert screen_colour(rainbow, x + w // 3, y - layout.CUSHION_PX // 2) == colour["cushion"]


def test_frame_number_bottom_right_help_top_left_selected_ball_top_right(rainbow, prog):
    for box in (layout.HELP_BOX, layout.INFO_BOX, layout.FRAME_BOX):
        x, y, w, h = box
        assert 0 <= x and x + w <= layout.SCREEN_W and 0 <= y and y + h <= layout.SCREEN_H
    assert layout.HELP_BOX[0] < 20 and layout.HELP_BOX[1] < 20  # top left
    x, y, w, _ = layout.INFO_BOX
    assert x + w > layout.SCREEN_W - 20 and y < 20 and x > layout.SCREEN_W / 2  # top right
    x, y, w, h = layout.FRAME_BOX
    assert x + w > layout.SCREEN_W - 20 and y + h > layout.SCREEN_H - 40  # bottom right
    d = prog.display
    assert d.info.shown[0] == "no ball selected" and d.frame_box.shown[0] == "frame 0"
    feed(rainbow, prog, "move 175 325\nwait 1")  # over the cue ball
    assert d.info.shown[0].startswith("cue\nposition (")


def test_velocity_arrows_on_every_moving_ball_when_not_simulating(rainbow, prog):
    s = prog.session
    s.strike(CUE, 1.0, 0.0)
    s.strike(BLUE, 0.5, 90.0)
    _, _, overlay = prog.scene()
    starts = {(round(x0), round(y0)) for x0, y0, _, _, value in overlay.lines
              if value == pads.MOVING}
    for ball in (CUE, BLUE):
        sx, sy = prog.view.to_screen(*s.balls.pos[ball])
        assert (round(sx), round(sy)) in starts
    prog.mode = "running"
    _, _, overlay = prog.scene()
    assert not [ln for ln in overlay.lines if ln[4] == pads.MOVING]
