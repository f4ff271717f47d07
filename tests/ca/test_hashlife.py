"""HashLife equals the direct engine cell for cell (issue 17), on both edge modes."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca import log
from camlab88.apps.ca.algorithms import AUTO_MIN_GENERATIONS, choose_engine
from camlab88.apps.ca.engine import SIDE, Engine, Rect
from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.rules import load_rules, parse_rules

LIBRARY = {name: load_rules(rules_path(name))
           for name in ("life", "maze", "turing_primes", "circuits", "overgrazing")}
# Where soups are put: inside the plane, and across its corner (the seam / the edge).
PLACES = [(30000, 30000), (SIDE - 12, SIDE - 9)]


def soup(rules, seed: int, x0: int, y0: int, n: int = 260, side: int = 28,
         edges: str = "wrap") -> Engine:
    rng = np.random.default_rng(seed)
    forms = sorted(rules.forms)
    e = Engine(rules, edges=edges)
    xs, ys = rng.integers(0, side, n) + x0, rng.integers(0, side, n) + y0
    if edges == "wrap":  # across the seam
        xs, ys = xs % SIDE, ys % SIDE
    else:  # a bounded plane has no seam: up to its edge
        xs, ys = np.minimum(xs, SIDE - 1), np.minimum(ys, SIDE - 1)
    e.set_cells(xs, ys, rng.choice(forms, n))
    return e


def both(e: Engine, generations: list[int]) -> None:
    """Step a copy of ``e`` directly and another by HashLife; compare after each count."""
    direct = e.copy()
    jumps = e.copy()
    jumps.algorithm = "hashlife"
    for n in generations:
        direct.step(n)
        jumps.step(n)
        assert jumps.generation == direct.generation
        assert jumps.same_state(direct), f"differ after {direct.generation} generations"


@pytest.mark.parametrize("name", sorted(LIBRARY))
@pytest.mark.parametrize("edges", ["wrap", "bounded"])
@pytest.mark.parametrize("place", PLACES)
def test_library_rules_match_the_direct_engine(name: str, edges: str, place) -> None:
    # 1, 2, 3, 8, 13, 32 and 37: powers of two and not, adding up to 96 generations.
    both(soup(LIBRARY[name], 7, *place, edges=edges), [1, 2, 3, 8, 13, 32, 37])


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(sorted(LIBRARY)), st.integers(0, 2**32 - 1),
       st.sampled_from(["wrap", "bounded"]), st.sampled_from(PLACES),
       st.lists(st.integers(1, 70), min_size=1, max_size=3))
def test_random_soups_match(name: str, seed: int, edges: str, place, counts) -> None:
    both(soup(LIBRARY[name], seed, *place, n=120, side=20, edges=edges), counts)


@st.composite
def deterministic_rules(draw) -> str:
    """Random rule sets of up to three life-forms, reach 0..3, every operation mixed."""
    forms = draw(st.integers(1, 3))
    text = []
    for n in range(1, forms + 1):
        r = draw(st.integers(0, 3))
        entries = []
        for _ in range((2 * r + 1) ** 2):
            op = draw(st.sampled_from([".", ".", "+", "|", "&", "^"]))
            entries.append(op if op == "." else f"{op}{draw(st.integers(1, 60))}")
        text.append(f"{n} {r} {r} {r} {r} {' '.join(entries)}")
    text.append("$")
    for _ in range(draw(st.integers(1, 8))):
        form = draw(st.integers(0, forms))
        kind = draw(st.sampled_from(["exact", "range", "pattern"]))
        if kind == "exact":
            text.append(f"{draw(st.integers(0, 80))} {form}")
        elif kind == "range":
            lo = draw(st.integers(0, 80))
            text.append(f"R {lo} {lo + draw(st.integers(0, 60))} {form}")
        else:
            bits = "".join(draw(st.lists(st.sampled_from("01?"), min_size=1, max_size=8)))
            text.append(f"#B{bits} {form}")
    return "\n".join(text)


@settings(max_examples=30, deadline=None)
@given(deterministic_rules(), st.integers(0, 2**32 - 1), st.sampled_from(["wrap", "bounded"]),
       st.sampled_from(PLACES), st.integers(1, 40))
def test_random_rule_sets_match(text: str, seed: int, edges: str, place, count: int) -> None:
    both(soup(parse_rules(text), seed, *place, n=80, side=16, edges=edges), [count])


def test_a_glider_crosses_the_seam_and_stops_at_the_bounded_edge() -> None:
    glider = ([1, 2, 0, 1, 2], [0, 1, 2, 2, 2])  # heading right and down
    for edges in ("wrap", "bounded"):
        e = Engine(LIBRARY["life"], edges=edges)
        e.set_cells(np.array(glider[0]) + SIDE - 40, np.array(glider[1]) + SIDE - 40, 1)
        both(e, [100, 1000])


def test_checkpoint_after_a_jump_equals_one_after_stepping(tmp_path) -> None:
    e = soup(LIBRARY["maze"], 3, *PLACES[1])
    stepped, jumped = e.copy(), e.copy()
    jumped.algorithm = "hashlife"
    stepped.step(300)
    jumped.step(300)
    assert log.format_checkpoint(jumped) == log.format_checkpoint(stepped)
    back = log.parse_checkpoint(log.format_checkpoint(jumped))
    assert back.same_state(stepped)


@pytest.mark.parametrize("name", ["life", "maze"])  # bit leaves; value leaves
def test_jumps_interleave_with_edits_and_direct_steps(name: str) -> None:
    e = soup(LIBRARY[name], 11, *PLACES[0])
    ref = e.copy()
    e.algorithm = "hashlife"
    for n in (5, 64, 300):
        e.step(n)
        ref.step_direct(n)
        e.set(30010, 30010, 1)
        ref.set(30010, 30010, 1)
        e.step_direct(3)
        ref.step_direct(3)
    assert e.same_state(ref)


def test_auto_choice_and_forcing() -> None:
    life = LIBRARY["life"]
    assert choose_engine(life, AUTO_MIN_GENERATIONS) == "hashlife"
    assert choose_engine(life, AUTO_MIN_GENERATIONS - 1) == "direct"
    assert choose_engine(life, 10**6, engine="direct") == "direct"
    random_rules = parse_rules("1 1 1 1 1 +1 +1 +1 +1 . +1 +1 +1 +1 $ 3 50% 1 50% 0 2 1")
    assert choose_engine(random_rules, 10**6) == "direct"
    with pytest.raises(ValueError, match="probabilistic outcomes"):
        choose_engine(random_rules, 10, engine="hashlife")
    area = Rect(0, 0, 99, 99)
    assert choose_engine(life, 10**6, advance_area=area) == "direct"
    e = Engine(life, algorithm="hashlife")
    e.set_advance_area(area)
    with pytest.raises(ValueError, match="advance area"):
        e.step(5)
    with pytest.raises(ValueError, match="engine must be one of"):
        choose_engine(life, 5, engine="quick")


def test_broadcast_rules_keep_the_direct_engine() -> None:
    rules = parse_rules("1 0 0 0 0 BROADCAST |#X100 +1 $ #X101 1")
    assert choose_engine(rules, 10**6) == "direct"
    with pytest.raises(ValueError, match="broadcast"):
        choose_engine(rules, 1, engine="hashlife")


def test_progress_is_reported_per_jump() -> None:
    # the generic path (the maze runner's reach is 2); Life's binary path jumps any length
    # at once (test_hashlife_bits.py)
    e = soup(LIBRARY["maze"], 5, *PLACES[0])
    e.algorithm = "hashlife"
    seen: list[tuple[int, int]] = []
    e.step(100, progress=lambda done, total: seen.append((done, total)))
    assert seen == [(64, 100), (96, 100), (100, 100)]  # 100 = 64 + 32 + 4
    assert e.generation == 100


def test_a_small_memory_limit_collects_garbage_and_stays_exact() -> None:
    rules = parse_rules(LIBRARY["life"].text, source="life-small-memory")  # its own table
    e = soup(rules, 9, *PLACES[0], n=3000, side=100)
    ref = e.copy()
    e.algorithm = "hashlife"
    e.hashlife_memory = 1 << 20  # Life takes the binary path: 8192 nodes, 4096 leaves
    e.step(1000)
    ref.step(1000)
    assert e.same_state(ref)
    store = rules._tables["hashlife_bits_run"].store
    assert store.epoch > 0  # it did collect
    assert store.bytes <= 1 << 20


def test_memory_limit_too_small_is_a_clear_error() -> None:
    rules = parse_rules(LIBRARY["life"].text, source="life-tiny-memory")
    e = soup(rules, 9, *PLACES[0], n=2000, side=80)
    e.algorithm = "hashlife"
    e.hashlife_memory = 200 << 10  # below the smallest tables of either path
    with pytest.raises(MemoryError, match="memory limit"):
        e.step(64)


def test_cells_are_read_from_the_tree_only_when_looked_at() -> None:
    e = soup(LIBRARY["life"], 1, *PLACES[0])
    e.algorithm = "hashlife"
    e.step(64)
    tree = e.tree
    e.step(64)  # the second jump starts from the kept tree
    assert e.tree is not tree and e.tree is not None
    copy = e.copy()
    assert copy.tree is e.tree and copy.same_state(e)
    copy.set(0, 0, 1)
    assert copy.tree is None and e.tree is not None


def test_a_direct_run_does_not_load_hashlife() -> None:
    """HashLife's modules (80-odd kernels to set up, ~0.06 s of start-up) load on its
    first use only; an auto run long enough for it still gets it."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    code = ("import sys; from camlab88.cli import main; "
            "main(['ca', 'run', '--rules', 'life', '--pattern', 'glider', '--generations', "
            "'8', '--engine', 'direct']); print('camlab88.apps.ca.hashlife' in sys.modules); "
            "main(['ca', 'run', '--rules', 'life', '--pattern', 'glider', '--generations', "
            "'4096']); print('camlab88.apps.ca.hashlife.algorithm' in sys.modules)")
    env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])}
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            timeout=120, env=env)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("generation 8  population 5") and lines[1] == "False"
    assert lines[2].startswith("generation 4096  population 5") and lines[3] == "True"
