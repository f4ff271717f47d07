"""Surface colours (linear light, 0..1) and Phong coefficients (thesis 6.4.1).

Reconstructed: the thesis gives no colour values. Balls are the standard set; the baize,
cushion, wood and legs are plausible period materials (docs/fidelity/snooker.md).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.table import N_BALLS


@dataclass(frozen=True)
class Phong:
    """I = ka*A*albedo + sum over lights of (kd*albedo*max(N.L, 0) + ks*max(R.V, 0)^n) * I_l."""

    ka: float = 1.0
    kd: float = 1.0
    ks: float = 0.55
    n: float = 40.0


# in the checkpoint's ball order: cue, yellow, green, brown, blue, pink, black, 15 reds
_COLOURS = {
    "cue": (0.80, 0.78, 0.70), "yellow": (0.78, 0.60, 0.03), "green": (0.02, 0.22, 0.06),
    "brown": (0.22, 0.08, 0.02), "blue": (0.02, 0.07, 0.45), "pink": (0.85, 0.32, 0.38),
    "black": (0.015, 0.015, 0.015), "red": (0.55, 0.015, 0.015),
}
BALL_ALBEDO = np.array([_COLOURS[n] for n in
                        ("cue", "yellow", "green", "brown", "blue", "pink", "black")]
                       + [_COLOURS["red"]] * (N_BALLS - 7), dtype=np.float64)
BALL_PHONG = Phong()
SPECK_ALBEDO = np.array((0.30, 0.34, 0.45))  # chalk-blue smudges / grey dust

SURFACES: dict[str, tuple[float, float, float]] = {
    "baize": (0.035, 0.22, 0.045),
    "cushion": (0.030, 0.19, 0.038),
    "wood": (0.20, 0.075, 0.022),
    "leg": (0.12, 0.045, 0.014),
    "pocket": (0.004, 0.004, 0.004),
}
BACKGROUND = np.array((0.012, 0.010, 0.010))  # the dark room round the table
WOOD_PHONG = Phong(ks=0.12, n=20.0)  # lacquered, reconstructed
