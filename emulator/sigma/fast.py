"""numba-compiled copies of protocol loops that dominate a vector-heavy stream.

The protocol package defines the decoding once, in plain Python (protocols.sigma.abbreviated
.scan_points); the device compiles that same function (``fast_kernels``), so the two cannot
differ. That module is imported on first use, so a run without abbreviated mode never
imports numba.
"""

from __future__ import annotations

from typing import Any


def scan_points_fast(buf: Any, start: int, state: Any, out: Any, k: int) -> tuple[int, int]:
    from camlab88.emulator.sigma.fast_kernels import scan_points

    return scan_points(buf, start, state, out, k)
