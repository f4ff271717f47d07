"""``camlab88 tablet calibrate SOURCE``: touch two corners; saved per device."""

from __future__ import annotations

import argparse
import sys
import time

# the scripted stroke of an emulated ?drive=demo tablet: a tap near each corner
TAPS = ([(0.1, 0.1, 0)] * 3 + [(0.1, 0.1, 1)] * 3 + [(0.1, 0.1, 0)] * 3
        + [(0.9, 0.9, 0)] * 3 + [(0.9, 0.9, 1)] * 3 + [(0.9, 0.9, 0)] * 3)


def calibrate(args: argparse.Namespace) -> int:
    from emulator.tablet_input.emulated_source import open_tablet
    from protocols.tablets.calibration import CalibrationSession, save_calibration

    source, emu, spec = open_tablet(args.source, script=TAPS)
    if emu is not None and emu.drive == "mouse":
        emu.open_window()
    session = CalibrationSession(spec.device_key)
    print(session.prompt, flush=True)
    try:
        if not _touch(session, source, emu, args.seconds):
            return 1
    finally:
        (emu or source).close()
    try:
        cal = session.result()
        path = save_calibration(cal)
    except (ValueError, OSError) as exc:
        print(f"camlab88 tablet: {exc}", file=sys.stderr)
        return 1
    print(f"saved {spec.device_key}: top-left {cal.top_left}, bottom-right "
          f"{cal.bottom_right} -> {path}")
    return 0


def _touch(session, source, emu, seconds: float) -> bool:
    """Read reports until both corners are touched; False on a timeout or a lost tablet."""
    from protocols.tablets.sources import SourceLost

    start, seen = time.monotonic(), 0
    while not session.done:
        if time.monotonic() - start > seconds:
            print(f"camlab88 tablet: {source.name}: calibration gave up after {seconds:g} s: "
                  f"{_hint(source, seen)}", file=sys.stderr)
            return False
        if emu is not None:
            emu.step()
        try:
            events = source.read(timeout=0.02)
        except SourceLost as exc:
            print(f"camlab88 tablet: {exc}", file=sys.stderr)
            return False
        seen += len(events)
        if emu is not None:
            emu.show(events)
        for e in events:
            if session.feed(e):
                print(f"corner at x={e.x} y={e.y}", flush=True)
                if session.prompt:
                    print(session.prompt, flush=True)
    return True


def _hint(source, seen: int) -> str:
    """What to check when no corner came: nothing at all from the device, or no press."""
    if seen:
        return (f"{seen} reports came but no corner was pressed: touch each corner with the "
                "tip (or press the first puck button) and lift it again")
    if getattr(source, "heard", 0):
        return ("bytes came but none decoded as a report: check the protocol "
                "(?protocol=...) and the line speed (?baud=N)")
    return ("nothing came from the tablet: check the cable and that the tablet is switched "
            "on, the port, the protocol and the baud ('camlab88 tablet monitor SOURCE' shows "
            "every report)")
