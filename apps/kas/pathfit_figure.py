"""The pictures of docs/kas.md comparing the sample-path fits on one pair of keyframes.

A rectangle (white, first keyframe; red, second) moves left and up; the sample path (green)
is an arch drawn from lower left to upper right.  Each picture superimposes the in-betweens
(yellow) and the curve each corner follows (cyan) under one fit mode (figure 3.6 of the
thesis draws the same kind of picture).  ``python -m camlab88.apps.kas.pathfit_figure DIR`` writes
the PNGs.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from camlab88.apps.kas import pathfit, raster
from camlab88.apps.kas.files import SamplePath
from camlab88.apps.kas.inbetween import inbetween
from camlab88.apps.kas.model import Chain, Drawing
from camlab88.base.png import write_png

RECT = [(0, 0), (1.2, 0), (1.2, 0.8), (0, 0.8), (0, 0)]
PATH = SamplePath([(-5, -3.5), (-4.6, -2.3), (-3.6, -1.3), (-2.2, -1.1), (-1, -1.5)])
MOVE = (-3.0, 2.5)
START = (2.0, -2.5)


def _rect(x: float, y: float, colour: int) -> Chain:
    return Chain.from_points([(x + px, y + py) for px, py in RECT], colour)


def figure(mode: str, frames: int = 7) -> Drawing:
    """Keyframes, in-betweens, corner curves and the path, as one drawing."""
    a = Drawing([_rect(*START, 1)])
    b = Drawing([_rect(START[0] + MOVE[0], START[1] + MOVE[1], 1)])
    seq = inbetween(a, b, frames, PATH, fit=mode, drop=False)
    corners = np.array(RECT[:4]) + START
    d = np.linspace(0, 1, 41)
    curves = pathfit.fit(corners, corners + MOVE, d, PATH, mode)
    chains = [Chain.from_points(curves[:, m], 6) for m in range(4)]
    for f in seq.frames[1:-1]:
        chains += [Chain(c.points, np.full(len(c), 5, np.int16), 0) for c in f.chains]
    chains += [_rect(*START, 1), _rect(START[0] + MOVE[0], START[1] + MOVE[1], 2),
               Chain.from_points(PATH.points, 3)]
    return Drawing(chains)


def write(directory: str | Path, width: int = 384) -> list[Path]:
    out = []
    for mode in ("axis-stretch", "similarity-reflect"):
        path = Path(directory) / f"kas_fit_{mode.replace('-', '_')}.png"
        out.append(write_png(raster.render(figure(mode), width), path))
    return out


if __name__ == "__main__":
    for p in write(sys.argv[1] if len(sys.argv) > 1 else "docs/images"):
        print(f"wrote {p}")
