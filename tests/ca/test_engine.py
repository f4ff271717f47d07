"""The engine on known Game of Life behaviour and on the chapter 7 message semantics."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.ca import engine as engine_mod
from camlab88.apps.ca.engine import Engine, Rect
from camlab88.apps.ca.library import pattern_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import parse_rules
from tests.ca.helpers import LIFE, cellset, kernels_used, life, shifted

BLOCK = "OO\nOO"
BEEHIVE = ".OO.\nO..O\n.OO."
BOAT = "OO.\nO.O\n.O."
BLINKER = "OOO"
BEACON = "OO..\nOO..\n..OO\n..OO"
TOAD = ".OOO\nOOO."
GLIDER = ".O.\n..O\nOOO"


@pytest.mark.parametrize("still", [BLOCK, BEEHIVE, BOAT])
def test_still_lifes_stay(still: str) -> None:
    e = life(still)
    start = cellset(e)
    e.step(5)
    assert cellset(e) == start


@pytest.mark.parametrize("osc", [BLINKER, BEACON, TOAD])
def test_period_two_oscillators(osc: str) -> None:
    e = life(osc)
    start = cellset(e)
    e.step()
    assert cellset(e) != start
    e.step()
    assert cellset(e) == start


def test_glider_moves_one_cell_every_four_generations() -> None:
    e = life(GLIDER)
    start = cellset(e)
    for k in range(1, 6):
        e.step(4)
        assert cellset(e) == shifted(start, k, k)


def _gun_engine(**kw) -> Engine:
    e = Engine(LIFE, **kw)
    xs, ys, ts = read_pattern(pattern_path("gosper_gun")).placed(1000, 1000)
    e.set_cells(xs, ys, ts)
    return e


def test_gosper_gun_has_period_30_and_emits_a_glider_each_period() -> None:
    e = _gun_engine()
    gun_box = Rect(1000, 1000, 1035, 1008)
    start = set(zip(*(a.tolist() for a in e.cells_in_rect(gun_box))))
    pops = []
    for _ in range(4):
        e.step(30)
        now = set(zip(*(a.tolist() for a in e.cells_in_rect(gun_box))))
        assert now == start
        pops.append(e.population)
    assert np.diff(pops).tolist() == [5, 5, 5]


def test_r_pentomino_methuselah_and_both_kernels_agree(monkeypatch) -> None:
    e = life(".OO\nOO.\n.O.", 32768, 32768)
    e.step(200)
    assert e.last_kernel == "window"  # compact: the dense workspace
    e.step(903)
    assert e.population == 116
    assert e.last_kernel == "hash"  # gliders have escaped: the box is too sparse
    monkeypatch.setattr(engine_mod, "WINDOW_MIN", 0)
    monkeypatch.setattr(engine_mod, "WINDOW_CELLS_PER_SENDER", 0)
    h = life(".OO\nOO.\n.O.", 32768, 32768)
    h.step(1103)
    assert h.last_kernel == "hash"
    assert h.same_state(e)


def test_wrapping_and_bounded_edges() -> None:
    # A glider heading up-left across the corner of the plane.
    up_left = "OOO\nO..\n.O."
    w = life(up_left, 1, 1, edges="wrap")
    start = cellset(w)
    w.step(16)
    assert cellset(w) == shifted(start, -4, -4)
    assert w.last_kernel == "hash"  # the reach box crosses the edge
    b = life(up_left, 1, 1, edges="bounded")
    b.step(16)
    assert b.population > 0 and int(b.xs.min()) >= 0 and int(b.ys.max()) < 10
    assert cellset(b) != cellset(w)  # the glider hit the edge and broke up


def test_cells_receiving_nothing_die_and_self_message_keeps_alive() -> None:
    r = parse_rules("1 0 0 0 0 |1  2 0 0 0 1 . +1 $ 1 1")
    e = Engine(r)
    e.set_cells([5, 9], [5, 9], [1, 2])
    e.step()
    # Type 1 kept itself alive; type 2 sent only to its right, where the sum 1 means life.
    assert cellset(e) == {(5, 5, 1), (10, 9, 1)}
    e.set_rules(parse_rules("2 0 0 0 0 |1 $ 1 2"))
    e.step()  # life-form 1 has no rules any more: it sends nothing and dies
    assert e.population == 0


def test_a_cell_receiving_nothing_dies_though_a_zero_message_would_live() -> None:
    # a cell's message area is 0 whether it received +0 or nothing; only the first lives
    e = Engine(parse_rules("1 0 0 0 1 . +0 $ 0 1"))
    e.set(5, 5, 1)
    e.step()
    assert cellset(e) == {(6, 5, 1)}


def test_messages_any_distance_and_and_xor_ops() -> None:
    far = parse_rules("1 0 0 0 3000 " + ". " * 3000 + "|1 $ 1 1")
    e = Engine(far)
    e.set(100, 100, 1)
    e.step(2)
    assert cellset(e) == {(6100, 100, 1)}
    ops = parse_rules("1 0 0 0 0 |15 2 0 0 -1 -1 &6 3 0 0 -2 -2 ^5 $ 6 1 3 2 15 3 9 4")
    e = Engine(ops)
    e.set_cells([10, 11, 12], [0, 0, 0], [1, 2, 3])  # 15 & 6 ^ 5 in sender order = 3
    e.step()
    assert cellset(e) == {(10, 0, 2)}


def test_mixed_operations_apply_in_row_by_row_sender_order() -> None:
    # (0 + 1) | 2 = 3 when the adder is above; (0 | 2) + 1 = 3 too, but & is order-sensitive:
    r = parse_rules("1 0 1 0 0 . +5  2 1 0 0 0 &4 . $ 4 1 5 2 1 3")
    e = Engine(r)
    e.set_cells([0, 0], [10, 12], [1, 2])  # row 10 sends +5 to row 11, then row 12 sends &4
    e.step()
    assert cellset(e) == {(0, 11, 1)}  # (0 + 5) & 4 = 4 -> 1
    r2 = parse_rules("1 0 0 0 1 . +5  2 0 0 1 0 &4 . $ 4 1 5 2 1 3")
    e = Engine(r2)
    e.set_cells([10, 12], [0, 0], [1, 2])  # same row: left sender first, (0 + 5) & 4
    e.step()
    assert cellset(e) == {(11, 0, 1)}
    e = Engine(parse_rules("2 0 0 0 1 . &4  1 0 0 1 0 +5 . $ 4 1 5 2 1 3"))
    e.set_cells([10, 12], [0, 0], [2, 1])  # & first then +: (0 & 4) + 5 = 5
    e.step()
    assert cellset(e) == {(11, 0, 2)}


def test_broadcast_reaches_only_cells_with_local_messages() -> None:
    r = parse_rules("""
        1 0 0 0 0 |1          // an ordinary cell keeps itself alive
        2 0 0 0 0 BROADCAST |#X100 .   // a beacon: no local messages, only a broadcast
        $ 1 1  #X101 3
    """)
    e = Engine(r)
    e.set_cells([5, 500, 40000], [5, 600, 7], [1, 1, 2])
    e.step()
    assert cellset(e) == {(5, 5, 3), (500, 600, 3)}  # the beacon itself received nothing


def test_every_beacons_broadcast_arrives() -> None:
    # two beacons broadcasting +#X100: a receiving cell's message is 1 + 2 x #X100
    r = parse_rules("""
        1 0 0 0 0 +1
        2 0 0 0 0 BROADCAST +#X100 .
        $ 1 1  #X101 2  #X201 3
    """)
    e = Engine(r)
    e.set_cells([5, 900, 40000], [5, 7, 7], [1, 2, 2])
    e.step()
    assert cellset(e) == {(5, 5, 3)}


def test_probabilistic_outcomes_reproducible_from_seed_position_generation() -> None:
    r = parse_rules("1 0 0 0 0 |1 $ 1 50% 1 30% 2 20% 0")
    xs, ys = np.meshgrid(np.arange(100), np.arange(100))

    def run(seed: int) -> Engine:
        e = Engine(r, seed=seed)
        e.set_cells(xs.ravel(), ys.ravel(), 1)
        e.step()
        return e

    a, b, c = run(7), run(7), run(8)
    assert a.same_state(b) and not a.same_state(c)
    counts = a.by_type()
    assert abs(counts[1] - 5000) < 300 and abs(counts[2] - 3000) < 300
    assert abs(a.population - 8000) < 300
    # the generation is in the number too: one cell's choices differ from one to the next
    e = Engine(parse_rules("1 0 0 0 0 |1 $ 1 50% 1 50% 2  2 1"), seed=7)
    e.set(3, 3, 1)
    seen = []
    for _ in range(64):
        e.step()
        seen.append(e.get(3, 3))
        e.set(3, 3, 1)
    assert 16 < seen.count(2) < 48


def test_advance_area_freezes_outside_and_hides_it_from_inside() -> None:
    e = life(BLINKER + "\n\n\n" + BLINKER, 10, 10)
    e.set(11, 9, 1)  # outside cell next to the top blinker, but outside the area
    e.set_advance_area(Rect(10, 13, 12, 15))  # only the lower blinker advances
    before = cellset(e)
    e.step()
    after = cellset(e)
    upper = {c for c in before if c[1] <= 11}
    assert upper == {c for c in after if c[1] <= 11}  # frozen, nothing born outside
    lower = {c for c in after if c[1] >= 12}
    # The lower blinker turned vertical but its top cell (row 12) is outside the area.
    assert lower == {(11, 13, 1), (11, 14, 1)}


def test_edit_query_rectangle_density_and_statistics() -> None:
    e = Engine(LIFE)
    e.set_cells([10, 11, 12, 4000], [20, 20, 21, 5], [1, 2, 1, 3])
    assert e.get(11, 20) == 2 and e.get(13, 20) == 0
    e.set(11, 20, 0)
    assert e.get(11, 20) == 0
    xs, ys, ts = e.cells_in_rect(Rect(0, 0, 100, 100))
    assert sorted(zip(xs.tolist(), ys.tolist())) == [(10, 20), (12, 21)]
    d = e.density(0, 0, 16, 4, 4)
    assert d[1, 0] == 2 and d.sum() == 2
    stats = e.stats()
    assert stats == {"generation": 0, "population": 3, "by_type": {"1": 2, "3": 1},
                     "bbox": [10, 5, 4000, 21]}
    e.clear(Rect(0, 0, 100, 100))
    assert e.population == 1
    with pytest.raises(ValueError):
        e.set(65536, 0, 1)


def test_deterministic_random_soup_same_twice() -> None:
    rng = np.random.default_rng(3)
    ys, xs = np.nonzero(rng.random((128, 128)) < 0.4)

    def run() -> Engine:
        e = Engine(LIFE)
        e.set_cells(xs + 30000, ys + 30000, 1)
        e.step(60)
        return e

    assert run().same_state(run())


def test_matches_a_plain_numpy_life() -> None:
    rng = np.random.default_rng(5)
    grid = (rng.random((64, 64)) < 0.35).astype(np.uint8)
    e = Engine(LIFE, edges="bounded")
    ys, xs = np.nonzero(grid)
    e.set_cells(xs + 200, ys + 200, 1)
    big = np.zeros((64 + 80, 64 + 80), np.uint8)
    big[40:104, 40:104] = grid
    for _ in range(30):
        n = sum(np.roll(np.roll(big, dy, 0), dx, 1)
                for dy in (-1, 0, 1) for dx in (-1, 0, 1) if (dy, dx) != (0, 0))
        big = ((n == 3) | ((big == 1) & (n == 2))).astype(np.uint8)
    e.step(30)
    ys2, xs2 = np.nonzero(big)
    assert cellset(e) == {(int(x) + 160, int(y) + 160, 1) for x, y in zip(xs2, ys2)}


def test_advance_area_inside_evolves_as_if_outside_did_not_exist() -> None:
    rng = np.random.default_rng(11)
    ys, xs = np.nonzero(rng.random((40, 40)) < 0.4)
    area = Rect(110, 110, 129, 129)
    full = Engine(LIFE)
    full.set_cells(xs + 100, ys + 100, 1)
    alone = Engine(LIFE)
    inside = (xs + 100 >= 110) & (xs + 100 <= 129) & (ys + 100 >= 110) & (ys + 100 <= 129)
    alone.set_cells(xs[inside] + 100, ys[inside] + 100, 1)
    outside_before = cellset(full) - cellset(alone)
    for e in (full, alone):
        e.set_advance_area(area)
        e.step(7)
    assert cellset(full) - outside_before == cellset(alone)
    assert outside_before <= cellset(full)


@pytest.mark.parametrize("rules_name", ["life", "overgrazing", "maze"])
def test_dense_fast_path_equals_general_kernels(rules_name: str, monkeypatch) -> None:
    from camlab88.apps.ca.library import rules_path
    from camlab88.apps.ca.rules import load_rules
    from camlab88.apps.ca.tables import compile_rules

    rules = load_rules(rules_path(rules_name))
    assert compile_rules(rules).dense is not None
    rng = np.random.default_rng(2)
    top = max(rules.forms)
    ys, xs = np.nonzero(rng.random((90, 90)) < 0.45)
    ts = rng.integers(1, top + 1, size=xs.size)

    def run() -> tuple[Engine, set]:
        e = Engine(rules)
        e.set_cells(xs + 5000, ys + 5000, ts)
        return e, kernels_used(e, 40)

    fast, used = run()
    assert "dense" in used
    monkeypatch.setattr(engine_mod, "DENSE_MIN_FILL", 0)  # never dense
    slow, used_slow = run()
    assert "dense" not in used_slow
    assert fast.same_state(slow)


def test_dense_plan_refuses_order_sensitive_rules() -> None:
    from camlab88.apps.ca.tables import compile_rules

    assert compile_rules(parse_rules("1 1 1 1 1 +1 +1 +1 +1 |4 +1 +1 +1 +1 $ 3 1")).dense is None
    assert compile_rules(parse_rules("1 0 0 0 0 &1 $ 0 1")).dense is None
    assert compile_rules(parse_rules("1 0 0 0 0 |1 $ 1 50% 1 50% 0")).dense is None
    assert compile_rules(parse_rules("1 0 0 0 0 |1 $ 0 1")).dense is None


def test_sixty_lifeforms_run() -> None:
    # Life-form n keeps itself alive as n + 1 (60 wraps to 1): each form has its own rules.
    body = "".join(f"{n} 0 0 0 0 |{n}\n" for n in range(1, 61))
    interp = "".join(f"{n} {n % 60 + 1}\n" for n in range(1, 61))
    e = Engine(parse_rules(body + "$\n" + interp))
    e.set_cells(list(range(60)), [7] * 60, list(range(1, 61)))
    e.step(3)
    assert [int(t) for t in e.ts] == [(n + 3) % 60 + 1 for n in range(60)]
