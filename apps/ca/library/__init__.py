"""The rule sets and demo patterns shipped with the project, found by name or by path."""

from __future__ import annotations

import os
from pathlib import Path

from camlab88.base.suggest import did_you_mean

LIBRARY = Path(__file__).resolve().parent
PATTERN_SUFFIXES = (".pat", ".rle", ".cells", ".mc")


def _resolve(name: str, suffixes: tuple[str, ...], what: str) -> str:
    if os.path.exists(name):
        return name
    for suffix in ("", *suffixes):
        candidate = LIBRARY / f"{name}{suffix}"
        if candidate.is_file():
            return str(candidate)
    entries = sorted({p.stem for p in LIBRARY.iterdir() if p.suffix in suffixes})
    hint = did_you_mean(Path(name).stem if Path(name).suffix in suffixes else name, entries)
    raise FileNotFoundError(f"no {what} file or library entry named {name!r}{hint} "
                            f"(library: {', '.join(entries)})")


def rules_path(name: str) -> str:
    """A path, or a library rule set's name such as 'life' or 'maze'."""
    return _resolve(name, (".rules",), "rules")


def pattern_path(name: str) -> str:
    """A path, or a library pattern's name such as 'gosper_gun' or 'maze_demo'."""
    return _resolve(name, PATTERN_SUFFIXES, "pattern")


def names() -> dict[str, list[str]]:
    rules = sorted(p.stem for p in LIBRARY.glob("*.rules"))
    pats = sorted(p.name for p in LIBRARY.iterdir() if p.suffix in PATTERN_SUFFIXES)
    return {"rules": rules, "patterns": pats}
