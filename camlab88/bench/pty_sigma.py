"""A Sigma serving a pseudo-terminal from a background thread, for tests that drive the
emulated terminal with a real program (any language) through the pty's path.

What paces what: the program's writes, nothing else.  While bytes are on the line either way,
virtual time jumps ahead to when they will all have arrived (at the baud rate, on the
virtual line), in steps of at most ``MAX_STEP``, with no sleep; when the line is idle the
thread waits on the pty for the program and virtual time stands still.  So a program that
writes flat out runs as fast as the terminal can decode, and one that waits (a cursor read)
loses no virtual time."""

from __future__ import annotations

import select
import threading
import time
from collections.abc import Callable
from fractions import Fraction

import numpy as np

from camlab88.bench.sigma import Sigma
from camlab88.emulator.protocol_trace import ProtocolError

IDLE_WAIT = 0.01  # wall s the thread waits on the idle pty before looking at keys again
MAX_STEP = Fraction(1)  # virtual s advanced at most per step (the lock is held that long)


class PtySigma:
    """``path`` to open, ``terminal`` (the emulated terminal), ``sigma`` (its API object);
    ``wait_idle()`` until the program has gone quiet and the line has drained."""

    def __init__(self, model: str = "t5684", baud: int = 9600, strict: bool = False,
                 trace: bool = True) -> None:
        from camlab88.protocols.link.transports import PtyBridge

        self.sigma = Sigma(model, baud, trace=trace, strict=strict)
        self.terminal = self.sigma.machine.terminal
        self._lock = threading.Lock()
        self._bridge = PtyBridge(self.sigma.machine.outside)
        self.path: str = self._bridge.slave_path
        self._last_input = time.monotonic()
        self._polls = 0  # polls of the pty so far (wait_idle waits for fresh ones)
        self._stop = threading.Event()
        self.error: BaseException | None = None
        self._error_raised = False
        self._thread = threading.Thread(target=self._serve, name="camlab88-sigma-pty",
                                        daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        fd = self._bridge.port.fileno()
        try:
            while not self._stop.is_set():
                with self._lock:
                    got = self._bridge.poll(timeout=0.0)
                    m = self.sigma.machine
                    ahead = m.idle_time() - m.now  # bytes on their way, either direction
                    if ahead > 0:
                        m.tick(min(ahead, MAX_STEP))
                if got.inbound:
                    self._last_input = time.monotonic()
                self._polls += 1
                if ahead <= 0:  # idle: wait for the program, virtual time stands still
                    select.select([fd], [], [], IDLE_WAIT)
        except BaseException as exc:  # reported by wait_idle, wait_for and close
            self.error = exc

    def _raise_error(self) -> None:
        if self.error is None:
            return
        self._error_raised = True
        if isinstance(self.error, ProtocolError):  # strict: the first protocol error
            raise self.error
        raise RuntimeError(f"the pty thread failed: {self.error!r}") from self.error

    def wait_idle(self, quiet: float = 0.2, timeout: float = 10.0) -> None:
        """Return once nothing has come from the program for ``quiet`` wall seconds and the
        line has delivered everything; TimeoutError after ``timeout`` seconds."""
        end = time.monotonic() + timeout
        first = self._polls + 2  # what the program wrote before this call has been seen
        while time.monotonic() < end:
            self._raise_error()
            with self._lock:
                drained = self.sigma.machine.host.drained() and self._polls >= first
            if drained and time.monotonic() - self._last_input >= quiet:
                return
            time.sleep(0.01)
        raise TimeoutError(f"the Sigma on {self.path} was still busy after {timeout} s")

    def wait_for(self, condition: Callable[[Sigma], bool], timeout: float = 10.0) -> None:
        """Return once ``condition(sigma)`` holds (checked with the line stopped), e.g.
        ``lambda s: "HF" in s.trace.orders()``; TimeoutError after ``timeout`` seconds."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            self._raise_error()
            with self._lock:
                if condition(self.sigma):
                    return
            time.sleep(0.01)
        raise TimeoutError(f"the Sigma on {self.path}: condition not met after {timeout} s")

    def screen(self) -> np.ndarray:
        """The screen now, (512, 768, 3) uint8."""
        with self._lock:
            return self.sigma.screen

    def key(self, char: str) -> None:
        """A key on the terminal (a cursor report or the key goes to the program)."""
        with self._lock:
            self.sigma.key(char)

    def cursor(self, x: int, y: int) -> None:
        """Move the crosshair to drawing-area (x, y)."""
        with self._lock:
            self.sigma.cursor(x, y)

    def close(self) -> None:
        """Stop serving; a strict run's protocol error not yet raised is raised here."""
        self._stop.set()
        self._thread.join(timeout=5)
        self._bridge.close()
        if not self._error_raised and isinstance(self.error, ProtocolError):
            self._raise_error()
