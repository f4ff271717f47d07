"""Golden frames (regenerate with CAMLAB88_REGEN_GOLDEN=1 and look at them first)."""

from __future__ import annotations

from camlab88.apps.snooker.render.palette import fixed_palette
from camlab88.apps.snooker.render.sigma_host import SigmaHost
from camlab88.apps.snooker.render.sigma_session import SigmaSession
from camlab88.apps.snooker.render.truecolour import RenderOptions, render_frame
from camlab88.emulator.harness.sigma_batch import t5688_link
from tests.snooker_render.helpers import DATA, break_scene, break_views, overhead
from tests.support.golden import assert_matches_golden

GOLDEN = DATA / "golden"


def test_truecolour_break_from_behind_baulk() -> None:
    frame = render_frame(break_scene(), break_views()[14], RenderOptions(384, 256))
    assert_matches_golden(frame, GOLDEN / "truecolour_break_15.png")


def test_truecolour_close_up_from_above() -> None:
    frame = render_frame(break_scene(), overhead(16, focal=120.0), RenderOptions(256, 192))
    assert_matches_golden(frame, GOLDEN / "truecolour_overhead_16.png")


def test_period_frame_on_the_t5688() -> None:
    scene = break_scene()
    link = t5688_link()
    SigmaSession(SigmaHost(scene, fixed_palette(scene), "period"), link).show(break_views()[14])
    assert_matches_golden(link.frame(), GOLDEN / "period_break_15.png")
