"""One ahead-of-time build of every listed kernel module per test run, shared by the xdist
workers: built under the run's directory (tests/conftest.py) behind a file lock, so the
second worker finds the extensions up to date instead of building them again."""

from __future__ import annotations

import fcntl
import os
import tempfile
from pathlib import Path

import pytest
from camlab88.base import aot_build

from camlab88.commands.warmup.aot import AOT_MODULES


@pytest.fixture(scope="session")
def aot_dir() -> Path:
    run = Path(os.environ.get("CAMLAB88_NUMBA_RUN") or tempfile.gettempdir())
    where = run / "aot"
    where.mkdir(parents=True, exist_ok=True)
    with open(run / "aot.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        outcomes = aot_build.build(AOT_MODULES, where)
    failed = {m: o for m, o in outcomes.items() if o.startswith("failed")}
    if failed and all("C compiler" in o for o in failed.values()):
        pytest.skip(f"no working C compiler for numba.pycc: {failed}")
    assert not failed, failed
    return where
