"""Kernel sets of one process run one way: a module taking the JIT path (not built) whose
kernels call kernels of modules loaded ahead of time turns those into JIT ones, so compiled
code only ever meets numba dispatchers; Python callers keep working throughout."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from camlab88.base import aot_load

ROOT = Path(__file__).resolve().parents[2]

TOY = """
import numpy as np
from camlab88.apps.ca import grid_stats
from camlab88.apps.ca.rle_scan import _KIND, _STATE, _symbol
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__)


@kernels.export("int64(uint8[::1])")
def symbols_and_ones(b):
    n = 0
    for i in range(b.shape[0]):
        state, length = _symbol(b, i, _KIND, _STATE)  # a plain kernel of rle_scan
        n += length
    return n + grid_stats._histogram(b)[1]  # an export of grid_stats
"""

CODE = """
import sys
import numpy as np
import camlab88.apps.ca.grid_stats as g, camlab88.apps.ca.rle_scan as r
grid = np.array([[0, 1], [1, 7]], np.uint8)
before = (g.kernels.mode, r.kernels.mode, g.by_type(grid))
import mixedtoy
after = (g.kernels.mode, r.kernels.mode, mixedtoy.kernels.mode, g.by_type(grid))
b = np.frombuffer(b"3o$1b!x", np.uint8).copy()
b[6] = 1
print(before, after, mixedtoy.symbols_and_ones(b))
"""


def test_a_jit_module_calling_ahead_of_time_kernels(aot_dir: Path, tmp_path: Path) -> None:
    (tmp_path / "mixedtoy.py").write_text(TOY)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]),
               **{aot_load.DIR_VARIABLE: str(aot_dir), aot_load.OFF_VARIABLE: "1"})
    done = subprocess.run([sys.executable, "-c", CODE], env=env, capture_output=True,
                          text=True, timeout=600, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    census = "{1: 2, 7: 1}"
    # of the bytes of "3o$1b!" four ('o', '$', 'b', '!') are symbols; one byte is 1
    assert done.stdout == (f"('aot', 'aot', {census}) ('jit', 'jit', 'jit', {census}) 5\n")
