"""§3.1.4: "abbreviated graphics mode ... requires approximately half the characters of the
standard mode".  The KAS demo's vectors, as the viewer sends them, counted in both modes."""

from __future__ import annotations

from camlab88.apps.kas import demo
from camlab88.apps.kas.program.draw import encode
from camlab88.apps.kas.program.viewer import VIEW_CLIP, chain_prims, frame_points_px
from camlab88.protocols.sigma import Encoder


def test_demo_vectors_take_about_half_the_characters_abbreviated() -> None:
    enc = Encoder()
    abbreviated = standard = 0
    for frame in demo.build().frames:
        for pts, cols in frame_points_px(frame):
            for p in chain_prims(pts, cols, VIEW_CLIP):
                abbreviated += len(encode(enc, p))
                xy = list(zip(p.data[0::2], p.data[1::2], strict=True))
                standard += len(enc.colour(p.colour)
                                + enc.polyline(xy if len(xy) > 1 else xy * 2))
    # docs/perf/kas_front.md: 0.45; "approximately half", and a real saving
    assert 0.40 <= abbreviated / standard <= 0.50, abbreviated / standard
