"""numba kernels compiled on first use, so importing a device module never imports numba.

A module registers its kernels with ``kernels = LazyKernels(globals(), ...)`` and decorates
each with ``@kernels.kernel`` (or ``@kernels.signed("...")``): the module name is bound to a
stub until the first call of any kernel, which compiles (or loads from numba's cache) all of
them, callees first so callers resolve them as compiled kernels. Used by the Sigma raster and
the Rainbow compiler (about 0.15-0.2 s of numba import, plus 0.2 s of cache loads, that a run
which never draws does not pay).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class LazyKernels:
    """The kernels of one module, compiled together on the first call of any of them."""

    def __init__(self, namespace: dict[str, Any], before: Callable[[], None] | None = None,
                 **njit_options: Any) -> None:
        self._ns = namespace            # the module's globals(): where the stubs are replaced
        self._before = before           # e.g. the cold-cache notice
        self._options = njit_options    # besides cache=True
        self._py: dict[str, Callable[..., Any]] = {}  # name -> Python definition, in order
        self._signatures: dict[str, str] = {}

    def kernel(self, fn: Callable[..., Any], signature: str | None = None) -> Callable[..., Any]:
        """Register ``fn``; its module name is bound to the returned stub until first use."""
        self._py[fn.__name__] = fn
        if signature:
            self._signatures[fn.__name__] = signature

        def first_call(*args: Any) -> Any:
            self.compile_all()
            return self._ns[fn.__name__](*args)

        first_call.__name__ = fn.__name__
        first_call.__doc__ = fn.__doc__
        first_call.py_func = fn
        first_call._lazy = True
        return first_call

    def signed(self, signature: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
        """``kernel`` with an explicit numba signature (one signature per cached kernel)."""
        return lambda fn: self.kernel(fn, signature)

    def compile_all(self) -> None:
        from numba import njit

        if self._before is not None:
            self._before()
        for name, fn in self._py.items():
            stub = self._ns.get(name)
            if getattr(stub, "_lazy", False) and getattr(stub, "py_func", None) is fn:
                sig = self._signatures.get(name)
                jit = njit(sig, cache=True, **self._options) if sig else \
                    njit(cache=True, **self._options)
                self._ns[name] = jit(fn)
