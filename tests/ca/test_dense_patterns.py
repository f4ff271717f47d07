"""Dense patterns at memory speed: the compiled RLE reader, patterns kept as grids, and an
engine started from a grid (direct and HashLife) — the same results as the cell lists."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.patterns import ORIENTATIONS, GridPattern, Pattern, PatternError, parse_rle
from camlab88.apps.ca.rle_body import SMALL_BODY, decode, decode_body, decode_compiled
from camlab88.cli import main
from tests.ca.helpers import LIFE
from tests.support.processes import fresh_python


def _fail(offset: int, message: str) -> PatternError:
    return PatternError("<t>", 0, offset + 1, message)


def _cells(result):  # what decode_compiled returns, as a cell set
    cells, (left, top) = result
    if isinstance(cells, np.ndarray):
        ys, xs = np.nonzero(cells)
        return {(int(x) + left, int(y) + top, int(cells[y, x])) for y, x in zip(ys, xs)}
    xs, ys, ts = cells
    return {(int(x) + left, int(y) + top, int(t)) for x, y, t in zip(xs, ys, ts)}


def _outcome(decode, body):
    try:
        return decode(body)
    except PatternError as exc:
        return str(exc)


tokens = st.sampled_from(["b", "o", ".", "$", "!", "A", "X", "pA", "yO", "zA", "q", "0",
                          "12", "3", "999999", "1000000", " ", "\n", "\t", "?", "é",
                          "\x1c", "65536", "pB"])


@settings(max_examples=400, deadline=None)
@given(st.lists(tokens, max_size=30))
def test_the_compiled_reader_agrees_with_the_token_reader(parts: list[str]) -> None:
    """Same cells, or the same error at the same place, on any mix of tokens and faults."""
    body = "".join(parts)
    old = _outcome(lambda b: _cells(((decode_body(b, _fail)), (0, 0))), body)
    new = _outcome(lambda b: _cells(decode_compiled(b, _fail)), body)
    assert new == old


def test_a_dense_rle_becomes_a_grid_and_a_sparse_one_cells() -> None:
    block = parse_rle("x = 300, y = 200\n" + "300o$" * 199 + "300o!\n")
    assert isinstance(block, GridPattern) and block.grid.shape == (200, 300)
    assert int(block.grid.sum()) == 60000 and block.width == 300
    sparse = parse_rle("x = 300, y = 1\no298bo!\n")
    assert not isinstance(sparse, GridPattern) and sparse.cell_set() == {(0, 0, 1),
                                                                         (299, 0, 1)}


@pytest.mark.parametrize("orientation", list(ORIENTATIONS))
def test_a_grid_is_placed_where_its_cells_would_be(orientation: str) -> None:
    rng = np.random.default_rng(7)
    grid = (rng.random((5, 9)) < 0.6).astype(np.uint8) * rng.integers(1, 4, (5, 9),
                                                                      dtype=np.uint8)
    grid[0, 0] = grid[-1, -1] = 1  # live cells on every edge: the box is the grid
    p = GridPattern(grid, ref=(3, -2))
    left, top, g = p.placed_grid(1000, 2000, orientation)
    ys, xs = np.nonzero(g)
    placed = {(int(x) + left, int(y) + top, int(g[y, x])) for y, x in zip(ys, xs)}
    sparse = Pattern(p.xs, p.ys, p.ts, p.ref)
    assert placed == set(zip(*(a.tolist() for a in sparse.placed(1000, 2000, orientation))))


def test_a_grid_crossing_the_plane_edge_is_placed_as_cells() -> None:
    p = GridPattern(np.ones((4, 4), np.uint8))
    assert p.placed_grid(65534, 10) is None
    assert sorted(p.placed(65534, 10)[0].tolist())[-1] == 65535


def _soup(side: int, seed: int) -> np.ndarray:
    return (np.random.default_rng(seed).random((side, side)) < 0.45).astype(np.uint8)


@pytest.mark.parametrize("algorithm", ["direct", "hashlife"])
def test_an_engine_started_from_a_grid_steps_as_from_cells(algorithm: str) -> None:
    grid = _soup(150, 3)
    a = Engine(LIFE, algorithm=algorithm)
    a.set_grid(5000, 7000, grid)
    assert a.dense_window is not None and a.population == int(grid.sum())
    ys, xs = np.nonzero(grid)
    b = Engine(LIFE, algorithm="direct")
    b.set_cells(xs + 5000, ys + 7000, 1)
    assert a.stats() == b.stats()
    a.step(5)
    b.step(5)
    assert a.stats() == b.stats()
    assert a.same_state(b)


def test_stats_of_a_dense_window_are_read_from_the_grid() -> None:
    e = Engine(LIFE)
    e.set_grid(100, 200, np.array([[1, 0, 2], [0, 0, 0], [0, 3, 3]], np.uint8))
    assert e.by_type() == {1: 1, 2: 1, 3: 2}
    box = e.bbox()
    assert (box.x0, box.y0, box.x1, box.y1) == (100, 200, 102, 202)


def test_set_cells_on_an_empty_plane_in_row_order_keeps_them_all() -> None:
    e = Engine(LIFE)
    e.set_cells([5, 7, 2], [1, 1, 3], [1, 0, 2])  # row order, a 0 among them
    assert e.cells()[0].tolist() == [5, 2] and e.ts.tolist() == [1, 2]


@pytest.mark.parametrize("engine", ["direct", "hashlife"])
def test_ca_run_takes_a_dense_block(tmp_path: Path, capsys, engine: str) -> None:
    side = 600
    rle = tmp_path / "block.rle"
    rle.write_text(f"x = {side}, y = {side}\n" + f"{side}o$\n" * (side - 1) + f"{side}o!\n")
    assert main(["ca", "run", "--rules", "life", "--pattern", str(rle), "--generations", "3",
                 "--engine", engine, "--json"]) == 0
    out = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    e = Engine(LIFE)  # the same block as cells, stepped by the direct engine
    ys, xs = np.nonzero(np.ones((side, side), np.uint8))
    e.set_cells(xs + CENTRE, ys + CENTRE, 1)
    e.step(3)
    assert out["population"] == e.population
    assert out["bbox"] == e.stats()["bbox"]


def test_auto_keeps_a_dense_plane_on_the_direct_engine_for_longer() -> None:
    from camlab88.apps.ca.algorithms import (
        AUTO_MIN_GENERATIONS,
        AUTO_MIN_GENERATIONS_DENSE,
        choose_engine,
    )

    assert choose_engine(LIFE, AUTO_MIN_GENERATIONS, dense=True) == "direct"
    assert choose_engine(LIFE, AUTO_MIN_GENERATIONS_DENSE, dense=True) == "hashlife"
    assert choose_engine(LIFE, AUTO_MIN_GENERATIONS) == "hashlife"
    e = Engine(LIFE, algorithm="auto")
    e.set_grid(3000, 3000, _soup(64, 5))
    assert e.is_dense()
    e.step(AUTO_MIN_GENERATIONS)
    assert e.tree is None  # stepped directly: no HashLife tree was made
    sparse = Engine(LIFE, algorithm="auto")
    sparse.set_cells([100, 101, 102, 5000], [100, 100, 100, 5000], 1)
    assert not sparse.is_dense()


@settings(max_examples=300, deadline=None)
@given(st.lists(tokens, max_size=40))
def test_the_small_body_reader_agrees_with_the_compiled_reader(parts: list[str]) -> None:
    """A short body skips the compiled scanner: the same cells, or the same error."""
    body = "".join(parts)
    assert len(body) < SMALL_BODY
    assert _outcome(lambda b: _cells(decode(b, _fail)), body) == \
        _outcome(lambda b: _cells(decode_compiled(b, _fail)), body)


def test_a_short_rle_is_read_without_loading_the_compiled_scanner() -> None:
    code = ("import sys; from camlab88.apps.ca.patterns import read_pattern; "
            "from camlab88.apps.ca.library import pattern_path; "
            "p = read_pattern(pattern_path('gosper_gun')); print(len(p.cell_set()), "
            "'camlab88.apps.ca.rle_scan' in sys.modules)")
    assert fresh_python(code).split() == ["36", "False"]
