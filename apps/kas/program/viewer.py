"""The viewer - the line test of §3.1.4 - on the Sigma over the serial line.

Double buffering as §3.1.4 describes it on the T5684 ("dividing the 4-bit deep graphics
memory into two 2-bit buffers and drawing into one while the other was displayed"): planes
0-1 = buffer 0, planes 2-3 = buffer 1.  How the buffers were switched the thesis does not
say; the two ways below are reconstructions.  A frame is drawn into the hidden buffer
with the write mask (``KW``) selecting its two planes, after erasing them (``DA`` clears
only writable planes); then the buffers are swapped:

* ``lut`` (default): the 12 LUT entries whose two buffers' bits differ are rewritten so
  that every index shows the colour of the new buffer's bits (the 4 entries where both
  buffers hold the same value never change), in the order of ``swap_order`` so that the
  screen shows the union of the two frames while the orders arrive, never neither;
* ``mask``: the LUT holds both buffers' colours once and the display mask (``KD``) picks
  the buffer - one 4-byte order, so the switch is instantaneous.

Two bits a pixel give four colours: the background and the three pens used most in the
sequence; other pens take the nearest of those three (the thesis accepted this).

Real time: the program keeps period-line time from the moment it starts sending the first
frame.  When a frame has been drawn it sends the swap so that it arrives no earlier than the
frame's due time, then sends the frame due *now* (or the next one if that is already shown);
frames passed over are dropped.  All on the line's virtual clock, so the counts are exactly
``camlab88.apps.kas.viewer_schedule.realtime`` of the frame sizes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np

from camlab88.apps.kas.model import FIELD_H, PALETTE, AnimSequence, Drawing
from camlab88.apps.kas.pens import pen_slots
from camlab88.apps.kas.program.base import setup_bytes
from camlab88.apps.kas.program.draw import chain_prims, encode
from camlab88.protocols.link import LineSettings
from camlab88.protocols.link.host_only import HostOnlyLine
from camlab88.protocols.link.port import HostPort
from camlab88.protocols.sigma import Encoder

VIEW_SCALE = 512 / FIELD_H          # the twelve-field fills the screen's height
VIEW_CLIP = (0, 0, 767, 511)


@dataclass(frozen=True)
class FourColours:
    """Which of the 3 drawing slots each pen uses, and the 4 slot colours (4-bit RGB)."""

    slot_of_pen: dict[int, int]
    rgb: tuple[tuple[int, int, int], ...]

    def slot(self, pen: int) -> int:
        return self.slot_of_pen.get(pen, 1)


def _pen_rgb(pen: int, background: str) -> tuple[int, int, int]:
    rgb = PALETTE.get(pen, ("", (255, 255, 255)))[1]
    if background == "white" and pen == 1:
        rgb = (0, 0, 0)
    return rgb


def four_colours(seq: AnimSequence, background: str = "black") -> FourColours:
    """The three most used pens (by points, ties to the lower pen) keep their colours."""
    top, slot_of_pen = pen_slots(seq, lambda pen: _pen_rgb(pen, background))
    bg = (15, 15, 15) if background == "white" else (0, 0, 0)
    rgb = [bg] + [tuple(round(v / 17) for v in _pen_rgb(p, background)) for p in top]
    while len(rgb) < 4:
        rgb.append(rgb[-1])
    return FourColours(slot_of_pen, tuple(rgb))


def frame_points_px(frame: Drawing) -> list[tuple[np.ndarray, np.ndarray]]:
    return [(np.column_stack([384 + c.points[:, 0] * VIEW_SCALE,
                              256 + c.points[:, 1] * VIEW_SCALE]), c.colours)
            for c in frame.chains]


def draw_frame(enc: Encoder, frame: Drawing, buffer: int, plan: FourColours) -> bytes:
    """Select the hidden buffer's planes, erase them, draw the frame into them."""
    shift = 2 * buffer
    out = bytearray(enc.write_mask(3 << shift) + enc.erase())
    for pts, cols in frame_points_px(frame):
        for p in chain_prims(pts, cols, VIEW_CLIP, lambda c: plan.slot(c) << shift):
            out += encode(enc, p)
    return bytes(out)


def lut_showing(buffer: int, plan: FourColours) -> list[tuple[int, int, int]]:
    return [plan.rgb[(i >> (2 * buffer)) & 3] for i in range(16)]


