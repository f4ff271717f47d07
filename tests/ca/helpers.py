"""Small helpers shared by the ca tests."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from hypothesis import strategies as st

from camlab88.apps.ca import engine as engine_mod
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.patterns import PatternError, read_pattern
from camlab88.apps.ca.rules import load_rules

LIFE = load_rules(rules_path("life"))


def life(cells: str, x0: int = 100, y0: int = 100, **kw) -> Engine:
    """Engine running figure 7.6 Life with ``cells`` drawn as text ('O' alive)."""
    e = Engine(LIFE, **kw)
    pts = [(x0 + x, y0 + y) for y, row in enumerate(cells.strip().splitlines())
           for x, ch in enumerate(row.strip()) if ch == "O"]
    e.set_cells([p[0] for p in pts], [p[1] for p in pts], 1)
    return e


def kernels_used(e: Engine, generations: int) -> set[str]:
    """Step ``e`` ``generations`` times; the kernels (``Engine.last_kernel``) the steps took."""
    used = set()
    for _ in range(generations):
        e.step()
        used.add(e.last_kernel)
    return used


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


def interpretation_lines(forms: int, low: int = 0, top: int = 80, width: int = 60,
                         bits: int = 8, prefix: str = "#B",
                         random: bool = False) -> st.SearchStrategy[list[str]]:
    """One to eight lines of a rule set's table after the '$', each giving a life-form (0 ..
    ``forms``) to a neighbourhood value: one value (``low`` .. ``top``), a range ``R lo hi``
    at most ``width`` wide, a bit pattern (``prefix`` then up to ``bits`` of 0, 1, ?) and, with
    ``random``, a 50/50 choice between a form and the last form."""
    form, value = st.integers(0, forms), st.integers(low, top)
    exact = st.tuples(value, form).map(lambda t: f"{t[0]} {t[1]}")
    span = st.tuples(value, st.integers(0, width), form).map(
        lambda t: f"R {t[0]} {t[0] + t[1]} {t[2]}")
    pattern = st.tuples(st.lists(st.sampled_from("01?"), min_size=1, max_size=bits), form).map(
        lambda t: f"{prefix}{''.join(t[0])} {t[1]}")
    kinds = [exact, span, pattern]
    if random:
        kinds.append(st.tuples(value, form).map(lambda t: f"{t[0]} 50% {t[1]} 50% {forms}"))
    return st.lists(st.one_of(kinds), min_size=1, max_size=8)


def refused_pattern_file(path: Path, text: str) -> str:
    """Write ``text`` to ``path`` and read it as a pattern, which must refuse it with a
    message naming the file first: the rest of the message (``:line:column: ...``)."""
    path.write_text(text)
    with pytest.raises(PatternError) as exc:
        read_pattern(path)
    message = str(exc.value)
    assert message.startswith(str(path)), message
    return message[len(str(path)):]
