"""§8.1's "each cell as an animated object in its own right (a human figure for example)":
the walker of examples/ca/walker.actors swings its limbs, each walker on its own clock,
a clock that carries on through a glide."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.actors.mesh import actor_mesh, posed_actor_mesh, swing_angle
from camlab88.apps.actors.model import ActorSet, parse_actors, read_actors
from camlab88.apps.actors.render import Placed, Stage, canopy_over, world_triangles
from camlab88.apps.cafilm.motion import change, clock_shift, facing, lineage, posed
from tests.cafilm.test_cafilm_motion import _gen

WALKER = Path(__file__).resolve().parents[2] / "examples" / "ca" / "walker.actors"
ACTORS = read_actors(WALKER)
MAN = ACTORS.actors[2]


def test_the_walkers_legs_and_arms_swing_in_opposition() -> None:
    legs = [p for p in MAN.parts if p.kind == "box" and p.swing is not None
            and p.swing[0] < 0.5]  # the boxes: each foot swings with its leg
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
    together = parse_actors(WALKER.read_text().replace("  phase individual\n", ""), "w")
    g = _gen({(0, 0): 2, (5, 3): 2})
    placed, _ = posed(change(g, g), 0.0, together, 7, lineage([g], 0), 0)
    assert {p.clock for p in placed} == {7}


def _still() -> ActorSet:
    """The walker on the film's own clock (no individual shift): frame 0 is its rest pose,
    limbs hanging, so its shape shows which way it faces."""
    return parse_actors(WALKER.read_text().replace("  phase individual\n", ""), "w")


def _reach(placed: Placed, actors: ActorSet) -> tuple[float, float, float]:
    """(ahead, behind, across) of the placed walker's triangles from its own centre, along
    its glide east (+x in the world) and across it."""
    tri = world_triangles(Stage(actors, (-2, -2, 8, 8), canopy_over((-2, -2, 8, 8)), (placed,)))
    v = tri[0].reshape(-1, 3)
    centre = np.array([placed.col + 0.5, -(placed.row + 0.5)])
    d = v[:, :2] - centre
    return float(d[:, 0].max()), float(-d[:, 0].min()), float(np.ptp(d[:, 1]))


def test_the_walker_faces_the_way_it_glides_and_keeps_facing_it() -> None:
    actors = _still()
    gens = [_gen({(0, 0): 2}), _gen({(1, 0): 2}), _gen({(1, 0): 2}), _gen({(1, 1): 2})]
    end_of_glide, _ = posed(change(gens[0], gens[1]), 1.0, actors, 0,
                            faces=facing(gens, 0))
    ahead, behind, across = _reach(end_of_glide[0], actors)
    assert ahead > behind + 0.04  # its feet and nose point east, the way it went
    assert across > ahead + behind  # shoulders across its path, not along it
    standing, _ = posed(change(gens[1], gens[2]), 0.5, actors, 0, faces=facing(gens, 1))
    assert standing[0].turn == pytest.approx(end_of_glide[0].turn)  # still facing east
    # turning a corner south: from east (90 degrees) round to south (0), in the glide's
    # first half, through the smaller angle
    ch = change(gens[2], gens[3])
    turns = [posed(ch, u, actors, 0, faces=facing(gens, 2))[0][0].turn
             for u in (0.0, 0.25, 0.5, 1.0)]
    assert turns[0] == pytest.approx(90.0) and turns[2] == turns[3] == pytest.approx(0.0)
    assert 0.0 < turns[1] < 90.0


def test_a_runner_born_beside_its_parent_faces_away_from_it_and_a_fixed_actor_never_turns(
) -> None:
    g0, g1 = _gen({(3, 3): 2}), _gen({(4, 3): 2, (3, 2): 2})  # the head splits
    gens = [g0, g1]
    heads = facing(gens, 1)
    assert heads[(3, 2)] == pytest.approx(180.0)  # north, gliding on (rows first)
    assert heads[(4, 3)] == pytest.approx(90.0)  # east, born away from (3, 3)
    born, _ = posed(change(g0, g1), 0.5, _still(), 0, faces=facing(gens, 0))
    assert [p.turn for p in born if p.scale < 1] == [pytest.approx(90.0)]  # grows facing east
    chess = read_actors(WALKER.parent / "chess.actors")  # its knight does not `face glide`
    placed, _ = posed(change(g0, g1), 1.0, chess, 0, faces=facing(gens, 0))
    assert {p.turn for p in placed} == {0.0}
