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

A group names its kernels by module (every kernel of ``package.module``) or one by one
(``package.module:function``), as HashLife's kernels share one module but compile in groups.
It lives in base/ because apps, emulator and the command line may all import it; a kernel
module registers its group as it is imported (numba is imported by then).
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from dataclasses import dataclass, field
from typing import Any

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


def announce_compiles(label: str, seconds: float, *kernels: str,
                      completion: str | None = None) -> None:
    """Register the kernels named in ``kernels`` (a module: all of its kernels;
    "module:function": that one) as one group named ``label`` whose cold compile takes
    about ``seconds`` (measured on the project's 2-core machine); ``completion``
    ("module:function") compiles the rest of the group after its first cold compile."""
    group = _Group(label, seconds, completion)
    with _lock:
        for name in kernels:
            _state.groups.setdefault(name, group)
        if not _state.listening:
            _listen()
            _state.listening = True


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


def _group_of(data: Any) -> _Group | None:
    """The group of the kernel a ``numba:compile`` event is about (by its own name first)."""
    py_func = getattr(data.get("dispatcher"), "py_func", None) if isinstance(data, dict) else None
    module = getattr(py_func, "__module__", "") or ""
    found = _state.groups.get(f"{module}:{getattr(py_func, '__qualname__', '')}")
    return found if found is not None else _state.groups.get(module)


def _compile_started(data: Any) -> None:
    with _lock:
        _state.depth += 1
        outermost = _state.depth == 1
        group = _group_of(data)
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
