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
