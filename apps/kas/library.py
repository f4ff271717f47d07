"""The shipped library (apps/kas/library/): demo keyframes, sample paths and timings.

A name without a directory part and without an existing file of that name is looked up in
the library (``walk_a`` -> library/walk_a.kas).
"""

from __future__ import annotations

import os
from pathlib import Path

LIBRARY = Path(__file__).with_name("library")


def resolve(name: str | os.PathLike[str]) -> Path:
    p = Path(name)
    if p.exists() or p.parent != Path("."):
        return p
    for cand in (LIBRARY / p, LIBRARY / f"{p}.kas"):
        if cand.exists():
            return cand
    return p  # let the loader report it missing, by the name the user gave


def entries() -> list[tuple[str, str]]:
    """(name, kind) of every library file."""
    out = []
    for f in sorted(LIBRARY.glob("*.kas")):
        first = f.read_text(encoding="utf-8").split("\n", 1)[0].split()
        out.append((f.stem, first[1] if len(first) == 3 else "?"))
    return out
