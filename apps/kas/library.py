"""The libraries of keyframes, sample paths and timings (§3.1.2 "a library of paths and
timings saved and reused").

Two places: the shipped library (apps/kas/library/, read-only: demo keyframes, paths,
timing curves) and the animator's own library, a directory of ordinary KAS files:
``$CAMLAB88_KAS_LIBRARY`` if set, else ``$XDG_DATA_HOME/camlab88/kas`` (default
``~/.local/share/camlab88/kas``).  A name without a directory part and without an existing
file of that name is looked up in the user library first, then the shipped one
(``walk_a`` -> library/walk_a.kas).

Paths drawn with ``kas path A B`` are also kept in the user library under the pair's name
(``pair_<A>--<B>_path.kas`` and ``..._ticks.kas``), so that drawing the path of the next pair
(B, C) shows the previous pair's path automatically, to help continuity (§3.1.2).
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from camlab88.base.suggest import did_you_mean

LIBRARY = Path(__file__).with_name("library")
ENV = "CAMLAB88_KAS_LIBRARY"


def user_dir() -> Path:
    """The user library directory (not created here)."""
    if os.environ.get(ENV):
        return Path(os.environ[ENV])
    base = os.environ.get("XDG_DATA_HOME") or Path.home() / ".local" / "share"
    return Path(base) / "camlab88" / "kas"


def _dirs() -> list[Path]:
    return [user_dir(), LIBRARY]


class LibraryNameError(FileNotFoundError):
    """A name that is neither a file nor a library entry (the message suggests near ones)."""


def resolve(name: str | os.PathLike[str]) -> Path:
    """The file ``name`` names: itself if it exists, else a library entry of that name;
    LibraryNameError (a FileNotFoundError) if neither, naming the near library names."""
    p = Path(name)
    if p.exists():
        return p
    if p.parent == Path("."):
        for d in _dirs():
            for cand in (d / p, d / f"{p}.kas"):
                if cand.is_file():
                    return cand
    raise LibraryNameError(missing_message(str(name)))


def missing_message(name: str) -> str:
    """What to say about a name that is neither a file nor a library entry."""
    if Path(name).parent != Path("."):
        return f"{name}: no such file"
    stem = name[:-4] if name.endswith(".kas") else name
    hint = did_you_mean(stem, [entry for entry, _, _ in entries()])
    return (f"{name}: no such file, and no library entry of that name{hint} "
            "('camlab88 kas library' lists them)")


def _kind(f: Path) -> str:
    try:
        with f.open(encoding="utf-8") as fh:
            first = fh.readline().split()
    except (OSError, UnicodeDecodeError):
        return "?"
    return first[1] if len(first) == 3 and first[0] == "KAS" else "?"


def entries() -> list[tuple[str, str, str]]:
    """(name, kind, where) of every library file: the user's first, then the shipped."""
    out = []
    for where, d in (("user", user_dir()), ("shipped", LIBRARY)):
        if d.is_dir():
            out += [(f.stem, _kind(f), where) for f in sorted(d.glob("*.kas"))]
    return out


def user_file(name: str) -> Path:
    """Where ``name`` goes in the user library (the directory is created)."""
    if not re.fullmatch(r"[A-Za-z0-9_.+-]+", name) or name.startswith("."):
        raise ValueError(f"library name {name!r}: use letters, digits and _ . + - only")
    d = user_dir()
    d.mkdir(parents=True, exist_ok=True)
    return d / (name if name.endswith(".kas") else f"{name}.kas")


def key_name(keyframe: str | os.PathLike[str]) -> str:
    """A keyframe's name in pair names: its file stem, made safe."""
    return re.sub(r"[^A-Za-z0-9_.+-]", "_", Path(keyframe).stem) or "_"


def pair_names(first: str | os.PathLike[str], second: str | os.PathLike[str]
               ) -> tuple[str, str]:
    """User-library names of the path and the ticks drawn for the pair (first, second)."""
    stem = f"pair_{key_name(first)}--{key_name(second)}"
    return f"{stem}_path", f"{stem}_ticks"


def previous_pair_path(first: str | os.PathLike[str]) -> Path | None:
    """The path saved for a pair ending at keyframe ``first`` (the previous pair), if any;
    of several, the most recently saved."""
    d = user_dir()
    if not d.is_dir():
        return None
    cands = [f for f in d.glob(f"pair_*--{key_name(first)}_path.kas") if f.is_file()]
    if not cands:
        return None
    return max(cands, key=lambda f: (f.stat().st_mtime_ns, f.name))
