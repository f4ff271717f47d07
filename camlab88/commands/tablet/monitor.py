"""``camlab88 tablet monitor SOURCE``: one line per decoded tablet event."""

from __future__ import annotations

import argparse
import sys
import time

COMMAND = "camlab88 tablet monitor"
SILENT_HINT = 5.0  # s without a single report before the monitor says what to check


def monitor(args: argparse.Namespace) -> int:
    from emulator.tablet import demo_path
    from emulator.tablet_input.emulated_source import open_tablet

    def raw(data: bytes) -> None:
        print("raw " + data.hex(" "), flush=True)

    _refuse_before_opening(args.source)
    source, emu, spec = open_tablet(args.source, raw if args.raw else None, demo_path())
    held = _Held(source, spec, raw if args.raw else None)
    try:
        _maybe_window(emu, args)
        for note in getattr(source, "size_notes", ()):  # a size reply we could not trust
            print(f"camlab88 tablet: {note}", file=sys.stderr)
        print(f"# {source.name}: {source.model.name}, 0..{source.model.max_x} x "
              f"0..{source.model.max_y}, {source.model.lines_per_inch:g} lpi", flush=True)
        return _loop(held, emu, args)
    finally:
        if emu is not None:
            emu.close()
        elif held.source is not None:
            held.source.close()


class _Held:
    """The real tablet being monitored: lost (unplugged, cable out) it is reopened every
    RETRY s until it comes back; the monitor keeps running meanwhile."""

    RETRY = 0.5

    def __init__(self, source, spec, on_raw) -> None:
        self.source, self.spec, self.on_raw = source, spec, on_raw
        self._next_try = 0.0
        self._opened_at = time.monotonic()
        self._hinted = False

    def hint_if_silent(self, count: int) -> None:
        """Said once: nothing at all for SILENT_HINT s (a tablet without a start-up query
        cannot be told from an empty port any sooner)."""
        if count or self._hinted or time.monotonic() - self._opened_at < SILENT_HINT:
            return
        self._hinted = True
        heard = getattr(self.source, "heard", 0)
        what = ("bytes came but no report decoded: check the protocol and the baud" if heard
                else "nothing at all came: put the pen on the tablet; if still nothing, check "
                "the cable, that the tablet is switched on, the port, the protocol and the baud")
        print(f"camlab88 tablet: {self.spec.text}: no report in {SILENT_HINT:g} s; {what} "
              "(still listening)", file=sys.stderr, flush=True)

    def read(self, timeout: float) -> list:
        from protocols.tablets.sources import SourceLost, open_source

        if self.source is None:
            if time.monotonic() < self._next_try:
                time.sleep(timeout)
                return []
            self._next_try = time.monotonic() + self.RETRY
            try:
                self.source = open_source(self.spec, on_raw=self.on_raw)
            except SourceLost:
                return []
            print(f"camlab88 tablet: {self.spec.text}: back", file=sys.stderr, flush=True)
        try:
            return self.source.read(timeout=timeout)
        except SourceLost as exc:
            self.source.close()
            self.source = None
            self._next_try = time.monotonic() + self.RETRY
            print(f"camlab88 tablet: lost {exc}; waiting for it to come back (Ctrl-C stops)",
                  file=sys.stderr, flush=True)
            return []


def _refuse_before_opening(source_text: str) -> None:
    """A mouse-driven emulated tablet needs a window: without a display refuse before its pty
    is opened and announced (a newcomer saw the pty's path, then the refusal)."""
    from emulator.harness import choose_headless
    from protocols.tablets.sources import SourceError, parse_source

    try:
        spec = parse_source(source_text)
    except (SourceError, ValueError):
        return  # open_tablet reports it
    if spec.kind == "emulated" and spec.options.get("drive", "mouse") == "mouse":
        choose_headless(COMMAND, False, None, "use SOURCE?drive=demo, or a real tablet")


def _maybe_window(emu, args: argparse.Namespace) -> None:
    """The emulated tablet's window: needed for the mouse (the one display rule)."""
    from emulator.harness import choose_headless

    if emu is None or not (emu.drive == "mouse" or args.screenshot):
        return
    can = None if emu.drive == "mouse" else "the scripted stroke, no window"
    if not choose_headless(COMMAND, False, can, "use SOURCE?drive=demo, or a real tablet"):
        emu.open_window()
        print(f"{COMMAND}: window open; the mouse is the pen (o: out of proximity, "
              "e: eraser); close it to quit", file=sys.stderr)


def _loop(held: _Held, emu, args: argparse.Namespace) -> int:
    from protocols.tablets.sources import SourceLost

    count, idle, start = 0, 0, time.monotonic()
    while args.seconds is None or time.monotonic() - start < args.seconds:
        if emu is not None and not emu.step():
            idle += 1
            if (emu.window is not None and emu.script is None) or idle > 20:
                break  # window closed, or the scripted stroke finished and drained
        try:
            events = held.source.read(timeout=0.02) if emu is not None else held.read(0.02)
        except SourceLost as exc:  # the emulated tablet does not come back
            print(f"camlab88 tablet: {exc}", file=sys.stderr)
            return 1
        for e in events[: None if args.count is None else args.count - count]:
            print(e.describe(), flush=True)
            count += 1
        held.hint_if_silent(count)
        if emu is not None:
            emu.show(events)
            if args.screenshot and emu.frames >= 30 and emu.window is not None:
                emu.window.screenshot(args.screenshot)
                print(f"{COMMAND}: screenshot {args.screenshot}", file=sys.stderr)
                break
        if args.count is not None and count >= args.count:
            break
    return 0
