"""Link benchmarks: how many times faster than the line itself the line model runs.

Run by hand: ``python benchmarks/bench_link.py``. Prints figures; docs/perf/link.md holds a
copy. Each figure is virtual line seconds simulated per wall second (the "x line" multiple),
so 1000x means one wall second carries 1000 s of 9600-baud traffic.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

from camlab88.protocols.link import (
    LineSettings,
    Recorder,
    SerialLine,
    chunks_by_period,
    read_recording,
)


def timed(fn) -> float:
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def bench_big_write_read_per_frame(nbytes: int = 1_000_000) -> str:
    data = bytes(i % 97 + 32 for i in range(nbytes))
    line = SerialLine()

    def run() -> None:
        line.host.write(data)
        got = 0
        k = 0
        while got < nbytes:
            k += 1
            line.clock.advance_to(Fraction(k, 25))
            got += len(line.device.read())

    wall = timed(run)
    virtual = nbytes / 960
    return f"one {nbytes} B write, read every 1/25 s: {virtual / wall:,.0f}x line ({wall:.3f} s)"


def bench_small_writes(nwrites: int = 50_000, size: int = 20) -> str:
    line = SerialLine()
    chunk = b"+-*/GA123456789012"[:size]

    def run() -> None:
        for i in range(nwrites):
            if i % 48 == 0:  # ~ a poll every 1/25 s of line time
                line.clock.advance_to(Fraction(i * size, 960))
                line.device.read()
            line.host.write(chunk)
        line.finish()
        line.device.read(until=10**9)

    wall = timed(run)
    virtual = nwrites * size / 960
    return f"{nwrites} writes of {size} B with reads: {virtual / wall:,.0f}x line ({wall:.3f} s)"


def bench_xonxoff(cycles: int = 2_000) -> str:
    line = SerialLine()

    def run() -> None:
        line.host.write(bytes(100) * cycles)
        for k in range(cycles):
            line.clock.advance_to(Fraction(k * 100 + 50, 960))
            line.device.read()
            line.device.write(b"\x13")
            line.clock.advance_to(Fraction(k * 100 + 80, 960))
            line.device.write(b"\x11")
        line.finish()

    wall = timed(run)
    virtual = line.finish()
    return f"XOFF/XON every 100 B, {cycles} cycles: {virtual / wall:,.0f}x line ({wall:.3f} s)"


def bench_chunks(nbytes: int = 1_000_000) -> str:
    data = bytes(nbytes)
    wall = timed(lambda: sum(1 for _ in chunks_by_period(data, LineSettings(), 0.04)))
    return f"chunks_by_period 1/25 s on {nbytes} B: {nbytes / 960 / wall:,.0f}x line ({wall:.3f} s)"


def bench_recording(nbytes: int = 200_000) -> str:
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "b.rec")
        line = SerialLine(recorder=Recorder(path, LineSettings()))
        data = bytes(i % 251 for i in range(nbytes))

        def record() -> None:
            for k in range(0, nbytes, 130):  # PGPLOT-sized buffers
                line.clock.advance_to(Fraction(k, 960))
                line.host.write(data[k : k + 130])
                line.device.read()
            line.close()

        w1 = timed(record)
        size = os.path.getsize(path)
        w2 = timed(lambda: read_recording(path))
    virtual = nbytes / 960
    return (
        f"record {nbytes} B in 130 B writes: {virtual / w1:,.0f}x line ({w1:.3f} s), "
        f"file {size / nbytes:.2f} B per byte; read back {virtual / w2:,.0f}x ({w2:.3f} s)"
    )


def main() -> None:
    base = timed(lambda: subprocess.run([sys.executable, "-c", "pass"], check=True))
    full = timed(
        lambda: subprocess.run([sys.executable, "-c", "import camlab88.protocols.link"], check=True)
    )
    print(f"import camlab88.protocols.link: {1000 * (full - base):.0f} ms over a bare interpreter")
    for bench in (
        bench_big_write_read_per_frame,
        bench_small_writes,
        bench_xonxoff,
        bench_chunks,
        bench_recording,
    ):
        print(bench())


if __name__ == "__main__":
    main()
