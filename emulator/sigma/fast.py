"""numba-compiled copies of protocol loops that dominate a vector-heavy stream.

The protocol package defines the decoding once, in plain Python (protocols.sigma.abbreviated
.scan_points); the device compiles that same function, so the two cannot differ.
"""

from __future__ import annotations

from numba import njit

from protocols.sigma.abbreviated import scan_points

scan_points_fast = njit(cache=True, nogil=True)(scan_points)
