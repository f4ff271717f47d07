"""camlab88.base.kernel_load: a cached kernel loads without numba's context refresh, and gives
what numba's own load gives; a later real compile, a failing lean load and the switch-off
variable all fall back to numba's behaviour."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

from camlab88.base.kernel_load import OFF_VARIABLE

ROOT = Path(__file__).resolve().parents[2]
# imported by the refresh only, never by a plain cache load
REFRESHED = "'numba.np.polynomial.polynomial_functions' in sys.modules"

KERNELS = """
import math
import numpy as np
from numba import njit
from camlab88.base.kernel_notice import announce_compiles

announce_compiles("lean toy", 1.0, __name__)

@njit(cache=True)
def wave(n):  # allocates (the memory runtime) and calls libm
    out = np.empty(n, np.float64)
    for i in range(n):
        out[i] = math.sin(0.1 * i) * math.sqrt(i + 0.5)
    return out, out.sum()
"""

CALLER = """
from numba import njit
from leantoy import wave

@njit
def doubled(n):
    out, total = wave(n)
    return 2.0 * total
"""

REPORT = """
import sys
import leantoy
out, total = leantoy.wave(37)
print(repr(total), out.tobytes().hex()[:64], leantoy.wave.stats.cache_hits.get(
    next(iter(leantoy.wave.signatures)), 0), {refreshed})
""".replace("{refreshed}", REFRESHED)


def _run(tmp: Path, code: str, **env: str) -> list[str]:
    (tmp / "leantoy.py").write_text(KERNELS)
    (tmp / "leancaller.py").write_text(CALLER)
    full = dict(os.environ, NUMBA_CACHE_DIR=str(tmp / "cache"),
                PYTHONPATH=os.pathsep.join([str(tmp), str(ROOT)]), **env)
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=full,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout.split()


def test_a_warm_load_skips_the_refresh_and_matches_numbas_own_load(tmp_path: Path) -> None:
    cold = _run(tmp_path, REPORT)
    lean = _run(tmp_path, REPORT)
    full = _run(tmp_path, REPORT, **{OFF_VARIABLE: "1"})
    assert cold[3] == "True" and cold[2] == "0"  # compiled: the compiler refreshed
    assert lean[2] == "1" and full[2] == "1"  # both loaded from the cache
    assert lean[3] == "False" and full[3] == "True"
    assert lean[:2] == full[:2] == cold[:2]


def test_a_compile_after_a_lean_load_still_works(tmp_path: Path) -> None:
    _run(tmp_path, REPORT)  # fill the cache
    code = f"""
    import sys
    import leantoy
    _, total = leantoy.wave(37)
    before = {REFRESHED}
    import leancaller
    print(before, leancaller.doubled(37) == 2.0 * total, {REFRESHED})
    """
    assert _run(tmp_path, code) == ["False", "True", "True"]


def test_a_failing_lean_load_falls_back_to_numbas_own(tmp_path: Path) -> None:
    _run(tmp_path, REPORT)
    code = f"""
    import sys
    from numba.core import caching
    real = caching.Cache._load_overload
    calls = []
    def flaky(self, sig, ctx):
        calls.append(1)
        if len(calls) == 1:
            raise RuntimeError("a numba whose internals differ")
        return real(self, sig, ctx)
    caching.Cache._load_overload = flaky
    import leantoy
    out, total = leantoy.wave(37)
    print(len(calls), leantoy.wave.stats.cache_hits[next(iter(leantoy.wave.signatures))],
          {REFRESHED}, repr(total))
    """
    fell_back = _run(tmp_path, code)
    assert fell_back[:3] == ["2", "1", "True"]
    assert fell_back[3] == _run(tmp_path, REPORT)[0]


def test_the_variable_turns_it_off(tmp_path: Path) -> None:
    code = ("from camlab88.base import kernel_load\n"
            "print(kernel_load.lean_cache_loads(), kernel_load.active())\n")
    assert _run(tmp_path, code, **{OFF_VARIABLE: "1"}) == ["False", "False"]
    assert _run(tmp_path, code, **{OFF_VARIABLE: "0"}) == ["True", "True"]


COMMANDS = {
    "snooker": (["snooker", "simulate", "--break", "5", "--out", "out.cp"], "out.cp"),
    "sigma": (["sigma", "render", "--in", str(ROOT / "examples/sigma/ral_gks_t5688.sig"),
               "--out", "out.png"], "out.png"),
    "rainbow": (["rainbow", "render", str(ROOT / "examples/rainbow/scene.json"),
                 "--out", "out.png"], "out.png"),
}


def _command(tmp: Path, argv: list[str], out: str, **env: str) -> tuple[bytes, str]:
    code = ("import sys\nfrom camlab88.cli import main\n"
            f"rc = main({argv!r})\nprint(rc, {REFRESHED}, file=sys.stderr)\n")
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp, capture_output=True,
                          text=True, timeout=600, env=dict(os.environ, **env))
    assert done.returncode == 0, done.stderr
    return (tmp / out).read_bytes(), done.stderr.splitlines()[-1]


def test_the_devices_give_the_same_bytes_loaded_either_way(tmp_path: Path) -> None:
    # the worker's own cache (tests/conftest.py): the first run may compile, the rest load
    for argv, out in COMMANDS.values():
        first, _ = _command(tmp_path, argv, out)
        lean, lean_state = _command(tmp_path, argv, out)
        full, full_state = _command(tmp_path, argv, out, **{OFF_VARIABLE: "1"})
        assert (lean_state, full_state) == ("0 False", "0 True"), argv
        assert first == lean == full, argv
