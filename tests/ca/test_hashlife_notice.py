"""Every HashLife module with numba kernels is announced (issue 18's repeat trial: a first
`ca run` spent 8–20 s compiling HashLife's kernels without a word)."""

from __future__ import annotations

from pathlib import Path

import apps.ca.hashlife  # noqa: F401 - registers its kernel groups
from base import kernel_notice

ROOT = Path(__file__).resolve().parents[2]


def test_every_hashlife_kernel_module_is_in_an_announced_group() -> None:
    package = ROOT / "apps" / "ca" / "hashlife"
    with_kernels = {".".join(p.relative_to(ROOT).with_suffix("").parts)
                    for p in package.rglob("*.py") if "@njit" in p.read_text()}
    assert {"apps.ca.hashlife.evolve", "apps.ca.hashlife.bits.evolve"} <= with_kernels
    missing = with_kernels - set(kernel_notice._state.groups)
    assert not missing, f"kernels compiled without the notice: {sorted(missing)}"
    labels = {kernel_notice._state.groups[m].label for m in with_kernels}
    assert labels == {"HashLife", "binary HashLife"}
