"""numba-compiled copies of protocol loops that dominate a vector-heavy stream.

The protocol package defines the decoding once, in plain Python (protocols.sigma.abbreviated
.scan_points); the device compiles that same function, so the two cannot differ. Compiled on
first use, so that a run without abbreviated mode never imports numba.
"""

from __future__ import annotations

from typing import Any

from camlab88.protocols.sigma.abbreviated import scan_points

_compiled: Any = None


def scan_points_fast(buf: Any, start: int, state: Any, out: Any, k: int) -> tuple[int, int]:
    global _compiled
    if _compiled is None:
        from camlab88.base.kernel_load import lean_cache_loads
        from numba import njit

        lean_cache_loads()  # this may be the process's first kernel: load it lean (faster start)
        _compiled = njit(cache=True, nogil=True)(scan_points)
    return _compiled(buf, start, state, out, k)
