"""Shared test set-up: headless SDL, and a private numba cache for each test process.

numba's on-disk cache is not safe when processes compile different signatures of one
kernel at the same time (tests/support/numba_cache.py): pytest-xdist workers sharing one
cache directory intermittently loaded the wrong machine code (black Rainbow frames). So:

- the controlling process makes one fresh directory for the run, ``CAMLAB88_NUMBA_RUN``,
  which the workers inherit through the environment;
- each worker (and the ``camlab88`` subprocesses it starts, one at a time) caches in its own
  subdirectory of it, assigned unconditionally: ``setdefault`` would keep the controller's
  value, which every worker inherits;
- at the end the controller checks that no cached kernel got more than one signature (the
  property that makes the cache safe for users' concurrent runs too), then removes the run.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import pytest

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

_WORKER = os.environ.get("PYTEST_XDIST_WORKER")
if _WORKER is None:  # the controller, or a run without xdist: this process owns the run
    _RUN: Path | None = Path(tempfile.mkdtemp(prefix=f"camlab88-numba-{os.getuid()}-"))
    os.environ["CAMLAB88_NUMBA_RUN"] = str(_RUN)
    os.environ["NUMBA_CACHE_DIR"] = str(_RUN / "main")
else:
    _RUN = None
    os.environ["NUMBA_CACHE_DIR"] = str(Path(os.environ["CAMLAB88_NUMBA_RUN"]) / _WORKER)


@pytest.hookimpl(hookwrapper=True, trylast=True)
def pytest_sessionfinish(session: pytest.Session, exitstatus: int):
    yield
    if _RUN is None:
        return
    from tests.support.numba_cache import overloaded_kernels

    bad = overloaded_kernels(_RUN)
    shutil.rmtree(_RUN, ignore_errors=True)
    if bad:
        tr = session.config.pluginmanager.get_plugin("terminalreporter")
        lines = [f"  {name}: {', '.join(sigs)}" for name, sigs in bad.items()]
        msg = ("numba kernels compiled with more than one signature (unsafe in numba's cache; "
               "call them with one set of argument types):\n" + "\n".join(lines))
        if tr is not None:
            tr.write_line(msg, red=True)
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
