"""The separable dense kernel (box sums, bit-set interpretation) gives exactly the results of
the plain dense kernel and of the hash kernel, on random commuting rule sets and grids."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca import engine as engine_mod
from camlab88.apps.ca import tables as tables_mod
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.rules import parse_rules
from camlab88.apps.ca.tables import compile_rules
from tests.ca.helpers import engine_constants, interpretation_lines, kernels_used


@st.composite
def commuting_rules(draw) -> str:
    """Dense, mostly additive neighbourhoods with few distinct values (so groups form), some
    ORs / XORs on high bits, and interpretations hitting small values."""
    forms = draw(st.integers(1, 3))
    high = draw(st.sampled_from(["|", "^"]))
    text = []
    for n in range(1, forms + 1):
        r = draw(st.integers(1, 2))
        value = draw(st.integers(1, 3))
        entries = []
        for _ in range((2 * r + 1) ** 2):
            kind = draw(st.sampled_from(["add", "add", "add", "other", "none", "bit"]))
            if kind == "add":
                entries.append(f"+{value}")
            elif kind == "other":
                entries.append(f"+{draw(st.integers(1, 4))}")
            elif kind == "bit":
                entries.append(f"{high}{draw(st.sampled_from([128, 256, 512]))}")
            else:
                entries.append(".")
        text.append(f"{n} {r} {r} {r} {r} {' '.join(entries)}")
    text.append("$")
    text += draw(interpretation_lines(forms, low=1, top=40, width=20, bits=6, prefix="#B1"))
    return "\n".join(text)


def _run(rules_text: str, cells: np.ndarray, types: np.ndarray, edges: str, **consts):
    with engine_constants(**consts):
        e = Engine(parse_rules(rules_text), edges=edges)
        ys, xs = cells
        e.set_cells(xs + 40, ys + 40, types)
        return e, kernels_used(e, 5)


@settings(max_examples=30, deadline=None)
@given(commuting_rules(), st.integers(0, 2**32 - 1), st.floats(0.2, 0.8),
       st.sampled_from([0, 2]), st.sampled_from(["wrap", "bounded"]))
def test_separable_equals_plain_and_hash(text: str, seed: int, density: float, factor: int,
                                         edges: str) -> None:
    saved = tables_mod.GROUP_COST_FACTOR
    tables_mod.GROUP_COST_FACTOR = factor  # 0: box sums wherever possible
    try:
        _check(text, seed, density, edges)
    finally:
        tables_mod.GROUP_COST_FACTOR = saved


def _check(text: str, seed: int, density: float, edges: str) -> None:
    plan = compile_rules(parse_rules(text)).dense
    rng = np.random.default_rng(seed)
    grid = rng.random((30, 34)) < density
    cells = np.nonzero(grid)
    if cells[0].size == 0:
        return
    types = rng.integers(1, max(parse_rules(text).forms) + 1, size=cells[0].size)
    dense_always = {"DENSE_MIN_FILL": 1 << 20}
    sep, used = _run(text, cells, types, edges, **dense_always)
    plain, _ = _run(text, cells, types, edges, DENSE_SEPARABLE=False, **dense_always)
    hashed, _ = _run(text, cells, types, edges, DENSE_MIN_FILL=0, WINDOW_MIN=0,
                     WINDOW_CELLS_PER_SENDER=0)
    assert sep.same_state(plain)
    assert sep.same_state(hashed)
    if plan is not None and sep.population:
        assert "dense" in used


def test_groups_and_bit_sets_are_planned() -> None:
    """Without the cost factor a full neighbourhood of equal additions becomes one box sum
    less the missing cells; small values are interpreted by bit sets."""
    saved = tables_mod.GROUP_COST_FACTOR
    tables_mod.GROUP_COST_FACTOR = 0
    try:
        rules = parse_rules("1 1 1 1 1 +1 +1 +1 +1 |16 +1 +1 +1 +1 $ #X12 1 #B?0011 1")
        sep = compile_rules(rules).dense.sep
    finally:
        tables_mod.GROUP_COST_FACTOR = saved
    assert list(sep.gtype) == [1] and (sep.gy0[0], sep.gy1[0], sep.gx0[0], sep.gx1[0]) == (
        -1, 1, -1, 1)
    assert list(zip(sep.xdy, sep.xdx)) == [(0, 0)]  # the centre is not an addition
    assert list(sep.eop) == [2]  # the OR stays an ordinary pass
    assert sep.interp == 1 and list(sep.mforms) == [1]
    assert int(sep.masks32[0]) == (1 << 0x12) | (1 << 3) | (1 << 0x13)
    big = compile_rules(parse_rules("1 2 2 2 2 " + " ".join(["+1"] * 25) + " $ 3 1"))
    assert big.dense.sep.gtype.size == 1  # 25 offsets: a box sum even with the factor


def test_separable_life_soup_matches_plain_kernel(monkeypatch) -> None:
    """A soup that spreads: the dense window grows in place and stays exact."""
    from camlab88.apps.ca.library import rules_path
    from camlab88.apps.ca.rules import load_rules

    grown = []
    real_grow = Engine._grow_dense

    def counting_grow(self, my, mx):
        ok = real_grow(self, my, mx)
        grown.append(ok)
        return ok

    monkeypatch.setattr(Engine, "_grow_dense", counting_grow)
    rules = load_rules(rules_path("life"))
    rng = np.random.default_rng(7)
    ys, xs = np.nonzero(rng.random((120, 120)) < 0.5)
    engines = []
    for flag in (True, False):
        with engine_constants(DENSE_SEPARABLE=flag):
            e = Engine(rules)
            e.set_cells(xs + 3000, ys + 3000, 1)
            e.step(60)
        assert e.last_kernel == "dense"
        engines.append(e)
    assert engines[0].same_state(engines[1])
    assert any(grown)
    slow = Engine(rules)
    slow.set_cells(xs + 3000, ys + 3000, 1)
    monkeypatch.setattr(engine_mod, "DENSE_MIN_FILL", 0)  # never dense
    slow.step(60)
    assert slow.last_kernel != "dense" and slow.same_state(engines[0])
