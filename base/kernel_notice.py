"""Say once when compiled kernels are being built, and let Ctrl-C stop a build cleanly.

numba compiles a kernel on its first call unless its on-disk cache already holds it; on a
first run after install that is several seconds of silence. numba broadcasts a
``numba:compile`` event only when it really compiles (a cache hit loads without one), so a
listener on that event knows the cache was cold *before* the work starts. A kernel module
registers its group once (``announce_compiles("snooker", 7.0, __name__)``) and the first cold
compile of any of its kernels prints one line to stderr:

    camlab88: compiling snooker kernels, once: ~7 s

A warm run prints nothing and pays nothing (no event fires).

A group may name a *completion* (``completion="package.module:function"``) that calls every
kernel of the group once with the argument types real work uses. After the first cold
compile of such a group the completion runs as the process ends (atexit: the program's own
work and output come first, and numba cannot compile a kernel again from inside that
kernel's compile), so the whole group is compiled and cached by that first run, under the
one notice: a program that later needs another kernel of the group (the T5688's stream after
the T5684's, a second rule set after Life) loads it instead of compiling with a second
notice. ``camlab88 warm-up`` runs every group's completion, or a small command.

Ctrl-C during a build: the default handler raises KeyboardInterrupt wherever Python happens
to be, and inside llvmlite that can be a destructor or callback whose exception is only
printed ("Exception ignored ...") while the build carries on and the program exits 0. While
the outermost compile runs, SIGINT instead ends the process at once with status 130 and one
line on stderr. Nothing is lost that would have been kept: numba writes its cache files by
rename, and the project writes user files atomically (base.atomicfile).

It lives in base/ because apps, emulator and the command line may all import it. It never
imports numba itself: a group registered before numba is imported starts the listening
(and the lean cache loads) as numba's import finishes, so a process whose kernels all come
from ahead-of-time extensions never imports numba at all.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from dataclasses import dataclass, field
from typing import Any

from camlab88.base.kernel_load import lean_cache_loads

INTERRUPTED_STATUS = 130  # the shell's status for a process ended by SIGINT


@dataclass
class _Group:
    label: str
    seconds: float
    completion: str | None = None  # "module:function" that compiles the whole group
    announced: bool = False


@dataclass
class _State:
    groups: dict[str, _Group] = field(default_factory=dict)  # module name -> its group
    pending: list[_Group] = field(default_factory=list)  # cold groups to complete
    at_exit: bool = False
    depth: int = 0
    saved_handler: Any = None
    listening: bool = False


_state = _State()
_lock = threading.Lock()


def announce_compiles(label: str, seconds: float, *modules: str,
                      completion: str | None = None) -> None:
    """Register the kernels defined in `modules` as one group named `label` whose cold
    compile takes about `seconds` (measured on the project's 2-core machine); `completion`
    ("module:function") compiles the rest of the group after its first cold compile."""
    group = _Group(label, seconds, completion)
    with _lock:
        for name in modules:
            _state.groups.setdefault(name, group)
    if "numba" in sys.modules:
        _start_listening()
    else:  # nothing can compile before numba is imported; a process that never does
        _watch_for_numba()  # (ahead-of-time kernels, base/kernel_set.py) pays nothing


def _start_listening() -> None:
    with _lock:
        if not _state.listening:
            _listen()
            lean_cache_loads()  # a warm run's first kernel call: ~0.2 s less
            _state.listening = True


class _NumbaWatch:
    """Starts listening as soon as numba's own import has finished (once). A finder on
    ``sys.meta_path`` needs only ``find_spec``: importing importlib.abc for its base class
    cost ~10 ms of every start (it imports importlib.resources, tempfile and random)."""

    def find_spec(self, name: str, path: Any, target: Any = None) -> Any:
        if name != "numba":
            return None
        for finder in list(sys.meta_path):  # the spec the other finders give
            found = getattr(finder, "find_spec", None)
            spec = found(name, path, target) if finder is not self and found else None
            if spec is not None:
                break
        else:
            return None
        loader = getattr(spec, "loader", None)
        if loader is None or not hasattr(loader, "exec_module"):
            return spec
        original = loader.exec_module

        def exec_module(module: Any) -> None:  # (a spec only looked up is never executed)
            original(module)
            _unwatch()
            _start_listening()

        loader.exec_module = exec_module
        return spec


_watch = _NumbaWatch()


def _watch_for_numba() -> None:
    with _lock:
        if _watch not in sys.meta_path and not _state.listening:
            sys.meta_path.insert(0, _watch)


def _unwatch() -> None:
    with _lock:
        if _watch in sys.meta_path:
            sys.meta_path.remove(_watch)


def notice_line(label: str, seconds: float) -> str:
    """The one line printed before a cold group compiles."""
    return f"camlab88: compiling {label} kernels, once: ~{max(1, round(seconds))} s"


def _listen() -> None:
    from numba.core import event

    class CompileListener(event.Listener):
        def on_start(self, ev: Any) -> None:
            _compile_started(ev.data)

        def on_end(self, ev: Any) -> None:
            _compile_ended()

    event.register("numba:compile", CompileListener())


def _kernel_module(data: Any) -> str:
    py_func = getattr(data.get("dispatcher"), "py_func", None) if isinstance(data, dict) else None
    return getattr(py_func, "__module__", "") or ""


def _compile_started(data: Any) -> None:
    with _lock:
        _state.depth += 1
        outermost = _state.depth == 1
        group = _state.groups.get(_kernel_module(data))
        announce = group is not None and not group.announced
        if announce:
            group.announced = True
            if group.completion:
                _state.pending.append(group)
                _complete_at_exit()
    if outermost:
        _guard_sigint()
    if announce:
        print(notice_line(group.label, group.seconds), file=sys.stderr, flush=True)


def _compile_ended() -> None:
    with _lock:
        _state.depth = max(0, _state.depth - 1)
        last = _state.depth == 0
    if last:
        _unguard_sigint()


def run_completion(completion: str) -> None:
    """Call "module:function" (every kernel of one group, once)."""
    import importlib

    module, _, function = completion.partition(":")
    getattr(importlib.import_module(module), function)()


def _complete_at_exit() -> None:
    if not _state.at_exit:
        import atexit

        atexit.register(complete_pending)
        _state.at_exit = True


def complete_pending() -> None:
    """Run the completion of every group that compiled cold in this process (each once)."""
    done: set[str] = set()
    while _state.pending:
        group = _state.pending.pop(0)
        if group.completion in done:
            continue
        done.add(group.completion or "")
        try:
            run_completion(group.completion or "")
        except Exception as exc:  # a later call still compiles its own kernel
            print(f"camlab88: the rest of the {group.label} kernels were not compiled ahead "
                  f"({type(exc).__name__}: {exc})", file=sys.stderr, flush=True)


def _in_main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


def _guard_sigint() -> None:
    # Only replace Python's own handler: a program with its own SIGINT policy keeps it.
    if not _in_main_thread() or signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        return
    _state.saved_handler = signal.signal(signal.SIGINT, _interrupted)


def _unguard_sigint() -> None:
    if _state.saved_handler is not None and _in_main_thread():
        signal.signal(signal.SIGINT, _state.saved_handler)
        _state.saved_handler = None


def _interrupted(signum: int, frame: Any) -> None:
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    os.write(2, b"\ncamlab88: interrupted while compiling kernels\n")
    os._exit(INTERRUPTED_STATUS)
