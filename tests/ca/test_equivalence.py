"""All engine paths (dense, window, hash) give identical generations for random rule sets."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.rules import parse_rules
from tests.ca.helpers import engine_constants, interpretation_lines, kernels_used

OPS = ["+", "|", "&", "^"]


@st.composite
def rule_sets(draw) -> str:
    forms = draw(st.integers(1, 3))
    ops = draw(st.sampled_from([["+", "|"], ["+"], ["|"], OPS, ["^"]]))
    text = []
    for n in range(1, forms + 1):
        r = draw(st.integers(0, 2))
        entries = []
        for _ in range((2 * r + 1) ** 2):
            if draw(st.booleans()):
                entries.append(".")
            else:
                op = draw(st.sampled_from(ops))
                val = draw(st.integers(1, 40)) if op == "+" else draw(st.integers(1, 255))
                entries.append(f"{op}{val}")
        text.append(f"{n} {r} {r} {r} {r} {' '.join(entries)}")
    text.append("$")
    text += draw(interpretation_lines(forms, random=True))
    return "\n".join(text)


@settings(max_examples=40, deadline=None)
@given(rule_sets(), st.lists(st.tuples(st.integers(0, 24), st.integers(0, 24),
                                       st.integers(1, 3)), min_size=1, max_size=120),
       st.sampled_from(["wrap", "bounded"]), st.sampled_from([-12, 1000]))
def test_all_paths_agree(text: str, cells, edges: str, shift: int) -> None:
    rules = parse_rules(text)
    top = max(rules.forms)
    cells = [(x, y, min(t, top)) for x, y, t in cells]

    def run(**consts) -> tuple[Engine, set]:
        with engine_constants(**consts):
            e = Engine(rules, edges=edges, seed=5)
            # Across the plane's corner (wrapping and the bounded edge matter) or inside it.
            e.set_cells([(x + shift) % 65536 for x, _, _ in cells],
                        [(y + shift) % 65536 for _, y, _ in cells], [t for _, _, t in cells])
            return e, kernels_used(e, 6)

    hashed, _ = run(DENSE_MIN_FILL=0, WINDOW_MIN=0, WINDOW_CELLS_PER_SENDER=0)
    windowed, _ = run(DENSE_MIN_FILL=0, WINDOW_MIN=1 << 30, WINDOW_CELLS_PER_SENDER=1 << 20)
    default, _ = run(DENSE_MIN_FILL=1 << 20)  # dense whenever the rules allow it
    assert hashed.same_state(windowed)
    assert hashed.same_state(default)


def test_dense_and_window_agree_away_from_edges() -> None:
    rules = parse_rules("1 1 1 1 1 +1 +2 +1 +2 |64 +2 +1 +2 +1 $ R 66 70 1 3 1 4 1 R 5 7 1")
    e1 = Engine(rules)
    e1.set_cells([100 + i % 37 for i in range(0, 900, 7)], [100 + i // 37 for i in
                                                           range(0, 900, 7)], 1)
    e2 = e1.copy()
    e1.step(10)
    with engine_constants(DENSE_MIN_FILL=0):
        e2.step(10)
    assert e1.same_state(e2)
