"""The pointer the programs use: working coordinates from a tablet, or the mouse.

A program (e.g. KAS, whose drawing area is the animator's twelve-field, 12 x 8.75 inches,
thesis §2.2.1/§3.1.1) asks for pointer events in its own units.  Whatever source is configured
feeds them; if the tablet is unplugged or its stream breaks mid-stroke the layer ends that
stroke with a release at the last position, says so once, carries on with the mouse, and
retries the tablet every ``retry_every`` polls (a poll count, not wall time, so runs replay).
Reopening runs on a worker (a serial tablet's start-up takes seconds) so ``poll`` never blocks.
A stream that merely goes silent (cable pulled, no OS error) is judged on the source's own
clock: tip down and no bytes for ``stall_release`` s ends the stroke; ``stall_fallback`` s
hands over to the mouse until bytes come again.
Mouse input arrives as plain data; this module imports no window code.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from camlab88.protocols.tablets.calibration import Calibration, default_calibration
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.sources import SourceLost, TabletSource


@dataclass(frozen=True)
class WorkingArea:
    """A program's working coordinates: (0, 0) top-left, x right, y down, in ``unit``s."""

    width: float
    height: float
    unit: str = "inch"
    name: str = ""


TWELVE_FIELD = WorkingArea(12.0, 8.75, "inch", "twelve-field")


@dataclass(frozen=True)
class MouseSample:
    """The window's mouse: pixel position (row 0 = top) in a view of ``view_size`` pixels that
    shows the whole working area; ``buttons`` bit 0 = left."""

    x: float
    y: float
    buttons: int
    view_size: tuple[int, int]


@dataclass(frozen=True)
class PointerEvent:
    kind: str  # "move", "press", "release"
    x: float
    y: float
    down: bool
    proximity: bool
    pressure: float | None  # 0..1 where the source has pressure
    buttons: int
    source: str  # "tablet" or "mouse"


def _in_thread(job: Callable[[], None]) -> None:
    threading.Thread(target=job, name="tablet-reopen", daemon=True).start()


class _Reopen:
    """One attempt to reopen the tablet, run by ``spawn`` (a thread by default)."""

    def __init__(self, reopen: Callable[[], TabletSource]) -> None:
        self._reopen = reopen
        self._lock = threading.Lock()
        self.done = threading.Event()
        self.source: TabletSource | None = None
        self.cancelled = False

    def run(self) -> None:
        source = None
        try:
            source = self._reopen()
        except Exception:  # still unplugged (or half-plugged and broken): try again later
            source = None
        with self._lock:
            if self.cancelled and source is not None:
                source.close()
                source = None
            self.source = source
        self.done.set()

    def cancel(self) -> None:
        with self._lock:
            self.cancelled = True
            if self.source is not None:
                self.source.close()
                self.source = None


