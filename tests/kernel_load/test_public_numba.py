"""The product stands on numba's public ground: no module of numba's internals it could
patch (its cache, its runtime), no deprecated module (numba.pycc), no intrinsics building
arrays that own nothing, no choice by what the process imported before
(docs/development.md, "Kernels")."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PRODUCT = ("apps", "emulator", "protocols", "base", "roms", "camlab88")
REFUSED = ("numba.pycc", "numba.core.caching", "numba.core.runtime", "numba.extending",
           "intrinsic", "meminfo", "load_overload", "_locator_classes",
           '"numba" in sys.modules')  # a numpy-or-numba choice by import history
# the command line sets numba's documented NUMBA_CACHE_DIR, which only counts before numba's
# import: the one place that asks whether numba is imported
ASKS_WHETHER_IMPORTED = {"camlab88/cli.py"}


def test_no_private_or_deprecated_numba_and_no_import_history_choices() -> None:
    found = []
    for top in PRODUCT:
        for path in sorted((ROOT / top).rglob("*.py")):
            if path.is_symlink() or any(p.is_symlink() for p in path.parents if p != ROOT):
                continue
            text = path.read_text()
            for word in REFUSED:
                if word in text and not (word.endswith("sys.modules")
                                         and path.relative_to(ROOT).as_posix()
                                         in ASKS_WHETHER_IMPORTED):
                    found.append(f"{path.relative_to(ROOT)}: {word}")
    assert not found, "\n".join(found)
