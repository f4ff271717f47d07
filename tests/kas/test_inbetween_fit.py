"""The sample-path fits of §3.1.2: the thesis's literal per-axis stretch beside ours, the
old mode name, and unusable path files."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas import pathfit
from camlab88.apps.kas.files import KasFileError, SamplePath
from camlab88.apps.kas.inbetween import inbetween
from camlab88.apps.kas.model import Chain, Drawing

ARCH = SamplePath([(0, 0), (1, 1), (2, 0)])


def _one(a, b, d, path, mode):
    return pathfit.fit(np.array([a], float), np.array([b], float), np.array(d, float), path,
                       mode)[:, 0]


@pytest.mark.claim("§3.1.2: the sample path is translated, stretched and reflected to fit "
                   "each pair of corresponding points", measured="axis-stretch: x and y "
                   "stretched by δ/c per axis, mirrored where the ratio is negative, no "
                   "rotation; ends exact", verdict="agrees (axis-stretch mode; the default "
                   "similarity-reflect is ours, docs/kas.md)")
def test_axis_stretch_is_the_literal_per_axis_stretch() -> None:
    path = SamplePath([(0, 0), (1, 2), (3, 1)])       # chord (3, 1), mid-length at (1, 2)
    pos = _one((0, 0), (6, -3), [0, 0.5, 1], path, "axis-stretch")
    # x stretched by 6/3 = 2, y by -3/1 = -3 (reflected): (1, 2) -> (2, -6)
    assert np.allclose(pos, [[0, 0], [2, -6], [6, -3]])
    # drawn right to left, chord (-3, 1): x by 6/-3 = -2 (reflected): (-1, 2) -> (2, -6)
    back = SamplePath([(0, 0), (-1, 2), (-3, 1)])
    assert np.allclose(_one((0, 0), (6, -3), [0, 0.5, 1], back, "axis-stretch"),
                       [[0, 0], [2, -6], [6, -3]])


def test_axis_stretch_reflects_each_axis_by_its_own_sign() -> None:
    path = SamplePath([(0, 0), (1, 3), (2, 2)])        # chord (2, 2): no degenerate axis
    right_up = _one((0, 0), (4, 4), [0.5], path, "axis-stretch")
    left_up = _one((0, 0), (-4, 4), [0.5], path, "axis-stretch")
    assert np.allclose(left_up[:, 0], -right_up[:, 0])  # mirrored in x only
    assert np.allclose(left_up[:, 1], right_up[:, 1])
    rotated = _one((0, 0), (-4, 4), [0.5], path, "similarity")
    assert not np.allclose(rotated, left_up)            # the similarity turns it instead


def test_level_chord_keeps_its_arch_instead_of_zero_over_zero() -> None:
    # cy = 0: the literal ratio dy/cy is undefined; the blend gives the uniform scale, so
    # the arch keeps its drawn side (up) whichever way the point moves along x.
    for b, mid in (((14, 0), (12, 2)), ((6, 0), (8, 2))):
        assert np.allclose(_one((10, 0), b, [0, 0.5, 1], ARCH, "axis-stretch"),
                           [(10, 0), mid, b])


def test_near_degenerate_chord_is_bounded_where_the_literal_ratio_blows_up() -> None:
    # The hand-drawn arch with ends 0.03" apart in y (tests/kas/test_inbetween.py).
    path = SamplePath([(-4, -1), (-3, 0.5), (-2, 1.4), (0, 2), (2, 1.5), (3, 0.4),
                       (4, -0.97)])
    a = np.array([[0.0, 0.0]])
    b = np.array([[1.0, 1.0]])
    d = np.linspace(0, 1, 9)
    pos = pathfit.fit(a, b, d, path, "axis-stretch")[:, 0]
    q = pathfit.point_at(path, d) - path.points[0]
    literal = q * ((b - a) / (path.points[-1] - path.points[0]))  # δ/c per axis, unblended
    assert np.abs(literal[:, 1]).max() > 60                      # 3" of arch x 33: off screen
    chord = np.hypot(8, 0.03)
    bound = np.hypot(1, 1) / (pathfit.DEGENERATE * chord) * 3.0 + 1.0  # arch height 3"
    assert np.abs(pos[:, 1]).max() <= bound
    assert np.allclose(pos[0], a[0]) and np.allclose(pos[-1], b[0])


def test_axis_scales_are_continuous_at_the_blend_threshold() -> None:
    delta = np.array([[2.0, 3.0]])
    for eps in (1e-9, -1e-9):
        k = pathfit.DEGENERATE + eps
        chord = np.array([np.sqrt(1 - k * k), k])               # |c| = 1, cy = k|c|
        s = pathfit.axis_scales(chord, delta)
        assert s[0, 1] == pytest.approx(3.0 / pathfit.DEGENERATE, rel=1e-6)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(pathfit.FIT_MODES),
       st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5)), min_size=2, max_size=6),
       st.tuples(st.floats(-5, 5), st.floats(-5, 5)), st.tuples(st.floats(-5, 5),
                                                                st.floats(-5, 5)))
def test_every_mode_lands_on_both_keyframes(mode, pts, a, b) -> None:
    path = SamplePath(pts)
    try:
        pathfit.check(path)
    except ValueError:
        return
    chord = np.hypot(*(path.points[-1] - path.points[0]))
    if mode == "similarity" and chord < 1e-6:
        return
    pos = _one(a, b, [0.0, 1.0], path, mode)
    assert np.allclose(pos, [a, b], atol=1e-6 * (1 + np.abs(pos).max()))
    assert np.isfinite(_one(a, b, np.linspace(-0.2, 1.2, 8), path, mode)).all()


def test_old_name_stretch_is_similarity_reflect() -> None:
    assert pathfit.canonical("stretch") == "similarity-reflect" == pathfit.DEFAULT_FIT
    a, b = (0.0, 0.0), (-4.0, 1.0)
    assert np.array_equal(_one(a, b, [0.3, 0.7], ARCH, "stretch"),
                          _one(a, b, [0.3, 0.7], ARCH, "similarity-reflect"))
    with pytest.raises(ValueError, match="axis-stretch"):
        pathfit.canonical("bend")


def _key(x: float) -> Drawing:
    return Drawing([Chain.from_points([(x, 0), (x + 1, 0)], 1, 0)])


@pytest.mark.parametrize("pts", [[], [(1.0, 2.0)], [(1.0, 1.0), (1.0, 1.0)]])
def test_unusable_path_is_a_clear_error_not_an_index_error(pts) -> None:
    # `points 0` must be this error, not an IndexError inside the fit.
    with pytest.raises(ValueError, match="two points|no length"):
        inbetween(_key(0), _key(3), frames=4, path=SamplePath(pts))


def test_path_file_with_no_points_names_the_file_and_line(tmp_path) -> None:
    f = tmp_path / "empty.kas"
    f.write_text("KAS path 1\n# drawn by hand\npoints 0\nend\n")
    with pytest.raises(KasFileError, match=r"empty\.kas:3: a sample path needs at least two"):
        pathfit.load_checked(f)
    good = tmp_path / "good.kas"
    good.write_text("KAS path 1\npoints 2\n0 0\n1 1\nend\n")
    assert pathfit.load_checked(good).points.shape == (2, 2)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), max_size=4),
       st.integers(0, 6))
def test_any_path_file_loads_fits_or_names_its_line(tmp_path_factory, pts, n) -> None:
    f = tmp_path_factory.mktemp("paths") / "p.kas"
    rows = "".join(f"{x} {y}\n" for x, y in pts)
    f.write_text(f"KAS path 1\npoints {n}\n{rows}end\n")
    try:
        path = pathfit.load_checked(f)
    except KasFileError as exc:
        assert str(exc).startswith(f"{f}:") and exc.line >= 1
        return
    pos = pathfit.fit(np.zeros((1, 2)), np.ones((1, 2)), np.linspace(0, 1, 5), path,
                      "axis-stretch")
    assert np.isfinite(pos).all()


@pytest.mark.parametrize("k", [0.5, 0.25, 0.8])
def test_axis_scales_blend_weight_is_the_square_of_the_chords_share(k: float) -> None:
    """docs/fidelity/kas.md: on an almost level or upright chord the per-axis ratio is
    blended towards the uniform scale with weight (c_axis / (|chord|/4))², worked by hand:
    c_y = k·|c|/4 gives weight k², scale_y = k²·δy/c_y + (1 - k²)·|δ|/|c|."""
    floor = pathfit.DEGENERATE                      # |c| = 1
    cy = k * floor
    chord = np.array([np.sqrt(1 - cy * cy), cy])
    delta = np.array([[2.0, 3.0]])
    uniform = np.hypot(2.0, 3.0)
    s = pathfit.axis_scales(chord, delta)
    assert s[0, 1] == pytest.approx(k * k * 3.0 / cy + (1 - k * k) * uniform, rel=1e-12)
    assert s[0, 0] == pytest.approx(2.0 / chord[0], rel=1e-12)  # the long axis: literal
