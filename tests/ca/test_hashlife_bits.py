"""HashLife's binary path (apps/ca/hashlife/bits, issue 17): two-state rules on a plane of 1s
give exactly the direct engine's answers on both edge modes; everything else keeps the
generic path and its answers."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca import log
from camlab88.apps.ca.engine import SIDE, Engine
from camlab88.apps.ca.hashlife.algorithm import HashLife
from camlab88.apps.ca.hashlife.bits.rule import binary_rule, derive_table, totalistic_terms
from camlab88.apps.ca.hashlife.bits.run import BitRun
from camlab88.apps.ca.hashlife.generic import GenericRun
from camlab88.apps.ca.hashlife.tree import Tree
from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.rules import load_rules, parse_rules

LIFE = load_rules(rules_path("life"))
# Not outer-totalistic: orthogonal neighbours add 1, diagonal ones 16, the cell itself ORs
# 256 in; a dead cell is born with two orthogonal and one diagonal neighbour or one and
# two, a live one survives with 1 + 1, 2 + 0 or 0 + 2 (a rule invented for this test).
SKEW_TEXT = """
1 1 1 1 1
+16 +1 +16
+1 |#X100 +1
+16 +1 +16
$
#X12 1
#X21 1
#X111 1
#X102 1
#X120 1
"""
SKEW = parse_rules(SKEW_TEXT, source="skew")
# Day & Night (B3678/S34678): outer-totalistic with seven block-sum terms, so the base case
# runs its pairs of terms after the first (Life has two: one pair).
DAY_AND_NIGHT = parse_rules("""
1 1 1 1 1
+1 +1 +1
+1 |#X10 +1
+1 +1 +1
$
#X3 1
#X6 1
#X7 1
#X8 1
#X13 1
#X14 1
#X16 1
#X17 1
#X18 1
""", source="day_and_night")
BINARY = {"life": LIFE, "skew": SKEW, "day_and_night": DAY_AND_NIGHT}
GENERIC = {name: load_rules(rules_path(name)) for name in ("maze", "turing_primes", "circuits")}
PLACES = [(30000, 30000), (SIDE - 12, SIDE - 9)]  # inside; across the corner (seam / edge)


def soup(rules, seed: int, x0: int, y0: int, n: int = 260, side: int = 28,
         edges: str = "wrap", forms: list[int] | None = None) -> Engine:
    rng = np.random.default_rng(seed)
    e = Engine(rules, edges=edges)
    xs, ys = rng.integers(0, side, n) + x0, rng.integers(0, side, n) + y0
    if edges == "wrap":
        xs, ys = xs % SIDE, ys % SIDE
    else:
        xs, ys = np.minimum(xs, SIDE - 1), np.minimum(ys, SIDE - 1)
    e.set_cells(xs, ys, rng.choice(forms or [1], n))
    return e


def both(e: Engine, counts: list[int], binary: bool) -> Engine:
    """Step a copy of ``e`` directly and another by HashLife; compare after each count and
    check which path the jumps took."""
    direct, jumps = e.copy(), e.copy()
    jumps.algorithm = "hashlife"
    for n in counts:
        direct.step(n)
        jumps.step(n)
        assert isinstance(jumps.tree.run, BitRun) == binary
        assert jumps.generation == direct.generation
        assert jumps.population == direct.population
        assert jumps.bbox() == direct.bbox()
        assert jumps.same_state(direct), f"differ after {direct.generation} generations"
    return jumps


def table_by_direct_engine(rules) -> np.ndarray:
    """The 512 outcomes by the direct engine: every 3 x 3 block at once, 5 cells apart."""
    e = Engine(rules, edges="bounded")
    xs, ys = [], []
    for index in range(512):
        bx, by = 100 + 5 * (index % 32), 100 + 5 * (index // 32)
        for bit in range(9):
            if index >> bit & 1:
                xs.append(bx + bit % 3)
                ys.append(by + bit // 3)
    e.set_cells(xs, ys, 1)
    e.step_direct(1)
    return np.array([e.get(101 + 5 * (i % 32), 101 + 5 * (i // 32)) for i in range(512)])


def test_the_table_is_found_by_running_the_rules() -> None:
    for rules in BINARY.values():
        assert np.array_equal(derive_table(rules), table_by_direct_engine(rules))
    life = binary_rule(LIFE)
    index = np.arange(512)
    alive = (index >> 4) & 1
    count = np.array([bin(i & ~16).count("1") for i in index])
    assert np.array_equal(life.table, (count == 3) | ((count == 2) & (alive == 1)))
    assert life.totalistic and totalistic_terms(life.table) is not None
    skew = binary_rule(SKEW)
    assert not skew.totalistic and totalistic_terms(skew.table) is None
    assert len(totalistic_terms(binary_rule(DAY_AND_NIGHT).table)) == 7


def test_rules_that_do_not_qualify_say_why() -> None:
    assert "reach" in binary_rule(GENERIC["maze"])
    for rules in GENERIC.values():
        assert isinstance(binary_rule(rules), str)
    three = parse_rules("1 1 1 1 1 +1 +1 +1 +1 . +1 +1 +1 +1 $ 3 2 2 1", source="three")
    assert "another life-form" in binary_rule(three)  # 0s and 1s can become 2s


@pytest.mark.parametrize("name", sorted(BINARY))
@pytest.mark.parametrize("edges", ["wrap", "bounded"])
@pytest.mark.parametrize("place", PLACES)
def test_binary_rules_match_the_direct_engine(name: str, edges: str, place) -> None:
    # powers of two and not, past one base case (8) and one level (16, 32), 199 in all
    both(soup(BINARY[name], 7, *place, edges=edges), [1, 2, 3, 8, 13, 32, 37, 103], True)


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(sorted(BINARY)), st.integers(0, 2**32 - 1),
       st.sampled_from(["wrap", "bounded"]), st.sampled_from(PLACES),
       st.lists(st.integers(1, 300), min_size=1, max_size=3))
def test_random_soups_match(name: str, seed: int, edges: str, place, counts) -> None:
    both(soup(BINARY[name], seed, *place, n=150, side=24, edges=edges), counts, True)


@pytest.mark.parametrize("name", sorted(GENERIC))
def test_rules_that_fail_the_qualification_keep_the_generic_path(name: str) -> None:
    rules = GENERIC[name]  # (inside the plane: at the seam the circuits step directly)
    e = soup(rules, 3, *PLACES[0], forms=sorted(rules.forms))
    assert HashLife.binary(e) is None
    jumps = both(e, [5, 40], False)
    assert isinstance(jumps.tree, Tree) and isinstance(jumps.tree.run, GenericRun)


def test_a_plane_holding_other_life_forms_takes_the_generic_path() -> None:
    e = soup(LIFE, 4, *PLACES[0])
    e.set(30005, 30005, 2)  # Life has no rules for 2: it dies next generation
    assert HashLife.binary(e) is None
    jumps = both(e, [1], False)
    assert HashLife.binary(jumps) is not None  # the 2 died: from now on the binary path
    both(jumps, [50], True)


def test_a_small_memory_limit_collects_and_stays_exact() -> None:
    for edges in ("wrap", "bounded"):
        rules = parse_rules(LIFE.text, source=f"life-bits-small-{edges}")  # its own tables
        e = soup(rules, 9, *PLACES[0], n=3000, side=100, edges=edges)
        e.hashlife_memory = 512 << 10  # the smallest tables: 4096 nodes, 2048 leaves
        seen: list[int] = []
        jumps = e.copy()
        jumps.algorithm = "hashlife"
        jumps.step(1000, progress=lambda done, total, seen=seen: seen.append(done))
        e.step_direct(1000)
        assert jumps.same_state(e) and seen == [1000]
        store = rules._tables["hashlife_bits_run"].store
        assert store.epoch > 0 and store.bytes <= 512 << 10


def test_long_runs_report_progress_per_jump_of_at_most_2_to_the_15() -> None:
    e = soup(LIFE, 5, *PLACES[0])
    e.algorithm = "hashlife"
    seen: list[tuple[int, int]] = []
    e.step(70000, progress=lambda done, total: seen.append((done, total)))
    assert seen == [(32768, 70000), (65536, 70000), (70000, 70000)]


def test_checkpoint_after_a_jump_equals_one_after_stepping() -> None:
    e = soup(LIFE, 3, *PLACES[1])
    stepped, jumped = e.copy(), e.copy()
    jumped.algorithm = "hashlife"
    stepped.step_direct(300)
    jumped.step(300)
    assert isinstance(jumped.tree.run, BitRun)
    assert log.format_checkpoint(jumped) == log.format_checkpoint(stepped)
    assert log.parse_checkpoint(log.format_checkpoint(jumped)).same_state(stepped)


def test_a_collection_for_one_engine_keeps_another_engines_tree() -> None:
    rules = parse_rules(LIFE.text, source="life-bits-two-engines")  # its own tables
    first, second = soup(rules, 21, *PLACES[0]), soup(rules, 22, 20000, 20000, n=3000,
                                                       side=100)
    ref = first.copy()
    for e in (first, second):
        e.algorithm = "hashlife"
        e.hashlife_memory = 512 << 10
    first.step(500)  # its state is now only a tree
    second.step(1000)  # collects garbage, renumbering the first engine's tree too
    assert rules._tables["hashlife_bits_run"].store.epoch > 0
    ref.step_direct(500)
    assert first.population == ref.population and first.same_state(ref)
    first.step(100)
    ref.step_direct(100)
    assert first.same_state(ref)