def swap(enc: Encoder, buffer: int, plan: FourColours, how: str) -> bytes:
    """Make ``buffer`` the one displayed."""
    if how == "mask":
        return enc.display_mask(3 << (2 * buffer))
    lut = lut_showing(buffer, plan)
    return b"".join(enc.lut(i, *lut[i]) for i in swap_order(buffer))


def swap_order(buffer: int) -> list[int]:
    """LUT entries to rewrite to show ``buffer`` instead of the other one, in an order that
    keeps one whole frame on the screen throughout the ~40 ms the 12 orders take at 9600
    baud: first the entries that add the new frame's pixels (old buffer empty there), then
    the recolourings (both set), last those that remove the old frame's pixels (new buffer
    empty).  Entries whose two buffers hold equal bits look the same either way: never
    resent."""
    def bits(i: int, b: int) -> int:
        return (i >> (2 * b)) & 3

    old = 1 - buffer
    changed = [i for i in range(16) if bits(i, 0) != bits(i, 1)]
    return sorted(changed, key=lambda i: (0 if bits(i, old) == 0 else
                                          2 if bits(i, buffer) == 0 else 1, i))


def setup(enc: Encoder, plan: FourColours, how: str) -> bytes:
    """Reset, LUT showing buffer 1 (empty) - or both buffers' colours for the mask swap."""
    if how == "mask":
        lut = [(0, 0, 0)] * 16
        for v in range(4):
            lut[v] = plan.rgb[v]
            lut[v << 2] = plan.rgb[v]
        out = setup_bytes(enc, lut, cursor=False) + enc.display_mask(0x0C)
    else:
        out = setup_bytes(enc, lut_showing(1, plan), cursor=False)
    return out + enc.write_mask(0x0F) + enc.erase()


@dataclass
class ViewerReport:
    mode: str
    baud: int
    fps: float
    sizes: list[int]                      # characters per frame: drawing + swap
    shown: list[tuple[int, float]] = field(default_factory=list)  # (frame, line time shown)
    dropped: list[int] = field(default_factory=list)
    start: float = 0.0                    # line time the first frame started (after set-up)
    end: float = 0.0                      # line time the last byte arrived
    end_exact: Fraction = Fraction(0)
    sent: list[tuple[Fraction, bytes]] = field(default_factory=list)

    @property
    def shown_frames(self) -> list[int]:
        return [f for f, _ in self.shown]

    @property
    def frame_chars(self) -> int:
        """Characters really sent for frames (drawing + swap), set-up excluded: dropped
        frames are never sent."""
        return sum(len(d) for _, d in self.sent[1:])

    def summary(self) -> str:
        every = "" if not self.dropped else f" (all {len(self.sizes)} would be {sum(self.sizes)})"
        return (f"{self.mode} at {self.baud} baud, {self.fps:g} fps: {len(self.shown)} shown, "
                f"{len(self.dropped)} dropped of {len(self.sizes)} frames; "
                f"{self.frame_chars} characters sent for the frames shown{every}, "
                f"{self.end - self.start:.2f} s of line time")


class LineTest:
    """The viewer program for one sequence: its bytes and its real-time loop."""

    def __init__(self, seq: AnimSequence, swap_how: str = "lut",
                 background: str = "black") -> None:
        if swap_how not in ("lut", "mask"):
            raise ValueError(f"swap is lut or mask, not {swap_how!r}")
        if not seq.frames:
            raise ValueError("the sequence has no frames")
        self.seq = seq
        self.how = swap_how
        self.enc = Encoder()
        self.plan = four_colours(seq, background)

    def frame_bytes(self, j: int, buffer: int) -> tuple[bytes, bytes]:
        return (draw_frame(self.enc, self.seq.frames[j], buffer, self.plan),
                swap(self.enc, buffer, self.plan, self.how))

    def sizes(self) -> list[int]:
        return [sum(map(len, self.frame_bytes(j, 0))) for j in range(len(self.seq.frames))]

    def run(self, mode: str = "realtime", baud: int = 9600, fps: float | None = None
            ) -> ViewerReport:
        """Play the sequence over a line at ``baud`` with nobody at its end: what the host
        sends and when (a line of its own: the host's side only)."""
        settings = LineSettings(baud=baud)
        line = HostOnlyLine(settings)
        host = ViewerHost(self, mode, line.port, settings, fps)
        while host.wake is not None:
            line.run_to(host.wake)
            host.act()
        return host.finish()


