"""Tablet sources for the tablet tools: a real one (HID, serial) or an emulated tablet on a
pty, driven by the window's mouse or a scripted stroke (host input beside the emulated
tablet).  ``open_tablet`` gives ``(source, emulated-or-None, spec)``.

The emulated tablet owns no window: the harness polls the window and hands its events to
``handle``; ``frame`` is the tablet's view (``with_view``) for the harness to show."""

from __future__ import annotations

import sys
from collections.abc import Iterable

import numpy as np

PUCK_PROTOCOLS = ("bitpad1", "bitpad2", "calcomp")  # a four-button puck, not a stylus


class EmulatedSource:
    """An emulated tablet plus the serial source reading its pty, for monitor/calibrate."""

    def __init__(self, spec, on_raw=None, script=None, reader: bool = True) -> None:
        from camlab88.emulator.tablet import EmulatedTablet
        from camlab88.protocols.tablets.registry import make_parser
        from camlab88.protocols.tablets.serial_source import SerialSource
        from camlab88.protocols.tablets.sources import parse_source

        options = {k: v for k, v in spec.options.items() if k != "drive"}
        self.drive = spec.options.get("drive", "mouse")
        if self.drive not in ("mouse", "demo"):
            raise ValueError(f"{spec.text}: drive must be mouse or demo")
        self.tablet = EmulatedTablet(spec.protocol, options)
        self.tablet.serve_in_background()
        query = "&".join(f"{k}={v}" for k, v in options.items())
        url = f"serial:{self.tablet.slave_path}?protocol={spec.protocol}" + (
            f"&{query}" if query else "")
        # With ``reader`` we are the program on the pty (monitor, calibrate).  Without it the
        # pty is left to an outside program and the view decodes the bytes as they are sent.
        self.source = SerialSource(parse_source(url), on_raw=on_raw) if reader else None
        if self.source is not None:
            self.source.name = spec.text
        self.local = make_parser(spec.protocol, options)
        self.local_events: list = []
        self.script = iter(script) if script is not None else None
        self.view = None
        self.frames = 0
        self._pointer = None
        self.away = False  # key "o": out of proximity
        self.eraser = False  # key "e": eraser end (protocols that have one)
        print(f"emulated {self.tablet.model.name} ({spec.protocol}) on {self.tablet.slave_path}",
              file=sys.stderr)

    @property
    def tool(self) -> str:
        return "puck" if self.tablet.protocol in PUCK_PROTOCOLS else "pen"

    @property
    def title(self) -> str:
        return f"camlab88 emulated tablet: {self.tablet.protocol}"

    def with_view(self) -> None:
        """Draw what the tablet sends (for a window), and take the window's mouse."""
        from camlab88.emulator.tablet import TabletView
        from camlab88.emulator.tablet.drive import PointerState

        self.view = TabletView(self.tablet.model)
        self._pointer = PointerState()

    def step(self) -> bool:
        """Advance the scripted stroke one tick; False once it has ended (never without one)."""
        from camlab88.emulator.tablet import pointer_to_tablet

        if self.script is None:
            return True
        nxt = next(self.script, None)
        if nxt is None:
            return False
        fx, fy, buttons = nxt
        w, h = self.view.size if self.view else (1001, 1001)
        self._send(pointer_to_tablet(fx * (w - 1), fy * (h - 1), (w, h), self.tablet.model,
                                     buttons, tool=self.tool))
        return True

    def handle(self, events: Iterable[object]) -> None:
        """The window's events: o (out of proximity), e (eraser end), and the mouse as the
        pen unless a script draws."""
        from camlab88.emulator.host_input import KeyDown
        from camlab88.emulator.tablet import pointer_to_tablet

        if self.view is None:
            return
        tool = self.tool
        for ev in events:
            if isinstance(ev, KeyDown) and ev.key == "o":  # lift the pen out of range
                self.away = not self.away
            elif isinstance(ev, KeyDown) and ev.key == "e" and tool == "pen":
                self.eraser = not self.eraser  # turn the stylus over
            elif not (self.script is None and self._pointer.apply(ev)):
                continue
            p = self._pointer
            self._send(pointer_to_tablet(
                p.x, p.y, self.view.size, self.tablet.model, p.mask, proximity=not self.away,
                tool="eraser" if self.eraser and tool == "pen" else tool))

    def _send(self, event) -> None:
        data = self.tablet.send(event)
        if self.source is None:
            self.local_events += self.local.feed(data)

    def take_local(self) -> list:
        events, self.local_events = self.local_events, []
        return events

    def show(self, events) -> None:
        """One frame's time has passed; the view draws ``events``."""
        self.frames += 1
        if self.view is None:
            return
        # the host may have moved the origin (Summagraphics "b"): draw as the tablet reports
        self.view.model = self.tablet.model
        for e in events:
            self.view.add(e)

    def frame(self) -> np.ndarray:
        """The view (a single black pixel without one: headless)."""
        if self.view is None:
            return np.zeros((1, 1, 3), dtype=np.uint8)
        return self.view.frame()

    def close(self) -> None:
        if self.source is not None:
            self.source.close()
        self.tablet.close()


def open_tablet(source_text: str, on_raw=None, script=None):
    """(source, emulated-or-None, spec) for a SOURCE string; errors become SystemExit
    messages."""
    from camlab88.protocols.tablets.sources import (
        SourceError,
        SourceLost,
        open_source,
        parse_source,
    )

    try:
        spec = parse_source(source_text)
        if spec.kind == "emulated":
            emu = EmulatedSource(spec, on_raw=on_raw,
                                 script=script if spec.options.get("drive") == "demo" else None)
            return emu.source, emu, spec
        return open_source(spec, on_raw=on_raw), None, spec
    except (SourceError, SourceLost, ValueError) as exc:
        raise SystemExit(f"camlab88 tablet: {exc}") from None


def needs_window(source_text: str) -> bool:
    """A SOURCE that is the emulated tablet driven by the mouse (a parse error: False,
    ``open_tablet`` reports it)."""
    from camlab88.protocols.tablets.sources import SourceError, parse_source

    try:
        spec = parse_source(source_text)
    except (SourceError, ValueError):
        return False
    return spec.kind == "emulated" and spec.options.get("drive", "mouse") == "mouse"
