"""Load cached numba kernels without numba's full context refresh (start-up time).

Before numba runs a kernel it loaded from its on-disk cache, ``Cache.load_overload`` calls
``target_context.refresh()``: it imports some seventy modules of numba's own
implementations (unicode, typed dicts, linear algebra, random generators, jitclass, ...) and
installs 252 typing and lowering registries. A cache hit needs none of that: the loaded
object code is complete machine code, and the registries are read only by the compiler,
which refreshes the context itself before every real compile (``CompilerBase.__init__``)
and when lowering finds a function missing (``BaseContext.get_function``). What the
loaded code does need at run time is numba's memory runtime (NRT: its C entry points and
a few compiled atomics), so that is initialised here as ``refresh()`` would.

Measured on the project's 2-core machine (docs/perf/startup.md): a warm command's first
kernel call drops from 0.18-0.25 s (quiet machine) to a few hundredths; the kernels and so
every result are byte for byte the ones numba would load anyway. If a lean load fails for
any reason (a numba whose internals differ), the full refresh runs and the ordinary load
is retried, so the worst case is numba's own behaviour. ``CAMLAB88_NUMBA_FULL_REFRESH=1``
turns the lean load off (the tests compare both ways).
"""

from __future__ import annotations

import os
from typing import Any

OFF_VARIABLE = "CAMLAB88_NUMBA_FULL_REFRESH"
_installed: list[Any] = []  # the original Cache.load_overload once patched


def lean_cache_loads() -> bool:
    """Make numba's cache hits skip the context refresh; True if now active. Idempotent.
    Imports numba, so call it only where numba is imported already (a kernel module)."""
    if _installed:
        return True
    if os.environ.get(OFF_VARIABLE, "") not in ("", "0"):
        return False
    from numba.core import caching
    from numba.core.runtime import nrt

    original = caching.Cache.load_overload
    needed = (hasattr(caching.Cache, "_load_overload"),
              hasattr(caching.Cache, "_guard_against_spurious_io_errors"),
              hasattr(nrt, "rtsys"))
    if not all(needed):
        return False

    def load_overload(self: Any, sig: Any, target_context: Any) -> Any:
        try:
            nrt.rtsys.initialize(target_context)
            with self._guard_against_spurious_io_errors():
                return self._load_overload(sig, target_context)
        except Exception:  # any surprise: numba's own path decides
            return original(self, sig, target_context)

    load_overload.__doc__ = original.__doc__
    caching.Cache.load_overload = load_overload
    _installed.append(original)
    return True


def active() -> bool:
    """True while cache hits load without the refresh."""
    return bool(_installed)


_stamped: list[Any] = []  # the locator class once installed


def stamps_cover_sources() -> bool:
    """Make the on-disk cache of a KernelSet kernel stale when any module its set names in
    ``sources`` changes, not only its own file; True if active. Idempotent. Imports numba.

    numba keys a cached kernel to its own source file's content, but a kernel's machine code
    includes the kernels it calls from other modules: after an edit or upgrade of only a
    callee's module, a warm cache ran the old callee's code (here: an old recursion writing
    past a scratch array that had shrunk, "double free or corruption"). The locator numba
    would have chosen is kept (same directory, same file names); only the stamp it checks
    also covers the set's ``sources`` (base/kernel_set.py, which the ahead-of-time build
    checks are complete)."""
    if _stamped:
        return True
    from numba.core import caching

    impl = getattr(caching, "CacheImpl", None)
    original = list(getattr(impl, "_locator_classes", ()))
    locator_base = getattr(caching, "_CacheLocator", None)
    hash_file = getattr(caching, "_hash_source_file", None)
    if not original or locator_base is None or hash_file is None:
        return False

    class WithSources(locator_base):
        def __init__(self, inner: Any, files: tuple[str, ...]) -> None:
            self._inner, self._files = inner, files

        def ensure_cache_path(self) -> None:
            self._inner.ensure_cache_path()

        def get_cache_path(self) -> str:
            return self._inner.get_cache_path()

        def get_disambiguator(self) -> str:
            return self._inner.get_disambiguator()

        def get_source_stamp(self) -> Any:
            stamps = []
            for path in self._files:
                st = os.stat(path)
                stamps.append(hash_file(path, st.st_mtime, st.st_size))
            return self._inner.get_source_stamp(), tuple(stamps)

        @classmethod
        def from_function(cls, py_func: Any, py_file: str) -> Any:
            files = _source_files(getattr(py_func, "__module__", ""))
            if not files:
                return None
            for locator in original:
                inner = locator.from_function(py_func, py_file)
                if inner is not None:
                    return cls(inner, files)
            return None

    impl._locator_classes = [WithSources, *original]
    _stamped.append(WithSources)
    return True


def _source_files(module: str) -> tuple[str, ...]:
    """The files of the modules ``module``'s KernelSet names as sources (none: not a set's)."""
    import importlib.util
    import sys

    from camlab88.base.kernel_set import SETS

    kernels = SETS.get(module)
    files = []
    for name in kernels.sources if kernels is not None else ():
        loaded = sys.modules.get(name)
        path = getattr(loaded, "__file__", None)
        if path is None:
            spec = importlib.util.find_spec(name)
            path = spec.origin if spec is not None else None
        if path and os.path.exists(path):
            files.append(path)
    return tuple(files)
