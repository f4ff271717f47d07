"""The event-free stretch of the frame loop, compiled with numba.

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
from camlab88.apps.snooker.events import _jit, scan

REST, EVENT, LIMIT = 0, 1, 2


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


interp = _jit(_interp)


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


run_frames = _jit(_run_frames)
