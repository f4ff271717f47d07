"""Tablet decoding throughput: serial parsers (events/s vs the line's own rate) and HID.

Run: python benchmarks/bench_tablets.py   (prints figures; copy them to docs/perf/tablets.md)
"""

from __future__ import annotations

import platform
import time
from pathlib import Path

from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.hid_decode import PenDecoder
from camlab88.protocols.tablets.hid_descriptor import parse_descriptor, parse_hex_text
from camlab88.protocols.tablets.registry import PROTOCOL_NAMES, make_encoder, make_parser

DATA = Path(__file__).resolve().parents[1] / "tests" / "data" / "tablets" / "digimend-tablets"
N = 20000


def events_for(name: str) -> list[TabletEvent]:
    tool = "puck" if name in ("bitpad1", "bitpad2", "calcomp") else "pen"
    pressure = 100 if name == "wacom4" else None
    return [TabletEvent(k % 2000, (k * 7) % 2000, True, k % 2, pressure, tool=tool)
            for k in range(N)]


def bench_serial() -> None:
    print(f"{'protocol':10} {'bytes/event':>11} {'events/s':>10} {'x 9600-baud line':>17}")
    for name in PROTOCOL_NAMES:
        enc = make_encoder(name)
        data = b"".join(enc.encode(e) for e in events_for(name))
        parser = make_parser(name)
        t = time.perf_counter()
        for k in range(0, len(data), 64):  # 64-byte reads, as a serial port delivers them
            parser.feed(data[k : k + 64])
        dt = time.perf_counter() - t
        per_event = len(data) / N
        line_rate = 960 / per_event  # events/s a 9600-baud 10-bit-char line can carry
        print(f"{name:10} {per_event:11.1f} {N / dt:10.0f} {N / dt / line_rate:17.0f}")


def bench_hid() -> None:
    desc_path = DATA / "Huion_H610" / "rd" / "original0.txt"
    desc = parse_descriptor(parse_hex_text(desc_path.read_text()))
    pen = PenDecoder(desc)
    reports = [bytes.fromhex(line.strip()) for line in
               (DATA / "Huion_H610" / "dumps" / "pen_pressure.txt").read_text().splitlines()
               if line.strip() and ":" not in line]
    reps = max(1, N // len(reports))
    t = time.perf_counter()
    for _ in range(reps):
        for r in reports:
            pen.decode(r)
    dt = time.perf_counter() - t
    print(f"HID Huion H610 pen reports: {reps * len(reports) / dt:.0f} reports/s "
          "(a USB tablet sends ~200-1000/s)")
    t = time.perf_counter()
    for _ in range(200):
        parse_descriptor(desc.data)
    print(f"HID descriptor parse (179 bytes): {(time.perf_counter() - t) / 200 * 1e6:.0f} us")


if __name__ == "__main__":
    print(f"machine: 2-core x86_64 sandbox, Python {platform.python_version()}")
    bench_serial()
    bench_hid()