class InputLayer:
    _state_exclude = ("source", "reopen", "_spawn")  # the device: kept as opened

    def __init__(
        self,
        area: WorkingArea = TWELVE_FIELD,
        source: TabletSource | None = None,
        *,
        reopen: Callable[[], TabletSource] | None = None,
        calibration: Calibration | None = None,
        retry_every: int = 60,
        notify: Callable[[str], None] | None = None,
        spawn: Callable[[Callable[[], None]], None] = _in_thread,
    ) -> None:
        self.area = area
        self._spawn = spawn  # runs a reopen attempt; ``lambda job: job()`` = synchronous
        self._reopening: _Reopen | None = None
        self._stall = 0  # 0 streaming, 1 silent mid-stroke (stroke ended), 2 on the mouse
        self.source = source
        self.reopen = reopen
        self.retry_every = max(1, retry_every)
        self.notices: list[str] = []
        self._notify = notify
        self.calibration = calibration
        self._down = False
        self._last = (0.0, 0.0)
        self._polls_since_loss = 0
        self._source_name = getattr(source, "name", "tablet") if source else "tablet"

    @property
    def active(self) -> str:
        return "tablet" if self.source is not None else "mouse"

    def _say(self, text: str) -> None:
        self.notices.append(text)
        if self._notify is not None:
            self._notify(text)

    # -- conversions ------------------------------------------------------------------------
    def _tablet_xy(self, event: TabletEvent) -> tuple[float, float]:
        cal = self.calibration
        if cal is None:  # not cached: the source's model may change (HID report IDs, ~C)
            model = getattr(self.source, "model", None)
            if model is None:
                return self._last
            cal = default_calibration(self._source_name, model)
        fx, fy = cal.to_fraction(event.x, event.y)
        return fx * self.area.width, fy * self.area.height

    def _emit(self, out: list[PointerEvent], x: float, y: float, down: bool, proximity: bool,
              pressure: float | None, buttons: int, source: str) -> None:
        if down and not self._down:
            kind = "press"
        elif self._down and not down:
            kind = "release"
        else:
            kind = "move"
        self._down = down
        self._last = (x, y)
        out.append(PointerEvent(kind, x, y, down, proximity, pressure, buttons, source))

    def _end_stroke(self, out: list[PointerEvent], source: str) -> None:
        if self._down:
            x, y = self._last
            self._emit(out, x, y, False, True, 0.0, 0, source)

    # -- polling ----------------------------------------------------------------------------
    def poll(self, mouse: Sequence[MouseSample] = (), timeout: float = 0.0) -> list[PointerEvent]:
        out: list[PointerEvent] = []
        if self.source is None:
            self._try_reopen(out)
        if self.source is not None:
            try:
                events = self.source.read(timeout)
            except (SourceLost, OSError) as exc:
                self._lost(out, exc)
            else:
                self._check_silence(out)
                model = self.source.model
                for e in events:
                    x, y = self._tablet_xy(e)
                    pressure = None
                    if e.pressure is not None and model.pressure_max:
                        pressure = max(0.0, min(1.0, e.pressure / model.pressure_max))
                    down = e.proximity and e.tip
                    self._emit(out, x, y, down, e.proximity, pressure, e.buttons, "tablet")
                if self._stall < 2:
                    return out
        for m in mouse:
            w, h = m.view_size
            x = m.x / max(w, 1) * self.area.width
            y = m.y / max(h, 1) * self.area.height
            self._emit(out, x, y, bool(m.buttons & 1), True, None, m.buttons, "mouse")
        return out

    def _check_silence(self, out: list[PointerEvent]) -> None:
        """Act on a stream that stopped without an error (sources that stream continuously
        while in proximity expose ``clock``/``last_data``/``stall_release``/``stall_fallback``)."""
        source = self.source
        clock = getattr(source, "clock", None)
        if clock is None:
            return
        idle = clock() - source.last_data
        if self._stall and idle < source.stall_release:  # bytes again
            if self._stall == 2:
                self._end_stroke(out, "mouse")
                self._say(f"{self._source_name}: data again; using the tablet again")
            self._stall = 0
        elif self._stall == 0 and self._down and idle >= source.stall_release:
            self._end_stroke(out, "tablet")
            self._stall = 1
            self._say(f"{self._source_name}: no data for {idle:.1f} s mid-stroke (cable?); "
                      "stroke ended")
        elif self._stall == 1 and idle >= source.stall_fallback:
            self._stall = 2
            self._say(f"{self._source_name}: still silent; using the mouse until it resumes")

    def _lost(self, out: list[PointerEvent], exc: BaseException) -> None:
        self._end_stroke(out, "tablet")
        try:
            if self.source is not None:
                self.source.close()
        except OSError:
            pass
        self.source = None
        self._stall = 0
        self._polls_since_loss = 0
        self._say(f"{self._source_name}: lost ({exc}); using the mouse until it comes back")

    def _try_reopen(self, out: list[PointerEvent]) -> None:
        if self.reopen is None:
            return
        if self._reopening is None:
            self._polls_since_loss += 1
            if self._polls_since_loss % self.retry_every:
                return
            self._reopening = _Reopen(self.reopen)
            self._spawn(self._reopening.run)
        job = self._reopening
        if not job.done.is_set():
            return  # still opening: keep going on the mouse
        self._reopening = None
        if job.source is None:
            return  # still unplugged: stay quiet, try again later
        self._end_stroke(out, "mouse")
        self.source = job.source
        self._stall = 0
        self._source_name = getattr(job.source, "name", self._source_name)
        self._say(f"{self._source_name}: back; using the tablet again")

    def carry_on_from(self, other: InputLayer) -> None:
        """Go on from where ``other`` left the pointer (its pen down or up, its place, a
        silent stream's stage): a loaded state's session ran again on a tape; this layer's
        own source carries on."""
        self._down, self._last, self._stall = other._down, other._last, other._stall

    def close(self) -> None:
        if self._reopening is not None:
            self._reopening.cancel()
            self._reopening = None
        if self.source is not None:
            self.source.close()
            self.source = None
