"""The compiled AGS point scanner: protocols.sigma.abbreviated.scan_points itself, compiled
(numba's cache keys it to that function's own file, which it reads nothing outside of)."""

from __future__ import annotations

from numba import njit

from camlab88.base.kernel_notice import announce_compiles
from camlab88.protocols.sigma import abbreviated

announce_compiles("Sigma raster", 2.0, abbreviated.__name__,
                  completion="camlab88.emulator.sigma.kernel_warmup:compile_kernels")

scan_points = njit(cache=True, nogil=True)(abbreviated.scan_points)
