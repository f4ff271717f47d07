"""Host programs tested the way docs/api.md shows: a Python one on the ``sigma`` fixture and
a compiled C one on ``sigma_pty`` (built here with cc; skipped, saying so, without one)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

GOLDEN = Path(__file__).resolve().parents[1] / "data" / "bench"

C_PROGRAM = r"""
#include <fcntl.h>
#include <string.h>
#include <unistd.h>
int main(int argc, char **argv) {
    const char *s = "\r+-*/HI3GI200200GJ500200500400200400200200BH";
    char reply[16] = {0};
    int fd = open(argv[1], O_RDWR | O_NOCTTY);
    if (fd < 0) return 1;
    if (write(fd, s, strlen(s)) != (ssize_t) strlen(s)) return 2;
    if (argc > 2) {   /* a cursor read: arm the report, wait for the key and the position */
        const char *ask = "\r+-*/GHBH+-*/GICECA484356CFHF";
        int got = 0;
        write(fd, ask, strlen(ask));
        while (got < 9) {
            ssize_t n = read(fd, reply + got, 9 - got);
            if (n <= 0) return 3;
            got += n;
        }
        write(1, reply, 9);
    }
    return close(fd);
}
"""


def plot_box(port, x0: int, y0: int, x1: int, y1: int) -> None:
    """A small host program: a box through any port with write()."""
    def p(x: int, y: int) -> bytes:
        return b"%03d%03d" % (x + 100, y + 100)
    port.write(b"\r+-*/GI" + p(x0, y0) + b"GJ" + p(x1, y0) + p(x1, y1) + p(x0, y1)
               + p(x0, y0) + b"BH")


def test_a_python_host_program_draws_its_box(sigma, assert_no_protocol_errors):
    plot_box(sigma, 100, 100, 300, 200)
    sigma.run()
    assert_no_protocol_errors(sigma)
    assert sigma.screen[511 - 100, 200].any() and sigma.screen[511 - 200, 300].any()
    assert not sigma.screen[511 - 150, 200].any()  # a box, not a block


def test_a_golden_screen_compares_exactly(sigma, camlab88_golden):
    plot_box(sigma, 100, 100, 300, 200)
    sigma.run()
    camlab88_golden(sigma.screen, "python_box", GOLDEN)
    from camlab88.bench.golden import compare_golden

    with pytest.raises(AssertionError, match="pixels differ from the golden image"):
        compare_golden(sigma.screen[::-1], GOLDEN / "python_box.png", regen=False)


def _build(tmp_path) -> str:
    cc = shutil.which("cc")
    if cc is None:
        pytest.skip("no C compiler (cc) on PATH: the compiled host program is not built")
    src, exe = tmp_path / "box.c", tmp_path / "box"
    src.write_text(C_PROGRAM)
    subprocess.run([cc, "-o", str(exe), str(src)], check=True, capture_output=True)
    return str(exe)


def test_a_compiled_c_program_drives_the_terminal_through_a_pty(sigma_pty, tmp_path,
                                                                assert_no_protocol_errors):
    exe = _build(tmp_path)
    subprocess.run([exe, sigma_pty.path], check=True, timeout=10)
    sigma_pty.wait_idle()
    assert_no_protocol_errors(sigma_pty)
    screen = sigma_pty.screen()
    assert screen[511 - 100, 150].any() and screen[511 - 300, 150].any()
    assert sigma_pty.sigma.stats["bytes"] == 44


def test_a_compiled_c_program_reads_the_cursor_through_the_pty(sigma_pty, tmp_path):
    exe = _build(tmp_path)
    prog = subprocess.Popen([exe, sigma_pty.path, "cursor"], stdout=subprocess.PIPE)
    try:
        sigma_pty.wait_for(lambda s: s.machine.terminal.reg.cursor_report)  # HF has armed it
        sigma_pty.cursor(468, 356)
        sigma_pty.key("A")
        out, _ = prog.communicate(timeout=10)
    finally:
        if prog.poll() is None:
            prog.kill()
    assert prog.returncode == 0
    assert out == b"A468,356\r"


def _write_to(path: str, data: bytes) -> None:
    """A host in another process writing ``data`` flat out, then closing the pty."""
    writer = ("import os, sys\nfd = os.open(sys.argv[1], os.O_WRONLY | os.O_NOCTTY)\n"
              "v = memoryview(bytes.fromhex(sys.argv[2]))\n"
              "while v:\n    v = v[os.write(fd, v):]\n")
    subprocess.run([sys.executable, "-c", writer, path, data.hex()], check=True, timeout=60)


def test_sigma_pty_virtual_time_is_line_time_only(sigma_pty):
    """The program's writes pace the line: after a burst of N bytes the clock reads about
    N / 960 s (the line's time for them), and it stands still while the program is idle."""
    box = b"\r+-*/HI3GI200200GJ500200500400200400200200BH"
    data = box * 100  # 4400 bytes: 4.58 s of line time
    _write_to(sigma_pty.path, data)
    sigma_pty.wait_idle()
    took = sigma_pty.sigma.now
    assert len(data) / 960 <= took <= len(data) / 960 + 0.05
    sigma_pty.wait_idle(quiet=0.3)  # wall time passes with nothing written
    assert sigma_pty.sigma.now == took
    assert sigma_pty.sigma.stats["bytes"] == len(data)


@pytest.mark.parametrize("sigma_pty", [{"strict": True}], indirect=True)
def test_sigma_pty_strict_raises_the_first_protocol_error(sigma_pty):
    from camlab88 import ProtocolError

    _write_to(sigma_pty.path, b"\r+-*/GI200200QQ")  # Q starts no order
    with pytest.raises(ProtocolError, match="byte 13 .*unknown byte 0x51"):
        sigma_pty.wait_idle()


@pytest.mark.parametrize("sigma_pty", [{"trace": False, "model": "t5688"}], indirect=True)
def test_sigma_pty_options_model_and_no_trace(sigma_pty):
    assert sigma_pty.terminal.model.name.lower().endswith("5688")
    _write_to(sigma_pty.path, b"\r+-*/HI3GI200200GJ500200BH")
    sigma_pty.wait_idle()
    assert sigma_pty.sigma.trace.orders() == [] and sigma_pty.sigma.stats["bytes"] == 26
