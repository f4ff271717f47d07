"""Resolving events (WHAT a collision does) and advancing the balls to the next frame.

* Ball-ball: the thesis's impulse along the line of centres,
  V1' = V1 + (c.(V2 - V1)) c,  V2' = V2 - (c.(V2 - V1)) c   (§6.1.2),
  generalised by a restitution e (impulse factor (1 + e)/2; e = 1 is the thesis's formula).
  When the struck ball touches others, the pair calculation is repeated over every touching
  pair, spreading out from the point of impact, pass after pass "until no touching pair of
  balls is attempting to move closer together" (§6.1.2).
* Cushion and jaw: the velocity component along the normal is reversed and scaled by the
  cushion restitution (values above 1 allowed); the tangential component is unaltered.
* Spin (§6.1.2): collisions use the main velocity; then the spinning ball's remaining spin
  component (along its old direction) is added to its new velocity and it stops spinning.
* Pocket: the ball leaves the playing area and is parked behind the pocket.

A ball whose velocity a collision with another ball changed starts a new speed curve at the
event time (a struck ball slides first); after a cushion the ball carries on along its curve,
scaled by the change of speed.
"""

from __future__ import annotations

import math

import numpy as np

from camlab88.apps.snooker import kernels
from camlab88.apps.snooker.events import (
    Event,
    EventKind,
    scan,
    scan_python,
    table_arrays,
)
from camlab88.apps.snooker.speed_curve import CURVE_TABLES, curve_for
from camlab88.apps.snooker.state import BallState, Motion, effective_velocity
from camlab88.apps.snooker.table import Table

TOUCH_TOLERANCE_M = 1e-9  # centres within d + this count as touching
APPROACH_TOLERANCE_M_S = 1e-12
MAX_PASSES = 2000  # multi-pass resolution; far above anything a real pack needs
MAX_EVENTS_PER_FRAME = 20000  # a guard so a pathological table cannot hang the program


class SimulationError(RuntimeError):
    pass


