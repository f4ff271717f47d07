"""The camera control language (thesis 6.3.1) over the automaton's grid.

The script is snooker's CCL, interpreted with one "frame" per generation: event numbers
(``FROM 10 UNTIL 40``, ``FRAME 10``) are generation numbers 1..N, ``END`` is generation N,
and the interpreter's messages that say "frame" mean generation. Generation 0 (the pattern
as loaded) is seen as generation 1 is. There are no balls, so ball events and ball names are
errors; the table's pockets and spots keep their snooker places (in cells: not useful).

Coordinates ``(x, y, z)`` are cells: x along the grid's columns, y along its rows (down the
2-D picture), z up from the board, with (0, 0) the top-left corner of the pattern's box at
generation 0 (the cell centre of the pattern's top-left cell is (0.5, 0.5)). ``COORDS``
scales and moves them as in snooker. Within a generation the film's frames interpolate the
camera linearly between the generation's values and the next one's.

Without a script the camera looks at the board's centre from the front (the side of the
last rows) and above, far enough back for a 35 mm lens to hold the whole board.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.actors.render import Shot


@dataclass(frozen=True, eq=False)
class GenerationViews:
    """observer, viewpoint (G + 1, 3) in the render's world frame and focal (G + 1,) mm,
    row g = generation g."""

    observer: np.ndarray
    viewpoint: np.ndarray
    focal: np.ndarray

    def at(self, tau: float) -> Shot:
        """The camera at generation time ``tau`` (0..G), linear between generations."""
        last = len(self.focal) - 1
        g = min(int(np.floor(tau)), last)
        u = tau - g
        h = min(g + 1, last)
        o = self.observer[g] + (self.observer[h] - self.observer[g]) * u
        v = self.viewpoint[g] + (self.viewpoint[h] - self.viewpoint[g]) * u
        f = self.focal[g] + (self.focal[h] - self.focal[g]) * u
        return Shot(tuple(o.tolist()), tuple(v.tolist()), float(f))


def auto_views(floor: tuple[int, int, int, int], generations: int,
               focal_mm: float = 35.0) -> GenerationViews:
    c0, r0, c1, r1 = floor
    centre = np.array([(c0 + c1) / 2.0, -(r0 + r1) / 2.0, 0.0])
    span = max(c1 - c0, 1.5 * (r1 - r0), 4.0) * focal_mm / 35.0
    obs = centre + np.array([0.0, -0.85 * span, 0.6 * span])
    n = generations + 1
    return GenerationViews(np.tile(obs, (n, 1)), np.tile(centre, (n, 1)),
                           np.full(n, float(focal_mm)))


def _grid_motion(generations: int) -> object:
    from camlab88.apps.snooker.camera.motion import Motion
    from camlab88.apps.snooker.table import N_BALLS, Table

    n = max(generations, 1)
    return Motion(Table(), np.zeros((n, N_BALLS, 3)), np.zeros((n, N_BALLS), dtype=bool), ())


def script_views(text: str, generations: int, path: str) -> GenerationViews:
    """Interpret the script (CclErrors listing every error if it has any)."""
    from camlab88.apps.snooker.camera.ccl import compile_script

    result = compile_script(text, _grid_motion(generations), path)
    # the table frame is CCL's space with x mirrored: (-x, y, z); the board's world frame
    # is (x, -y, z) of CCL's, so world = (-tx, -ty, tz)
    flip = np.array([-1.0, -1.0, 1.0])
    obs, vp, focal = result.observer * flip, result.viewpoint * flip, result.focal
    return GenerationViews(np.vstack([obs[:1], obs]), np.vstack([vp[:1], vp]),
                           np.concatenate([focal[:1], focal]))
