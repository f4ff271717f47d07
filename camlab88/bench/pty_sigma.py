"""A Sigma serving a pseudo-terminal from a background thread, for tests that drive the
emulated terminal with a real program (any language) through the pty's path."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

import numpy as np

from camlab88.bench.sigma import Sigma

POLL_WAIT = 0.002  # wall seconds the thread waits for the program between ticks


class PtySigma:
    """``path`` to open, ``terminal`` (the emulated terminal), ``sigma`` (its API object);
    ``wait_idle()`` until the program has gone quiet and the line has drained."""

    def __init__(self, model: str = "t5684", baud: int = 9600) -> None:
        from camlab88.protocols.link.transports import PtyBridge

        self.sigma = Sigma(model, baud)
        self.terminal = self.sigma.machine.terminal
        self._lock = threading.Lock()
        self._bridge = PtyBridge(self.sigma.machine.line.host)
        self.path: str = self._bridge.slave_path
        self._last_input = time.monotonic()
        self._polls = 0  # polls of the pty so far (wait_idle waits for fresh ones)
        self._stop = threading.Event()
        self.error: BaseException | None = None
        self._thread = threading.Thread(target=self._serve, name="camlab88-sigma-pty",
                                        daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        try:
            while not self._stop.is_set():
                with self._lock:
                    got = self._bridge.poll(timeout=0.0)
                    self.sigma.machine.tick()
                if got.inbound:
                    self._last_input = time.monotonic()
                self._polls += 1
                time.sleep(POLL_WAIT)
        except BaseException as exc:  # reported by wait_idle and close
            self.error = exc

    def wait_idle(self, quiet: float = 0.2, timeout: float = 10.0) -> None:
        """Return once nothing has come from the program for ``quiet`` wall seconds and the
        line has delivered everything; TimeoutError after ``timeout`` seconds."""
        end = time.monotonic() + timeout
        first = self._polls + 2  # what the program wrote before this call has been seen
        while time.monotonic() < end:
            if self.error is not None:
                raise RuntimeError(f"the pty thread failed: {self.error!r}") from self.error
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
            if self.error is not None:
                raise RuntimeError(f"the pty thread failed: {self.error!r}") from self.error
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
        self._stop.set()
        self._thread.join(timeout=5)
        self._bridge.close()