class Physics:
    """The simulator for one table: detect (events.scan) + resolve (methods below)."""

    def __init__(self, table: Table, use_numba: bool = True) -> None:
        """`use_numba=False` runs the same algorithm as plain Python (for comparison)."""
        self.table = table
        self.scan = scan if use_numba else scan_python
        self.curve = curve_for(table)
        self.seg, self.jaws, self.mouths = table_arrays(table)
        self.r = table.radius
        self.curve_table = CURVE_TABLES.get(table.speed_curve) if use_numba else None

    # --- many frames -----------------------------------------------------------------
    def run(self, m: Motion, n_next: int, max_frames: int
            ) -> list[tuple[Event | None, BallState]]:
        """Simulate from m.t through at most `max_frames` frame boundaries, starting with
        boundary `n_next`; stops early once every ball has stopped.  Returns, in order,
        (event, state after it) for each event and (None, state) for each time frame."""
        out: list[tuple[Event | None, BallState]] = []
        done = 0
        fr = self.table.frame_rate
        mid_frame = (n_next - 1) + 1e-9 < m.t * fr < n_next - 1e-9
        in_frame = 0  # events since the last frame boundary: a guard against endless loops
        while done < max_frames:
            if not state_moving(m):
                if mid_frame:  # the last ball stopped or dropped mid-frame: finish the frame
                    m.t = (n_next + done) / fr
                    self.frame_boundary(m)
                    out.append((None, m.freeze()))
                break
            if self.curve_table is None:
                events: list[tuple[Event, BallState]] = []
                self.advance(m, (n_next + done) / fr, events)
                self.frame_boundary(m)
                out.extend(events)
                out.append((None, m.freeze()))
                done += 1
                mid_frame = False
                continue
            k, status, kind, a, b = self._compiled(m, n_next + done, max_frames - done, out)
            done += k
            mid_frame = mid_frame and k == 0
            in_frame = 0 if k else in_frame
            if status == kernels.EVENT:
                out.append((self.resolve(m, kind, a, b), m.freeze()))
                mid_frame = True
                in_frame += 1
                if not np.all(np.isfinite(m.vel)):
                    raise SimulationError(f"velocities overflowed at t={m.t:.6f} s")
                if in_frame > MAX_EVENTS_PER_FRAME:
                    raise SimulationError(
                        f"more than {MAX_EVENTS_PER_FRAME} events in one frame at t={m.t:.6f} s"
                    )
        return out

    def _compiled(self, m: Motion, n_next: int, max_frames: int,
                  out: list[tuple[Event | None, BallState]]) -> tuple[int, int, int, int, int]:
        cap = min(max_frames, 256)
        U, G = self.curve_table
        o_pos = np.empty((cap, *m.pos.shape))
        o_vel = np.empty((cap, *m.vel.shape))
        o_spin = np.empty((cap, *m.spin.shape))
        o_t = np.empty(cap)
        k, t, status, kind, a, b = kernels.run_frames(
            m.pos, m.vel, m.spin, m.curve_v0, m.curve_t0, m.spin0, m.spin_t0, m.on_table,
            m.t, n_next, float(self.table.frame_rate), self.r, self.seg, self.jaws,
            self.mouths, U, G, self.table.deceleration_m_s2,
            self.table.spin_deceleration_m_s2, o_pos, o_vel, o_spin, o_t, cap,
        )
        m.t = t
        if k:
            shared = m.freeze()  # curve and on-table arrays do not change between events
            for j in range(k):
                out.append((None, BallState(
                    float(o_t[j]), _ro(o_pos[j]), _ro(o_vel[j]), _ro(o_spin[j]),
                    shared.curve_v0, shared.curve_t0, shared.spin0, shared.spin_t0,
                    shared.on_table)))
        return k, status, kind, a, b

    # --- the frame loop --------------------------------------------------------------
    def advance(self, m: Motion, t_end: float, events: list[tuple[Event, BallState]]) -> None:
        """Move the balls from m.t to t_end (<= the next frame boundary) with constant
        velocities, stopping at every event on the way (appended with the state after it)."""
        guard = 0
        while m.t < t_end:
            ev = effective_velocity(m.vel, m.spin)
            moving = m.on_table & ((ev[:, 0] != 0.0) | (ev[:, 1] != 0.0))
            if not moving.any():
                m.t = t_end
                return
            dt, kind, a, b = self.scan(
                m.pos, ev, m.on_table, moving, self.r, self.seg, self.jaws, self.mouths,
                t_end - m.t,
            )
            if kind < 0:
                m.pos[moving] += ev[moving] * (t_end - m.t)
                m.t = t_end
                return
            if dt > 0.0:
                m.pos[moving] += ev[moving] * dt
                m.t = min(m.t + dt, t_end)
            events.append((self.resolve(m, int(kind), int(a), int(b)), m.freeze()))
            guard += 1
            if guard > MAX_EVENTS_PER_FRAME:
                raise SimulationError(
                    f"more than {MAX_EVENTS_PER_FRAME} events in one frame at t={m.t:.6f} s"
                )

    def frame_boundary(self, m: Motion) -> None:
        """Step every moving ball's speed (and spin) to the curve's value for this frame."""
        speed = np.hypot(m.vel[:, 0], m.vel[:, 1])
        live = m.on_table & ((speed > 0) | (m.spin != 0))
        if not live.any():
            return
        new = self.curve(m.curve_v0[live], m.t - m.curve_t0[live], self.table)
        old = speed[live]
        with np.errstate(divide="ignore", invalid="ignore"):
            scale = np.where(old > 0, new / np.where(old > 0, old, 1.0), 0.0)
        m.vel[live] *= scale[:, None]
        s0 = m.spin0[live]
        decay = self.table.spin_deceleration_m_s2 * (m.t - m.spin_t0[live])
        left = np.maximum(0.0, np.abs(s0) - decay)
        spin = np.sign(s0) * left
        m.spin[live] = np.where(new > 0, spin, 0.0)

    # --- resolution ------------------------------------------------------------------
    def resolve(self, m: Motion, kind: int, a: int, b: int) -> Event:
        if kind == EventKind.BALL_BALL:
            chain = self.resolve_contacts(m, a, b)
            return Event(EventKind.BALL_BALL, m.t, a, b, chain)
        if kind == EventKind.CUSHION:
            nx, ny = self.seg[b, 4], self.seg[b, 5]
            self._bounce(m, a, nx, ny)
            return Event(EventKind.CUSHION, m.t, a, b, (a,), self.table.segments[b].name)
        if kind == EventKind.JAW:
            dx = m.pos[a, 0] - self.jaws[b, 0]
            dy = m.pos[a, 1] - self.jaws[b, 1]
            n = math.hypot(dx, dy) or 1.0
            self._bounce(m, a, dx / n, dy / n)
            return Event(EventKind.JAW, m.t, a, b, (a,))
        if kind == EventKind.POCKET:
            pocket = self.table.pockets[b]
            m.on_table[a] = False
            m.pos[a] = pocket.drop
            m.vel[a] = 0.0
            m.spin[a] = m.spin0[a] = m.curve_v0[a] = 0.0
            return Event(EventKind.POCKET, m.t, a, b, (a,), pocket.name)
        raise SimulationError(f"unknown event kind {kind}")

    def _bounce(self, m: Motion, a: int, nx: float, ny: float) -> None:
        vn = m.vel[a, 0] * nx + m.vel[a, 1] * ny
        if vn >= 0.0:
            return
        before = math.hypot(m.vel[a, 0], m.vel[a, 1])
        k = (1.0 + self.table.cushion_restitution) * vn
        m.vel[a, 0] -= k * nx
        m.vel[a, 1] -= k * ny
        after = math.hypot(m.vel[a, 0], m.vel[a, 1])
        if after > self.table.max_speed_m_s:  # restitution > 1 would otherwise run away
            m.vel[a] *= self.table.max_speed_m_s / after
        # The ball stays at the same point of its (rescaled) speed curve: a rolling ball
        # that meets a cushion keeps rolling.  This keeps the motion continuous when a
        # bounce falls either side of a frame boundary, which the aiming aids rely on.
        f = math.hypot(m.vel[a, 0], m.vel[a, 1]) / before
        m.curve_v0[a] *= f
        m.curve_t0[a] = m.t - f * (m.t - m.curve_t0[a])
        if f == 0.0:
            m.spin[a] = m.spin0[a] = 0.0

    def _restart_curve(self, m: Motion, a: int) -> None:
        m.curve_v0[a] = math.hypot(m.vel[a, 0], m.vel[a, 1])
        m.curve_t0[a] = m.t
        if m.curve_v0[a] == 0.0:
            m.spin[a] = m.spin0[a] = 0.0

    def resolve_contacts(self, m: Motion, a: int, b: int) -> tuple[int, ...]:
        """Multi-pass resolution through every touching pair, spreading out from (a, b)."""
        pairs = self._touching_pairs(m, a, b)
        old = m.vel.copy()
        factor = (1.0 + self.table.ball_restitution) / 2.0
        vel = m.vel
        for passes in range(2 * MAX_PASSES):
            if passes == MAX_PASSES:
                factor = 0.5  # never converging (not seen in practice): plastic contacts
            changed = False
            for i, j, cx, cy in pairs:
                w = (vel[j, 0] - vel[i, 0]) * cx + (vel[j, 1] - vel[i, 1]) * cy
                if w < -APPROACH_TOLERANCE_M_S:
                    k = factor * w
                    vel[i, 0] += k * cx
                    vel[i, 1] += k * cy
                    vel[j, 0] -= k * cx
                    vel[j, 1] -= k * cy
                    changed = True
            if not changed:
                break
        else:
            raise SimulationError(f"touching balls still approach after {MAX_PASSES} passes")
        chain = tuple(int(i) for i in np.nonzero(np.any(vel != old, axis=1))[0])
        for i in chain:
            if m.spin[i] != 0.0:  # §6.1.2: spin added after the collision, then it stops
                sp = math.hypot(old[i, 0], old[i, 1])
                if sp > 0:
                    vel[i, 0] += m.spin[i] * old[i, 0] / sp
                    vel[i, 1] += m.spin[i] * old[i, 1] / sp
                m.spin[i] = m.spin0[i] = 0.0
            self._restart_curve(m, i)
        return chain

    def _touching_pairs(self, m: Motion, a: int, b: int) -> list[tuple[int, int, float, float]]:
        """Touching pairs ordered by distance (in contacts) from the colliding pair."""
        idx = np.nonzero(m.on_table)[0]
        p = m.pos[idx]
        diff = p[None, :, :] - p[:, None, :]
        dist = np.hypot(diff[..., 0], diff[..., 1])
        touch = dist <= 2.0 * self.r + TOUCH_TOLERANCE_M
        np.fill_diagonal(touch, False)
        local = {int(g): k for k, g in enumerate(idx)}
        depth = {local[a]: 0, local[b]: 0}
        frontier = [local[a], local[b]]
        while frontier:  # breadth-first from the point of impact
            nxt = []
            for u in frontier:
                for v in np.nonzero(touch[u])[0]:
                    v = int(v)
                    if v not in depth:
                        depth[v] = depth[u] + 1
                        nxt.append(v)
            frontier = nxt
        pairs = []
        for u in depth:
            for v in np.nonzero(touch[u])[0]:
                v = int(v)
                if u < v:
                    d = dist[u, v]
                    cx, cy = diff[u, v, 0] / d, diff[u, v, 1] / d
                    pairs.append((min(depth[u], depth[v]), int(idx[u]), int(idx[v]), cx, cy))
        pairs.sort(key=lambda q: (q[0], q[1], q[2]))
        if not any(q[1:3] == (min(a, b), max(a, b)) for q in pairs):
            # Detected from a grazing root but a hair outside the tolerance: include it.
            d = m.pos[b] - m.pos[a]
            n = math.hypot(d[0], d[1])
            pairs.insert(0, (0, a, b, d[0] / n, d[1] / n))
        return [(i, j, cx, cy) for _, i, j, cx, cy in pairs]


def _ro(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


def simulate_to_rest(
    table: Table, state: BallState, max_seconds: float = 600.0, use_numba: bool = True
) -> tuple[list[BallState], list[tuple[Event, BallState]]]:
    """Convenience: time frames (one every 1/25 s, starting with `state`'s frame) and the
    events, until every ball has stopped.  Frame n is at time n / frame_rate."""
    phys = Physics(table, use_numba)
    m = state.thaw()
    fr = table.frame_rate
    n = math.floor(m.t * fr + 1e-9)
    limit = n + math.ceil(max_seconds * fr)
    frames = [state]
    events: list[tuple[Event, BallState]] = []
    while state_moving(m):
        n = math.floor(m.t * fr + 1e-9)
        if n >= limit:
            raise SimulationError(f"balls still moving after {max_seconds} s")
        for ev, balls in phys.run(m, n + 1, min(500, limit - n)):
            if ev is None:
                frames.append(balls)
            else:
                events.append((ev, balls))
    return frames, events


def state_moving(m: Motion | BallState) -> bool:
    """Some ball still has a velocity (its spin may be cancelling it for the moment)."""
    return bool(np.any(m.on_table & ((m.vel[:, 0] != 0.0) | (m.vel[:, 1] != 0.0))))
