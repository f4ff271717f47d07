"""The snooker simulation's compiled kernels: the event finder (``scan``: WHEN the next
thing happens, see events.py) and the event-free stretch of the frame loop, which calls it
(one file: numba's cache checks a kernel against its own file only).

Between events nothing but arithmetic happens: move every ball at its held velocity to the
next frame boundary, step its speed (and spin) down the speed curve, record the frame.
`run_frames` does that in compiled code until the scan finds an event (which Python
resolves, see physics.Physics.run), the balls come to rest, or enough frames are done.
It mirrors `Physics.advance` + `Physics.frame_boundary` operation for operation; the
Python path remains for tables whose speed curve is not a tabulated one.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

# Cached, so only the first run after install compiles; every kernel here is called with
# one set of argument types (docs/development.md, "numba's cache").
announce_compiles("snooker", 6.0, __name__)  # a cold compile, measured

REST, EVENT, LIMIT = 0, 1, 2
NO_EVENT = -1


def _scan(pos, vel, active, moving, r, seg, jaws, mouths, horizon):
    """Earliest event within `horizon` seconds: (dt, kind, a, b) or (horizon, -1, -1, -1).

    seg rows: ax ay tx ty nx ny length; jaws rows: x y; mouths rows: ax ay tx ty ox oy width.
    """
    best = horizon
    kind = -1
    ea = -1
    eb = -1
    n = pos.shape[0]
    d2 = 4.0 * r * r
    for i in range(n):
        if not active[i]:
            continue
        px = pos[i, 0]
        py = pos[i, 1]
        vx = vel[i, 0]
        vy = vel[i, 1]
        if moving[i]:
            for k in range(seg.shape[0]):
                vn = vx * seg[k, 4] + vy * seg[k, 5]
                if vn >= 0.0:
                    continue
                s = (px - seg[k, 0]) * seg[k, 4] + (py - seg[k, 1]) * seg[k, 5] - r
                if s < -r:  # centre already behind the face: not this cushion's business
                    continue
                lam = -s / vn
                if lam < 0.0:
                    lam = 0.0
                if lam >= best:
                    continue
                u = (px + vx * lam - seg[k, 0]) * seg[k, 2] + (
                    py + vy * lam - seg[k, 1]
                ) * seg[k, 3]
                if u < 0.0 or u > seg[k, 6]:
                    continue
                best = lam
                kind = 1
                ea = i
                eb = k
            k1 = vx * vx + vy * vy
            for k in range(jaws.shape[0]):
                dx = px - jaws[k, 0]
                dy = py - jaws[k, 1]
                k2 = dx * vx + dy * vy
                if k2 >= 0.0:
                    continue
                k3 = dx * dx + dy * dy - r * r
                disc = k2 * k2 - k1 * k3
                if disc < 0.0:
                    continue
                lam = k3 / (-k2 + math.sqrt(disc)) if k3 > 0.0 else 0.0
                if lam < best:
                    best = lam
                    kind = 2
                    ea = i
                    eb = k
            for k in range(mouths.shape[0]):
                vo = vx * mouths[k, 4] + vy * mouths[k, 5]
                if vo <= 0.0:
                    continue
                s = (px - mouths[k, 0]) * mouths[k, 4] + (py - mouths[k, 1]) * mouths[k, 5]
                lam = -s / vo
                if lam < 0.0:
                    lam = 0.0
                if lam >= best:
                    continue
                u = (px + vx * lam - mouths[k, 0]) * mouths[k, 2] + (
                    py + vy * lam - mouths[k, 1]
                ) * mouths[k, 3]
                if u < -r or u > mouths[k, 6] + r:
                    continue
                best = lam
                kind = 3
                ea = i
                eb = k
        for j in range(i + 1, n):
            if not active[j]:
                continue
            if not (moving[i] or moving[j]):
                continue
            wx = vel[j, 0] - vx
            wy = vel[j, 1] - vy
            x = pos[j, 0] - px
            y = pos[j, 1] - py
            k2 = x * wx + y * wy
            # Not approaching (or slower than physics.APPROACH_TOLERANCE_M_S, which the
            # resolution also ignores): no collision.
            if k2 >= -1e-12 * 2.0 * r:
                continue
            k1 = wx * wx + wy * wy
            k3 = x * x + y * y - d2
            disc = k2 * k2 - k1 * k3
            if disc < 0.0:  # complex roots: they miss
                continue
            lam = k3 / (-k2 + math.sqrt(disc)) if k3 > 0.0 else 0.0
            if lam < best:
                best = lam
                kind = 0
                ea = i
                eb = j
    return best, kind, ea, eb


# the event finder: compiled, and as Python (physics' path for tables without a tabulated
# speed curve, and the tests' reference)
scan_python = _scan
scan = njit(cache=True, nogil=True)(_scan)


def _interp(u, U, G):
    """np.interp(u, U, G, right=0.0) with numpy's own formula."""
    n = U.shape[0]
    if u >= U[n - 1]:
        return 0.0 if u > U[n - 1] else G[n - 1]
    if u <= U[0]:
        return G[0]
    j = 0
    while U[j + 1] <= u:
        j += 1
    slope = (G[j + 1] - G[j]) / (U[j + 1] - U[j])
    return slope * (u - U[j]) + G[j]


