"""Specks of dust on the balls that turn as the ball rolls (thesis 6.4: "subtle texture to
the balls ... which could move in such a way as to give the viewer visual clues to the fact
that a ball was rolling, and in which direction"; 6.4.1: "a rudimentary representation of
specks of dust on the balls was included").

Each ball carries a fixed set of specks in its own frame (the same for every render). Its
orientation at a frame is the product of the rolling rotations of every frame step before
it: a ball that moves d on the baize without slipping turns |d| / radius about the
horizontal axis z x d. Reconstructed: the checkpoint holds no spin, so rolling is assumed.
"""

from __future__ import annotations

import numpy as np

N_SPECKS = 6
SPECK_RADIUS_RAD = 0.04  # subtle (§6.5): small, few and faint (SPECK_MIX in balls.py)
SPECK_SEED = 1987


def speck_directions(ball: int) -> np.ndarray:
    """(N_SPECKS, 3) unit vectors, fixed per ball (seeded, so every process agrees)."""
    rng = np.random.default_rng(SPECK_SEED + ball)
    v = rng.normal(size=(N_SPECKS, 3))
    return np.ascontiguousarray(v / np.linalg.norm(v, axis=1, keepdims=True))


def rolling_rotations(step: np.ndarray, radius: float) -> np.ndarray:
    """(n, 2) displacements on the baize -> (n, 3, 3) rolling rotations (Rodrigues)."""
    dist = np.linalg.norm(step, axis=1)
    safe = np.where(dist > 0, dist, 1.0)
    x, y = -step[:, 1] / safe, step[:, 0] / safe  # axis z x d, horizontal
    z = np.zeros_like(x)
    k = np.stack([np.stack([z, -z, y], -1), np.stack([z, z, -x], -1),
                  np.stack([-y, x, z], -1)], axis=1)
    ang = dist / radius
    eye = np.broadcast_to(np.eye(3), k.shape)
    return eye + np.sin(ang)[:, None, None] * k + (1 - np.cos(ang))[:, None, None] * (k @ k)


def orientations(centres: np.ndarray, on_table: np.ndarray, radius: float) -> np.ndarray:
    """(frames, 22, 3, 3) rotations (ball frame -> world) at every row of ``centres``."""
    f, n = centres.shape[:2]
    out = np.empty((f, n, 3, 3))
    out[0] = np.eye(3)
    for k in range(1, f):
        step = centres[k, :, :2] - centres[k - 1, :, :2]
        step[~(on_table[k] & on_table[k - 1])] = 0.0  # potting or re-spotting is no roll
        out[k] = rolling_rotations(step, radius) @ out[k - 1]
    return out
