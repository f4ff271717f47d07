"""Any pyserial URL: opened with only the options its handler supports, read at line speed.

Two rules every caller (the line's serial bridge, a serial tablet) follows:

* **Never trust ``in_waiting`` for how much to read.**  pyserial's ``socket://`` handler
  answers 0 or 1 there (it only asks ``select`` whether the socket is readable), so reading
  ``in_waiting`` bytes a poll drew a picture at a tenth of the line.  With the port's timeout
  at 0, ``read(CHUNK)`` never blocks in any handler (posix, ``socket://``, ``rfc2217://``,
  ``loop://``, ``spy://``), but may return less than has arrived: ``rfc2217://`` returns one
  byte per call (its non-blocking read stops after one item of its byte queue).  So reads
  repeat until one returns nothing (or CHUNK bytes are in hand).
* **Never pass an option the handler does not support.**  pyserial 3.5's ``rfc2217://``
  raises ``NotImplementedError('write_timeout is currently not supported')`` from ``open()``.

The timeout is set once, at open: changing it later reconfigures the port (a ``tcsetattr`` on
a tty, a round of RFC 2217 option negotiation on the network), so waits use ``select`` on
the port's descriptor where it has one, else a short sleep loop.
"""

from __future__ import annotations

import select
import time
from collections.abc import Callable
from typing import Any

CHUNK = 4096  # bytes taken from the port per read; a 9600-baud line brings 960 a second
POLL_STEP = 0.002  # s between looks at a port without a descriptor (loop://, rfc2217://)
NO_WRITE_TIMEOUT = ("rfc2217",)  # URL schemes whose handler refuses write_timeout


def scheme(url: str) -> str:
    """``rfc2217`` for ``rfc2217://h:p``; ``""`` for a device path (``/dev/ttyUSB0``, ``COM3``)."""
    return url.split("://", 1)[0].lower() if "://" in url else ""


def open_url(url: str, *, write_timeout: float | None = None, **settings: Any) -> Any:
    """``serial.serial_for_url(url, timeout=0, ...)`` with ``write_timeout`` only where the
    handler supports it.  Raises what pyserial raises (SerialException, OSError, ValueError)."""
    import serial

    kwargs = dict(settings, timeout=0)
    if write_timeout is not None and scheme(url) not in NO_WRITE_TIMEOUT:
        kwargs["write_timeout"] = write_timeout
    return serial.serial_for_url(url, **kwargs)


def descriptor(port: Any) -> int | None:
    """The port's file descriptor for ``select``, or None (loop://, rfc2217://)."""
    try:
        fd = port.fileno()
    except Exception:  # handlers without one raise assorted errors
        return None
    return fd if isinstance(fd, int) and fd >= 0 else None


def wait_readable(port: Any, timeout: float, sleep: Callable[[float], None] = time.sleep) -> None:
    """Return once the port may have bytes, or after ``timeout`` s."""
    if timeout <= 0:
        return
    fd = descriptor(port)
    if fd is not None:
        select.select([fd], [], [], timeout)
        return
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        # Only a hint to stop waiting; the read itself takes whatever is there.
        if port.in_waiting:
            return
        sleep(POLL_STEP)


def drain(port: Any, limit: int = CHUNK) -> bytes:
    """Everything that has arrived, up to ``limit`` bytes, without waiting."""
    data = bytearray()
    while len(data) < limit:
        more = port.read(limit - len(data))
        if not more:
            break
        data += more
    return bytes(data)


def read_available(port: Any, timeout: float = 0.0,
                   sleep: Callable[[float], None] = time.sleep, limit: int = CHUNK) -> bytes:
    """Whatever has arrived (at most ``limit`` bytes), waiting up to ``timeout`` s for the
    first.  A ``limit`` of 0 reads nothing: what is not taken waits in the port's buffer."""
    if limit <= 0:
        return b""
    data = drain(port, limit)
    if data or timeout <= 0:
        return data
    wait_readable(port, timeout, sleep)
    return drain(port, limit)
