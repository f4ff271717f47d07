"""camlab88.base.kernel_notice: one line before a cold compile, silence when warm, and Ctrl-C
during a compile ends the process cleanly (status 130, no traceback)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

from camlab88.base import kernel_notice

ROOT = Path(__file__).resolve().parents[1]

KERNEL_MODULE = """
from numba import njit
from camlab88.base.kernel_notice import announce_compiles

announce_compiles("toy", 3.4, __name__)

@njit(cache=True)
def twice(x):
    return 2 * x
"""


def _run(tmp_path: Path, code: str, cache: Path) -> subprocess.CompletedProcess[str]:
    (tmp_path / "toykernels.py").write_text(KERNEL_MODULE)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache),
               PYTHONPATH=os.pathsep.join([str(tmp_path), str(ROOT)]))
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=env,
                          capture_output=True, text=True, timeout=120)


def test_a_cold_compile_is_announced_once_and_a_warm_load_silently(tmp_path: Path) -> None:
    code = "import toykernels\nprint(toykernels.twice(21), toykernels.twice(1))\n"
    cold = _run(tmp_path, code, tmp_path / "cache")
    assert cold.returncode == 0, cold.stderr
    assert cold.stdout.split() == ["42", "2"]
    assert cold.stderr.splitlines() == [kernel_notice.notice_line("toy", 3.4)]
    assert cold.stderr == "camlab88: compiling toy kernels, once: ~3 s\n"
    warm = _run(tmp_path, code, tmp_path / "cache")
    assert warm.returncode == 0 and warm.stdout.split() == ["42", "2"]
    assert warm.stderr == ""


def test_ctrl_c_during_a_compile_ends_the_process_cleanly(tmp_path: Path) -> None:
    # A second listener sends SIGINT from inside the compile, so the signal lands mid-build
    # every time (a timed kill would race the compiler).
    code = """
    import os, signal
    from numba.core import event
    import toykernels

    class Interrupt(event.Listener):
        def on_start(self, ev):
            os.kill(os.getpid(), signal.SIGINT)
        def on_end(self, ev):
            pass

    event.register("numba:compile", Interrupt())
    toykernels.twice(21)
    print("carried on")
    """
    done = _run(tmp_path, code, tmp_path / "cache")
    assert done.returncode == kernel_notice.INTERRUPTED_STATUS
    assert "carried on" not in done.stdout
    assert "Traceback" not in done.stderr and "Exception ignored" not in done.stderr
    assert done.stderr.splitlines()[-1] == "camlab88: interrupted while compiling kernels"


def test_ctrl_c_while_the_snooker_kernels_compile(tmp_path: Path) -> None:
    """The issue's case: Ctrl-C during `snooker simulate`'s first compile."""
    code = ("from camlab88.apps.snooker.session import Session\n"
            "from camlab88.apps.snooker.layout import break_off_direction\n"
            "from camlab88.apps.snooker.table import CUE, Table\n"
            "t = Table(); s = Session.new_game(t)\n"
            "ux, uy = break_off_direction(t, s.balls); s.set_velocity(CUE, 5 * ux, 5 * uy)\n"
            "s.simulate_to_rest()\nprint('simulated')\n")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-c", code], env=env, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        first = proc.stderr.readline()  # printed just before the compile starts
        assert first.startswith("camlab88: compiling snooker kernels, once: ~"), first
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
        proc.wait()
    assert proc.returncode == kernel_notice.INTERRUPTED_STATUS, err
    assert "simulated" not in out and "Traceback" not in err


def test_the_guard_is_only_there_during_a_compile(tmp_path: Path) -> None:
    code = """
    import signal
    import toykernels
    before = signal.getsignal(signal.SIGINT)
    toykernels.twice(2)
    print(before is signal.default_int_handler, signal.getsignal(signal.SIGINT) is before)
    mine = lambda s, f: None
    signal.signal(signal.SIGINT, mine)
    toykernels.twice(2.5)  # a second compile (a new signature) under the program's handler
    print(signal.getsignal(signal.SIGINT) is mine)
    """
    done = _run(tmp_path, code, tmp_path / "cache")
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["True", "True", "True"]


def test_notice_line_rounds_to_whole_seconds() -> None:
    line = kernel_notice.notice_line("Rainbow", 8.6)
    assert line == "camlab88: compiling Rainbow kernels, once: ~9 s"
    assert kernel_notice.notice_line("KAS", 0.2).endswith("~1 s")
