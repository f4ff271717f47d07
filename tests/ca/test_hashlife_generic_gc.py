"""The generic (multi-state) HashLife store renumbers every live tree when it collects
garbage, as the binary store does: an engine whose state is only a tree (after a jump) and
shares a rule set's table with another engine (the CA program's look-ahead copies) still
reads its own cells after the other engine's collection."""

from __future__ import annotations

from camlab88.apps.ca.rules import parse_rules
from tests.ca.test_hashlife import LIBRARY, PLACES, soup


def test_a_collection_for_one_engine_keeps_another_engines_tree() -> None:
    name = "maze"  # multi-state: the generic path
    rules = parse_rules(LIBRARY[name].text, source=f"{name}-generic-two-engines")
    first = soup(rules, 31, *PLACES[0])
    second = soup(rules, 32, 20000, 20000, n=12000, side=300)
    ref = first.copy()
    for e in (first, second):
        e.algorithm = "hashlife"
        e.hashlife_memory = 3 << 20  # the smallest generic table, and no room to grow
    first.step(300)  # its state is now only a tree
    assert first.tree is not None and "hashlife_bits_run" not in rules._tables
    store = rules._tables["hashlife_run"].store
    epoch = store.epoch
    second.step(300)  # collects garbage in the shared table
    assert store.epoch > epoch, "the second engine's run did not collect: make it bigger"
    ref.step_direct(300)
    assert first.population == ref.population and first.same_state(ref)
    first.step(50)
    ref.step_direct(50)
    assert first.same_state(ref)