class ViewerHost:
    """The viewer as a host program on its port (thesis §3.1.4), a small state machine on
    the line's clock: it acts at line times it chooses (``wake``; None when it is done) --
    choose a frame (dropping those the line cannot carry in real time), write it into the
    hidden buffer, then the swap -- and whoever runs the line runs it to each ``wake`` and
    calls ``act`` (emulator.harness.sigma_batch.host_periods, or ``LineTest.run``)."""

    def __init__(self, test: LineTest, mode: str, port: HostPort, settings: LineSettings,
                 fps: float | None = None) -> None:
        if mode not in ("realtime", "every"):
            raise ValueError(f"mode is realtime or every, not {mode!r}")
        fps = float(fps or test.seq.fps)
        if not (math.isfinite(fps) and fps > 0):
            raise ValueError("fps must be positive")
        self.test, self.mode, self.port = test, mode, port
        self.rate = Fraction(fps).limit_denominator(10000)
        self.ct = settings.char_time
        self.n = len(test.seq.frames)
        self.rep = ViewerReport(mode, settings.baud, fps, test.sizes())
        t0 = self._send(setup(test.enc, test.plan, test.how))
        self.t0 = t0
        self.rep.start = float(t0)
        self.step, self.last, self.buffer, self.j, self.sw = "choose", -1, 0, 0, b""
        self.origin = t0
        self.wake: Fraction | None = t0

    def _send(self, data: bytes) -> Fraction:
        self.rep.sent.append((self.port.exact, data))
        self.port.write(data)
        return Fraction(self.port.drain_exact())

    def act(self) -> None:
        """The host's turn, at line time ``wake``."""
        if self.step == "choose":
            self._choose()
        elif self.step == "swap":
            shown = self._send(self.sw)
            if self.last < 0:  # §3.1.4: time runs from the first frame displayed
                self.origin = shown
            self.rep.shown.append((self.j, float(shown - self.t0)))
            self.last, self.buffer, self.step, self.wake = self.j, 1 - self.buffer, "choose", shown

    def _choose(self) -> None:
        now = self.port.exact
        if self.mode == "every":
            j = self.last + 1
        else:
            due = math.floor((now - self.origin) * self.rate + Fraction(1, 10**9))
            j = max(due, self.last + 1)
        if j >= self.n:
            self.rep.dropped.extend(range(self.last + 1, self.n))
            self.step, self.wake = "done", None
            return
        self.rep.dropped.extend(range(self.last + 1, j))
        draw, sw = self.test.frame_bytes(j, self.buffer)
        drawn = self._send(draw)
        self.j, self.sw, self.step = j, sw, "swap"
        # the swap arrives when the frame is drawn, never before the frame is due
        due_t = self.origin + j / self.rate if self.mode == "realtime" else drawn
        self.wake = max(drawn, due_t - len(sw) * self.ct)

    @property
    def period(self) -> Fraction:
        """One shown frame's worth of line time (1/fps)."""
        return 1 / self.rate

    def finish(self) -> ViewerReport:
        """The report, once done (the line time the last byte arrives)."""
        self.rep.end_exact = Fraction(self.port.drain_exact())
        self.rep.end = float(self.rep.end_exact)
        return self.rep


def run_line_test(seq: AnimSequence, mode: str = "realtime", baud: int = 9600,
                  swap_how: str = "lut", background: str = "black", **kw: Any) -> ViewerReport:
    return LineTest(seq, swap_how, background).run(mode, baud, **kw)


def still_bytes(frame: Drawing, background: str = "black") -> bytes:
    """One frame in full colour (all 4 planes, the editor's LUT): for exports and stills."""
    from camlab88.apps.kas.program.layout import lut_plan

    enc = Encoder()
    out = bytearray(setup_bytes(enc, lut_plan(background), cursor=False) + enc.erase())
    for pts, cols in frame_points_px(frame):
        for p in chain_prims(pts, cols, VIEW_CLIP, lambda c: c if c in PALETTE else 1):
            out += encode(enc, p)
    return bytes(out)
