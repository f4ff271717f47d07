"""Appendix I: an anti-aliased red polygon (5-bit pad) over colour splodges (3-bit pad),
moved independently, stays correctly blended with no pixel redrawn."""

from __future__ import annotations

import numpy as np

from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow import transparency as tx
from camlab88.protocols.rainbow.antialias import coverage


def expected(poly_at, spl_at) -> np.ndarray:
    shade = coverage(tx.polygon_points(), tx.POLY_W, tx.POLY_H, levels=32)
    spl = tx.splodge_image()
    out = np.zeros((576, 768, 3), np.int64)  # LUT[0] is black
    s_img = np.full((576, 768), -1)
    p_img = np.full((576, 768), -1)
    for img, src, (x, y) in ((s_img, spl, spl_at), (p_img, shade, poly_at)):
        h, w = src.shape
        ys, xs = slice(max(y, 0), min(y + h, 576)), slice(max(x, 0), min(x + w, 768))
        img[ys, xs] = src[ys.start - y: ys.stop - y, xs.start - x: xs.stop - x]
    table = tx.combined_table()
    both = (s_img >= 0) & (p_img >= 0)
    out[both] = table[(p_img[both] << 3) | s_img[both]]
    only_p = (p_img >= 0) & (s_img < 0)
    out[only_p] = table[p_img[only_p] << 3]
    only_s = (s_img >= 0) & (p_img < 0)
    out[only_s] = tx.SPLODGES[s_img[only_s]]
    return out.astype(np.uint8)


def test_polygon_blends_over_splodges_while_both_move() -> None:
    s = RainbowMachine()
    ex = tx.build(s.client, poly_at=(100, 80), splodge_at=(40, 40))
    s.client.wait_frame()  # LUT writes take effect at the next frame
    words = s.device.memory.words.copy()
    drawing_calls = s.client.calls
    moves = [((100, 80), (40, 40)), ((180, 120), (40, 40)), ((180, 120), (300, 200)),
             ((-50, 400), (500, -30)), ((420, 260), (380, 250))]
    for poly_at, spl_at in moves:
        s.client.move(ex.poly_arc, *poly_at)
        s.client.move(ex.splodge_arc, *spl_at)
        s.client.wait_frame()
        frame = s.executor.last_frame
        want = expected(poly_at, spl_at)
        bad = np.argwhere(np.any(frame != want, axis=-1))
        assert len(bad) == 0, f"{poly_at} {spl_at}: {len(bad)} pixels wrong, first {bad[0]}"
        assert np.array_equal(frame, s.device.reference())
    # Nothing was redrawn: memory is byte for byte what it was, and only moves were sent.
    assert np.array_equal(s.device.memory.words, words)
    assert s.client.calls - drawing_calls == 3 * len(moves)


def test_edge_shades_really_mix() -> None:
    """An edge pixel over a splodge differs from the same shade over black: it is a blend."""
    s = RainbowMachine()
    tx.build(s.client, poly_at=(40, 40), splodge_at=(40, 40))
    s.client.wait_frame()
    shade = coverage(tx.polygon_points(), tx.POLY_W, tx.POLY_H, levels=32)
    spl = tx.splodge_image()
    ys, xs = np.nonzero((shade > 4) & (shade < 27) & (spl[: tx.POLY_H, : tx.POLY_W] > 0))
    assert len(ys) > 10
    frame = s.executor.last_frame
    for y, x in list(zip(ys, xs))[:50]:
        got = frame[40 + y, 40 + x]
        assert np.array_equal(got, tx.mix(int(shade[y, x]), int(spl[y, x])))
        assert not np.array_equal(got, tx.mix(int(shade[y, x]), 0))
