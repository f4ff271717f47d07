"""The ledger's mutation table (tests/support/mutations.toml) still points at real rows and
real code, and its committed report (docs/fidelity/mutations.md) covers every entry: the
run itself is `python -m tests.support.mutations` (minutes; its report is committed)."""

from __future__ import annotations

import pytest

from tests.support import mutations


def test_every_mutation_names_a_ledger_row_and_text_found_once() -> None:
    table = mutations.load()
    assert len(table) >= 14
    for m in table:
        assert m.tests and all("::" in t or t.endswith(".py") for t in m.tests), m.label()


def test_the_committed_report_covers_the_table() -> None:
    report = mutations.REPORT.read_text(encoding="utf-8")
    for m in mutations.load():
        assert f"| {m.label().replace('|', '/')} | `{m.file}` | {m.what} |" in report, \
            f"{m.label()} is not in {mutations.REPORT.name}: run python -m tests.support.mutations"


@pytest.mark.parametrize(("text", "says"), [
    ("version = 2\n", "version 2"),
    ("version = 1\n[[mutation]]\nledger = \"docs/fidelity.md\"\n", "missing or unknown"),
    ('version = 1\n[[mutation]]\nledger = "docs/fidelity.md"\nrow = "no such row at all"\n'
     'file = "apps/ca/rules.py"\nfind = "x"\nreplace = "y"\nwhat = "w"\ntests = []\n',
     "found in 0 rows"),
])
def test_a_damaged_table_is_named(text: str, says: str) -> None:
    with pytest.raises(mutations.TableError, match=says):
        mutations.load(text)
