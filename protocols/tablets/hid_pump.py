"""Blocking HID reads on a worker thread, taken from a bounded queue with a timeout.

Why not poll: hidapi's ``read(n, timeout)`` and its non-blocking read both ``poll()`` the
device first, and a reader that only polls sees nothing where ``poll`` is not emulated --
umockdev 0.17's ``/dev/hidrawN`` (the test bed that runs hidapi's real hidraw backend
without hardware) answers reads, not ``poll``.  A plain blocking ``read`` works on every
backend and on umockdev alike, but a pen held still sends nothing, so it may block for
ever: it runs here, on its own thread (hidapi 0.15 releases the GIL while it waits), and
the program's poll waits on the queue for at most its own timeout.

The device is closed by whichever of the two sides finishes last: freeing hidapi's handle
under a read still blocked in it would be a use after free.  A closed source whose pen never
reports again leaves that one thread (a daemon) and its descriptor until the process ends.
"""

from __future__ import annotations

import queue
import threading
import time
from typing import Any

CLOSE_WAIT = 0.2  # s close() waits for the read thread (it returns when any report comes)
MAX_QUEUED = 4096  # reports kept when the program stops reading; the oldest are dropped
READ_SIZE = 256
EMPTY_PAUSE = 0.001  # s after an empty read (a backend's own timeout), so it cannot spin


class ReportPump:
    def __init__(self, device: Any, name: str) -> None:
        self.device = device
        self.name = name
        self.error: BaseException | None = None
        self._queue: queue.Queue[bytes] = queue.Queue(MAX_QUEUED)
        self._lock = threading.Lock()
        self._closing = False
        self._finished = False
        self._thread = threading.Thread(target=self._run, name=f"hid-read {name}",
                                        daemon=True)
        self._thread.start()

    def _run(self) -> None:
        try:
            while not self._closing:
                data = self.device.read(READ_SIZE)
                if data:
                    self._put(bytes(data))
                else:
                    time.sleep(EMPTY_PAUSE)
        except (OSError, ValueError) as exc:  # unplugged: hidapi's "read error"
            self.error = exc
        finally:
            with self._lock:
                self._finished = True
                if self._closing:
                    self._close_device()

    def _put(self, report: bytes) -> None:
        while True:
            try:
                self._queue.put_nowait(report)
                return
            except queue.Full:
                try:
                    self._queue.get_nowait()
                except queue.Empty:
                    pass

    def take(self, timeout: float) -> list[bytes]:
        """The reports queued now, waiting up to ``timeout`` s for the first."""
        out: list[bytes] = []
        try:
            out.append(self._queue.get(timeout=timeout) if timeout > 0
                       else self._queue.get_nowait())
        except queue.Empty:
            return out
        while True:
            try:
                out.append(self._queue.get_nowait())
            except queue.Empty:
                return out

    @property
    def alive(self) -> bool:
        return not self._finished

    def close(self) -> None:
        with self._lock:
            self._closing = True
            if self._finished:
                self._close_device()
                return
        # a streaming pen (or a backend whose blocking read times out) ends the read soon:
        # then the device is closed before close() returns; a still pen is not waited for
        self._thread.join(CLOSE_WAIT)

    def _close_device(self) -> None:
        try:
            self.device.close()
        except (OSError, ValueError):
            pass
