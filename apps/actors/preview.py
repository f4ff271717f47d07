"""One actor alone on a small board, lit and turned: the picture editor's turntable."""

from __future__ import annotations

import numpy as np

from camlab88.apps.actors.mesh import actor_mesh
from camlab88.apps.actors.model import Actor, ActorSet
from camlab88.apps.actors.render import Look, Placed, Shot, Stage, canopy_over, render_frame

FLOOR = (-2, -2, 3, 3)  # 5 x 5 cells round the actor's cell (0, 0)
FOCAL_MM = 50.0


def _height(actor: Actor) -> float:
    v = actor_mesh(actor).verts
    return float(v[..., 2].max()) if len(v) else 1.0


def turntable(actor: Actor, angle_deg: float, size: tuple[int, int]) -> np.ndarray:
    """(h, w, 3) uint8: ``actor`` on a 5 x 5 board under four lights, turned ``angle_deg``
    about its vertical axis, seen from a fixed camera a little above; deterministic (the
    same actor, angle and size give the same bytes)."""
    w, h = int(size[0]), int(size[1])
    top = max(min(_height(actor), 20.0), 0.2)
    stage = Stage(ActorSet("preview", {actor.state: actor}), FLOOR, canopy_over(FLOOR),
                  (Placed(actor.state, 0.0, 0.0, 1.0, float(angle_deg)),))
    centre = (0.5, -0.5, top / 2.0)
    dist = 3.2 * max(top, 0.9)
    shot = Shot((centre[0], centre[1] - dist, centre[2] + 0.45 * dist), centre, FOCAL_MM)
    return render_frame(stage, shot, Look(w, h, ss=2, shadow_map=512))
