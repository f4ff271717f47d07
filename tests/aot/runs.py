"""Run in a child process by test_equal_results.py: every exported kernel of the listed
modules on real work (Life with the window, hash and dense kernels, a 16-bit-message rule on
both dense kernels, RLE bodies decoded to cells and to a grid, a grid's census). Prints one
JSON object: a digest of each case's result, which kernels ran, each module's mode, and
whether numba was imported."""

from __future__ import annotations

import hashlib
import importlib
import json
import sys

import numpy as np
from camlab88.apps.ca import engine as engine_mod
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import parse_pattern, read_pattern
from camlab88.apps.ca.rules import load_rules, parse_rules
from camlab88.apps.ca.tables import compile_rules

LIFE_U16 = """
1 1 1 1 1
+1 +1 +1
+1 |#X100 +1
+1 +1 +1
$
#X103 1
#X102 1
3 1
"""


def digest(*arrays: np.ndarray) -> str:
    h = hashlib.sha256()
    for a in arrays:
        h.update(np.ascontiguousarray(a, np.int64).tobytes())
    return h.hexdigest()[:16]


def soup_rle(side: int, seed: int, density: float) -> str:
    grid = np.random.default_rng(seed).random((side, side)) < density
    rows = ["".join("o" if c else "b" for c in row) for row in grid]
    return f"x = {side}, y = {side}, rule = B3/S23\n" + "$\n".join(rows) + "!\n"


def run(rules, cells, generations: int, **consts) -> tuple[str, list[str]]:
    saved = {k: getattr(engine_mod, k) for k in consts}
    for k, v in consts.items():
        setattr(engine_mod, k, v)
    try:
        e = Engine(rules)
        xs, ys, ts = cells
        e.set_cells(xs, ys, ts)
        used = []
        for _ in range(generations):
            e.step(1)
            used.append(e.last_kernel)
        return digest(e.ys, e.xs, e.ts) + f" pop {e.population}", sorted(set(used))
    finally:
        for k, v in saved.items():
            setattr(engine_mod, k, v)


def main() -> None:
    life = load_rules(rules_path("life"))
    u16 = parse_rules(LIFE_U16)
    acorn = read_pattern(pattern_path("acorn")).placed(32768, 32768)
    far = (np.array([100, 101, 100, 101, 100, 101, 100, 101]),
           np.array([100, 100, 101, 101, 20100, 20100, 20101, 20101]), 1)
    # bodies over 8192 bytes: the compiled scanner, decoding to a grid and to cells
    soup = parse_pattern(soup_rle(150, 1, 0.4), "rle")
    sparse = parse_pattern(soup_rle(300, 2, 0.03), "rle")
    soup_cells = (soup.xs + 1000, soup.ys + 1000, soup.ts)
    out: dict[str, object] = {"cases": {}, "kernels": {}}
    cases = {
        "acorn window": (life, acorn, 200, {}),
        "far blocks hash": (life, far, 5, {}),
        "soup dense separable": (life, soup_cells, 30, {}),
        "soup dense plain": (life, soup_cells, 30, {"DENSE_SEPARABLE": False}),
        "u16 soup separable": (u16, soup_cells, 30, {}),
        "u16 soup plain": (u16, soup_cells, 30, {"DENSE_SEPARABLE": False}),
    }
    for name, (rules, cells, gens, consts) in cases.items():
        if not isinstance(cells[2], np.ndarray):
            cells = (cells[0], cells[1], np.full(len(cells[0]), cells[2], np.int64))
        out["cases"][name], out["kernels"][name] = run(rules, cells, gens, **consts)
    out["cases"]["rle grid"] = digest(soup.xs, soup.ys, soup.ts)
    out["cases"]["rle cells"] = digest(sparse.xs, sparse.ys, sparse.ts)
    from camlab88.apps.ca import grid_stats

    grid = np.random.default_rng(3).integers(0, 5, (300, 400)).astype(np.uint8)
    out["cases"]["census"] = sorted(grid_stats.by_type(grid).items())
    out["u16 messages"] = np.dtype(compile_rules(u16).dense.msg_dtype).name
    # every listed module, also those these cases do not reach (HashLife's: compared through
    # whole `ca run`s in test_equal_results.py)
    out["modes"] = {m: importlib.import_module(m).kernels.mode for m in sys.argv[1:]}
    out["numba"] = "numba" in sys.modules
    print(json.dumps(out, sort_keys=True))


if __name__ == "__main__":
    main()
