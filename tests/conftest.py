"""Shared test set-up: headless SDL, and one numba cache per test process.

numba's on-disk cache numbers a function's compiled overloads per process; two processes
compiling new overloads of the same function at once (pytest-xdist workers) can leave an index
that points at the other process's machine code, which crashes or corrupts memory later. Each
worker therefore gets its own cache directory (set before anything imports numba).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

_worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
os.environ.setdefault(
    "NUMBA_CACHE_DIR",
    str(Path(tempfile.gettempdir()) / f"camlab88-numba-{os.getuid()}-{_worker}"),
)
