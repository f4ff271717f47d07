"""Helpers for the listener tests: real sockets on 127.0.0.1 ports the tests open, servers
the tests start (and kill by pid), every wait bounded."""

from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import sys
import time
from fractions import Fraction

from camlab88.protocols.link import LineSettings, SerialLine
from camlab88.protocols.link.transports import TcpBridge

STEP = Fraction(1, 100)


def echo_step(bridge: TcpBridge, line: SerialLine, k: int, wait: float = 0.0) -> int:
    """One step of the echo device (as protocols.link.cli.run_echo does), waiting at most
    ``wait`` real seconds for the sockets; returns k + 1."""
    line.clock.advance_to(k * STEP)
    bridge.poll(timeout=wait)
    data = line.device.read()
    if data:
        line.device.write(data)
    return k + 1


class EchoLine:
    """The echo device on a fresh line, its host end a TcpBridge on a 127.0.0.1 port the test
    opens (``with EchoLine() as echo``); ``step(n)`` runs it n steps of the virtual clock,
    each waiting at most ``wait`` real seconds for the sockets."""

    def __init__(self, wait: float = 0.0) -> None:
        self.line = SerialLine(LineSettings())
        self.bridge = TcpBridge(0, endpoint=self.line.host)
        self.wait, self.k = wait, 0

    def connect(self) -> socket.socket:
        return socket.create_connection(("127.0.0.1", self.bridge.port), timeout=5)

    def step(self, n: int = 1) -> None:
        for _ in range(n):
            self.k = echo_step(self.bridge, self.line, self.k, self.wait)

    def __enter__(self) -> EchoLine:
        return self

    def __exit__(self, *exc: object) -> None:
        self.bridge.close()


def drain(s: socket.socket) -> bytes:
    """What the socket has for us now (never blocks)."""
    s.setblocking(False)
    out = b""
    while True:
        try:
            chunk = s.recv(65536)
        except (BlockingIOError, ConnectionResetError):
            return out
        if not chunk:
            return out
        out += chunk


def start(args: list[str], cwd: str | None = None) -> tuple[subprocess.Popen, str]:
    """``python -m camlab88 ARGS`` headless; returns the process and its first line."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    proc = subprocess.Popen([sys.executable, "-m", "camlab88", *args], cwd=cwd, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = proc.stdout.readline()
    if not first:
        proc.kill()
        raise AssertionError(f"{args} printed nothing: {proc.communicate(timeout=10)}")
    return proc, first


def port_of(first_line: str) -> int:
    m = re.search(r"127\.0\.0\.1:(\d+)", first_line)
    assert m, first_line
    return int(m[1])


def stop(proc: subprocess.Popen) -> tuple[str, str]:
    """Stop the server we started (Ctrl-C, then SIGKILL after 10 s; by its pid) and
    collect its output."""
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
        try:
            return proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
    return proc.communicate(timeout=30)


def rss_mb(pid: int) -> float:
    with open(f"/proc/{pid}/status", encoding="ascii") as fh:
        for line in fh:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    raise AssertionError(f"no VmRSS for {pid}")


def cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat", encoding="ascii") as fh:
        fields = fh.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def wait_for(predicate, timeout: float, every: float = 0.05) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(every)
    return predicate()


def wait_idle(pid: int, timeout: float = 30.0, window: float = 0.3) -> bool:
    """Wait until process ``pid`` uses under 10 % of a core over ``window`` seconds (it has
    dealt with what it was sent: drawn it, compiled what it needed); bounded."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        c0 = cpu_seconds(pid)
        time.sleep(window)
        if cpu_seconds(pid) - c0 < 0.1 * window:
            return True
    return False
