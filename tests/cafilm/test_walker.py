"""§8.1's "each cell as an animated object in its own right (a human figure for example)":
the walker of examples/ca/walker.actors swings its limbs, each walker on its own clock,
a clock that carries on through a glide."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.actors.mesh import actor_mesh, posed_actor_mesh, swing_angle
from camlab88.apps.actors.model import read_actors
from camlab88.apps.actors.render import Stage, canopy_over, world_triangles
from camlab88.apps.cafilm.motion import change, clock_shift, lineage, posed
from tests.cafilm.test_cafilm_motion import _gen

WALKER = Path(__file__).resolve().parents[2] / "examples" / "ca" / "walker.actors"
ACTORS = read_actors(WALKER)
MAN = ACTORS.actors[2]


def test_the_walkers_legs_and_arms_swing_in_opposition() -> None:
    legs = [p for p in MAN.parts if p.swing is not None and p.swing[0] < 0.5]
    arms = [p for p in MAN.parts if p.swing is not None and p.swing[0] > 0.5]
    assert len(legs) == 2 and len(arms) == 2 and MAN.phase == "individual"
    for clock in (2, 4, 9):
        left_leg, right_leg = (swing_angle(p, clock) for p in legs)
        left_arm, right_arm = (swing_angle(p, clock) for p in arms)
        assert left_leg == pytest.approx(-right_leg) and left_arm == pytest.approx(-right_arm)
        assert np.sign(left_leg) == -np.sign(left_arm)  # arm against leg, as people walk
    rest, stride = actor_mesh(MAN).verts, posed_actor_mesh(MAN, 4).verts
    assert np.abs(rest - stride).max() > 0.15  # a quarter period: the feet well apart
    assert np.allclose(posed_actor_mesh(MAN, 16).verts, posed_actor_mesh(MAN, 0).verts)


def test_two_walkers_are_out_of_step_and_a_walkers_clock_survives_its_glide() -> None:
    g0 = _gen({(0, 0): 2, (5, 3): 2})
    g1 = _gen({(1, 0): 2, (5, 3): 2})  # the first walker glides one cell on
    gens = [g0, g1]
    born0 = lineage(gens, 0)
    placed, _ = posed(change(g0, g1), 0.0, ACTORS, 10, born0, 0)
    assert len({p.clock for p in placed}) == 2  # born in different cells: own clocks
    tri = world_triangles(Stage(ACTORS, (-2, -2, 8, 8), canopy_over((-2, -2, 8, 8)), placed))
    assert len(tri[0]) == 2 * len(actor_mesh(MAN).verts)
    born1 = lineage(gens, 1)
    assert born1[(1, 0)] == ((0, 0), 0)  # the glide carries the birth on
    later, _ = posed(change(g1, g1), 0.0, ACTORS, 11, born1, 1)
    at = {(p.col, p.row): p.clock for p in later}
    assert at[(1, 0)] == 11 + clock_shift(((0, 0), 0))  # one frame on: no jump


def test_a_together_actor_keeps_the_films_clock() -> None:
    from camlab88.apps.actors.model import parse_actors

    together = parse_actors(WALKER.read_text().replace("  phase individual\n", ""), "w")
    g = _gen({(0, 0): 2, (5, 3): 2})
    placed, _ = posed(change(g, g), 0.0, together, 7, lineage([g], 0), 0)
    assert {p.clock for p in placed} == {7}
