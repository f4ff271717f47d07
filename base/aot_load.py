"""Where a kernel module's ahead-of-time extension lives, when it is up to date, and loading it
without importing numba.

``camlab88 warm-up`` builds one extension per listed kernel module (base/aot_build.py) into a
per-user directory: ``$CAMLAB88_AOT_DIR`` if set, else ``camlab88-aot`` inside
``$NUMBA_CACHE_DIR`` (beside numba's own cache) if that is set, else
``~/.cache/camlab88/aot`` (``$XDG_CACHE_HOME`` honoured). The file name carries a key: a
hash of the module's source and the sources it declares, of the files that build and load
these extensions, of numba's and numpy's versions, of the Python build and of the CPU (the
code is compiled for the host's instruction set). A module whose key has no file — never
built, edited since, another numba, another machine — is simply not found, and its kernels
are JIT-compiled as before. ``CAMLAB88_AOT=0`` turns the extensions off.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import importlib.util
import os
import sys
from pathlib import Path
from types import ModuleType

import numpy as np

OFF_VARIABLE = "CAMLAB88_AOT"
DIR_VARIABLE = "CAMLAB88_AOT_DIR"
FORMAT = "1"  # bump when the extensions' layout or contents change in a way the files miss
_HERE = Path(__file__).resolve().parent
# the files whose change changes what a build makes
_BUILD_FILES = ("kernel_set.py", "aot_load.py", "aot_build.py")
_SUFFIX = importlib.machinery.EXTENSION_SUFFIXES[0]
_shared: list[bytes] = []  # the part of every key that is the same for all modules


def enabled() -> bool:
    """False when ``CAMLAB88_AOT`` turns the ahead-of-time path off."""
    return os.environ.get(OFF_VARIABLE, "") not in ("0", "off", "no", "false")


def directory() -> Path:
    """The directory holding the built extensions (see the module doc)."""
    own = os.environ.get(DIR_VARIABLE)
    if own:
        return Path(own)
    numba_cache = os.environ.get("NUMBA_CACHE_DIR")
    if numba_cache:
        return Path(numba_cache) / "camlab88-aot"
    home = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(home) / "camlab88" / "aot"


def extension_name(module: str) -> str:
    """The extension's own (init function) name for kernel module ``module``."""
    return "camlab88_aot_" + module.replace(".", "_")


def source_files(module: str, sources: tuple[str, ...] = ()) -> list[Path]:
    """The module's file and the files of the modules it declares as ``sources``."""
    files = []
    for name in (module, *sources):
        loaded = sys.modules.get(name)
        origin = getattr(loaded, "__file__", None) if loaded else None
        if origin is None:
            spec = importlib.util.find_spec(name)
            origin = spec.origin if spec else None
        if not origin:
            raise ImportError(f"no source file for kernel module {name}")
        files.append(Path(origin))
    return files


def key(module: str, sources: tuple[str, ...] = ()) -> str:
    """The key of the extension built from the module's current sources (module doc)."""
    h = hashlib.sha256(_shared_part())
    h.update(module.encode())
    for path in source_files(module, sources):
        h.update(path.read_bytes())
    return h.hexdigest()[:20]


def path(module: str, key_: str, where: Path | None = None) -> Path:
    """The file of ``module``'s extension with key ``key_``."""
    return (where or directory()) / f"{module}-{key_}{_SUFFIX}"


def kernels_only(extension: Path) -> Path:
    """The marker a build leaves for a module without exports (its kernels are compiled
    into the extensions of the modules calling them): there is no extension to load, but
    its sources are the ones those extensions were built from."""
    return extension.with_name(extension.name.removesuffix(_SUFFIX) + ".kernels-only")


def load(module: str, sources: tuple[str, ...] = ()) -> tuple[ModuleType | None, str]:
    """(the module's up-to-date extension, "") or (None, why not)."""
    if not enabled():
        return None, f"{OFF_VARIABLE} is off"
    try:
        file = path(module, key(module, sources))
        if not file.is_file():
            if kernels_only(file).is_file():  # built: nothing to load, nothing to compile
                return ModuleType(extension_name(module)), ""
            return None, "not built for these sources"
        name = extension_name(module)
        loader = importlib.machinery.ExtensionFileLoader(name, str(file))
        spec = importlib.util.spec_from_file_location(name, file, loader=loader)
        if spec is None:
            return None, "not loadable"
        extension = importlib.util.module_from_spec(spec)
        loader.exec_module(extension)
        return extension, ""
    except Exception as exc:  # any failure to load means the JIT path
        return None, f"not loadable ({type(exc).__name__}: {exc})"


def _shared_part() -> bytes:
    if not _shared:
        parts = [FORMAT, sys.version, importlib.machinery.EXTENSION_SUFFIXES[0],
                 np.__version__, _numba_version(), _cpu()]
        parts += [(_HERE / f).read_text() for f in _BUILD_FILES]
        _shared.append("\0".join(parts).encode())
    return _shared[0]


def _numba_version() -> str:
    """numba's version file, found without importing numba."""
    spec = importlib.machinery.PathFinder.find_spec("numba")  # (no import hooks run)
    if spec is None or not spec.submodule_search_locations:
        return "no numba"
    try:
        return (Path(spec.submodule_search_locations[0]) / "_version.py").read_text()
    except OSError:
        return str(spec.origin)


def _cpu() -> str:
    """The processor's model and instruction-set flags (the code uses the host's)."""
    try:
        text = Path("/proc/cpuinfo").read_text()
    except OSError:
        import platform

        return f"{platform.machine()} {platform.processor()}"
    wanted = ("model name", "flags", "Features", "CPU part")
    lines = [ln for ln in text.splitlines() if ln.split(":")[0].strip() in wanted]
    return "\n".join(dict.fromkeys(lines))  # the first core's lines (the others repeat)
