"""The logic-circuit rules (section 7.4.3, reconstructed): gates, turns, crossings, eaters
and the 4-bit adder adding streams of pairs of 4-bit numbers into 5-bit results."""

from __future__ import annotations

import random

import pytest

from camlab88.apps.ca import circuits as C
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules

RULES = load_rules(rules_path("circuits"))
F = C.FORMS
INV = {n: k for k, n in F.numbers.items()}


def _engine(cells: list[tuple[int, int, tuple]]) -> Engine:
    e = Engine(RULES)
    for x, y, key in cells:
        e.set(x, y, F[key])
    return e


def _state(e: Engine) -> set:
    return {(int(x), int(y), INV[int(t)]) for x, y, t in zip(e.xs, e.ys, e.ts)}


@pytest.mark.parametrize("gate", C.GATES)
def test_gate_truth_tables_with_two_three_and_one_inputs(gate: str) -> None:
    for inputs in ((0, 0), (0, 1), (1, 0), (1, 1), (1, 1, 1), (1, 0, 1), (0,), (1,)):
        cells = [(50, 50, ("G", gate)), (53, 50, ("M", "E")), (80, 50, ("E",)),
                 (65, 49, ("E",)), (65, 51, ("E",))]
        rows = [49, 51]
        for v, y in zip(inputs, rows):
            cells.append((47, y, ("P", v, "E")))
        if len(inputs) == 3:  # head-on third input, one column behind (absorbed by the gate)
            cells.append((46, 50, ("P", inputs[2], "E")))
        e = _engine(cells)
        e.step(6)
        want = int(C._gate_fn(gate, len(inputs), sum(inputs)))
        assert (54, 50, ("P", want, "E")) in _state(e), (gate, inputs)
        e.step(30)
        assert {k[0] for _, _, k in _state(e)} <= {"G", "M", "E"}  # all values absorbed


def test_turns_crossing_and_eater() -> None:
    e = _engine([(10, 10, ("P", 1, "E")), (15, 10, ("M", "S")), (15, 14, ("X", None, None)),
                 (13, 14, ("P", 0, "E")), (15, 20, ("M", "W")), (5, 20, ("E",))])
    e.step(5)
    assert (15, 10, ("MH", "S", 1)) in _state(e)  # the 1 is turning south
    e.step(1)
    assert (15, 11, ("P", 1, "S")) in _state(e)
    e.step(4)  # the 0 crossed first; now the 1 passes the crossing heading south
    st = _state(e)
    assert (23, 14, ("P", 0, "E")) in st and (15, 15, ("P", 1, "S")) in st
    e.step(6)
    assert (14, 20, ("P", 1, "W")) in _state(e)  # turned west
    e.step(10)
    assert not any(k[0] == "P" and k[2] == "W" for _, _, k in _state(e))  # eaten


def test_crossing_passes_both_streams_at_once() -> None:
    e = _engine([(10, 7, ("P", 1, "S")), (7, 10, ("P", 0, "E")), (10, 10, ("X", None, None))])
    e.step(3)
    assert (10, 10, ("X", (0, "E"), (1, "S"))) in _state(e)
    e.step(2)
    st = _state(e)
    assert (12, 10, ("P", 0, "E")) in st and (10, 12, ("P", 1, "S")) in st
    # Without the crossing the two values meet in one cell and annihilate.
    e = _engine([(10, 7, ("P", 1, "S")), (7, 10, ("P", 0, "E"))])
    e.step(5)
    assert e.population == 0


def _sums(seen: dict[str, list[int]], n: int) -> list[int]:
    assert all(len(v) == n for v in seen.values()), seen
    return [sum(seen[k][j] << i for i, k in enumerate(["s0", "s1", "s2", "s3", "c4"]))
            for j in range(n)]


def _gate_with(gate: str, extra: list) -> Engine:
    return _engine([(50, 50, ("G", gate)), (53, 50, ("M", "E")), (80, 50, ("E",)),
                    (65, 49, ("E",)), (65, 51, ("E",)), *extra])


@pytest.mark.parametrize("level", [0, 1])
def test_static_value_alone_holds_its_level_and_never_fires_a_gate(level: int) -> None:
    e = _gate_with("NAND", [(50, 51, ("S", level))])
    before = _state(e)
    e.step(20)
    assert _state(e) == before  # nothing emitted; the static value is still there


@pytest.mark.parametrize("v", [0, 1])
def test_nand_with_a_static_one_is_a_not_gate(v: int) -> None:
    e = _gate_with("NAND", [(50, 51, ("S", 1)), (47, 49, ("P", v, "E"))])
    e.step(6)
    assert (54, 50, ("P", 1 - v, "E")) in _state(e)
    assert (50, 51, ("S", 1)) in _state(e)
    e = _gate_with("AND", [(50, 51, ("S", 0)), (47, 49, ("P", 1, "E"))])
    e.step(6)
    assert (54, 50, ("P", 0, "E")) in _state(e)  # 1 AND static 0


def test_a_moving_value_sets_a_static_value() -> None:
    e = _engine([(10, 10, ("S", 0)), (6, 10, ("P", 1, "E"))])
    e.step(4)
    assert _state(e) == {(10, 10, ("S", 1))}  # absorbed, and the level is now 1
    e.set(10, 7, F[("P", 0, "S")])
    e.step(3)
    assert _state(e) == {(10, 10, ("S", 0))}


@pytest.mark.claim("§7.4.3: logic values both static and moving; a 4-bit adder takes eight "
                   "streams of binary digits and adds them into a stream of 5-bit results",
                   measured="the adder's carry in is a static value; demo pairs and 40 "
                   "random pairs add correctly, with carry in 0 and 1", verdict="agrees "
                   "(the rules and the layout are reconstructed)")
def test_four_bit_adder_demo_sums() -> None:
    seen = C.run_adder(lambda: Engine(RULES), C.DEMO_PAIRS)
    assert _sums(seen, len(C.DEMO_PAIRS)) == [a + b for a, b in C.DEMO_PAIRS]


def test_four_bit_adder_with_a_static_carry_in_of_one() -> None:
    seen = C.run_adder(lambda: Engine(RULES), C.DEMO_PAIRS, carry_in=1)
    assert _sums(seen, len(C.DEMO_PAIRS)) == [a + b + 1 for a, b in C.DEMO_PAIRS]


def test_four_bit_adder_random_pairs() -> None:
    rng = random.Random(88)
    pairs = [(rng.randrange(16), rng.randrange(16)) for _ in range(40)]
    seen = C.run_adder(lambda: Engine(RULES), pairs)
    assert _sums(seen, len(pairs)) == [a + b for a, b in pairs]


def test_adder_demo_pattern_is_the_layout() -> None:
    p = read_pattern(pattern_path("adder_demo"))
    cells, _ = C.adder_layout(C.DEMO_PAIRS)
    assert len(p.cell_set()) == len(cells)
    kinds = {INV[t][0] for _, _, t in p.cell_set()}
    assert {"P", "S", "G", "M", "E", "X"} <= kinds  # moving and static values
