"""The fidelity ledger names every order, and never calls a reconstructed order documented."""

from __future__ import annotations

from pathlib import Path

from camlab88.protocols.sigma import ORDERS

LEDGER = Path(__file__).resolve().parents[2] / "docs" / "fidelity" / "sigma.md"


def test_every_order_is_in_the_ledger_with_its_status() -> None:
    rows = {}
    for line in LEDGER.read_text(encoding="utf-8").splitlines():
        if line.startswith("| `"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            for code in cells[0].replace("`", "").replace("/", " ").split():
                rows[code] = cells[-1]
    for spec in ORDERS:
        assert spec.code in rows, f"{spec.code} missing from {LEDGER.name}"
        status = rows[spec.code].lower()
        if spec.status.startswith("RECONSTRUCTED"):
            assert status.startswith("**reconstructed**"), spec.code
        else:
            assert "documented" in status, spec.code
