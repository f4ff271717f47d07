"""The numba kernels of one module, declared through one object instead of bare ``njit``.

A kernel module writes ``kernels = KernelSet(__name__)`` and decorates each kernel with
``@kernels.kernel`` (called only by other kernels) or ``@kernels.export("signature")``
(called from Python; the numba signature its Python callers use). Today both compile with
``njit(cache=True, ...)`` exactly as a bare decorator would; declaring the Python entry
points and their types is what lets a build compile the module ahead of time.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class KernelSet:
    """The kernels of one module: which exist, which Python calls, with what types."""

    def __init__(self, module: str, **options: Any) -> None:
        self.module = module
        self.options = options                  # njit options shared by the module's kernels
        self.exports: dict[str, str] = {}       # kernel name -> numba signature
        self.kernels: dict[str, Callable[..., Any]] = {}  # name -> compiled dispatcher

    def kernel(self, fn: Callable[..., Any] | None = None, **options: Any) -> Any:
        """``@kernels.kernel`` or ``@kernels.kernel(_nrt=False)``: a kernel other kernels call."""
        if fn is None:
            return lambda f: self.kernel(f, **options)
        from numba import njit

        compiled = njit(cache=True, **{**self.options, **options})(fn)
        self.kernels[fn.__name__] = compiled
        return compiled

    def export(self, signature: str, **options: Any) -> Callable[[Callable[..., Any]], Any]:
        """``@kernels.export("int64(int64, int64[:, :])")``: a kernel Python code calls."""
        def declare(fn: Callable[..., Any]) -> Any:
            self.exports[fn.__name__] = signature
            return self.kernel(fn, **options)
        return declare
