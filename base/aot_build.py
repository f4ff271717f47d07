"""Build kernel modules' ahead-of-time extensions with ``numba.pycc`` (``camlab88 warm-up``).

For each module named: import it with the JIT path forced, and compile every kernel its
KernelSet exports, with the export's signature, into one extension (``numba.pycc.CC``; the
kernels the exports call are compiled into it too). Each export is compiled as a small
wrapper calling the module's own njit dispatcher, so the kernel's njit options hold as in the
JIT path. The code is compiled for the host CPU, as numba's JIT does.

The build runs in a child process: it must import the modules in JIT mode whatever this
process did, and it uses a private, temporary numba cache, so its compiles (with the
exports' declared types, which need not be the exact types a JIT caller passes, e.g. a
read-only array) never add a second signature to a kernel in the user's cache. The
extension is written to a temporary directory beside its final place and renamed into it,
so a reader never sees half a file; older extensions of the same module are then removed.
A module whose extension is up to date is not rebuilt. A module without exports (kernels
only other modules' kernels call) gets a marker file instead of an extension, so it too
loads without numba. A module whose kernels call another
kernel module's must name it in ``KernelSet(..., sources=...)`` (the key then covers its
source too); the build refuses one that does not. Needs a C compiler (pycc compiles
numba's runtime helpers with it); without one each module reports why and commands go on
using the JIT-compiled kernels.

``python -m camlab88.base.aot_build --out DIR MODULE...`` is the child's command line.
"""

from __future__ import annotations

import argparse
import importlib
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

from camlab88.base import aot_load

if TYPE_CHECKING:
    from camlab88.base.kernel_set import KernelSet

BUILT, UP_TO_DATE = "built", "up to date"


def build(modules: tuple[str, ...], where: Path | None = None,
          timeout: float = 1800.0) -> dict[str, str]:
    """Build each module's extension into ``where`` (default aot_load.directory()) unless up
    to date; {module: "built" | "up to date" | "failed: why"}."""
    where = where or aot_load.directory()
    with tempfile.TemporaryDirectory(prefix="camlab88-aot-numba-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache, **{aot_load.OFF_VARIABLE: "0"})
        root = str(Path(__file__).resolve().parents[1])
        env["PYTHONPATH"] = os.pathsep.join(p for p in (root, env.get("PYTHONPATH")) if p)
        try:
            done = subprocess.run(
                [sys.executable, "-m", "camlab88.base.aot_build", "--out", str(where), *modules],
                capture_output=True, text=True, env=env, timeout=timeout)
        except (OSError, subprocess.TimeoutExpired) as exc:
            return {m: f"failed: {type(exc).__name__}: {exc}" for m in modules}
    outcome = dict(line.split("\t", 1) for line in done.stdout.splitlines() if "\t" in line)
    last = (done.stderr.strip().splitlines() or [f"exit status {done.returncode}"])[-1]
    return {m: outcome.get(m, f"failed: {last}") for m in modules}


def build_here(module: str, where: Path) -> str:
    """Build one module's extension in this process (which must be in JIT mode)."""
    from camlab88.base.kernel_set import SETS

    importlib.import_module(module)
    kernels = SETS.get(module)
    if kernels is None:
        return "failed: no KernelSet in the module"
    if kernels.mode != "jit":
        return "failed: the module was loaded ahead of time, not JIT"
    missing = sorted(kernel_dependencies(module) - set(kernels.sources))
    if missing:  # their code would be compiled in, unseen by the key
        return (f"failed: its kernels call kernels of {', '.join(missing)}: declare them as "
                "KernelSet(__name__, sources=(...))")
    final = aot_load.path(module, aot_load.key(module, kernels.sources), where)
    if not kernels.exports:  # kernels only other modules' kernels call: a marker
        final = aot_load.kernels_only(final)
    if final.is_file():
        return UP_TO_DATE
    where.mkdir(parents=True, exist_ok=True)
    if not kernels.exports:
        with tempfile.NamedTemporaryFile(dir=where, prefix=f".{module}-", delete=False) as f:
            f.write(b"kernels compiled into the extensions of the modules calling them\n")
        os.replace(f.name, final)
    else:
        _compile(module, kernels, final)
    for old in where.glob(f"{module}-*"):  # earlier builds of the module
        if old != final and old.is_file():
            old.unlink(missing_ok=True)
    return BUILT


def _compile(module: str, kernels: KernelSet, final: Path) -> None:
    from numba.pycc import CC
    from numba.pycc.platform import external_compiler_works

    if not external_compiler_works():  # (numba's own message is about conda)
        raise NoCompiler("no working C compiler (numba.pycc needs one: gcc, say)")

    with tempfile.TemporaryDirectory(prefix=f".{module}-", dir=final.parent) as tmp:
        cc = CC(aot_load.extension_name(module), source_module=module)
        cc.output_dir = tmp
        cc.output_file = final.name
        cc.target_cpu = "host"
        for name, signature in kernels.exports.items():
            cc.export(name, signature)(_entry(name, kernels.kernels[name], signature))
        cc.compile()
        os.replace(Path(tmp) / final.name, final)


class NoCompiler(RuntimeError):
    """numba.pycc cannot build without a C compiler."""


def kernel_dependencies(module: str) -> set[str]:
    """The other kernel modules whose kernels ``module``'s kernels may call (its globals
    holding such a module or one of its compiled kernels), transitively."""
    from camlab88.base.kernel_set import SETS

    found: set[str] = set()
    todo = [module]
    while todo:
        for value in vars(importlib.import_module(todo.pop())).values():
            if isinstance(value, ModuleType):
                owner = value.__name__
            else:
                owner = getattr(getattr(value, "py_func", None), "__module__", None)
            if owner in SETS and owner != module and owner not in found:
                found.add(owner)
                todo.append(owner)
    return found


def _entry(name: str, dispatcher: object, signature: str) -> object:
    """A plain function of the export's arity calling the module's dispatcher: what pycc
    compiles (it takes Python functions, not dispatchers)."""
    from camlab88.base.aot_args import parse

    params = ", ".join(f"a{i}" for i in range(len(parse(signature))))
    namespace = {"_kernel": dispatcher}
    exec(f"def {name}({params}):\n    return _kernel({params})\n", namespace)
    return namespace[name]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m camlab88.base.aot_build")
    p.add_argument("--out", type=Path, required=True)
    p.add_argument("modules", nargs="+")
    args = p.parse_args(argv)
    failed = 0
    for module in args.modules:
        try:
            outcome = build_here(module, args.out)
        except NoCompiler as exc:
            outcome = f"failed: {exc}"
        except Exception as exc:  # reported per module; the others still build
            first = (str(exc).strip().splitlines() or [""])[0]
            outcome = f"failed: {type(exc).__name__}: {first}"
        failed += outcome.startswith("failed")
        print(f"{module}\t{outcome}", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
