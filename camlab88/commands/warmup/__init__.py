"""``camlab88 warm-up``: compile every numba kernel now, once, with a progress line.

After install each kernel group compiles on the first run that needs it (one notice line;
base.kernel_notice). ``warm-up`` does all of it at once instead — useful before a demo
to an audience, or in CI so every test process loads the kernels from one cache. Each step
is a group's own completion (every kernel of the group called once) or, for groups without
one, a small command run in a scratch directory, in this process, so the kernels land in the
same cache every later command reads (numba's own, ``cache=True``: ``NUMBA_CACHE_DIR``, which
the command sets per user).
"""

from __future__ import annotations

import argparse
import sys

NAME = "warm-up"
COMMAND = f"camlab88 {NAME}"

# (what, a completion "module:function" or a camlab88 command line); order: cheapest first
STEPS: tuple[tuple[str, str | tuple[str, ...]], ...] = (
    ("KAS in-betweener", ("kas", "inbetween", "walk_a", "walk_b", "--path", "walk_path",
                          "--timing", "walk_ticks", "--out", "w.kas")),
    ("Sigma raster", "camlab88.emulator.sigma.kernel_warmup:compile_kernels"),
    ("snooker", ("snooker", "simulate", "--break", "5", "--out", "b.cp")),
    ("Rainbow", "camlab88.emulator.rainbow.kernel_warmup:compile_kernels"),
    ("KAS painting", ("demo", "--headless", "--only", "paint", "--out", "demo")),
    ("snooker visualiser and renderer",
     ("demo", "--headless", "--only", "snooker_camera", "--only", "film", "--out", "demo")),
    ("cellular automaton", ("ca", "run", "--rules", "life", "--pattern", "glider",
                            "--generations", "4", "--engine", "direct")),
    ("HashLife", "camlab88.apps.ca.hashlife.kernel_warmup:compile_kernels"),
)

DESCRIPTION = """\
Compile every kernel group of every program into numba's cache now, with a progress line, \
instead of on the first run that needs each group. Later commands load them from the cache \
(NUMBA_CACHE_DIR if set; the camlab88 command sets it to ~/.cache/camlab88/numba otherwise)."""


HELP = "compile every numba kernel now (otherwise: on first use)"


def run(args: argparse.Namespace) -> int:
    import time

    start = time.perf_counter()
    status = _steps(len(STEPS))
    if status:
        return status
    print(f"camlab88 warm-up: every kernel compiled in {time.perf_counter() - start:.0f} s",
          file=sys.stderr)
    return 0


def _steps(total: int) -> int:
    import contextlib
    import io
    import tempfile
    import time

    from camlab88.base.kernel_notice import complete_pending, run_completion

    with tempfile.TemporaryDirectory(prefix="camlab88-warm-up-") as scratch:
        for i, (what, step) in enumerate(STEPS, 1):
            print(f"[{i}/{total}] {what} ...", end="", file=sys.stderr, flush=True)
            t0 = time.perf_counter()
            with contextlib.redirect_stdout(io.StringIO()), contextlib.chdir(scratch):
                failed = _step(step, run_completion)
                complete_pending()  # a command's groups finish here, not at exit
            took = time.perf_counter() - t0
            print(f" {'FAILED: ' + failed if failed else 'done'} ({took:.1f} s)",
                  file=sys.stderr, flush=True)
            if failed:
                return 1
    return 0


def _step(step: str | tuple[str, ...], run_completion) -> str:
    """'' when the step worked, else why not."""
    if isinstance(step, str):
        run_completion(step)
        return ""
    from camlab88.cli import main

    status = main(list(step))
    return f"`camlab88 {' '.join(step)}` exited {status}" if status else ""

