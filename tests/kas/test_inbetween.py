"""The in-betweener on numbers: resampling, path fitting, timing, missing chains, splines."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas import correspond, pathfit, splines, timing
from camlab88.apps.kas.files import SamplePath, Timing
from camlab88.apps.kas.inbetween import inbetween, inbetween_keys
from camlab88.apps.kas.model import Chain, Drawing, drop_collinear


def chain(pts, colour=1, section=0):
    return Chain.from_points(pts, colour, section)


def key(*chains):
    return Drawing(list(chains))


def test_resample_adds_equally_spaced_points_and_keeps_vertices():
    c = chain([(0, 0), (4, 0), (4, 2)])  # length 6
    r = correspond.resample(c, 6)        # 3 extra at 1.5, 3.0, 4.5 along the length
    assert r.points.tolist() == [[0, 0], [1.5, 0], [3, 0], [4, 0], [4, 0.5], [4, 2]]


def test_resample_colour_of_segment():
    c = Chain(np.array([(0, 0), (2, 0), (2, 2)], float), np.array([1, 2, 3]))
    r = correspond.resample(c, 5)  # extras at 4/3 (segment to point 1) and 8/3 (to point 2)
    assert r.colours.tolist() == [1, 2, 2, 3, 3]


def test_resample_single_point_repeats():
    r = correspond.resample(chain([(1, 1)]), 3)
    assert r.points.tolist() == [[1, 1]] * 3


def test_redundant_collinear_points_dropped():
    p = np.array([(0, 0), (1, 0), (2, 0), (2, 0), (2, 1), (2, 3), (1, 3), (3, 3)], float)
    q, c = drop_collinear(p, np.ones(len(p), int))
    # (1,0),(2,0)dup,(2,1) go; (1,3) stays: the line doubles back through it
    assert q.tolist() == [[0, 0], [2, 0], [2, 3], [1, 3], [3, 3]]
    # a colour change keeps the point
    q, _ = drop_collinear(p[:3], np.array([1, 2, 3]))
    assert len(q) == 3


def test_chains_correspond_by_drawing_order_not_by_nearness():
    # chain 0 of a goes to chain 0 of b although chain 1 of b is nearer it (§3.1.2)
    a = key(chain([(0, 0)]), chain([(10, 0)]))
    b = key(chain([(10, 4)]), chain([(0, 8)]))
    s = inbetween(a, b, frames=3)
    assert [c.points.tolist() for c in s.frames[1].chains] == [[[5, 2]], [[5, 4]]]


def test_linear_without_path_and_keyframes_exact():
    a = key(chain([(0, 0), (1, 0)]))
    b = key(chain([(2, 2), (3, 2)]))
    s = inbetween(a, b, frames=5)
    assert len(s) == 5
    assert s.frames[0].equals(a) and s.frames[-1].equals(b)
    assert s.frames[2].chains[0].points.tolist() == [[1, 1], [2, 1]]


def test_path_stretched_and_translated_to_each_point_pair():
    # Path: an arch from (0,0) to (2,0) via (1,1).  A point going (10,0)->(14,0) follows it
    # scaled x2 as a whole (shape kept: the arch's height doubles too) and translated.
    path = SamplePath([(0, 0), (1, 1), (2, 0)])
    pos = pathfit.fit(np.array([[10.0, 0]]), np.array([[14.0, 0]]), np.array([0, 0.5, 1]),
                      path)
    assert np.allclose(pos[:, 0], [[10, 0], [12, 2], [14, 0]])


def test_path_reflected_when_points_move_the_other_way():
    # An upward arch drawn left to right stays an upward arch for a point moving right to
    # left: mirrored, not turned upside down.
    path = SamplePath([(0, 0), (1, 1), (2, 0)])
    pos = pathfit.fit(np.array([[0.0, 0.0]]), np.array([[-4.0, 0.0]]),
                      np.array([0.0, 0.5, 1.0]), path)
    assert np.allclose(pos[:, 0], [[0, 0], [-2, 2], [-4, 0]])
    rot = pathfit.fit(np.array([[0.0, 0.0]]), np.array([[-4.0, 0.0]]),
                      np.array([0.0, 0.5, 1.0]), path, "similarity")
    assert np.allclose(rot[:, 0], [[0, 0], [-2, -2], [-4, 0]])  # rotation alone: upside down


def test_path_fit_keeps_the_shape_in_the_chords_frame():
    # Rotated, scaled uniformly: every distance in the fitted path is |delta|/|chord| times
    # the drawn one, and the endpoints are hit exactly.
    path = SamplePath([(0, 0), (1, 2), (3, 1)])
    a, b = np.array([[1.0, 1.0], [0.0, 0.0]]), np.array([[1.0, 6.0], [-6.0, -1.0]])
    d = np.linspace(0, 1, 11)
    pos = pathfit.fit(a, b, d, path)
    drawn = pathfit.point_at(path, d)
    k = np.hypot(*(b - a).T) / np.hypot(3, 1)
    for m in range(2):
        got = np.hypot(*np.diff(pos[:, m], axis=0).T)
        assert np.allclose(got, k[m] * np.hypot(*np.diff(drawn, axis=0).T))
    assert np.allclose(pos[0], a) and np.allclose(pos[-1], b)


def test_path_with_almost_level_ends_stays_bounded():
    # The reviewer's hand-drawn arch: ends 0.03" apart in y.  Per-axis stretching sent the
    # in-betweens of keyframes near +-2" to y = 86..263; fitted in the chord frame they stay
    # within the arch's height scaled by |delta| / |chord|.
    path = SamplePath([(-4, -1), (-3, 0.5), (-2, 1.4), (0, 2), (2, 1.5), (3, 0.4),
                       (4, -0.97)])
    rng = np.random.default_rng(1)
    a = rng.uniform(-2, 2, size=(50, 2))
    b = a + rng.uniform(-1.5, 1.5, size=(50, 2))
    pos = pathfit.fit(a, b, np.linspace(0, 1, 9), path)
    k = np.hypot(*(b - a).T) / np.hypot(8, 0.03)
    reach = k * 3.1 + np.hypot(*(b - a).T)            # arch height 3" (+ a little) + chord
    assert np.all(np.hypot(*(pos - a[None]).transpose(2, 0, 1)) <= reach[None] + 1e-9)
    assert np.abs(pos).max() < 5
    assert np.allclose(pos[0], a) and np.allclose(pos[-1], b)


def test_path_fit_two_points_differently():
    # Figure 3.6: one path, two corners of a moved rectangle, each gets its own curve.
    path = SamplePath([(0, 0), (0.5, 1.0), (1, 1)])  # chord (1, 1)
    a = np.array([[0.0, 0.0], [1.0, 0.0]])
    b = np.array([[2.0, 2.0], [1.0, 4.0]])
    pos = pathfit.fit(a, b, np.array([0.0, 0.5, 1.0]), path)
    mid = pathfit.point_at(path, np.array([0.5]))[0]
    zm = complex(*mid)
    for m in range(2):
        z = complex(*a[m]) + zm * complex(*(b[m] - a[m])) / complex(1, 1)
        assert np.allclose(pos[1, m], [z.real, z.imag])
    assert np.allclose(pos[-1], b)


def test_closed_path_keeps_its_excursion():
    path = SamplePath([(0, 0), (1, 1), (2, 0), (0, 0)])
    pos = pathfit.fit(np.array([[5.0, 5.0]]), np.array([[6.0, 5.0]]), np.array([0, 0.5, 1]),
                      path)
    mid = pathfit.point_at(path, np.array([0.5]))[0]
    assert np.allclose(pos[:, 0], [[5, 5], [5 + mid[0] + 0.5, 5 + mid[1]], [6, 5]])


def test_similarity_fit_rotates_the_path():
    path = SamplePath([(0, 0), (1, 1), (2, 0)])
    pos = pathfit.fit(np.array([[0.0, 0]]), np.array([[0.0, 4]]), np.array([0, 0.5, 1]),
                      path, "similarity")
    assert np.allclose(pos[:, 0], [[0, 0], [-2, 2], [0, 4]])


def test_tick_timing_sets_frames_and_spacing():
    t = Timing("ticks", [0.1, 0.5])
    a, b = key(chain([(0, 0)])), key(chain([(10, 0)]))
    s = inbetween(a, b, timing=t)
    assert [f.chains[0].points[0, 0] for f in s.frames] == [0, 1, 5, 10]
    with pytest.raises(ValueError, match="2 in-betweens"):
        inbetween(a, b, frames=7, timing=t)


def test_timing_curve_independent_of_frame_count():
    ease = timing.curve("ease-in")
    for n in (3, 5, 11):
        d = timing.fractions(ease, n)
        u = np.linspace(0, 1, n)
        assert np.allclose(d, u * u, atol=1e-3)
    a, b = key(chain([(0, 0)])), key(chain([(8, 0)]))
    s = inbetween(a, b, frames=3, timing=ease)
    assert s.frames[1].chains[0].points[0, 0] == pytest.approx(2.0, abs=0.01)
    ticks = timing.ticks_from_curve(ease, 5)
    assert np.allclose(ticks.values, [1 / 16, 1 / 4, 9 / 16], atol=1e-3)


def test_missing_chain_copy_nearest():
    a = key(chain([(0, 0), (1, 0)]), chain([(10, 10), (11, 10)], 3))
    b = key(chain([(0, 5), (1, 5)]))
    s = inbetween(a, b, frames=3, missing="copy-nearest")
    last = s.frames[-1]
    assert len(last.chains) == 2
    assert last.chains[1].points.tolist() == [[0, 5], [1, 5]]   # hidden behind chain 0
    assert s.frames[1].chains[1].points.tolist() == [[5, 7.5], [6, 7.5]]


def test_missing_chain_copies_the_nearest_of_several():
    a = key(chain([(0, 0)]), chain([(9, 0)]), chain([(8, 1), (8, 2)]))
    b = key(chain([(0, 0)]), chain([(9, 12)]))
    m = correspond.match([a, b], "copy-nearest")
    assert m[1][2].points.tolist() == [[0, 0], [0, 0]]  # (0,0) is nearer (8,1.5) than (9,12)
    b = key(chain([(0, 0)]), chain([(9, 9)]))
    m = correspond.match([a, b], "copy-nearest")
    assert m[1][2].points.tolist() == [[9, 9], [9, 9]]  # now (9,9) is the nearer


def test_missing_chain_grow_and_stay():
    a = key(chain([(0, 0)]))
    b = key(chain([(0, 0)]), chain([(2, 0), (4, 0), (6, 3)]))
    grow = inbetween(a, b, frames=3, missing="grow", drop=False)
    assert grow.frames[0].chains[1].points.tolist() == [[4, 1]] * 3
    assert grow.frames[1].chains[1].points.tolist() == [[3, 0.5], [4, 0.5], [5, 2]]
    stay = inbetween(a, b, frames=3, missing="stay")
    assert all(f.chains[1].points.tolist() == [[2, 0], [4, 0], [6, 3]] for f in stay.frames)


def test_different_point_counts_in_betweened():
    a = key(chain([(0, 0), (2, 0)]))
    b = key(chain([(0, 2), (1, 3), (2, 2)]))
    s = inbetween(a, b, frames=3)
    assert s.frames[1].chains[0].points.tolist() == [[0, 1], [1, 1.5], [2, 1]]


@pytest.mark.parametrize("method", splines.METHODS)
def test_splines_pass_through_every_keyframe(method):
    rng = np.random.default_rng(5)
    keys = [key(chain(rng.normal(size=(6, 2)))) for _ in range(4)]
    s = inbetween_keys(keys, frames=6, method=method, drop=False, tension=0.3, bias=-0.2)
    assert len(s) == 3 * 5 + 1
    for k, kf in enumerate(keys):
        assert np.allclose(s.frames[5 * k].chains[0].points, kf.chains[0].points)


def test_spline_segment_exact_at_ends_and_formulae():
    k = np.array([[[0.0, 0]], [[1.0, 1]], [[2.0, 0]], [[3.0, 1]]])
    u = np.array([0.0, 0.5, 1.0])
    cr = splines.segment(k, 1, u, "catmull-rom")
    # Catmull-Rom midpoint: (-P0 + 9P1 + 9P2 - P3) / 16
    assert np.allclose(cr[1, 0], (-k[0, 0] + 9 * k[1, 0] + 9 * k[2, 0] - k[3, 0]) / 16)
    kb = splines.segment(k, 1, u, "kochanek-bartels")
    assert np.allclose(kb, cr)  # t = c = b = 0 is Catmull-Rom
    ov = splines.segment(k, 1, u, "overhauser")
    assert np.allclose(ov, cr)  # equal chord lengths: Overhauser equals Catmull-Rom
    tight = splines.segment(k, 1, u, "kochanek-bartels", tension=1.0)
    assert np.allclose(tight[1, 0], [1.5, 0.5])  # tension 1: zero tangents, straight mid


def test_catmull_rom_midpoint_on_uneven_keys():
    # keys whose neighbour chords differ, so the tangents' size shows in the midpoint
    k = np.array([[[0.0, 0]], [[1.0, 1]], [[3.0, 0]], [[4.0, 2]]])
    cr = splines.segment(k, 1, np.array([0.0, 0.5, 1.0]), "catmull-rom")
    assert np.allclose(cr[1, 0], (-k[0, 0] + 9 * k[1, 0] + 9 * k[2, 0] - k[3, 0]) / 16)


def test_kochanek_bartels_continuity_signs():
    k = np.array([[[0.0, 0]], [[1.0, 1]], [[3.0, 0]], [[4.0, 2]]])
    u = np.linspace(0, 1, 7)
    # c = -1: each segment's tangents are its own chord, i.e. a straight line at even speed
    kb = splines.segment(k, 1, u, "kochanek-bartels", continuity=-1.0)
    assert np.allclose(kb, splines.segment(k, 1, u, "linear"))
    # c = +1: the segment leaves p1 along the incoming chord (p1 - p0) and reaches p2
    # along the outgoing one (p3 - p2); central differences give the end tangents
    h = 1e-6
    e = np.array([0.0, h, 1 - h, 1.0])
    kb = splines.segment(k, 1, e, "kochanek-bartels", continuity=1.0)
    assert np.allclose((kb[1] - kb[0]) / h, k[1] - k[0], atol=1e-4)
    assert np.allclose((kb[3] - kb[2]) / h, k[3] - k[2], atol=1e-4)
    # bias +1 with c = 0: both tangents lean on the chord before each key
    kb = splines.segment(k, 1, e, "kochanek-bartels", bias=1.0)
    assert np.allclose((kb[1] - kb[0]) / h, k[1] - k[0], atol=1e-4)
    assert np.allclose((kb[3] - kb[2]) / h, k[2] - k[1], atol=1e-4)


def test_overhauser_differs_with_uneven_spacing():
    k = np.array([[[0.0, 0]], [[1.0, 0]], [[1.2, 1]], [[5.0, 1]]])
    u = np.linspace(0, 1, 5)
    ov = splines.segment(k, 1, u, "overhauser")
    assert np.allclose(ov[[0, -1], 0], [[1, 0], [1.2, 1]])
    assert not np.allclose(ov, splines.segment(k, 1, u, "catmull-rom"))


def test_colours_switch_halfway():
    a = key(chain([(0, 0), (1, 0)], 2))
    b = key(chain([(0, 1), (1, 1)], 5))
    s = inbetween(a, b, frames=4)
    assert [int(f.chains[0].colours[0]) for f in s.frames] == [2, 2, 5, 5]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=1,
                         max_size=8), min_size=1, max_size=4),
       st.integers(1, 3))
def test_frame_drop_equals_per_chain_drop(chains_pts, colour):
    """Dropping redundant points over all chains at once equals doing it chain by chain."""
    a = key(*[chain(p, colour) for p in chains_pts])
    b = key(*[chain([(x * 2, y) for x, y in p], colour) for p in chains_pts])
    kept = inbetween(a, b, frames=3)
    full = inbetween(a, b, frames=3, drop=False)
    for f_kept, f_full in zip(kept.frames, full.frames):
        for ck, cf in zip(f_kept.chains, f_full.chains):
            p, c = drop_collinear(cf.points, cf.colours)
            assert np.array_equal(ck.points, p) and np.array_equal(ck.colours, c)


def test_numba_mask_equals_numpy_reference():
    from camlab88.apps.kas import kernels
    from camlab88.apps.kas.model import redundant_mask

    rng = np.random.default_rng(3)
    pos = rng.integers(-2, 3, size=(20, 60, 2)).astype(float)  # many collinear runs/repeats
    cols = rng.integers(1, 3, size=(20, 60)).astype(np.int16)
    bounds = np.array([0, 1, 7, 30, 31, 60])
    fast = kernels.keep_mask(pos, cols, bounds, 1e-9)
    assert np.array_equal(fast, redundant_mask(pos, cols, bounds=bounds))
    assert 0 < (~fast).sum() < fast.size
