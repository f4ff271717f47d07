"""The ledger's mutation tables (tests/support/mutation_tables/) still point at real rows and
real code, their committed report (docs/fidelity/mutations.md) covers every entry, and every
row that claims agreement with a source bites: the run itself is
`python -m tests.support.mutations` (minutes; its report is committed)."""

from __future__ import annotations

import pytest

from tests.support import mutations

# Ledgers whose rows all bite or say they are untested (see unproven_rows); every ledger
# joins as its rows are mutation-checked or re-verdicted.
ENFORCED: tuple[str, ...] = ("ca", "ca_actors", "fidelity", "kas", "link", "rainbow", "sigma",
                             "snooker", "tablets")


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.strip().strip("|").split("|")]


def _claims(status: str) -> bool:
    """A status cell claiming a source: it says thesis or documented, or is docs/fidelity/
    ca.md's abbreviation D ("documented in the thesis"), alone or qualified: "D (idea) /
    R (method)"."""
    return "thesis" in status or "documented" in status or status == "d" \
        or status.startswith(("d ", "d("))


def claiming_rows(stem: str) -> list[str]:
    """The ledger's table rows that claim agreement with a source: a ``status`` column saying
    thesis or documented (or D), or a ``verdict`` column beginning "agrees"."""
    lines = (mutations.ROOT / mutations.ledger_of(stem)).read_text(encoding="utf-8") \
        .splitlines()
    out, column, kind = [], None, ""
    for i, line in enumerate(lines):
        if not line.startswith("|"):
            column = None
            continue
        if i + 1 < len(lines) and lines[i + 1].startswith("|---"):
            heads = [h.lower() for h in _cells(line)]
            kind = "status" if "status" in heads else "verdict" if "verdict" in heads else ""
            column = heads.index(kind) if kind else None
            continue
        if column is None or line.startswith("|---"):
            continue
        cells = _cells(line)
        cell = cells[column].lower() if column < len(cells) else ""
        claims = _claims(cell) if kind == "status" else cell.startswith("agrees")
        if claims and "untested" not in cell:
            out.append(line)
    return out


def unproven_rows(stem: str) -> list[str]:
    """Claiming rows with no caught mutation in the committed report."""
    report = mutations.REPORT.read_text(encoding="utf-8")
    caught = [m.row for m in mutations.load(stem)
              if f"| {m.label().replace('|', '/')} | `{m.file}` | {m.what} | caught |" in report]
    return [ln for ln in claiming_rows(stem) if not any(r in ln for r in caught)]


def test_every_mutation_names_a_ledger_row_and_text_found_once() -> None:
    tables = mutations.load_all()
    assert set(tables) == {"fidelity", "ca", "ca_actors", "kas", "link", "rainbow", "sigma",
                           "snooker", "tablets"}
    assert sum(map(len, tables.values())) >= 18
    for table in tables.values():
        for m in table:
            assert m.tests and all("::" in t or t.endswith(".py") for t in m.tests), m.label()


def test_the_committed_report_covers_the_tables() -> None:
    report = mutations.REPORT.read_text(encoding="utf-8")
    for table in mutations.load_all().values():
        for m in table:
            assert f"| {m.label().replace('|', '/')} | `{m.file}` | {m.what} |" in report, \
                f"{m.label()} is not in {mutations.REPORT.name}: run python -m " \
                "tests.support.mutations"


def test_every_row_claiming_agreement_bites_or_says_untested() -> None:
    for stem in ENFORCED:
        assert unproven_rows(stem) == [], f"{mutations.ledger_of(stem)}: rows claiming " \
            "agreement with no caught mutation (add one, or re-verdict the row 'untested')"


def test_the_ca_ledgers_abbreviation_d_claims_the_thesis() -> None:
    rows = claiming_rows("ca")
    assert any(r.startswith("| Life rules |") for r in rows)  # D
    assert any(r.startswith("| Sparse representation") for r in rows)  # D (idea) / R (method)
    assert not any(r.startswith("| Over-grazing Life |") for r in rows)  # R


def test_the_report_keeps_other_ledgers_sections_when_one_is_rerun() -> None:
    old = mutations.report({"docs/fidelity/kas.md": "## docs/fidelity/kas.md\n\nold kas\n",
                            "docs/fidelity/ca.md": "## docs/fidelity/ca.md\n\nold ca\n"})
    new = mutations.report({"docs/fidelity/kas.md": "## docs/fidelity/kas.md\n\nnew kas\n"},
                           old)
    assert "new kas" in new and "old kas" not in new and "old ca" in new
    assert new.index("docs/fidelity/ca.md") < new.index("docs/fidelity/kas.md")


@pytest.mark.parametrize(("text", "says"), [
    ("version = 1\n", "version 1"),
    ("version = 2\n[[mutation]]\nrow = \"x\"\n", "missing or unknown"),
    ('version = 2\n[[mutation]]\nrow = "no such row at all"\n'
     'file = "apps/ca/rules.py"\nfind = "x"\nreplace = "y"\nwhat = "w"\ntests = []\n',
     "found in 0 rows"),
])
def test_a_damaged_table_is_named(text: str, says: str) -> None:
    with pytest.raises(mutations.TableError, match=says):
        mutations.load("ca", text)
