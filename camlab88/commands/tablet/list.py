"""``camlab88 tablet list``: the HID digitizers and serial ports found."""

from __future__ import annotations

import argparse

HELP = "HID digitizers and serial ports found"



def run(args: argparse.Namespace) -> int:
    from camlab88.protocols.tablets.hid_source import backend_name, list_digitizers

    devices, note = list_digitizers()
    print(f"HID digitizers (backend: {backend_name()}):")
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


