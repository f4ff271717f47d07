"""The numba kernels of one module, declared through one object instead of bare ``njit``.

A kernel module writes ``kernels = KernelSet(__name__)`` and decorates each kernel with
``@kernels.kernel`` (called only by other kernels) or ``@kernels.export("signature")``
(called from Python; the one numba signature its Python callers use, e.g.
``"int64(uint8[:, ::1], int64)"``); ``@kernels.by_types`` makes a kernel whose body is
chosen from its arguments' numba types when a caller compiles (numba compiles both sides of
a run-time branch: a choice by type compiles only the side the types need). A set may name
``sources``: other modules whose code its kernels compile in (their kernels called from
this module's), so an edit there counts too.

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
from types import ModuleType
from typing import Any

from base import aot_args, aot_load

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
        self.choices: dict[str, tuple[Callable[..., Any], Callable[..., Any]]] = {}  # stub, pick
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
        from numba import njit

        swaps: dict[int, tuple[Any, Any]] = {}
        for name, (fn, options) in self.python.items():
            compiled = njit(cache=True, **options)(fn)
            for old in (self.kernels[name], fn):
                swaps[id(old)] = (old, compiled)
            self.kernels[name] = compiled
        for stub, pick in self.choices.values():
            _choose(stub, pick)
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
        from numba import njit

        compiled = njit(cache=True, **merged)(fn)
        self.kernels[fn.__name__] = compiled
        return compiled

    def by_types(self, pick: Callable[..., Any]) -> Callable[..., Any]:
        """``@kernels.by_types`` on ``pick(arg, ...)``, which is given the numba types of a
        call's arguments and returns the kernel to run (one of its arguments' names each):
        a kernel other kernels call, compiled into them as that kernel's call only."""
        stub = _signature_like(pick, "raise TypeError('only compiled kernels call this')")
        self.choices[pick.__name__] = (stub, pick)
        if self.aot is None:
            _choose(stub, pick)
        return stub

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


def is_none(numba_type: Any) -> bool:
    """Whether a numba type (as ``by_types`` picks are given) is None's."""
    return type(numba_type).__name__ in ("NoneType", "Omitted") or numba_type is None


def _params(fn: Callable[..., Any]) -> str:
    return ", ".join(fn.__code__.co_varnames[:fn.__code__.co_argcount])


def _signature_like(fn: Callable[..., Any], body: str,
                    namespace: dict[str, Any] | None = None) -> Callable[..., Any]:
    """A new function with ``fn``'s name and parameters and the one-line ``body``."""
    namespace = dict(namespace or {})
    exec(f"def {fn.__name__}({_params(fn)}):\n    {body}\n", namespace)
    made = namespace[fn.__name__]
    made.__doc__, made.__module__ = fn.__doc__, fn.__module__
    return made


def _choose(stub: Callable[..., Any], pick: Callable[..., Any]) -> None:
    """Register ``pick`` with numba: a call of ``stub`` compiles as a call of the kernel
    ``pick`` returns for the call's types (inlined: nothing costs more than that call).
    numba wants the typing function and the implementation with the stub's parameters."""
    from numba.extending import overload

    def implementation(*types: Any) -> Callable[..., Any]:
        call = f"return _chosen({_params(pick)})"
        return _signature_like(pick, call, {"_chosen": pick(*types)})

    typing = _signature_like(pick, f"return _implementation({_params(pick)})",
                             {"_implementation": implementation})
    overload(stub, inline="always")(typing)


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
