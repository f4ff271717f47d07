"""``camlab88 tablet emulate``: an emulated tablet on a pty, driven by the mouse."""

from __future__ import annotations

import argparse
import sys
import time

COMMAND = "camlab88 tablet emulate"


def emulate(args: argparse.Namespace) -> int:
    from emulator.harness import choose_headless
    from emulator.tablet import demo_path
    from emulator.tablet_input.emulated_source import EmulatedSource
    from protocols.tablets.sources import parse_source

    can = "the scripted stroke, no window" if args.demo and not args.screenshot else None
    headless = choose_headless(COMMAND, False, can, "it is driven by the mouse; try --demo")
    spec = parse_source(f"emulated:{args.protocol}" + ("?drive=demo" if args.demo else ""))
    emu = EmulatedSource(spec, script=demo_path() if args.demo else None, reader=False)
    if not headless:
        emu.open_window()
        print(f"{COMMAND}: window open; the mouse is the pen; close it to quit",
              file=sys.stderr)
    print(f"serial port: {emu.tablet.slave_path}  (open it with pyserial; "
          f"{emu.tablet.line.describe()})", flush=True)
    try:
        _loop(emu, args)
    finally:
        emu.close()
    return 0


def _loop(emu, args: argparse.Namespace) -> None:
    start = time.monotonic()
    while emu.step() or (args.demo and emu.frames < 300):
        if args.seconds is not None and time.monotonic() - start >= args.seconds:
            break
        emu.show(emu.take_local())
        if args.screenshot and emu.frames >= (270 if args.demo else 30):
            emu.window.screenshot(args.screenshot)
            print(f"{COMMAND}: screenshot {args.screenshot}", file=sys.stderr)
            break
        if emu.window is not None:
            emu.window.wait_frame(60)  # the demo too, so a client has time to open the port
        else:
            time.sleep(1 / 60)  # headless demo: the same pace for a client on the pty
