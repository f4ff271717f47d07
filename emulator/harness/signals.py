"""Ctrl-C, SIGTERM and SIGHUP while a harness runs take effect between two ticks, never inside one.

A tick is the unit a session recording counts and a replay repeats: a stop in the middle of
one (say after the tick's time advanced, before its frame was shown) recorded an end that no
replay could reach ("expected the end at frame 249, got frame 250"). So the first signal is
noted and the loop stops after the tick in progress; the run's plugins finish (a recording is
written) and then the signal is delivered as before (KeyboardInterrupt, or whatever the
handler that was installed raises). A second signal is delivered at once, so a wedged tick can
still be interrupted.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Callable
from typing import Any

_SIGNALS = (signal.SIGINT, signal.SIGTERM,
            *([signal.SIGHUP] if hasattr(signal, "SIGHUP") else []))  # not on Windows


class DeferredSignals:
    """``with DeferredSignals() as s:`` ... ``s.caught`` is the signal noted (or None);
    ``s.deliver()`` after the block raises what its handler raises."""

    def __init__(self) -> None:
        self.caught: int | None = None
        self._old: dict[int, Callable[[int, Any], Any]] = {}  # the handlers we stand in for
        self._installed = False

    def __enter__(self) -> DeferredSignals:
        if threading.current_thread() is not threading.main_thread():
            return self  # only the main thread receives signals
        for sig in _SIGNALS:
            old = signal.getsignal(sig)
            if callable(old):  # a Python handler (default_int_handler, cli's SIGTERM)
                self._old[sig] = old
                signal.signal(sig, self._note)
        self._installed = True
        return self

    def _note(self, signum: int, frame: Any) -> None:
        if self.caught is not None:
            self._old[signum](signum, frame)  # the second one: now
        self.caught = signum

    def __exit__(self, *exc: object) -> None:
        if self._installed:
            for sig, old in self._old.items():
                signal.signal(sig, old)
            self._installed = False

    def deliver(self) -> None:
        """Raise what the noted signal's own handler raises (nothing if none was noted)."""
        if self.caught is not None:
            self._old[self.caught](self.caught, None)
