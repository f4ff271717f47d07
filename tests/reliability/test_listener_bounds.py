"""`sigma run` serving a line is bounded whatever a client sends (docs/reliability.md,
"Listeners"): it takes at most MAX_QUEUED bytes beyond what the 9600-baud line has carried,
the rest waits outside (TCP flow control, the pty's kernel buffer), and nothing from outside
is kept unless --record. So its memory stays flat across 100 MB offered by successive
clients; idle, it sleeps; quick reconnects are not held back by the listen backlog. Servers
the tests start, on 127.0.0.1 ports they open, killed by pid; every wait bounded."""

from __future__ import annotations

import errno
import os
import select
import socket
import time

from tests.support.listeners import cpu_seconds, port_of, rss_mb, start, stop

MB = 1 << 20
CLIENTS = 4
OFFERED_EACH = 25 * MB  # 100 MB offered in all
BUDGET_EACH = 2.0  # wall seconds a client keeps offering
CHUNK = bytes(range(0x20, 0x7F)) * (64 * 1024 // 95)  # printable: drawn as alpha text


def _offer_tcp(port: int, offered: int = OFFERED_EACH) -> int:
    """Connect, offer ``offered`` bytes without ever blocking for BUDGET_EACH s, close
    (with megabytes still unsent in its kernel); returns the bytes the kernel accepted."""
    accepted = 0
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.setblocking(False)
        end = time.monotonic() + BUDGET_EACH
        while accepted < offered and time.monotonic() < end:
            try:
                accepted += s.send(CHUNK[:offered - accepted])
            except BlockingIOError:
                time.sleep(0.005)
            except (BrokenPipeError, ConnectionResetError):
                break
    return accepted


def _offer_pty(path: str, offered: int = OFFERED_EACH) -> int:
    """Open the pty as a writer, offer ``offered`` bytes without blocking, close it."""
    accepted = 0
    fd = os.open(path, os.O_WRONLY | os.O_NONBLOCK | os.O_NOCTTY)
    try:
        end = time.monotonic() + BUDGET_EACH
        while accepted < offered and time.monotonic() < end:
            try:
                accepted += os.write(fd, CHUNK[:offered - accepted])
            except BlockingIOError:
                time.sleep(0.005)
            except OSError as exc:
                if exc.errno != errno.EAGAIN:
                    raise
                time.sleep(0.005)
    finally:
        os.close(fd)
    return accepted


def _flat(pid: int, offer, where) -> tuple[float, float, int]:
    """The server's RSS once it has served one byte, then across CLIENTS successive clients
    offering OFFERED_EACH bytes each: (start RSS, peak RSS, bytes accepted)."""
    offer(where, 1)
    time.sleep(0.5)
    base = peak = rss_mb(pid)
    accepted = 0
    for _ in range(CLIENTS):
        accepted += offer(where)
        peak = max(peak, rss_mb(pid))
    time.sleep(0.5)
    return base, max(peak, rss_mb(pid)), accepted


def test_memory_stays_flat_across_100_mb_offered_by_successive_tcp_clients() -> None:
    proc, first = start(["sigma", "run", "--headless", "--listen", "0"])
    try:
        base, peak, accepted = _flat(proc.pid, _offer_tcp, port_of(first))
        assert proc.poll() is None, "the server died"
    finally:
        out, err = stop(proc)
    assert "Traceback" not in err, err
    assert peak - base < 20, f"RSS {base:.0f} -> {peak:.0f} MB; kernel took {accepted} bytes"
    assert "refused" not in err, err  # each client was served in turn, none held the line


def test_memory_stays_flat_and_the_writer_waits_on_the_pty() -> None:
    # --speed 1: the line paced, so the writer has to wait (without it the line takes what
    # the host writes flat out: docs/api.md, "What paces what"); memory stays flat either way
    proc, first = start(["sigma", "run", "--headless", "--pty", "--speed", "1"])
    try:
        assert "on pty" in first, first
        base, peak, accepted = _flat(proc.pid, _offer_pty, first.split()[-1])
        assert proc.poll() is None, "the server died"
    finally:
        out, err = stop(proc)
    assert "Traceback" not in err, err
    assert peak - base < 20, f"RSS {base:.0f} -> {peak:.0f} MB; the pty took {accepted} bytes"
    # A real port makes a fast writer wait: 8 s of offering, ~1 KB/s going down the line,
    # so the writers got no further than the kernel's pty buffer and our 4 KiB queue
    assert accepted < 2 * MB, accepted


def test_an_idle_headless_listener_sleeps() -> None:
    proc, first = start(["sigma", "run", "--headless", "--listen", "0"])
    try:
        port = port_of(first)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
            s.sendall(b"\r\n+-*/GI100100")  # served once, then idle with a client connected
            time.sleep(1.0)
            c0, t0 = cpu_seconds(proc.pid), time.monotonic()
            time.sleep(2.5)
            c1, t1 = cpu_seconds(proc.pid), time.monotonic()
    finally:
        stop(proc)
    share = (c1 - c0) / (t1 - t0)
    assert share < 0.05, f"{share:.0%} of a core while idle"


def test_clients_that_reconnect_at_once_are_not_held_back() -> None:
    proc, first = start(["sigma", "run", "--headless", "--listen", "0"])
    times = []
    try:
        port = port_of(first)
        for _ in range(30):  # a burst: connect and leave, faster than the server polls
            t0 = time.monotonic()
            socket.create_connection(("127.0.0.1", port), timeout=5).close()
            times.append(time.monotonic() - t0)
        held = []
        for _ in range(4):  # and newcomers while a client holds the line
            t0 = time.monotonic()
            held.append(socket.create_connection(("127.0.0.1", port), timeout=5))
            times.append(time.monotonic() - t0)
        for s in held:
            s.close()
    finally:
        stop(proc)
    # a dropped SYN is sent again after 1 s: that is what a too-short backlog costs
    assert max(times) < 0.5, f"a connect took {max(times):.2f} s"


def test_a_live_client_held_by_the_line_keeps_it_and_sees_nothing_of_a_newcomer() -> None:
    # --speed 1: a paced line, so the client's second of sending is a second of line time,
    # well inside its session time (flat out, that second is minutes of line time, and a
    # client over its session time gives way to the newcomer: test_listener_session_time)
    proc, first = start(["sigma", "run", "--headless", "--listen", "0", "--speed", "1"])
    try:
        port = port_of(first)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as live:
            live.setblocking(False)
            sent, end = 0, time.monotonic() + 1.0
            while time.monotonic() < end:  # far more than the line can take: it waits
                try:
                    sent += live.send(CHUNK)
                except BlockingIOError:
                    time.sleep(0.01)
            with socket.create_connection(("127.0.0.1", port), timeout=5) as newcomer:
                newcomer.settimeout(5)
                assert newcomer.recv(200).startswith(b"camlab88: another client")
            time.sleep(0.3)
            try:
                got = live.recv(100)  # the probe's urgent byte is not in its data
            except BlockingIOError:
                got = None
            watch = select.poll()
            watch.register(live, select.POLLOUT)
            alive = not any(ev & (select.POLLERR | select.POLLHUP) for _, ev in watch.poll(0))
            alive = alive and live.getsockopt(socket.SOL_SOCKET, socket.SO_ERROR) == 0
    finally:
        out, err = stop(proc)
    assert got is None, got
    assert alive
    assert "refused" in err and "disconnected" not in err.split("refused")[0], err