interp = njit(cache=True, nogil=True)(_interp)


def _run_frames(pos, vel, spin, cv0, ct0, spin0, spin_t0, on, t, n_next, fr, r, seg, jaws,
                mouths, U, G, decel, spin_decel, out_pos, out_vel, out_spin, out_t,
                max_frames):
    nb = pos.shape[0]
    ev = np.zeros((nb, 2))
    moving = np.zeros(nb, dtype=np.bool_)
    k = 0
    while k < max_frames:
        live = False
        for i in range(nb):
            if on[i] and (vel[i, 0] != 0.0 or vel[i, 1] != 0.0):
                live = True
        if not live:
            return k, t, REST, -1, -1, -1
        t_end = n_next / fr
        while t < t_end:
            anym = False
            for i in range(nb):
                sp = math.hypot(vel[i, 0], vel[i, 1])
                f = 0.0
                if sp > 0.0:
                    f = max(0.0, sp + spin[i]) / sp
                ev[i, 0] = vel[i, 0] * f
                ev[i, 1] = vel[i, 1] * f
                moving[i] = on[i] and (ev[i, 0] != 0.0 or ev[i, 1] != 0.0)
                anym = anym or moving[i]
            if not anym:  # back spin cancelling the main velocity: nobody moves this frame
                t = t_end
                break
            dt, kind, a, b = scan(pos, ev, on, moving, r, seg, jaws, mouths, t_end - t)
            if kind < 0:
                step = t_end - t
                for i in range(nb):
                    if moving[i]:
                        pos[i, 0] += ev[i, 0] * step
                        pos[i, 1] += ev[i, 1] * step
                t = t_end
                break
            if dt > 0.0:
                for i in range(nb):
                    if moving[i]:
                        pos[i, 0] += ev[i, 0] * dt
                        pos[i, 1] += ev[i, 1] * dt
                t = min(t + dt, t_end)
            return k, t, EVENT, kind, a, b
        # frame boundary: step speeds and spins down their curves
        for i in range(nb):
            sp = math.hypot(vel[i, 0], vel[i, 1])
            if not (on[i] and (sp > 0.0 or spin[i] != 0.0)):
                continue
            v0 = cv0[i]
            new = 0.0
            if v0 > 0.0:
                t_rest = v0 / decel
                u = (t - ct0[i]) / t_rest if t_rest > 0.0 else 1.0
                new = v0 * interp(u, U, G)
            scale = new / sp if sp > 0.0 else 0.0
            vel[i, 0] *= scale
            vel[i, 1] *= scale
            left = max(0.0, abs(spin0[i]) - spin_decel * (t - spin_t0[i]))
            s = math.copysign(left, spin0[i]) if spin0[i] != 0.0 else 0.0
            spin[i] = s if new > 0.0 else 0.0
        out_pos[k] = pos
        out_vel[k] = vel
        out_spin[k] = spin
        out_t[k] = t
        k += 1
        n_next += 1
    return k, t, LIMIT, -1, -1, -1


run_frames = njit(cache=True, nogil=True)(_run_frames)
