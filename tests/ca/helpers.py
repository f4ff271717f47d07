"""Small helpers shared by the ca tests."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from apps.ca import engine as engine_mod
from apps.ca.engine import Engine
from apps.ca.library import rules_path
from apps.ca.rules import load_rules

LIFE = load_rules(rules_path("life"))


def life(cells: str, x0: int = 100, y0: int = 100, **kw) -> Engine:
    """Engine running figure 7.6 Life with ``cells`` drawn as text ('O' alive)."""
    e = Engine(LIFE, **kw)
    pts = [(x0 + x, y0 + y) for y, row in enumerate(cells.strip().splitlines())
           for x, ch in enumerate(row.strip()) if ch == "O"]
    e.set_cells([p[0] for p in pts], [p[1] for p in pts], 1)
    return e


def cellset(e: Engine) -> set[tuple[int, int, int]]:
    return {(int(x), int(y), int(t)) for x, y, t in zip(e.xs, e.ys, e.ts)}


def shifted(cells: set[tuple[int, int, int]], dx: int, dy: int) -> set[tuple[int, int, int]]:
    return {((x + dx) % 65536, (y + dy) % 65536, t) for x, y, t in cells}


@contextmanager
def engine_constants(**consts) -> Iterator[None]:
    """Set module constants of apps.ca.engine (which kernel it picks) for a block, then put
    them back (hypothesis tests cannot use the function-scoped monkeypatch)."""
    saved = {k: getattr(engine_mod, k) for k in consts}
    for k, v in consts.items():
        setattr(engine_mod, k, v)
    try:
        yield
    finally:
        for k, v in saved.items():
            setattr(engine_mod, k, v)
