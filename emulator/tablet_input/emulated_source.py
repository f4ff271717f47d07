"""Tablet sources for the tablet tools: a real one (HID, serial) or an emulated tablet on a
pty, driven by the window's mouse or a scripted stroke (host input beside the emulated
tablet).  ``open_tablet`` gives ``(source, emulated-or-None, spec)``."""

from __future__ import annotations

import sys


class EmulatedSource:
    """An emulated tablet plus the serial source reading its pty, for monitor/calibrate."""

    def __init__(self, spec, on_raw=None, script=None, reader: bool = True) -> None:
        from emulator.tablet import EmulatedTablet
        from protocols.tablets.registry import make_parser
        from protocols.tablets.serial_source import SerialSource
        from protocols.tablets.sources import parse_source

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
        self.window = None
        self.view = None
        self.frames = 0
        self._pointer = None
        self.away = False  # key "o": out of proximity
        self.eraser = False  # key "e": eraser end (protocols that have one)
        print(f"emulated {self.tablet.model.name} ({spec.protocol}) on {self.tablet.slave_path}",
              file=sys.stderr)

    def open_window(self) -> None:
        from emulator.tablet import TabletView
        from emulator.tablet.drive import PointerState
        from emulator.window import Window

        self.view = TabletView(self.tablet.model)
        self.window = Window(f"camlab88 emulated tablet: {self.tablet.protocol}", self.view.size)
        self._pointer = PointerState()

    def step(self) -> bool:
        """Advance the driver one tick; False when the script ends or the window closes."""
        from emulator.host_input import KeyDown, Quit
        from emulator.tablet import pointer_to_tablet

        model = self.tablet.model
        tool = "puck" if self.tablet.protocol in ("bitpad1", "bitpad2", "calcomp") else "pen"
        if self.script is not None:
            nxt = next(self.script, None)
            if nxt is None:
                return False
            fx, fy, buttons = nxt
            w, h = self.view.size if self.view else (1001, 1001)
            event = pointer_to_tablet(fx * (w - 1), fy * (h - 1), (w, h), model, buttons,
                                      tool=tool)
            self._send(event)
        if self.window is not None:
            for ev in self.window.poll():
                if isinstance(ev, Quit):
                    return False
                if isinstance(ev, KeyDown) and ev.key == "o":  # lift the pen out of range
                    self.away = not self.away
                elif isinstance(ev, KeyDown) and ev.key == "e" and tool == "pen":
                    self.eraser = not self.eraser  # turn the stylus over
                elif not (self.script is None and self._pointer.apply(ev)):
                    continue
                p = self._pointer
                self._send(pointer_to_tablet(
                    p.x, p.y, self.view.size, model, p.mask, proximity=not self.away,
                    tool="eraser" if self.eraser and tool == "pen" else tool))
        return True

    def _send(self, event) -> None:
        data = self.tablet.send(event)
        if self.source is None:
            self.local_events += self.local.feed(data)

    def take_local(self) -> list:
        events, self.local_events = self.local_events, []
        return events

    def show(self, events) -> None:
        if self.window is None:
            self.frames += 1  # headless: a frame's time has still passed
            return
        # the host may have moved the origin (Summagraphics "b"): draw as the tablet reports
        self.view.model = self.tablet.model
        for e in events:
            self.view.add(e)
        self.window.show(self.view.frame())
        self.frames += 1

    def close(self) -> None:
        if self.source is not None:
            self.source.close()
        self.tablet.close()
        if self.window is not None:
            self.window.close()


def open_tablet(source_text: str, on_raw=None, script=None):
    """(source, emulated-or-None, spec) for a SOURCE string; errors become SystemExit
    messages."""
    from protocols.tablets.sources import SourceError, SourceLost, open_source, parse_source

    try:
        spec = parse_source(source_text)
        if spec.kind == "emulated":
            emu = EmulatedSource(spec, on_raw=on_raw,
                                 script=script if spec.options.get("drive") == "demo" else None)
            return emu.source, emu, spec
        return open_source(spec, on_raw=on_raw), None, spec
    except (SourceError, SourceLost, ValueError) as exc:
        raise SystemExit(f"camlab88 tablet: {exc}") from None


