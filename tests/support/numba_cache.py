"""Reading numba's on-disk cache: which cached kernels ended up with more than one signature.

numba numbers a function's cached signatures 1, 2, ... in one index file per function. Two
processes compiling *different* signatures of one function at the same moment can leave the
index naming one signature's data file while the file holds the other signature's code; the
next process to load it runs the wrong machine code (here: a kernel specialised for a
literal 0 answering 0 for every input, which blanked Rainbow frames). A kernel that only
ever has one signature cannot be mixed up this way, so the test session checks that.
"""

from __future__ import annotations

import pickle
from pathlib import Path


def index_signatures(index: Path) -> list[str]:
    """The signatures an index file (``*.nbi``) lists, as text."""
    with index.open("rb") as fh:
        pickle.load(fh)  # numba's version tag
        _stamp, overloads = pickle.loads(fh.read())
    return [str(key[0]) for key in overloads]


def overloaded_kernels(cache_dir: Path) -> dict[str, list[str]]:
    """{index file relative to cache_dir: its signatures} for every index with more than one."""
    found = {}
    for index in sorted(Path(cache_dir).rglob("*.nbi")):
        sigs = index_signatures(index)
        if len(sigs) > 1:
            found[str(index.relative_to(cache_dir))] = sigs
    return found
