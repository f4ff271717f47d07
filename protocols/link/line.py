"""A serial line with two directions, each paced at the baud rate on a virtual clock.

Every byte written at one end arrives at the other a whole character time after it starts;
bytes leave back to back. Arrival times are exact, computed by a small event simulation of the
two transmitters, so they are the same however fast the program runs.

Internally time is an integer count of ticks of the UART's 16x bit clock (with one more
factor 2 so 1.5 stop bits is whole): 1/(32*baud) s. A character is a whole number of ticks; a
byte written between ticks starts at the next tick, as a UART's transmitter starts on its
clock. Integer arithmetic keeps the model exact and fast; times are exposed as float seconds
or, on request, exact Fractions.

Scheduling is lazy: bytes are given their final start times ("committed") only when someone
reads or the line is flushed, because a DC3 travelling the other way may still pause them.
Committing up to the clock's ``now`` is always safe (a byte written at ``now`` arrives after
``now``). Reading ahead of the clock (``read(until > now)``) fixes the schedule up to
``until``; flow control written later, at an earlier virtual time, then takes effect from the
first byte not yet fixed.

XON/XOFF (when ``xonxoff``): a DC3 arriving at one end pauses that end's transmitter from its
arrival time: a character already started completes, no new one starts until a DC1 arrives.
DC1/DC3 are consumed by the line (recorded, not delivered). A paused transmitter still sends a
DC1/DC3 that is at the head of its queue, as a UART driver sends its flow characters with
priority, so two paused ends cannot deadlock.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Callable
from fractions import Fraction
from typing import Protocol

from camlab88.protocols.link.clock import TimeLike, VirtualClock, to_time
from camlab88.protocols.link.settings import LineSettings

XON = 0x11  # DC1
XOFF = 0x13  # DC3
_FLOW = (XON, XOFF)
HOST_TO_DEVICE = ">"
DEVICE_TO_HOST = "<"
_INF = math.inf


class RecorderLike(Protocol):
    def record(self, t: TimeLike, direction: str, data: bytes) -> None: ...


def _first_flow(data: bytes, start: int) -> int:
    """Index of the first DC1/DC3 at or after ``start``, or -1."""
    a = data.find(XON, start)
    b = data.find(XOFF, start)
    if a < 0:
        return b
    if b < 0:
        return a
    return min(a, b)


class _Segment:
    """Bytes written in one call, not yet all started; ``earliest`` = when they were written."""

    __slots__ = ("earliest", "data", "pos", "flows", "_next_flow")

    def __init__(self, earliest: int, data: bytes, flows: int) -> None:
        self.earliest = earliest
        self.data = data
        self.pos = 0
        self.flows = flows  # DC1/DC3 bytes not yet started
        self._next_flow = -1  # cached index of the next DC1/DC3 at or after pos

    def next_flow(self) -> int:
        """Index of the next DC1/DC3 not yet started, or -1 (cached: no rescans)."""
        if self.flows == 0:
            return -1
        if self._next_flow < self.pos:
            self._next_flow = _first_flow(self.data, self.pos)
        return self._next_flow

    def copy(self) -> _Segment:
        seg = _Segment(self.earliest, self.data, self.flows)
        seg.pos = self.pos
        seg._next_flow = self._next_flow
        return seg


class _Direction:
    """One transmitter and the receive queue at the far end."""

    def __init__(self, name: str, settings: LineSettings) -> None:
        self.name = name
        self.ct = int(settings.bits_exact * 32)  # ticks per character
        self.pending: deque[_Segment] = deque()
        self.pending_flows = 0
        self.tx_free = 0  # tick when the last started character has fully arrived
        # Flow events that control THIS transmitter: (arrival tick, is_xoff), time-ordered.
        self.control: deque[tuple[int, bool]] = deque()
        self.base_paused = False  # state given by control events already pruned
        # Delivered runs for the far end: [arrival of the first unread byte, bytes, offset of
        # the first unread byte]; the bytes of a run went back to back.
        self.delivered: deque[list] = deque()
        self.tail = 0  # predicted end of the pending queue if nothing pauses it
        self.tail_stale = False  # a pause delayed a start, so ``tail`` is not to be trusted
        self.sent = 0
        self.flow_sent = 0
        self.queued = 0  # bytes written that have not started on the wire (O(1) to ask)

    def clone(self) -> _Direction:
        other = _Direction.__new__(_Direction)
        other.__dict__.update(self.__dict__)
        other.pending = deque(seg.copy() for seg in self.pending)
        other.control = deque(self.control)
        other.delivered = deque()
        return other


class Endpoint:
    """One end of a SerialLine: writes go out on one direction, reads come from the other."""

    def __init__(self, line: SerialLine, name: str, tx: _Direction, rx: _Direction) -> None:
        self._line = line
        self.name = name
        self._tx = tx
        self._rx = rx

    @property
    def line(self) -> SerialLine:
        return self._line

    @property
    def direction(self) -> str:
        """The direction this end transmits on: ``>`` for the host, ``<`` for the device."""
        return self._tx.name

    def write(self, data: bytes, at: TimeLike | None = None) -> float:
        """Queue ``data`` from this end at ``at`` (default: clock now); returns when the last
        byte arrives, given the flow control known so far (inf if paused with no XON queued)."""
        end = self._line._write(self._tx, bytes(data), at)
        return float(self._line._seconds_or_inf(end, exact=False))

    def read(self, until: TimeLike | None = None) -> bytes:
        """Bytes that have arrived at this end by ``until`` (default clock now), consumed."""
        return b"".join(data for _, data in self._line._read(self._rx, until))

    def read_timed(
        self, until: TimeLike | None = None, *, exact: bool = False
    ) -> list[tuple[float, bytes]] | list[tuple[Fraction, bytes]]:
        """Like read(), as runs ``(arrival time of the run's last byte, bytes)``."""
        ct, hz = self._rx.ct, self._line.ticks_per_second
        runs = self._line._read(self._rx, until)
        if exact:
            return [(Fraction(first + (len(data) - 1) * ct, hz), data) for first, data in runs]
        return [((first + (len(data) - 1) * ct) / hz, data) for first, data in runs]

    def drain_time(self) -> float:
        """When everything written from this end so far will have arrived (inf if blocked)."""
        return self._line._seconds_or_inf(self._line._predict_end(self._tx), exact=False)

    def drain_time_exact(self) -> Fraction | float:
        return self._line._seconds_or_inf(self._line._predict_end(self._tx), exact=True)

    def queued(self) -> int:
        """Bytes written from this end that have not started on the wire by the clock's now."""
        self._line.flush()
        return self._tx.queued

    def hang_up(self) -> int:
        """The party at this end hangs up: the bytes it queued and the bytes queued for it or
        arrived (or arriving) at this end unread are dropped, and XON/XOFF is back to running
        both ways, so whoever comes next starts on an empty line. Characters this end had
        already started complete at the far end. Returns how many bytes were dropped."""
        return self._line._hang_up(self._tx, self._rx)

    def has_in_flight(self) -> bool:
        """Whether any byte written from this end has not yet been read at the far end
        (``in_flight() > 0``, without counting them all)."""
        return (any(len(seg.data) > seg.pos for seg in self._tx.pending)
                or any(len(data) > off for _, data, off in self._tx.delivered))

    def in_flight(self) -> int:
        """Bytes written from this end that have not yet been read at the far end."""
        queued = sum(len(seg.data) - seg.pos for seg in self._tx.pending)
        return queued + sum(len(data) - off for _, data, off in self._tx.delivered)

    @property
    def paused(self) -> bool:
        """Whether this end's transmitter is held by an XOFF at the clock's current time."""
        line = self._line
        now = line._ticks_down(line.clock.exact)
        line._commit(line._h2d, line._d2h, now)  # flow bytes that have arrived by now count
        return line._paused_at(self._tx, now)

    def __repr__(self) -> str:
        return f"<Endpoint {self.name} of {self._line!r}>"


class SerialLine:
    """Two directions between ``host`` and ``device``, paced at the line's character rate."""

    def __init__(
        self,
        settings: LineSettings | None = None,
        clock: VirtualClock | None = None,
        xonxoff: bool = True,
        recorder: RecorderLike | None = None,
    ) -> None:
        self.settings = settings or LineSettings()
        rec_settings = getattr(recorder, "settings", None)
        if rec_settings is not None and rec_settings != self.settings:
            raise ValueError(f"recorder is for a {rec_settings} line, this line is {self.settings}")
        if getattr(recorder, "xonxoff", xonxoff) != xonxoff:
            raise ValueError("recorder and line disagree about XON/XOFF")
        self.clock = clock or VirtualClock()
        self.ticks_per_second = 32 * self.settings.baud
        self.xonxoff = xonxoff
        self.recorder = recorder
        self._mask = self.settings.data_mask
        self._table = bytes(b & self._mask for b in range(256)) if self._mask != 0xFF else None
        self._h2d = _Direction(HOST_TO_DEVICE, self.settings)
        self._d2h = _Direction(DEVICE_TO_HOST, self.settings)
        self.host = Endpoint(self, "host", self._h2d, self._d2h)
        self.device = Endpoint(self, "device", self._d2h, self._h2d)
        self.on_commit: Callable[[Fraction, str, bytes], None] | None = None

    def __repr__(self) -> str:
        return f"SerialLine({self.settings}, xonxoff={self.xonxoff})"

    # Public helpers ---------------------------------------------------------------------
    def flush(self, until: TimeLike | None = None) -> None:
        """Fix (and record) every byte that starts by ``until`` (default clock now)."""
        horizon = self._ticks_down(self.clock.exact if until is None else to_time(until))
        self._commit(self._h2d, self._d2h, horizon)

    def finish(self) -> float:
        """Fix and record everything that can still be sent; returns the last arrival time."""
        self._commit(self._h2d, self._d2h, None)
        return max(self._h2d.tx_free, self._d2h.tx_free) / self.ticks_per_second

    def close(self) -> None:
        """finish(), then close the recorder if it has a close()."""
        self.finish()
        close = getattr(self.recorder, "close", None)
        if close is not None:
            close()

    def _hang_up(self, tx: _Direction, rx: _Direction) -> int:
        now = self._ticks_down(self.clock.exact)
        self._commit(self._h2d, self._d2h, now)  # what has started by now stays on the wire
        dropped = sum(len(data) - off for _, data, off in rx.delivered)
        rx.delivered.clear()
        for d in (tx, rx):
            dropped += d.queued
            d.pending.clear()
            d.pending_flows = d.queued = 0
            d.control.clear()
            d.base_paused = d.tail_stale = False
            d.tail = d.tx_free
        return dropped

    def save_state(self) -> dict[str, object]:
        """Both directions' queued bytes, flow events and unread bytes (JSON-able; the clock
        and the recorder are not included)."""
        from camlab88.protocols.link.line_state import save

        return save(self)

    def load_state(self, state: object) -> None:
        """Put back save_state()'s dict (ValueError naming a bad entry, nothing changed)."""
        from camlab88.protocols.link.line_state import load

        load(self, state)

    @property
    def stats(self) -> dict[str, int]:
        return {
            "host_to_device_bytes": self._h2d.sent,
            "device_to_host_bytes": self._d2h.sent,
            "host_to_device_flow": self._h2d.flow_sent,
            "device_to_host_flow": self._d2h.flow_sent,
        }

    # Internals --------------------------------------------------------------------------
    def _other(self, d: _Direction) -> _Direction:
        return self._d2h if d is self._h2d else self._h2d

    def _ticks_down(self, t: Fraction) -> int:
        return t.numerator * self.ticks_per_second // t.denominator

    def _ticks_up(self, t: Fraction) -> int:
        return -(-t.numerator * self.ticks_per_second // t.denominator)

    def _seconds_or_inf(self, ticks: int | float, exact: bool) -> Fraction | float:
        if ticks == _INF:
            return _INF
        assert isinstance(ticks, int)
        return Fraction(ticks, self.ticks_per_second) if exact else ticks / self.ticks_per_second

    def _write(self, tx: _Direction, data: bytes, at: TimeLike | None) -> int | float:
        now = self.clock.exact
        when_exact = now if at is None else to_time(at)
        if when_exact < now:
            raise ValueError(
                f"cannot write in the past (at {float(when_exact)} s, now {float(now)} s)"
            )
        when = self._ticks_up(when_exact)  # the transmitter starts on its next clock tick
        if self._table is not None:
            data = data.translate(self._table)
        now_ticks = self._ticks_down(now)
        self._commit(self._h2d, self._d2h, now_ticks)
        self._fold_idle(now_ticks)
        if not data:
            return self._predict_end(tx)
        flows = (data.count(XON) + data.count(XOFF)) if self.xonxoff else 0
        tx.pending.append(_Segment(when, data, flows))
        tx.pending_flows += flows
        tx.queued += len(data)
        tx.tail = max(tx.tail, tx.tx_free, when) + len(data) * tx.ct
        return self._predict_end(tx)

    def _read(self, rx: _Direction, until: TimeLike | None) -> list[tuple[int, bytes]]:
        now = self._ticks_down(self.clock.exact)
        horizon = now if until is None else self._ticks_down(to_time(until))
        self._commit(self._h2d, self._d2h, horizon)
        self._fold_idle(min(now, horizon))
        out: list[tuple[int, bytes]] = []
        ct = rx.ct
        while rx.delivered:
            run = rx.delivered[0]
            first, data, offset = run
            if first > horizon:
                break
            n = min(len(data) - offset, (horizon - first) // ct + 1)
            piece = data[offset : offset + n]
            if out and out[-1][0] + len(out[-1][1]) * ct == first:
                out[-1] = (out[-1][0], out[-1][1] + piece)  # back to back: one run
            else:
                out.append((first, piece))
            if offset + n == len(data):
                rx.delivered.popleft()
            else:
                # keep an offset rather than copying the rest: reads stay linear overall
                run[0], run[2] = first + n * ct, offset + n
                break
        return out

    def _fold_idle(self, now: int) -> None:
        """An idle transmitter's next byte starts at or after ``now``: flow events up to then
        only matter through the state they leave (keeps ``control`` bounded)."""
        for d in (self._h2d, self._d2h):
            if not d.pending:
                while d.control and d.control[0][0] <= now:
                    d.base_paused = d.control.popleft()[1]

    def _paused_at(self, d: _Direction, t: int) -> bool:
        if not self.xonxoff:
            return False
        state = d.base_paused
        for when, xoff in d.control:
            if when > t:
                break
            state = xoff
        return state

    def _candidate(self, d: _Direction) -> int | None:
        """Start time of d's next character, or None if it waits for a DC1 not yet known."""
        if not d.pending:
            return None
        seg = d.pending[0]
        start = max(d.tx_free, seg.earliest)
        if not self.xonxoff or seg.data[seg.pos] in _FLOW:
            return start
        state = d.base_paused
        for when, xoff in d.control:
            if when <= start:
                state = xoff
            elif state and not xoff:
                return when  # resumed by this DC1
            elif not state:
                break
            else:
                state = xoff
        return None if state else start

    def _flow_bound(self, d: _Direction, other_start: int) -> int | float:
        """Earliest time a DC1/DC3 still queued on ``d`` could arrive at the far end."""
        if not self.xonxoff or d.pending_flows == 0:
            return _INF
        t = other_start
        for seg in d.pending:
            t = max(t, seg.earliest)
            i = seg.next_flow()
            if i >= 0:
                return t + (i - seg.pos + 1) * d.ct
            t += (len(seg.data) - seg.pos) * d.ct
        return _INF  # pragma: no cover - pending_flows said there was one

    def _commit(
        self, a: _Direction, b: _Direction, horizon: int | None, dry: bool = False
    ) -> None:
        """Fix start times of every character that starts by ``horizon`` (None = all)."""
        while True:
            ca, cb = self._candidate(a), self._candidate(b)
            if ca is None and cb is None:
                return
            if cb is None or (ca is not None and ca <= cb):
                x, y, c = a, b, ca
            else:
                x, y, c = b, a, cb
            assert c is not None
            if horizon is not None and c > horizon:
                return
            y_start = self._candidate(y)
            if y_start is None and y.pending:
                # y is paused until x sends a DC1, which arrives one character after c at least
                y_start = max(y.tx_free, y.pending[0].earliest, c + x.ct)
            self._commit_run(x, y, c, horizon, y_start, dry)

    def _commit_run(
        self,
        x: _Direction,
        y: _Direction,
        c: int,
        horizon: int | None,
        y_start: int | None,
        dry: bool,
    ) -> None:
        seg = x.pending[0]
        ct = x.ct
        n = len(seg.data) - seg.pos
        if self.xonxoff:
            i = seg.next_flow()
            if i >= 0:
                n = min(n, i - seg.pos + 1)  # a flow byte ends the run: it acts on the other side
            # Stop before a pause: the next DC3 already known, or one y could still send.
            bound: int | float = _INF
            for when, xoff in x.control:
                if when > c and xoff:
                    bound = when
                    break
            if y_start is not None:
                bound = min(bound, self._flow_bound(y, y_start))
            if bound != _INF and seg.data[seg.pos] not in _FLOW:
                n = min(n, -((c - int(bound)) // ct))  # characters starting before bound
        if horizon is not None:
            n = min(n, (horizon - c) // ct + 1)
        data = seg.data[seg.pos : seg.pos + n]
        if c > max(x.tx_free, seg.earliest):
            x.tail_stale = True  # a pause delayed this start
        seg.pos += n
        x.queued -= n
        end = c + n * ct
        x.tx_free = end
        flow = self.xonxoff and data[-1] in _FLOW
        if flow:
            seg.flows -= 1
            x.pending_flows -= 1
        if seg.pos == len(seg.data):
            x.pending.popleft()
        # Control events at or before c can no longer change anything for x.
        while x.control and x.control[0][0] <= c:
            x.base_paused = x.control.popleft()[1]
        if flow:
            y.control.append((end, data[-1] == XOFF))
        if dry:
            return
        x.sent += n
        if self.recorder is not None or self.on_commit is not None:
            t_end = Fraction(end, self.ticks_per_second)
            if self.recorder is not None:
                self.recorder.record(t_end, x.name, data)
            if self.on_commit is not None:
                self.on_commit(t_end, x.name, data)
        payload = data[:-1] if flow else data
        if flow:
            x.flow_sent += 1
        if payload:
            x.delivered.append([c + ct, payload, 0])

    def _predict_end(self, d: _Direction) -> int | float:
        """When d's queue will have drained, given what is known (inf if it never will)."""
        if not d.pending:
            return d.tx_free
        other = self._other(d)
        simple = not self.xonxoff or (
            other.pending_flows == 0 and not d.control and not d.base_paused
        )
        if simple and not d.tail_stale:
            return d.tail
        x, y = d.clone(), other.clone()
        a, b = (x, y) if d is self._h2d else (y, x)
        self._commit(a, b, None, dry=True)
        if x.pending:
            return _INF
        if simple:
            d.tail, d.tail_stale = x.tx_free, False
        return x.tx_free
