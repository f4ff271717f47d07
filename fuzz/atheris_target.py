"""Coverage-guided fuzzing of one target with atheris (libFuzzer):
``python -m fuzz.atheris_target NAME [libFuzzer flags] SCRATCH_DIR SEED_DIR``.
New inputs go to the first directory (scratch), never into the repository's corpus.

Only our Python layer is instrumented. atheris rewrites the bytecode of every loaded
function to call its tracer; numba compiles a kernel from its function's bytecode, and a
kernel compiled after that fails with "Unknown attribute '_trace_branch' of type
Module(atheris)" (a false crash). So every function of a module that holds numba kernels
(a dispatcher, or a module registered with base.kernel_notice) keeps its original bytecode:
the kernels run compiled and uninstrumented, and their Python callers are still covered.
So does everything outside our packages (numba's compiler above all: instrumented, a
kernel's first compile took minutes).
"""

from __future__ import annotations

import gc
import sys
import types
from typing import Any

import atheris

from fuzz.targets import TARGETS

OURS = ("apps", "protocols", "emulator", "camlab88")  # the packages whose code is fuzzed


def _holds_kernels(module: Any) -> bool:
    dispatcher = getattr(sys.modules.get("numba.core.dispatcher"), "Dispatcher", None)
    return dispatcher is not None and any(isinstance(v, dispatcher) for v in vars(module).values())


def kernel_modules() -> set[str]:
    """Names of the loaded modules whose functions numba compiles (or may compile later)."""
    notice = sys.modules.get("camlab88.base.kernel_notice")
    names = {n.split(":")[0] for n in notice._state.groups} if notice is not None else set()
    names |= {name for name, mod in list(sys.modules.items())
              if mod is not None and _holds_kernels(mod)}
    return names


def instrument_python_layer() -> int:
    """atheris.instrument_all(), then the original bytecode back for the kernel modules'
    functions; returns how many functions were kept uninstrumented."""
    kernels = kernel_modules()
    original = {f: f.__code__ for f in gc.get_objects()
                if isinstance(f, types.FunctionType) and _uninstrumented(f, kernels)}
    atheris.instrument_all()
    for f, code in original.items():
        f.__code__ = code
    return len(original)


def _uninstrumented(f: types.FunctionType, kernels: set[str]) -> bool:
    module = f.__module__ or ""
    return module in kernels or module.split(".")[0] not in OURS


def main() -> None:
    target = TARGETS[sys.argv[1]]
    for seed in target.seeds()[:1]:
        target.check(seed)  # import everything the target uses, so it gets instrumented
    instrument_python_layer()
    atheris.Setup([sys.argv[0], *sys.argv[2:]], target.check)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
