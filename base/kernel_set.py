"""The numba kernels of one module, declared through one object instead of bare ``njit``.

A kernel module writes ``kernels = KernelSet(__name__)`` and decorates each kernel with
``@kernels.kernel`` (called only by other kernels) or ``@kernels.export("signature")``
(called from Python; the one numba signature its Python callers use, e.g.
``"int64(uint8[:, ::1], int64)"``); ``kernels.specialise(template, name, signature,
**bindings)`` makes an export of a plain function's code with some of its globals bound to
other kernels (one template for several kinds of argument, each export with one signature
as numba's cache needs: two processes compiling two signatures of one kernel can swap their
machine code). A set may name ``sources``: other modules whose code its kernels compile in
(their kernels called from this module's), so an edit there counts too.

Two ways to run, chosen when the set is made:

* **ahead of time**: an up-to-date extension built from this module by
  ``camlab88 warm-up`` (base/aot_build.py) exists (base/aot_load.py says where and when it
  is up to date). Then numba is never imported: each ``export`` is the extension's function
  behind a check of its argument types (base/aot_args.py), each ``kernel`` stays the plain
  Python function (only compiled code calls it, and that is in the extension).
* **just in time** otherwise (no extension, a stale one, ``CAMLAB88_AOT=0``, or another
  kernel set of the process already JIT: see the end of this file): every kernel is
  ``njit(cache=True, ...)`` exactly as a bare decorator would make it.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from types import FunctionType, ModuleType
from typing import Any

from camlab88.base import aot_args, aot_load

SETS: dict[str, KernelSet] = {}  # module name -> its set (the build looks them up here)


class KernelSet:
    """The kernels of one module: which exist, which Python calls, with what types."""

    def __init__(self, module: str, sources: tuple[str, ...] = (), **options: Any) -> None:
        self.module = module
        self.sources = sources
        self.options = options                  # njit options shared by the module's kernels
        self.exports: dict[str, str] = {}       # kernel name -> numba signature
        self.kernels: dict[str, Callable[..., Any]] = {}  # name -> compiled (or plain) kernel
        self.python: dict[str, tuple[Callable[..., Any], dict[str, Any]]] = {}  # plain, options
        self.aot: ModuleType | None = None
        if aot_load.enabled() and any(s.aot is None for s in SETS.values()):
            self.why_jit = _MIXED
        else:
            self.aot, self.why_jit = aot_load.load(module, sources)
        SETS[module] = self
        if self.aot is None:
            _all_jit()

    def _to_jit(self) -> dict[int, tuple[Any, Any]]:
        """Give up the extension: every kernel njit-compiled; {id(old): (old, new)} for the
        plain functions and checked exports replaced."""
        njit = _njit()
        swaps: dict[int, tuple[Any, Any]] = {}
        for name, (fn, options) in self.python.items():
            compiled = njit(cache=True, **options)(fn)
            for old in (self.kernels[name], fn):
                swaps[id(old)] = (old, compiled)
            self.kernels[name] = compiled
        self.aot, self.why_jit = None, _MIXED
        return swaps

    @property
    def mode(self) -> str:
        """"aot" when the kernels come from the ahead-of-time extension, else "jit"."""
        return "aot" if self.aot is not None else "jit"

    def kernel(self, fn: Callable[..., Any] | None = None, **options: Any) -> Any:
        """``@kernels.kernel`` or ``@kernels.kernel(_nrt=False)``: a kernel other kernels call."""
        if fn is None:
            return lambda f: self.kernel(f, **options)
        merged = {**self.options, **options}
        self.python[fn.__name__] = (fn, merged)
        if self.aot is not None:
            self.kernels[fn.__name__] = fn  # compiled into the extension's exports
            return fn
        compiled = _njit()(cache=True, **merged)(fn)
        self.kernels[fn.__name__] = compiled
        return compiled

    def export(self, signature: str, **options: Any) -> Callable[[Callable[..., Any]], Any]:
        """``@kernels.export("int64(int64, int64[:, :])")``: a kernel Python code calls."""
        aot_args.parse(signature)  # a signature the ahead-of-time path cannot check fails now

        def declare(fn: Callable[..., Any]) -> Any:
            name = fn.__name__
            self.exports[name] = signature
            if self.aot is None:
                return self.kernel(fn, **options)
            built = getattr(self.aot, name, None)
            if built is None:  # built from these very sources, so a broken build
                where = getattr(self.aot, "__file__", f"the build of {self.module}")
                raise ImportError(f"{where} has no kernel {name}: delete it and run "
                                  "camlab88 warm-up again")
            self.python[name] = (fn, {**self.options, **options})
            wrapped = aot_args.checked(built, name, signature)
            self.kernels[name] = wrapped
            return wrapped
        return declare

    def specialise(self, template: Callable[..., Any], name: str, signature: str | None,
                   options: dict[str, Any] | None = None, **bindings: Any) -> Any:
        """An export named ``name`` compiled from ``template``'s code with the globals
        named in ``bindings`` bound to those values, and the template's own name to the
        export itself (a recursive template recurses into its specialisation); a kernel
        (called only by other kernels) if ``signature`` is None.  Call it after the
        template's globals are defined: the export sees them as they are then."""
        namespace = dict(template.__globals__, **bindings)
        fn = FunctionType(template.__code__, namespace, name, template.__defaults__,
                          template.__closure__)
        fn.__qualname__ = name  # numba's cache names its files by it: one index each
        fn.__module__, fn.__doc__ = template.__module__, template.__doc__
        namespace[template.__name__] = fn  # replaced by the kernel in the JIT path
        if signature is None:
            exported = self.kernel(fn, **(options or {}))
        else:
            exported = self.export(signature, **(options or {}))(fn)
        if self.aot is None:
            namespace[template.__name__] = exported
        return exported


def _njit() -> Any:
    """numba's njit, with its cache made to notice edits of a kernel's ``sources`` too."""
    from camlab88.base import raw_views
    from camlab88.base.kernel_load import stamps_cover_sources
    from numba import njit

    stamps_cover_sources()
    raw_views.arm()  # kernels may hand arrays to each other by address
    return njit


# Compiled code can only call a kernel of another module that is a numba dispatcher, so the
# kernel sets of one process all run one way: the first set that takes the JIT path (its
# module not built, or edited since) turns every ahead-of-time set into JIT ones, rebinding
# their kernels and exports wherever kernel code looks them up (the modules' globals), and
# every later set takes the JIT path too. numba is imported by then anyway.
_MIXED = "another kernel module of this process is JIT-compiled"


def _all_jit() -> None:
    swaps: dict[int, tuple[Any, Any]] = {}  # (the old objects kept alive: ids stay theirs)
    for kernel_set in SETS.values():
        if kernel_set.aot is not None:
            swaps.update(kernel_set._to_jit())
    if not swaps:
        return
    namespaces = {id(d): d for d in (
        [vars(m) for m in map(sys.modules.get, SETS) if m is not None]
        + [fn.__globals__ for s in SETS.values() for fn, _ in s.python.values()])}
    for namespace in namespaces.values():
        for key, value in list(namespace.items()):
            swap = swaps.get(id(value))
            if swap is not None and swap[0] is value:
                namespace[key] = swap[1]
