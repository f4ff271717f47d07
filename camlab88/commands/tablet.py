"""``camlab88 tablet``: list, monitor, calibrate and emulate graphics tablets."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

SOURCE_HELP = (
    "hid:VID:PID | serial:PORT?protocol=P[&baud=N] | URL?protocol=P (loop://, socket://...) | "
    "emulated:P[?drive=demo]; P = wacom4, summa-mm, bitpad1, bitpad2, calcomp"
)


def _positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, not {value}")
    return value


def register(subparsers: Any) -> None:
    p = subparsers.add_parser("tablet", help="graphics tablets: real (HID/serial) and emulated",
                              description="Graphics tablets over USB HID or serial, and an "
                              "emulated tablet that speaks a real protocol on a pty.")
    sub = p.add_subparsers(dest="tablet_command", metavar="ACTION")
    sub.required = True

    s = sub.add_parser("list", help="HID digitizers and serial ports found")
    s.set_defaults(handler=cmd_list)

    s = sub.add_parser("monitor", help="print one line per decoded event",
                       description="Print one line per decoded event: x and y in tablet "
                       "units, pressure, buttons, proximity.")
    s.add_argument("source", metavar="SOURCE", help=SOURCE_HELP)
    s.add_argument("--raw", action="store_true", help="also print the raw bytes/reports in hex")
    s.add_argument("--count", type=_positive, default=None, help="stop after N events (N >= 1)")
    s.add_argument("--seconds", type=float, default=None, help="stop after S seconds")
    s.add_argument("--screenshot", default=None,
                   help="(emulated, mouse-driven) save the window after a few frames and exit")
    s.set_defaults(handler=cmd_monitor)

    s = sub.add_parser("calibrate", help="touch two corners; saved per device",
                       description="Touch the top-left then the bottom-right corner of the "
                       "working area. Saved under $CAMLAB88_CONFIG_DIR (else "
                       "~/.config/camlab88)/calibration.json.")
    s.add_argument("source", metavar="SOURCE", help=SOURCE_HELP)
    s.add_argument("--seconds", type=float, default=120.0, help="give up after S seconds")
    s.set_defaults(handler=cmd_calibrate)

    s = sub.add_parser("emulate", help="an emulated tablet on a pty, driven by the mouse",
                       description="Open a window; the mouse drives a tablet that writes its "
                       "protocol's bytes to a pseudo-terminal (path printed) that any program "
                       "can open as a serial port. Left button = tip, right = barrel, middle = "
                       "button 2; key o = out of proximity, e = eraser end.")
    s.add_argument("--protocol", default="summa-mm", help="wacom4, summa-mm (default), "
                   "bitpad1, bitpad2, calcomp, summa-flair")
    s.add_argument("--demo", action="store_true", help="draw a scripted stroke, not the mouse")
    s.add_argument("--seconds", type=float, default=None, help="exit after S seconds")
    s.add_argument("--screenshot", default=None, help="save the window after a few frames, exit")
    s.set_defaults(handler=cmd_emulate)


def cmd_list(args: argparse.Namespace) -> int:
    from protocols.tablets.hid_source import list_digitizers

    devices, note = list_digitizers()
    print("HID digitizers:")
    for d in devices:
        print("  " + d.describe())
    if not devices:
        print("  (none found)" + (f": {note}" if note else ""))
    print("Serial ports:")
    try:
        from serial.tools import list_ports

        ports = sorted(list_ports.comports(), key=lambda p: p.device)
    except (ImportError, OSError) as exc:
        ports = []
        print(f"  (cannot list: {exc})")
    for port in ports:
        extra = f"  {port.vid:04x}:{port.pid:04x}" if port.vid is not None else ""
        print(f"  {port.device}  {port.description}{extra}")
    if not ports:
        print("  (none found)")
    print("Serial protocols: wacom4, summa-mm, bitpad1, bitpad2, calcomp "
          "(use serial:PORT?protocol=NAME)")
    return 0


class _Emulated:
    """An emulated tablet plus the serial source reading its pty, for monitor/calibrate."""

    def __init__(self, spec, on_raw=None, script=None, reader: bool = True) -> None:
        from emulator.tablet import EmulatedTablet
        from protocols.tablets.registry import make_parser
        from protocols.tablets.serial_source import SerialSource
        from protocols.tablets.sources import parse_source

        options = {k: v for k, v in spec.options.items() if k != "drive"}
        self.drive = spec.options.get("drive", "mouse")
        if self.drive not in ("mouse", "demo"):
            raise SystemExit(f"{spec.text}: drive must be mouse or demo")
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


def _open(source_text: str, on_raw=None, script=None):
    """(source, emulated-or-None) for a SOURCE string; errors become SystemExit messages."""
    from protocols.tablets.sources import SourceError, SourceLost, open_source, parse_source

    try:
        spec = parse_source(source_text)
        if spec.kind == "emulated":
            emu = _Emulated(spec, on_raw=on_raw,
                            script=script if spec.options.get("drive") == "demo" else None)
            return emu.source, emu, spec
        return open_source(spec, on_raw=on_raw), None, spec
    except (SourceError, SourceLost, ValueError) as exc:
        raise SystemExit(f"camlab88 tablet: {exc}") from None


def cmd_monitor(args: argparse.Namespace) -> int:
    from emulator.tablet import demo_path
    from protocols.tablets.sources import SourceLost

    def raw(data: bytes) -> None:
        print("raw " + data.hex(" "), flush=True)

    source, emu, spec = _open(args.source, raw if args.raw else None, demo_path())
    if emu is not None and (emu.drive == "mouse" or args.screenshot):
        emu.open_window()
    for note in getattr(source, "size_notes", ()):  # a size reply we could not trust
        print(f"camlab88 tablet: {note}", file=sys.stderr)
    print(f"# {source.name}: {source.model.name}, 0..{source.model.max_x} x "
          f"0..{source.model.max_y}, {source.model.lines_per_inch:g} lpi", flush=True)
    count = 0
    start = time.monotonic()
    idle_after_script = 0
    try:
        while True:
            if args.seconds is not None and time.monotonic() - start >= args.seconds:
                break
            if emu is not None and not emu.step():
                idle_after_script += 1
                if emu.window is not None and emu.script is None:
                    break  # window closed
                if idle_after_script > 20:
                    break  # scripted stroke finished and drained
            try:
                events = source.read(timeout=0.02)
            except SourceLost as exc:
                print(f"camlab88 tablet: {exc}", file=sys.stderr)
                return 1
            for e in events:
                print(e.describe(), flush=True)
                count += 1
                if args.count is not None and count >= args.count:
                    break
            if emu is not None:
                emu.show(events)
                if args.screenshot and emu.frames >= 30 and emu.window is not None:
                    emu.window.screenshot(args.screenshot)
                    break
            if args.count is not None and count >= args.count:
                break
    finally:
        (emu or source).close()
    return 0


def cmd_calibrate(args: argparse.Namespace) -> int:
    from protocols.tablets.calibration import CalibrationSession, save_calibration
    from protocols.tablets.sources import SourceLost

    taps = [(0.1, 0.1, 0)] * 3 + [(0.1, 0.1, 1)] * 3 + [(0.1, 0.1, 0)] * 3
    taps += [(0.9, 0.9, 0)] * 3 + [(0.9, 0.9, 1)] * 3 + [(0.9, 0.9, 0)] * 3
    source, emu, spec = _open(args.source, script=taps)
    if emu is not None and emu.drive == "mouse":
        emu.open_window()
    key = spec.device_key
    session = CalibrationSession(key)
    print(session.prompt, flush=True)
    start = time.monotonic()
    try:
        while not session.done:
            if time.monotonic() - start > args.seconds:
                print("camlab88 tablet: calibration timed out", file=sys.stderr)
                return 1
            if emu is not None:
                emu.step()
            try:
                events = source.read(timeout=0.02)
            except SourceLost as exc:
                print(f"camlab88 tablet: {exc}", file=sys.stderr)
                return 1
            if emu is not None:
                emu.show(events)
            for e in events:
                if session.feed(e):
                    print(f"corner at x={e.x} y={e.y}", flush=True)
                    if session.prompt:
                        print(session.prompt, flush=True)
    finally:
        (emu or source).close()
    try:
        cal = session.result()
        path = save_calibration(cal)
    except (ValueError, OSError) as exc:
        print(f"camlab88 tablet: {exc}", file=sys.stderr)
        return 1
    print(f"saved {key}: top-left {cal.top_left}, bottom-right {cal.bottom_right} -> {path}")
    return 0


def cmd_emulate(args: argparse.Namespace) -> int:
    from emulator.tablet import demo_path
    from protocols.tablets.sources import parse_source

    spec = parse_source(f"emulated:{args.protocol}" + ("?drive=demo" if args.demo else ""))
    emu = _Emulated(spec, script=demo_path() if args.demo else None, reader=False)
    emu.open_window()
    print(f"serial port: {emu.tablet.slave_path}  (open it with pyserial; "
          f"{emu.tablet.line.describe()})", flush=True)
    start = time.monotonic()
    try:
        while emu.step() or (args.demo and emu.frames < 300):
            if args.seconds is not None and time.monotonic() - start >= args.seconds:
                break
            emu.show(emu.take_local())
            if args.screenshot and emu.frames >= (270 if args.demo else 30):
                emu.window.screenshot(args.screenshot)
                break
            emu.window.wait_frame(60)  # the demo too, so a client has time to open the port
    finally:
        emu.close()
    return 0


class TabletInput:
    """Pointer input for a program window: the configured tablet, or the mouse.

    ``source`` is a SOURCE string or None (mouse only).  With ``emulated:P`` the window's mouse
    drives the emulated tablet, whose bytes come back through its pty and the protocol parser
    -- the same path a real tablet takes.  Programs call :meth:`poll` once per frame with the
    window's mouse samples and get :class:`protocols.tablets.input_layer.PointerEvent`s in
    their working coordinates.
    """

    def __init__(self, source: str | None, area=None, notify=None) -> None:
        from protocols.tablets.calibration import load_calibration
        from protocols.tablets.input_layer import TWELVE_FIELD, InputLayer
        from protocols.tablets.sources import SourceLost, open_source, parse_source

        self._emu = None
        area = area or TWELVE_FIELD
        if source is None:
            self.layer = InputLayer(area, None, notify=notify)
            return
        spec = parse_source(source)
        calibration = load_calibration(spec.device_key)
        if spec.kind == "emulated":
            from emulator.tablet import EmulatedTablet
            from protocols.tablets.serial_source import SerialSource

            options = {k: v for k, v in spec.options.items() if k != "drive"}
            self._emu = EmulatedTablet(spec.protocol, options)
            self._emu.assume_initialised()  # read with init=0: set up as our start-up would
            query = "".join(f"&{k}={v}" for k, v in options.items())  # tilt=1, flair=1, ...
            url = f"serial:{self._emu.slave_path}?protocol={spec.protocol}&init=0{query}"
            opened = SerialSource(parse_source(url))
            opened.name = spec.text

            def reopen():
                raise SourceLost("the emulated tablet does not come back")
        else:
            def reopen():
                return open_source(spec)

            try:
                opened = open_source(spec)
            except SourceLost as exc:
                opened = None
                if notify:
                    notify(f"{source}: {exc}; using the mouse until it appears")
            for note in getattr(opened, "size_notes", ()):
                if notify:
                    notify(note)
        self.layer = InputLayer(area, opened, reopen=reopen, calibration=calibration,
                                notify=notify)

    def poll(self, mouse=()) -> list:
        if self._emu is not None and self.layer.active == "tablet":
            from emulator.tablet import pointer_to_tablet

            for m in mouse:
                self._emu.send(pointer_to_tablet(m.x, m.y, m.view_size, self._emu.model,
                                                 m.buttons))
            if not mouse:
                self._emu.repeat()  # a streaming tablet reports a still pen too
            return self.layer.poll((), timeout=0.0)
        return self.layer.poll(mouse)

    def close(self) -> None:
        self.layer.close()
        if self._emu is not None:
            self._emu.close()
