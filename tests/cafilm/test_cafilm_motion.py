"""Motion on two levels: births grow and deaths shrink across a generation's frames, moving
cells glide to a neighbouring birth, each actor's own cycle on top."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.actors.model import Actor, ActorSet, Cycle, Material, Part
from camlab88.apps.cafilm.film import phase, stage_at
from camlab88.apps.cafilm.motion import change, cycle_pose, posed
from camlab88.apps.cafilm.timeline import Generation
from tests.cafilm.helpers import glider_film

BOX = (Part("box", (), (0.5, 0.5, 0.5)),)
M = Material(1, 1, 0, 1)


def _gen(cells: dict[tuple[int, int], int]) -> Generation:
    items = sorted(cells.items())
    return Generation(np.array([c for (c, _r), _s in items], np.int64),
                      np.array([r for (_c, r), _s in items], np.int64),
                      np.array([s for _cr, s in items], np.int64))


def _actors(*states: int, cycles: tuple[Cycle, ...] = ()) -> ActorSet:
    return ActorSet("x", {s: Actor(s, f"a{s}", (200, 0, 0), M, BOX, cycles) for s in states})


def test_a_birth_grows_from_nothing_to_full_size_across_the_frames_of_a_generation() -> None:
    ch = change(_gen({}), _gen({(5, 5): 1}), frozenset())
    scales = []
    for u in np.linspace(0.0, 1.0, 9):
        placed, _tiles = posed(ch, float(u), _actors(1), 0)
        scales.append(placed[0].scale if placed else 0.0)
    assert scales[0] == 0.0 and scales[-1] == 1.0
    assert all(b > a for a, b in zip(scales, scales[1:]))


def test_a_death_shrinks_from_full_size_to_nothing() -> None:
    ch = change(_gen({(5, 5): 1}), _gen({}), frozenset())
    scales = []
    for u in np.linspace(0.0, 1.0, 9):
        placed, _tiles = posed(ch, float(u), _actors(1), 0)
        scales.append(placed[0].scale if placed else 0.0)
    assert scales[0] == 1.0 and scales[-1] == 0.0
    assert all(b < a for a, b in zip(scales, scales[1:]))


def test_a_film_in_betweens_each_birth_over_the_frames_of_its_generation() -> None:
    film = glider_film(generations=1, per_generation=4, glide="none")
    gens = film.timeline.generations
    born = sorted(set(gens[1].as_dict()) - set(gens[0].as_dict()))
    assert born
    seen = []
    for n in range(1, film.n_frames + 1):
        assert phase(film, n) == (0, (n - 1) / 4)
        stage, _shot = stage_at(film, n)
        at = {(p.col, p.row): p.scale for p in stage.placed}
        seen.append([at.get((float(c), float(r)), 0.0) for c, r in born])
    for k in range(len(born)):
        col = [s[k] for s in seen]
        assert col[0] == 0.0 and col[-1] == 1.0 and all(b > a for a, b in zip(col, col[1:]))


def test_a_death_next_to_a_birth_of_the_same_state_glides_between_them() -> None:
    ch = change(_gen({(1, 1): 2, (8, 8): 2}), _gen({(2, 1): 2, (8, 8): 2}))
    assert ch.glides == (((1, 1), (2, 1), 2),) and not ch.births and not ch.deaths
    placed, _ = posed(ch, 0.5, _actors(2), 0)
    glider = [p for p in placed if p.row == 1]
    assert glider[0].col == pytest.approx(1.5) and glider[0].scale == 1.0


def test_glides_prefer_orthogonal_neighbours_and_each_cell_is_used_once() -> None:
    # one death, births to its right (orthogonal) and below-right (diagonal)
    ch = change(_gen({(1, 1): 1}), _gen({(2, 1): 1, (2, 2): 1}))
    assert ch.glides == (((1, 1), (2, 1), 1),)
    assert ch.births == (((2, 2), 1),)


def test_a_state_change_in_place_is_a_death_and_a_birth_and_the_maze_head_glides_on() -> None:
    # the maze runner: the head (2) moves right, its old cell becomes tail (3)
    ch = change(_gen({(3, 3): 2}), _gen({(3, 3): 3, (4, 3): 2}))
    assert ch.glides == (((3, 3), (4, 3), 2),)
    assert ch.births == (((3, 3), 3),)


def test_states_that_do_not_glide_are_born_and_die_in_place() -> None:
    ch = change(_gen({(1, 1): 1}), _gen({(2, 1): 1}), frozenset({2}))
    assert not ch.glides and ch.births == (((2, 1), 1),) and ch.deaths == (((1, 1), 1),)


def test_a_state_without_an_actor_is_a_tile_switching_at_half_time() -> None:
    ch = change(_gen({(1, 1): 4}), _gen({(5, 5): 4}))
    assert posed(ch, 0.25, _actors(1), 0) == ((), ((1, 1, 4),))
    assert posed(ch, 0.75, _actors(1), 0) == ((), ((5, 5, 4),))


def test_each_actor_bobs_and_turns_on_its_own_cycle() -> None:
    cycles = (Cycle("bob", 0.2, 10), Cycle("turn", 90.0, 20))
    assert cycle_pose(cycles, 0) == (0.0, 0.0)
    turn, lift = cycle_pose(cycles, 5)
    assert turn == pytest.approx(22.5) and lift == pytest.approx(0.2)
    assert cycle_pose(cycles, 10)[1] == pytest.approx(0.0, abs=1e-12)
    ch = change(_gen({(0, 0): 1}), _gen({(0, 0): 1}))
    placed, _ = posed(ch, 0.0, _actors(1, cycles=cycles), 5)
    assert placed[0].lift == pytest.approx(0.2) and placed[0].turn == pytest.approx(22.5)
