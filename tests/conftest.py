"""Shared test set-up: headless SDL, and one numba cache per test process.

On fresh clones the suite failed now and then (black Rainbow frames, wrong band structures,
once a segfault) while two pytest-xdist workers were compiling and writing numba's shared
on-disk cache at the same time; numba's cache is not safe for concurrent writers. Each worker
therefore gets its own cache directory (set here, before anything imports numba).
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
