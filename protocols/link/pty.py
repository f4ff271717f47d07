"""A pseudo-terminal in raw mode that any program can open as a serial port.

The emulator holds the master side; a program opens ``slave_path`` (e.g. with pyserial's
``serial.Serial(slave_path)``) as if it were /dev/ttyS0. We keep our own handle on the slave
open so the pty survives clients coming and going and reads never fail with EIO.
"""

from __future__ import annotations

import errno
import fcntl
import os
import select
import termios
import tty

# Bytes a client has not read yet are kept up to this many; beyond it the oldest are dropped
# (and counted) so a program that never reads cannot make the emulator block or grow forever.
MAX_BACKLOG = 1 << 20


class PtyPort:
    """Master side of a raw pty; ``slave_path`` is the port's name for other programs."""

    def __init__(self) -> None:
        master, slave = os.openpty()
        try:
            tty.setraw(slave, termios.TCSANOW)  # no echo, no CR/LF mapping, no IXON in the kernel
            flags = fcntl.fcntl(master, fcntl.F_GETFL)
            fcntl.fcntl(master, fcntl.F_SETFL, flags | os.O_NONBLOCK)
            self.slave_path: str = os.ttyname(slave)
        except Exception:
            os.close(master)
            os.close(slave)
            raise
        self.master_fd: int = master
        self._slave_fd: int | None = slave
        self._backlog = bytearray()
        self.dropped = 0  # bytes discarded because nobody read them (see MAX_BACKLOG)
        self.closed = False

    def fileno(self) -> int:
        return self.master_fd

    def write(self, data: bytes) -> int:
        """Send bytes to the program on the slave side without blocking; returns bytes sent now
        (the rest wait in a bounded backlog, flushed by later write()/flush() calls)."""
        self._check_open()
        self._backlog += data
        if len(self._backlog) > MAX_BACKLOG:
            excess = len(self._backlog) - MAX_BACKLOG
            del self._backlog[:excess]
            self.dropped += excess
        return self.flush()

    def flush(self) -> int:
        sent = 0
        while self._backlog:
            try:
                n = os.write(self.master_fd, self._backlog)
            except BlockingIOError:
                break
            except OSError as exc:
                if exc.errno in (errno.EIO, errno.EAGAIN):
                    break
                raise
            del self._backlog[:n]
            sent += n
        return sent

    def discard_backlog(self) -> int:
        """Forget bytes not yet taken by the kernel (e.g. when a new client connects)."""
        n = len(self._backlog)
        self._backlog.clear()
        return n

    @property
    def backlog(self) -> int:
        return len(self._backlog)

    def read(self, max_bytes: int = 4096, timeout: float = 0.0) -> bytes:
        """Bytes the program wrote, waiting up to ``timeout`` seconds for the first."""
        self._check_open()
        self.flush()
        ready, _, _ = select.select([self.master_fd], [], [], max(0.0, timeout))
        if not ready:
            return b""
        try:
            return os.read(self.master_fd, max_bytes)
        except BlockingIOError:
            return b""
        except OSError as exc:
            if exc.errno == errno.EIO:  # no slave open (only if we gave ours up)
                return b""
            raise

    def close(self) -> None:
        if self.closed:
            return
        self.closed = True
        for fd in (self.master_fd, self._slave_fd):
            if fd is not None:
                try:
                    os.close(fd)
                except OSError:
                    pass
        self._slave_fd = None

    def _check_open(self) -> None:
        if self.closed:
            raise ValueError("PtyPort is closed")

    def __enter__(self) -> PtyPort:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        return f"PtyPort({self.slave_path!r})"
