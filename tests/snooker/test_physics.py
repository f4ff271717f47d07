"""Physics: exact event times, conservation laws, multi-pass resolution, spin, the break."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.apps.snooker.events import EventKind, ball_ball_time, scan, scan_python, table_arrays
from camlab88.apps.snooker.layout import break_off, opening_state, pack_positions
from camlab88.apps.snooker.physics import Physics, simulate_to_rest
from camlab88.apps.snooker.speed_curve import curve_for, stopping_distance
from camlab88.apps.snooker.state import BallState, effective_velocity
from camlab88.apps.snooker.table import CUE, PINK, REDS, Table
from tests.snooker.helpers import overlaps, state_with

T = Table()
R = T.radius
D = T.ball_diameter_m


def first_event(table: Table, s: BallState, frames: int = 1):
    phys = Physics(table)
    m = s.thaw()
    events: list = []
    for n in range(1, frames + 1):
        phys.advance(m, n / table.frame_rate, events)
        if events:
            return events[0][0]
        phys.frame_boundary(m)
    return None


# --- exact event times ---------------------------------------------------------------
def test_cushion_time_is_the_clipped_path() -> None:
    s = state_with(T, {CUE: (1.0, R + 0.02)}, {CUE: (0.0, -1.0)})
    ev = first_event(T, s)
    assert ev.kind == EventKind.CUSHION and T.segments[ev.b].side == "right"
    assert ev.t == pytest.approx(0.02, abs=1e-12)  # (c - r - b) / V


def test_cushion_time_across_frames_follows_the_held_speeds() -> None:
    """Several frames away: speed constant per frame, stepping on the curve at boundaries."""
    y0 = 0.6
    s = state_with(T, {CUE: (1.0, y0)}, {CUE: (0.0, -1.5)})
    ev = first_event(T, s, frames=100)
    curve = curve_for(T)
    dist, t, n = y0 - R, 0.0, 0
    v = 1.5
    while True:
        if v * T.frame_dt >= dist:
            expected = t + dist / v
            break
        dist -= v * T.frame_dt
        n += 1
        t = n / T.frame_rate
        v = float(curve(np.array([1.5]), np.array([t]), T)[0])
    assert ev.t == pytest.approx(expected, abs=1e-9)


def test_head_on_ball_ball_time() -> None:
    s = state_with(T, {CUE: (1.0, 0.9), 7: (1.0 + D + 0.03, 0.9)}, {CUE: (2.0, 0.0)})
    ev = first_event(T, s)
    assert ev.kind == EventKind.BALL_BALL and (ev.a, ev.b) == (CUE, 7)
    assert ev.t == pytest.approx(0.015, abs=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    dx=st.floats(0.06, 0.5), off=st.floats(-0.05, 0.05), v=st.floats(0.5, 8.0),
    ang=st.floats(-0.3, 0.3),
)
def test_oblique_ball_ball_time_matches_closed_form(dx, off, v, ang) -> None:
    p1, p2 = (1.0, 0.9), (1.0 + dx, 0.9 + off)
    vel = (v * math.cos(ang), v * math.sin(ang))
    # Closed form: along-track distance minus the half-chord, over the relative speed.
    rx, ry = p2[0] - p1[0], p2[1] - p1[1]
    ux, uy = vel[0] / v, vel[1] / v
    along = rx * ux + ry * uy
    b2 = rx * rx + ry * ry - along * along
    got = ball_ball_time(p1, vel, p2, (0.0, 0.0), D)
    if b2 >= D * D or along <= 0:
        assert got is None or b2 >= D * D - 1e-12
        return
    expected = (along - math.sqrt(D * D - b2)) / v
    assert got == pytest.approx(expected, abs=1e-9)
    if expected < T.frame_dt:
        s = state_with(T, {CUE: p1, 7: p2}, {CUE: vel})
        ev = first_event(T, s)
        assert ev is not None and ev.kind == EventKind.BALL_BALL
        assert ev.t == pytest.approx(expected, abs=1e-9)


def test_jaw_time() -> None:
    jx, jy = T.segments[0].ax, T.segments[0].ay  # the right cushion's jaw at the baulk corner
    s = state_with(T, {CUE: (jx - 0.01, jy + 0.03)}, {CUE: (0.0, -1.0)})
    ev = first_event(T, s)
    assert ev.kind == EventKind.JAW
    assert ev.t == pytest.approx(0.03 - math.sqrt(R * R - 0.01**2), abs=1e-9)


def test_pocket_when_centre_crosses_mouth() -> None:
    s = state_with(T, {CUE: (T.length_m / 2, 0.035)}, {CUE: (0.0, -1.0)})
    ev = first_event(T, s)
    assert ev.kind == EventKind.POCKET and T.pockets[ev.b].name == "middle-right"
    assert ev.t == pytest.approx(0.035, abs=1e-12)


# --- collisions ----------------------------------------------------------------------
@settings(max_examples=80, deadline=None)
@given(
    ang=st.floats(0, 2 * math.pi), v1=st.tuples(st.floats(-5, 5), st.floats(-5, 5)),
    v2=st.tuples(st.floats(-5, 5), st.floats(-5, 5)), e=st.sampled_from([1.0, 0.9, 0.5]),
)
def test_ball_ball_conserves_momentum_and_elastic_energy(ang, v1, v2, e) -> None:
    table = T.with_changes(ball_restitution=e)
    p1 = (1.5, 0.9)
    p2 = (p1[0] + D * math.cos(ang), p1[1] + D * math.sin(ang))
    m = state_with(table, {CUE: p1, 7: p2}, {CUE: v1, 7: v2}).thaw()
    before = m.vel.copy()
    Physics(table).resolve_contacts(m, CUE, 7)
    assert np.allclose(m.vel.sum(axis=0), before.sum(axis=0), atol=1e-12)
    ke0, ke1 = (before**2).sum(), (m.vel**2).sum()
    if e == 1.0:
        assert ke1 == pytest.approx(ke0, rel=1e-12, abs=1e-12)
    else:
        assert ke1 <= ke0 + 1e-12
    c = np.array(p2) - np.array(p1)
    assert (m.vel[7] - m.vel[CUE]) @ c >= -1e-12  # no longer approaching


def test_thesis_formula_for_a_stationary_target() -> None:
    """V1' = V1 + (c.(V2-V1))c, V2' = V2 - (c.(V2-V1))c with ball 2 at rest."""
    ang = math.radians(30)
    c = np.array([math.cos(ang), math.sin(ang)])
    m = state_with(T, {CUE: (1.0, 0.9), 7: tuple(np.array([1.0, 0.9]) + D * c)},
                   {CUE: (3.0, 0.0)}).thaw()
    Physics(T).resolve_contacts(m, CUE, 7)
    v1 = np.array([3.0, 0.0])
    k = c @ (np.zeros(2) - v1)
    assert np.allclose(m.vel[CUE], v1 + k * c) and np.allclose(m.vel[7], -k * c)
    assert m.vel[CUE] @ m.vel[7] == pytest.approx(0.0, abs=1e-12)  # the 90 degree rule


def test_multi_pass_newtons_cradle() -> None:
    balls = {CUE: (1.0, 0.9)}
    for k in range(4):
        balls[7 + k] = (1.0 + (k + 1) * D, 0.9)
    m = state_with(T, balls, {CUE: (2.0, 0.0)}).thaw()
    chain = Physics(T).resolve_contacts(m, CUE, 7)
    assert np.allclose(m.vel[10], (2.0, 0.0)) and np.allclose(m.vel[[0, 7, 8, 9]], 0.0)
    assert set(chain) == {0, 10}  # the balls whose velocity changed


def test_multi_pass_through_the_pack_leaves_no_touching_pair_approaching() -> None:
    s = opening_state(T)
    m = s.thaw()
    apex = pack_positions(T)[0]
    m.pos[CUE] = (apex[0] - D, apex[1])
    m.pos[PINK] = (1.0, 0.3)
    m.vel[CUE] = (6.0, 0.0)
    p0 = m.vel.sum(axis=0).copy()
    ke0 = (m.vel**2).sum()
    chain = Physics(T).resolve_contacts(m, CUE, REDS[0])
    assert len(chain) >= 10
    assert np.allclose(m.vel.sum(axis=0), p0, atol=1e-9)
    assert (m.vel**2).sum() == pytest.approx(ke0, rel=1e-9)
    for i in range(22):
        for j in range(i + 1, 22):
            c = m.pos[j] - m.pos[i]
            if np.hypot(*c) <= D + 1e-9:
                assert (m.vel[j] - m.vel[i]) @ c >= -1e-9


def test_cushion_restitution_above_one() -> None:
    table = T.with_changes(cushion_restitution=1.5)
    s = state_with(table, {CUE: (1.0, R + 0.01)}, {CUE: (0.3, -1.0)})
    phys = Physics(table)
    m = s.thaw()
    events: list = []
    phys.advance(m, 1 / 25, events)
    assert events[0][0].kind == EventKind.CUSHION
    assert np.allclose(m.vel[CUE], (0.3, 1.5))  # tangential kept, normal reversed x1.5


# --- spin ----------------------------------------------------------------------------
@pytest.mark.parametrize("spin,cue_after", [(0.0, 0.0), (-0.8, -0.8), (0.5, 0.5)])
def test_spin_added_after_a_full_ball_hit(spin, cue_after) -> None:
    s = state_with(T, {CUE: (1.0, 0.9), 7: (1.0 + D + 0.02, 0.9)}, {CUE: (2.0, 0.0)},
                   {CUE: spin})
    phys = Physics(T)
    m = s.thaw()
    events: list = []
    phys.advance(m, 1 / 25, events)
    ev, after = events[0]
    assert ev.kind == EventKind.BALL_BALL
    assert after.vel[7, 0] == pytest.approx(2.0)  # the main component went to the red
    assert after.vel[CUE, 0] == pytest.approx(cue_after)  # screw back / follow through
    assert after.spin[CUE] == 0.0


def test_spin_decays_linearly_and_faster_than_the_ball() -> None:
    s = state_with(T, {CUE: (0.5, 0.9)}, {CUE: (1.0, 0.0)}, {CUE: 0.3})
    frames, _ = simulate_to_rest(T, s)
    spins = [f.spin[CUE] for f in frames]
    steps = np.diff(spins[: 1 + int(0.3 / T.spin_deceleration_m_s2 * 25)])
    assert np.allclose(steps, -T.spin_deceleration_m_s2 / 25)
    first_zero_spin = next(k for k, s in enumerate(spins) if s == 0)
    first_stop = next(k for k, f in enumerate(frames) if f.speed(CUE) == 0)
    assert first_zero_spin < first_stop


# --- motion --------------------------------------------------------------------------
def test_velocity_constant_within_frames_and_distance_matches_curve() -> None:
    s = state_with(T, {CUE: (0.3, 0.9)}, {CUE: (1.0, 0.0)})
    frames, events = simulate_to_rest(T, s)
    assert not events
    xs = [f.pos[CUE, 0] for f in frames]
    assert xs[-1] - xs[0] == pytest.approx(stopping_distance(1.0, T), rel=1e-12)
    speeds = [f.speed(CUE) for f in frames]
    assert all(a >= b for a, b in zip(speeds, speeds[1:], strict=False))
    assert np.allclose(np.diff(xs), np.array(speeds[:-1]) / 25)


def test_break_splits_the_pack_and_everything_stops() -> None:
    s = break_off(T, 5.0)
    frames, events = simulate_to_rest(T, s)
    last = frames[-1]
    assert not last.any_moving()
    start = pack_positions(T)
    moved = [np.hypot(*(last.pos[r] - start[k])) for k, r in enumerate(REDS)]
    assert sum(d > D for d in moved) >= 5  # the pack has split
    kinds = {e.kind for e, _ in events}
    assert EventKind.BALL_BALL in kinds and EventKind.CUSHION in kinds
    for f in frames + [b for _, b in events]:
        assert overlaps(T, f) > -1e-9
        assert_inside(T, f)


def test_simulation_is_deterministic() -> None:
    a, ea = simulate_to_rest(T, break_off(T, 6.0))
    b, eb = simulate_to_rest(T, break_off(T, 6.0))
    assert len(a) == len(b) and all(x.same_as(y) for x, y in zip(a, b, strict=True))
    assert [e for e, _ in ea] == [e for e, _ in eb]


def assert_inside(table: Table, s: BallState, tol: float = 1e-9) -> None:
    r = table.radius
    for i in np.nonzero(s.on_table)[0]:
        x, y = s.pos[i]
        assert -tol <= x <= table.length_m + tol and -tol <= y <= table.width_m + tol
        for seg in table.segments:
            tx, ty = seg.tangent
            nx, ny = seg.normal
            u = (x - seg.ax) * tx + (y - seg.ay) * ty
            if 0 <= u <= seg.length:
                assert (x - seg.ax) * nx + (y - seg.ay) * ny >= r - tol, (i, seg.name)
        for jx, jy in table.jaws:
            assert math.hypot(x - jx, y - jy) >= r - tol
        for p in table.pockets:
            ox, oy = p.outward
            assert (x - p.ax) * ox + (y - p.ay) * oy <= tol
    assert not s.on_table.all() or True


# --- random tables -------------------------------------------------------------------
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    length=st.floats(1.5, 5.0), aspect=st.floats(0.35, 0.7), diameter=st.floats(0.03, 0.25),
    cushion_e=st.floats(0.3, 1.2), ball_e=st.floats(0.5, 1.0),
    seed=st.integers(0, 2**31 - 1), n=st.integers(2, 12),
)
def test_random_tables_keep_the_invariants(length, aspect, diameter, cushion_e, ball_e,
                                           seed, n) -> None:
    width = length * aspect
    diameter = min(diameter, width / 8)
    table = Table(length_m=length, width_m=width, ball_diameter_m=diameter,
                  corner_mouth_m=1.7 * diameter, middle_mouth_m=2.0 * diameter,
                  cushion_restitution=cushion_e, ball_restitution=ball_e)
    rng = np.random.default_rng(seed)
    cols, rows = int(length / (1.5 * diameter)) - 1, int(width / (1.5 * diameter)) - 1
    cells = rng.permutation(cols * rows)[:n]
    balls, vel = {}, {}
    for k, c in enumerate(cells):
        balls[k] = ((c % cols + 1) * 1.5 * diameter, (c // cols + 1) * 1.5 * diameter)
        if rng.random() < 0.6:
            vel[k] = tuple(rng.uniform(-3, 3, 2))
    s = state_with(table, balls, vel)
    # Cushions with restitution > 1 may pump energy in for ever: check 30 s of those.
    seconds = 400 if cushion_e <= 1.0 else 30
    m = s.thaw()
    items = Physics(table).run(m, 1, seconds * table.frame_rate)
    if cushion_e <= 1.0:
        assert not m.vel.any()  # everything came to rest
    times = [ev.t for ev, _ in items if ev is not None]
    assert times == sorted(times)
    for _, f in items:
        assert overlaps(table, f) > -1e-8 * max(1.0, diameter)
        assert_inside(table, f, tol=1e-8)
        # Cushions cap each ball's speed; ball-ball collisions never add energy.
        assert (f.vel**2).sum() <= len(balls) * table.max_speed_m_s**2 * (1 + 1e-9)


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31 - 1))
def test_numba_scan_equals_python_scan(seed) -> None:
    rng = np.random.default_rng(seed)
    s = opening_state(T)
    pos = np.array(s.pos) + rng.normal(0, 0.01, (22, 2))
    vel = rng.normal(0, 1, (22, 2))
    active = rng.random(22) < 0.9
    moving = active & (rng.random(22) < 0.5)
    seg, jaws, mouths = table_arrays(T)
    ev = effective_velocity(vel, np.zeros(22))
    a = scan(pos, ev, active, moving, R, seg, jaws, mouths, 0.04)
    b = scan_python(pos, ev, active, moving, R, seg, jaws, mouths, 0.04)
    assert tuple(a) == tuple(b)


def test_compiled_frame_loop_matches_the_python_one() -> None:
    a_frames, a_events = simulate_to_rest(T, break_off(T, 7.0))
    b_frames, b_events = simulate_to_rest(T, break_off(T, 7.0), use_numba=False)
    assert len(a_frames) == len(b_frames)
    assert [(e.kind, e.a, e.b) for e, _ in a_events] == [(e.kind, e.a, e.b) for e, _ in b_events]
    for x, y in zip(a_frames, b_frames, strict=True):
        assert x.t == y.t and np.allclose(x.pos, y.pos, rtol=0, atol=1e-9)
        assert np.allclose(x.vel, y.vel, rtol=0, atol=1e-9)


def test_theoretical_sliding_curve_runs_on_the_python_path() -> None:
    table = T.with_changes(speed_curve="pullen1987-sliding")
    frames, events = simulate_to_rest(table, break_off(table, 5.0))
    assert not frames[-1].any_moving() and events
    for f in frames:
        assert overlaps(table, f) > -1e-9
    with pytest.raises(ValueError, match="unknown speed curve"):
        simulate_to_rest(T.with_changes(speed_curve="nonsense"), break_off(T, 1.0))
